// libFuzzer target: the BVH reader (parseBvh, the public entry of readBvh) and the conversions
// to puppet and joint takes every import runs after it.
#include "fuzz/fuzz_support.h"

#include "analysis/io/bvh.h"
#include "analysis/io/bvh_import.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    using namespace bunraku;
    auto file = analysis::io::parseBvh(fuzz::textOf(data, size), "fuzz-input.bvh");
    if (!file) {
        fuzz::expect(fuzz::namesSource(file.error().message), "a BVH error names the file");
        return 0;
    }
    for (auto* convert : {&analysis::io::bvhToPuppetTake, &analysis::io::bvhToJointTake}) {
        auto take = convert(*file, {});
        if (take) fuzz::expect(analysis::validateTake(*take).ok(), "an imported BVH take is valid");
    }
    return 0;
}
