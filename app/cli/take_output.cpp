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

void writeTakeIntoFolder(const analysis::Take& take, analysis::io::StagedFolder& folder, const std::string& name)
{
    const std::filesystem::path shown = folder.target() / name;
    requireTakeOutput(name);
    // Errors name the file the user asked for, not the hidden staging folder.
    const auto named = [&](const analysis::Error& error) {
        std::string message = error.message;
        const std::string staged = (folder.path() / name).string();
        for (auto at = message.find(staged); at != std::string::npos; at = message.find(staged, at + 1))
            message.replace(at, staged.size(), shown.string());
        return CliError(message);
    };
    const std::filesystem::path file = folder.path() / name;
    if (auto written = render::exportTake(take, analysis::defaultBodyDescription(), file); !written) throw named(written.error());
    // Written atomically by exportTake; listed in the manifest like the folder's other files.
    if (auto recorded = folder.recordFile(name); !recorded) throw named(recorded.error());
    if (const std::string note = render::takeExportNote(take, shown); !note.empty()) std::cerr << "note: " << note << "\n";
}

} // namespace bunraku::app::cli
