// libFuzzer target: the CSV take reader. A take it accepts is valid and reads back unchanged
// from what the writer makes of it.
#include "fuzz/fuzz_support.h"

#include "analysis/io/take_csv.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    using namespace bunraku;
    auto take = analysis::io::parseTakeCsv(fuzz::textOf(data, size), "fuzz-input.csv");
    if (!take) {
        fuzz::expect(fuzz::namesSource(take.error().message), "a CSV error names the file");
        return 0;
    }
    fuzz::expect(analysis::validateTake(*take).ok(), "an accepted CSV take is valid");
    analysis::io::TakeCsvOptions options;
    options.rateHz = take->rateHz;
    auto back = analysis::io::parseTakeCsv(analysis::io::formatTakeCsv(*take), "fuzz-input.csv", options);
    fuzz::expect(back.ok(), "a written take reads back");
    fuzz::expect(back->values == take->values, "a written take reads back with the same values");
    fuzz::expect(back->channels.size() == take->channels.size(), "a written take reads back with the same channels");
    for (std::size_t c = 0; c < take->channels.size(); ++c)
        fuzz::expect(back->channels[c].name() == take->channels[c].name(), "channel names survive the round trip");
    return 0;
}
