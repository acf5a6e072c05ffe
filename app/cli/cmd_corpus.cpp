// Subcommand: corpus (a corpus folder from take files, labels parsed from their names).
#include "app/cli/commands.h"
#include "app/cli/import_options.h"

#include "analysis/io/corpus_build_report.h"
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
    const json summary{{"output", arguments.output},
                       {"name", corpus.name},
                       {"pattern", arguments.pattern},
                       {"rate_hz", corpus.rateHz},
                       {"functions", corpus.functions()},
                       {"emotions", corpus.emotions()},
                       {"neutral_emotion", corpus.neutralEmotion},
                       {"takes", io::corpusBuildFilesJson(build)},
                       {"notes", build.notes}};
    report(arguments.json, summary, [&] {
        std::cout << "corpus '" << corpus.name << "': " << corpus.takes.size() << " takes, " << corpus.functions().size()
                  << " function(s), " << corpus.emotions().size() << " emotion(s), " << corpus.rateHz << " Hz -> " << arguments.output
                  << "\n";
        std::cout << io::corpusBuildTable(build);
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
