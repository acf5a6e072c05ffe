// libFuzzer target: the gains JSON reader; accepted gains are applied to a small signal.
#include "fuzz/fuzz_support.h"

#include "analysis/design/phrase_gains.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    using namespace bunraku;
    auto gains = analysis::parseGainsJson(fuzz::textOf(data, size), "fuzz-input.json");
    if (!gains) {
        fuzz::expect(fuzz::namesSource(gains.error().message), "a gains error names the file");
        return 0;
    }
    const auto& phrases = gains->phrases;
    fuzz::expect(!phrases.empty() && phrases.front().begin == 0, "phrases start the take");
    for (std::size_t p = 0; p < phrases.size(); ++p) {
        fuzz::expect(phrases[p].begin < phrases[p].end, "phrases are not empty");
        if (p > 0) fuzz::expect(phrases[p].begin == phrases[p - 1].end, "phrases follow each other");
        fuzz::expect(phrases[p].dofs.size() == gains->dofNames.size(), "one gain per DOF");
    }
    // Applied over the phrases (bounded: small takes only, the signal is frames x DOF).
    const Eigen::Index frames = phrases.back().end + 1;
    if (frames <= 4096) {
        const Eigen::MatrixXd signal = Eigen::MatrixXd::Ones(frames, Eigen::Index(gains->dofNames.size()));
        const Eigen::MatrixXd designed = analysis::applyGains(signal, *gains);
        fuzz::expect(designed.rows() == frames, "the designed signal keeps its frames");
    }
    return 0;
}
