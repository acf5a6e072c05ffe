#include "app/cli/cli.h"

int main(int argc, char** argv) { return bunraku::app::cli::runCli(argc, argv); }
