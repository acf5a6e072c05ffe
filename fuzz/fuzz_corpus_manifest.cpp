// libFuzzer target: the corpus manifest reader (corpus.json).
#include "fuzz/fuzz_support.h"

#include "analysis/io/corpus_io.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    using namespace bunraku;
    auto manifest = analysis::io::parseCorpusManifest(fuzz::textOf(data, size), "fuzz-input/corpus.json");
    if (!manifest) {
        fuzz::expect(fuzz::namesSource(manifest.error().message), "a manifest error names the file");
        return 0;
    }
    fuzz::expect(analysis::plausibleRate(manifest->rateHz), "an accepted manifest has a plausible rate");
    fuzz::expect(!manifest->takes.empty(), "an accepted manifest lists takes");
    for (const auto& take : manifest->takes) {
        fuzz::expect(!take.file.empty() && take.file.front() != '.' && take.file.front() != '/', "take files stay in the folder");
        if (take.frames) fuzz::expect(*take.frames >= 1 && *take.frames <= analysis::io::kMaxCorpusTakeFrames, "frames bounded");
    }
    return 0;
}
