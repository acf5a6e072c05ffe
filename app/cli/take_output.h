#pragma once
/// Where a command writes one take (`-o X.bvh|X.glb|X.csv`): the same writer as the
/// workbench's File > Export Take (render/take_export.h), with the default puppet body for
/// takes that carry no skeleton of their own.

#include "analysis/cloth/kimono_cloth.h"
#include "analysis/core/take.h"
#include "analysis/io/staged_folder.h"

#include <CLI/CLI.hpp>

#include <string>

namespace bunraku::app::cli {

/// True when `output` names a take file the writer knows (.bvh, .glb, .csv).
bool isTakeOutput(const std::string& output);
/// Throws CliError unless `output` names a .bvh, .glb or .csv file (checked before any work).
void requireTakeOutput(const std::string& output);
/// Writes the take by the output's extension, atomically; throws CliError naming the file.
/// Prints render::takeExportNote (which of skeleton and channels the file holds, when they
/// differ) as a "note:" line on stderr. With `kimono` (--kimono), the simulated kimono goes into
/// the file too (render::exportTake: a .glb's morph-animated cloth, a .csv's 18 channels).
void writeTakeOutput(const analysis::Take& take, const std::string& output, const analysis::ClothParameters* kimono = nullptr);

/// --kimono and the cloth options (addClothOptions) of a command that writes one take (`-o
/// X.glb|X.csv`): the simulated kimono in the file.
struct KimonoOutputArguments {
    bool kimono = false;
    analysis::ClothParameters cloth;
    const analysis::ClothParameters* parameters() const { return kimono ? &cloth : nullptr; }
};
void addKimonoOutputOptions(CLI::App* command, KimonoOutputArguments& arguments);
/// Throws CliError when --kimono is given and `output` is not a .glb or .csv file (checked
/// before any work).
void requireKimonoOutput(const KimonoOutputArguments& arguments, const std::string& output);

/// The same writer (and note) for a take inside a folder output: written as `name` (.bvh, .glb,
/// .csv) into the staging folder and listed in its manifest like the folder's other files.
void writeTakeIntoFolder(const analysis::Take& take, analysis::io::StagedFolder& folder, const std::string& name);

} // namespace bunraku::app::cli
