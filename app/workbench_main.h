#pragma once
/// The workbench's entry point: `bunraku-workbench [PATH] [--screenshot FILE]`. PATH is a corpus
/// folder, a project file or a take file; without it the embedded demo corpus opens.
/// --screenshot grabs the window once it has shown, writes FILE and quits (docs, bug reports).

namespace bunraku::app {

int runWorkbench(int argc, char** argv);

} // namespace bunraku::app
