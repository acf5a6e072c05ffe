#pragma once
/// Import options shared by the commands that read take files (info, convert, corpus): the BVH
/// part map (--joints, --joint-map, --side), axes and units (--up-axis, --units), the layout
/// (--all-joints) and the rates of CSV and FASTRAK files.
#include "app/cli/cli.h"

#include "analysis/io/take_reader.h"

#include <string>

namespace bunraku::app::cli {

struct ImportArguments {
    std::string joints;
    std::string jointMapFile;
    std::string side = "right";
    std::string upAxis = "auto";
    std::string units = "auto";
    bool allJoints = false;
    double rateHz = 0.0;
    std::string fastrakUnits = "cm";
};

/// Registers the options on `command`; `withLayout` adds --all-joints.
void addImportOptions(CLI::App* command, ImportArguments& arguments, bool withLayout = true);
/// The library options the arguments stand for (CliError on a bad joint map or rate).
analysis::io::ImportOptions importOptions(const ImportArguments& arguments);

} // namespace bunraku::app::cli
