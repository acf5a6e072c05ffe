#include "analysis/synth/demo_corpus.h"

#include <catch2/catch.hpp>

#include <cmath>

using namespace bunraku::analysis;
using namespace bunraku::analysis::synth;

namespace {

const DemoGroundTruth& truth()
{
    static const DemoGroundTruth t = generateDemoCorpus().truth;
    return t;
}

/// Linear interpolation of samples at a fractional index.
double sampleAt(const Eigen::VectorXd& v, double index)
{
    const Eigen::Index k = std::min<Eigen::Index>(Eigen::Index(std::floor(index)), v.size() - 2);
    return v(k) + (index - double(k)) * (v(k + 1) - v(k));
}

TakeLabels labels(const std::string& function, const std::string& emotion, int k) { return {function, emotion, k, ""}; }

} // namespace

TEST_CASE("true correspondence maps a take to itself as the identity", "[synth]")
{
    for (const TakeTruth& t : truth().takes) {
        const auto map = trueCorrespondence(truth(), t.labels, t.labels);
        REQUIRE(map.ok());
        REQUIRE(map->size() == t.takeToCell.size());
        CHECK((*map - Eigen::VectorXd::LinSpaced(map->size(), 0.0, double(map->size() - 1))).cwiseAbs().maxCoeff() <
              1e-12);
    }
}

TEST_CASE("true correspondence between takes of a cell is monotone and matches cell times", "[synth]")
{
    for (const std::string function : {"greeting", "serving-tea"})
        for (const std::string emotion : {"none", "friendly", "hostile"})
            for (int r = 1; r <= 5; ++r)
                for (int s = 1; s <= 5; ++s) {
                    const TakeTruth& ref = *truth().take(labels(function, emotion, r));
                    const TakeTruth& smp = *truth().take(labels(function, emotion, s));
                    const auto map = trueCorrespondence(truth(), ref.labels, smp.labels);
                    REQUIRE(map.ok());
                    CHECK((map->tail(map->size() - 1) - map->head(map->size() - 1)).minCoeff() >= 0.0);
                    CHECK(map->minCoeff() >= 0.0);
                    CHECK(map->maxCoeff() <= double(smp.takeToCell.size() - 1));
                    CHECK((*map)(ref.lateStartFrames) == Approx(double(smp.lateStartFrames))); // onset to onset
                    CHECK((*map)(map->size() - 1) == Approx(double(smp.takeToCell.size() - 1)));
                    for (Eigen::Index t = ref.lateStartFrames + 1; t < map->size(); ++t)
                        CHECK(sampleAt(smp.takeToCell, (*map)(t)) == Approx(ref.takeToCell(t)).margin(1e-9));
                }
}

TEST_CASE("true correspondence across emotions goes through the functional time axis", "[synth]")
{
    const TakeTruth& ref = *truth().take(labels("serving-tea", "none", 2));
    const TakeTruth& smp = *truth().take(labels("serving-tea", "friendly", 3));
    const CellTruth& smpCell = *truth().cell("serving-tea", "friendly");
    const auto map = trueCorrespondence(truth(), ref.labels, smp.labels);
    REQUIRE(map.ok());
    CHECK((map->tail(map->size() - 1) - map->head(map->size() - 1)).minCoeff() >= 0.0);
    for (Eigen::Index t = ref.lateStartFrames + 1; t < map->size(); ++t) {
        // The neutral cell's time is functional time; the friendly sample shows it through its phase warp.
        const double functional = sampleAt(smpCell.phaseWarp, sampleAt(smp.takeToCell, (*map)(t)));
        CHECK(functional == Approx(ref.takeToCell(t)).margin(1e-9));
    }
    // The friendly tea is slower at first: its travel ends later than the neutral one's.
    const double neutralTravelEnd = 30.0; // functional frame of the end of "travel"
    Eigen::Index t = 0;
    while (ref.takeToCell(t) < neutralTravelEnd) ++t;
    CHECK((*map)(t) > double(t) - double(ref.lateStartFrames) + double(smp.lateStartFrames) + 2.0);
}

TEST_CASE("true correspondence rejects takes of different functions or unknown takes", "[synth]")
{
    const auto mixed = trueCorrespondence(truth(), labels("greeting", "none", 1), labels("serving-tea", "none", 1));
    REQUIRE_FALSE(mixed.ok());
    CHECK(mixed.error().code == ErrorCode::InvalidArgument);
    const auto unknown = trueCorrespondence(truth(), labels("greeting", "none", 9), labels("greeting", "none", 1));
    REQUIRE_FALSE(unknown.ok());
    CHECK(unknown.error().code == ErrorCode::NotFound);
}
