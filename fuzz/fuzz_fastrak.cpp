// libFuzzer target: the FASTRAK reader.
#include "fuzz/fuzz_support.h"

#include "analysis/io/fastrak.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    using namespace bunraku;
    auto take = analysis::io::parseFastrak(fuzz::textOf(data, size), "fuzz-input.txt");
    if (!take) {
        fuzz::expect(fuzz::namesSource(take.error().message), "a FASTRAK error names the file");
        return 0;
    }
    fuzz::expect(analysis::validateTake(*take).ok(), "an accepted FASTRAK take is valid");
    return 0;
}
