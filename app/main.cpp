#include "app/workbench_main.h"

int main(int argc, char** argv) { return bunraku::app::runWorkbench(argc, argv); }
