#pragma once
/// Import options shared by the commands that read take files (info, convert, corpus): the BVH
/// part map (--joints, --joint-map, --side), axes and units (--up-axis, --units), the layout
/// (--all-joints), the rates of CSV and FASTRAK files, and the animation and rate of FBX, glTF
/// and Collada files (--animation, --rate).
#include "app/cli/cli.h"

#include "analysis/io/take_reader.h"

#include <optional>
#include <string>

namespace bunraku::app::cli {

struct ImportArguments {
    std::string joints;
    std::string jointMapFile;
    std::string side = "right";
    std::string upAxis = "auto";
    std::string units = "auto";
    bool allJoints = false;
    std::optional<double> rateHz; ///< --rate, when given
    std::string fastrakUnits = "cm";
    std::string animation; ///< --animation NAME|INDEX (FBX, glTF, Collada)
};

/// Registers the options on `command`; `withLayout` adds --all-joints.
void addImportOptions(CLI::App* command, ImportArguments& arguments, bool withLayout = true);
/// The library options the arguments stand for (CliError on a bad joint map or rate; `path`,
/// the file they are for, names it in the error).
analysis::io::ImportOptions importOptions(const ImportArguments& arguments, const std::string& path = {});

} // namespace bunraku::app::cli
