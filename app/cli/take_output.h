#pragma once
/// Where a command writes: one take (`-o X.bvh|X.glb|X.csv`), by the same writer as the
/// workbench's File > Export Take (render/take_export.h), with the default puppet body for
/// takes that carry no skeleton of their own; or a folder of files with its summary.json.

#include "analysis/cloth/kimono_cloth.h"
#include "analysis/core/take.h"
#include "analysis/io/staged_folder.h"
#include "analysis/report/analysis_files.h"

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <string>
#include <vector>

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

/// A command's folder output (`-o DIR`): its files, then summary.json, built in a hidden folder
/// beside DIR and swapped in whole at commit, so a killed run leaves the previous output whole,
/// never some files of each (refused when DIR holds files this program did not write there).
class FolderOutput {
public:
    explicit FolderOutput(const std::string& folder);
    /// `text` as the file `name`.
    void add(const std::string& name, const std::string& text);
    void add(const std::vector<analysis::report::OutputFile>& files);
    /// The take as `name` (.bvh, .glb, .csv) by writeTakeOutput's writer (and note), listed in the
    /// folder's manifest like its other files; errors name the file asked for, not the hidden folder.
    void addTake(const analysis::Take& take, const std::string& name);
    /// The files added so far, in order.
    const std::vector<std::string>& files() const { return m_files; }
    /// The summary with "files" (their names) and "output" (the folder) written as summary.json,
    /// and the folder swapped in.
    void commit(nlohmann::json& summary);

private:
    std::string m_folder;
    analysis::io::StagedFolder m_staged;
    std::vector<std::string> m_files;
};

} // namespace bunraku::app::cli
