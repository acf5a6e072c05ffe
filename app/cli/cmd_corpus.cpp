// Subcommand: corpus (a corpus folder from take files, labels parsed from their names).
#include "app/cli/commands.h"
#include "app/cli/import_options.h"

#include "analysis/io/corpus_builder.h"
#include "analysis/io/corpus_io.h"

#include <filesystem>
#include <algorithm>
#include <iomanip>
#include <iostream>

namespace bunraku::app::cli {
namespace {

namespace fs = std::filesystem;
namespace io = analysis::io;
using nlohmann::json;

struct CorpusArguments {
    std::vector<std::string> inputs;
    std::string output;
    std::string pattern = io::kDefaultLabelPattern;
    std::string neutral;
    std::string name;
    double resampleHz = 0.0;
    bool json = false;
    ImportArguments import;
};

void runCorpus(const CorpusArguments& arguments)
{
    std::vector<fs::path> inputs(arguments.inputs.begin(), arguments.inputs.end());
    const auto files = unwrap(io::collectTakeFiles(inputs));
    const auto sources = unwrap(io::labelTakeFiles(files, arguments.pattern));
    io::CorpusBuildOptions options;
    options.import = importOptions(arguments.import);
    options.neutralEmotion = arguments.neutral;
    options.rateHz = arguments.resampleHz;
    options.name = arguments.name.empty() ? fs::absolute(arguments.output).lexically_normal().filename().string() : arguments.name;
    if (arguments.resampleHz < 0.0) throw CliError("--resample must be a positive number of Hz");
    io::CorpusBuild build = unwrap(io::buildCorpus(sources, options));
    unwrap(io::writeCorpus(build.corpus, arguments.output));

    const auto& corpus = build.corpus;
    json takes = json::array();
    for (const auto& f : build.files)
        takes.push_back({{"file", f.file.string()},
                         {"function", f.labels.function},
                         {"emotion", f.labels.emotion},
                         {"take", f.labels.takeIndex},
                         {"frames", f.frames},
                         {"rate_hz", f.rateHz},
                         {"frames_in_corpus", f.framesInCorpus},
                         {"resampled", f.resampled},
                         {"part_map", f.partMap}});
    const json summary{{"output", arguments.output},
                       {"name", corpus.name},
                       {"pattern", arguments.pattern},
                       {"rate_hz", corpus.rateHz},
                       {"functions", corpus.functions()},
                       {"emotions", corpus.emotions()},
                       {"neutral_emotion", corpus.neutralEmotion},
                       {"takes", takes},
                       {"notes", build.notes}};
    report(arguments.json, summary, [&] {
        std::cout << "corpus '" << corpus.name << "': " << corpus.takes.size() << " takes, " << corpus.functions().size()
                  << " function(s), " << corpus.emotions().size() << " emotion(s), " << corpus.rateHz << " Hz -> " << arguments.output
                  << "\n";
        // Columns as wide as their longest entry (and two spaces apart), so long names never run together.
        std::size_t fileWidth = 4, functionWidth = 8, emotionWidth = 7;
        for (const auto& f : build.files) {
            fileWidth = std::max(fileWidth, f.file.filename().string().size());
            functionWidth = std::max(functionWidth, f.labels.function.size());
            emotionWidth = std::max(emotionWidth, f.labels.emotion.size());
        }
        const auto left = [](std::size_t width) { return std::setw(int(width + 2)); };
        std::cout << "  " << std::left << left(fileWidth) << "file" << left(functionWidth) << "function" << left(emotionWidth)
                  << "emotion" << std::right << std::setw(4) << "take" << std::setw(8) << "frames" << std::setw(8) << "Hz"
                  << "  part map\n";
        for (const auto& f : build.files)
            std::cout << "  " << std::left << left(fileWidth) << f.file.filename().string() << left(functionWidth) << f.labels.function
                      << left(emotionWidth) << f.labels.emotion << std::right << std::setw(4) << f.labels.takeIndex << std::setw(8)
                      << f.frames << std::setw(8) << f.rateHz << "  " << (f.partMap.empty() ? std::string("-") : f.partMap)
                      << (f.resampled ? "  (resampled)" : "") << "\n";
        for (const auto& note : build.notes) std::cout << "note: " << note << "\n";
    });
}

} // namespace

void addCorpusCommands(CommandSet& commands)
{
    auto [command, arguments] = addCommand(commands.root, "corpus", runCorpus);
    command->add_option("INPUTS", arguments.inputs, "Take files and/or folders of take files")->required();
    command->add_option("-o,--output", arguments.output, "Corpus folder to write")->required();
    command->add_option("--pattern", arguments.pattern,
                        "File-name pattern: {function}, {emotion}, {take} (digits), {any}; other characters literal, e.g. "
                        "'{any}_{function}_{emotion}_{take}' for dataset-2_wave-right-hand_active_003.bvh")
        ->capture_default_str();
    command->add_option("--neutral", arguments.neutral, "The emotion label meaning 'no emotion' (default: neutral, normal or none)");
    command->add_option("--name", arguments.name, "The corpus's name (default: the output folder's name)");
    command->add_option("--resample", arguments.resampleHz, "Rate of the corpus in Hz, in (0, 1000000] (default: the rate most files have)");
    addImportOptions(command, arguments.import);
}

} // namespace bunraku::app::cli
