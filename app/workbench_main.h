#pragma once
/// The workbench's entry point: `bunraku-workbench [PATHS...] [--screenshot FILE]`. PATHS are a
/// corpus folder or its corpus.json, a project file, and/or take files (launch_paths.h); without
/// them the embedded demo corpus opens. --screenshot grabs the window once it has shown, writes
/// FILE and quits (docs, bug reports). --help and --version answer without a display.

namespace bunraku::app {

int runWorkbench(int argc, char** argv);

} // namespace bunraku::app
