// Subcommands: demo.
#include "app/cli/commands.h"

#include "analysis/synth/demo_corpus.h"
#include "analysis/synth/demo_corpus_io.h"
#include "analysis/synth/long_take.h"

#include <cstdint>
#include <filesystem>
#include <iostream>

namespace bunraku::app::cli {
namespace {

struct DemoArguments {
    std::string output;
    std::uint64_t seed = 1;
    long long longFrames = 0; ///< --long N: one long take instead of the corpus
    double rateHz = 120.0;
    bool json = false;
};

void runLongTake(const DemoArguments& arguments)
{
    namespace synth = analysis::synth;
    synth::LongTakeOptions options;
    options.frames = Eigen::Index(arguments.longFrames);
    options.rateHz = arguments.rateHz;
    options.seed = arguments.seed;
    const std::filesystem::path file = unwrap(synth::writeLongTake(options, arguments.output));
    std::error_code error;
    const auto bytes = std::filesystem::file_size(file, error);
    const nlohmann::json summary{{"file", file.string()},
                                 {"frames", options.frames},
                                 {"rate_hz", options.rateHz},
                                 {"seconds", double(options.frames - 1) / options.rateHz},
                                 {"joints", synth::kLongTakeJoints},
                                 {"channels", synth::kLongTakeChannels},
                                 {"bytes", error ? 0 : bytes},
                                 {"seed", arguments.seed}};
    report(arguments.json, summary, [&] {
        std::cout << "wrote one take of " << options.frames << " frames at " << options.rateHz << " Hz (" << synth::kLongTakeJoints
                  << " joints) to " << file.string() << "\n";
    });
}

void runDemo(const DemoArguments& arguments)
{
    if (arguments.longFrames > 0) return runLongTake(arguments);
    namespace synth = analysis::synth;
    synth::DemoOptions options;
    options.seed = arguments.seed;
    const synth::DemoCorpus demo = synth::generateDemoCorpus(options);
    const std::filesystem::path folder = arguments.output;
    unwrap(synth::writeDemoCorpus(demo, folder));

    Eigen::Index frames = 0;
    for (const auto& take : demo.corpus.takes) frames = std::max(frames, take.frameCount());
    const nlohmann::json summary{{"folder", folder.string()},
                                 {"truth", synth::groundTruthFolder(folder).string()},
                                 {"seed", arguments.seed},
                                 {"takes", demo.corpus.takes.size()},
                                 {"channels", demo.corpus.takes.front().channelCount()},
                                 {"frames", frames},
                                 {"rate_hz", demo.corpus.rateHz},
                                 {"functions", demo.corpus.functions()},
                                 {"emotions", demo.corpus.emotions()}};
    report(arguments.json, summary, [&] {
        std::cout << "wrote " << demo.corpus.takes.size() << " takes (" << frames << " frames at most, " << demo.corpus.rateHz
                  << " Hz) to " << folder.string() << ", ground truth in " << synth::groundTruthFolder(folder).string() << "\n";
    });
}

} // namespace

void addDemoCommands(CommandSet& commands)
{
    auto [demo, arguments] = addCommand(commands.root, "demo", runDemo);
    demo->add_option("-o,--output", arguments.output, "Corpus folder to write (replaced when it exists); with --long, the folder the take is written into")
        ->required()
        ->type_name("DIR");
    demo->add_option("--seed", arguments.seed, "Seed of the takes' randomisation")
        ->check(CLI::Validator(
            [](std::string& text) {
                const bool digits = !text.empty() && text.find_first_not_of("0123456789") == std::string::npos;
                return digits ? std::string() : "expected a non-negative integer, got '" + text + "'";
            },
            "UINT"))
        ->capture_default_str();
    demo->add_option("--long", arguments.longFrames,
                     "Instead of the corpus, write one synthetic take of N frames with a 22-joint skeleton as DIR/" +
                         analysis::synth::longTakeFileName() + " (BVH; for benchmarks of long takes)")
        ->check(CLI::Range(2LL, 100'000'000LL))
        ->type_name("N");
    demo->add_option("--rate", arguments.rateHz, "Frame rate of the --long take (Hz)")
        ->check(CLI::Range(1e-3, 1000.0))
        ->capture_default_str();
}

} // namespace bunraku::app::cli
