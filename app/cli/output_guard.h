#pragma once
/// One check every command runs before writing: an output must never be one of its inputs or
/// hold one. `phase --sample t.csv -o t.csv` would overwrite its input, `convert DIR -o DIR`
/// would replace the folder it reads; both are refused with a message naming the paths.

#include <initializer_list>
#include <string>
#include <vector>

namespace bunraku::app::cli {

enum class OutputKind {
    File,   ///< the output is one file: refused when it is an input (also through links)
    Folder, ///< the output is a folder that is replaced: refused when it is or holds an input
};

/// Throws CliError when `output` would overwrite or replace one of `inputs` (empty entries and
/// "demo:..." specs are ignored). `option` names the output option in the message ("-o").
void refuseOutputOverInputs(const std::string& output, OutputKind kind, const std::vector<std::string>& inputs,
                            const std::string& option = "-o");

} // namespace bunraku::app::cli
