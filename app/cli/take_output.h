#pragma once
/// Where a command writes one take (`-o X.bvh|X.glb|X.csv`): the same writer as the
/// workbench's File > Export Take (render/take_export.h), with the default puppet body for
/// takes that carry no skeleton of their own.

#include "analysis/core/take.h"
#include "analysis/io/staged_folder.h"

#include <string>

namespace bunraku::app::cli {

/// True when `output` names a take file the writer knows (.bvh, .glb, .csv).
bool isTakeOutput(const std::string& output);
/// Throws CliError unless `output` names a .bvh, .glb or .csv file (checked before any work).
void requireTakeOutput(const std::string& output);
/// Writes the take by the output's extension, atomically; throws CliError naming the file.
/// Prints render::takeExportNote (which of skeleton and channels the file holds, when they
/// differ) as a "note:" line on stderr.
void writeTakeOutput(const analysis::Take& take, const std::string& output);

/// The same writer (and note) for a take inside a folder output: written as `name` (.bvh, .glb,
/// .csv) into the staging folder and listed in its manifest like the folder's other files.
void writeTakeIntoFolder(const analysis::Take& take, analysis::io::StagedFolder& folder, const std::string& name);

} // namespace bunraku::app::cli
