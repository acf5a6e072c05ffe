// libFuzzer target: the warp curve CSV reader, and the curve evaluated where design uses it.
#include "fuzz/fuzz_support.h"

#include "analysis/design/warp_curve.h"

#include <cmath>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    using namespace bunraku;
    auto curve = analysis::parseWarpCsv(fuzz::textOf(data, size), "fuzz-input.csv");
    if (!curve) {
        fuzz::expect(fuzz::namesSource(curve.error().message), "a warp error names the file");
        return 0;
    }
    fuzz::expect(analysis::validateWarpCurve(*curve).ok(), "an accepted warp curve is valid");
    fuzz::expect(curve->outputFrames >= 1 && double(curve->outputFrames) <= analysis::kWarpCsvMaxFrame + 1, "output frames bounded");
    const double last = curve->points.back().output;
    for (const double x : {0.0, 0.5 * last, last, last + 1.0}) {
        const double source = analysis::evaluateWarp(*curve, x);
        fuzz::expect(std::isfinite(source), "the warp is finite");
        fuzz::expect(std::isfinite(analysis::inverseWarp(*curve, source)), "its inverse is finite");
    }
    return 0;
}
