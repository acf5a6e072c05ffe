#include "app/cli/take_output.h"

#include "app/cli/cli.h"
#include "app/cli/commands.h"

#include "analysis/body/body_description.h"
#include "render/take_export.h"

#include <filesystem>
#include <iostream>

namespace bunraku::app::cli {

bool isTakeOutput(const std::string& output) { return render::takeExportFormat(output) != render::TakeExportFormat::Unknown; }

void requireTakeOutput(const std::string& output)
{
    if (!isTakeOutput(output)) throw CliError(output + ": unknown output type, " + render::takeExportExpectation());
}

void writeTakeOutput(const analysis::Take& take, const std::string& output, const analysis::ClothParameters* kimono)
{
    requireTakeOutput(output);
    render::KimonoExport cloth;
    if (kimono) cloth.cloth = *kimono;
    unwrap(render::exportTake(take, analysis::defaultBodyDescription(), output, {}, {}, kimono ? &cloth : nullptr));
    // On stderr: a --json answer on stdout stays one document.
    if (const std::string note = render::takeExportNote(take, output); !note.empty()) std::cerr << "note: " << note << "\n";
}

void addKimonoOutputOptions(CLI::App* command, KimonoOutputArguments& arguments)
{
    command->add_flag("--kimono", arguments.kimono,
                      "Simulate the puppet's kimono as cloth over the written take and put it into the file: in a .glb a mesh "
                      "'kimono_cloth' moving by morph targets animated by weights (at most " +
                          std::to_string(render::kKimonoExportMaxKeys) +
                          " key shapes; the figure then without its skinned skirt and sleeves), in a .csv its 18 measured "
                          "channels (docs/KIMONO.md)");
    addClothOptions(command, arguments.cloth);
}

void requireKimonoOutput(const KimonoOutputArguments& arguments, const std::string& output)
{
    if (!arguments.kimono) return;
    const render::TakeExportFormat format = render::takeExportFormat(output);
    if (format != render::TakeExportFormat::Glb && format != render::TakeExportFormat::Csv)
        throw CliError(output + ": --kimono writes the simulated cloth into a .glb or a .csv take file");
}

FolderOutput::FolderOutput(const std::string& folder)
    : m_folder(folder), m_staged(unwrap(analysis::io::StagedFolder::begin(folder)))
{
}

void FolderOutput::add(const std::string& name, const std::string& text)
{
    unwrap(m_staged.writeFile(name, text));
    m_files.push_back(name);
}

void FolderOutput::add(const std::vector<analysis::report::OutputFile>& files)
{
    for (const auto& file : files) add(file.name, file.content);
}

void FolderOutput::addTake(const analysis::Take& take, const std::string& name)
{
    const std::filesystem::path shown = m_staged.target() / name;
    requireTakeOutput(name);
    // Errors name the file the user asked for, not the hidden staging folder.
    const auto named = [&](const analysis::Error& error) {
        std::string message = error.message;
        const std::string staged = (m_staged.path() / name).string();
        for (auto at = message.find(staged); at != std::string::npos; at = message.find(staged, at + 1))
            message.replace(at, staged.size(), shown.string());
        return CliError(message);
    };
    const std::filesystem::path file = m_staged.path() / name;
    if (auto written = render::exportTake(take, analysis::defaultBodyDescription(), file); !written) throw named(written.error());
    // Written atomically by exportTake; listed in the manifest like the folder's other files.
    if (auto recorded = m_staged.recordFile(name); !recorded) throw named(recorded.error());
    if (const std::string note = render::takeExportNote(take, shown); !note.empty()) std::cerr << "note: " << note << "\n";
    m_files.push_back(name);
}

void FolderOutput::commit(nlohmann::json& summary)
{
    summary["files"] = m_files;
    summary["output"] = m_folder;
    unwrap(m_staged.writeFile("summary.json", summary.dump(2, ' ', false, nlohmann::json::error_handler_t::replace) + "\n"));
    unwrap(m_staged.commit());
}

} // namespace bunraku::app::cli
