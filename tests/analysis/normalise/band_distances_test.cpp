#include "analysis/normalise/band_distances.h"

#include <catch2/catch.hpp>

#include <Eigen/Core>

#include <cmath>
#include <random>
#include <vector>

using namespace bunraku::analysis::detail;

TEST_CASE("every distance kernel the CPU runs gives the band's squared distances and writes nothing else", "[path][simd]")
{
    // Row counts that are not multiples of the kernels' 6- and 12-row blocks, widths that are not
    // multiples of their 8- and 16-frame blocks, feature counts from 1 up; each cell against
    // sum_f (a - b)^2 computed directly, or 0 before greedy's first sample frame. Cells outside
    // the band's width (the row stride is wider) must keep their sentinel.
    std::mt19937 random(5);
    std::normal_distribution<double> normal;
    const double sentinel = -12345.0;
    for (BandKernel kernel : availableBandKernels()) {
        for (int trial = 0; trial < 12; ++trial) {
            const std::size_t count = std::size_t(1 + trial * 7);
            const std::size_t width = std::size_t(1 + (trial * 13) % 50);
            const std::size_t features = std::size_t(1 + (trial * 5) % 17);
            const std::size_t sampleLength = count + width + kBandReadAhead;
            Eigen::MatrixXd a(static_cast<Eigen::Index>(count), static_cast<Eigen::Index>(features));
            Eigen::MatrixXd b(static_cast<Eigen::Index>(sampleLength), static_cast<Eigen::Index>(features));
            for (Eigen::Index i = 0; i < a.size(); ++i) a.data()[i] = normal(random);
            for (Eigen::Index i = 0; i < b.size(); ++i) b.data()[i] = normal(random);
            const Eigen::VectorXd aNorms = a.rowwise().squaredNorm();
            const Eigen::VectorXd bNorms = b.rowwise().squaredNorm();
            const std::size_t stride = width + 3;
            std::vector<double> e(count * stride + 3, sentinel);
            BandTile tile;
            tile.a = a.data();
            tile.aStride = count;
            tile.aNorms = aNorms.data();
            tile.b = b.data();
            tile.bStride = sampleLength;
            tile.bNorms = bNorms.data();
            tile.features = features;
            tile.count = count;
            tile.width = width;
            tile.e = e.data();
            tile.eStride = stride;
            tile.from = trial % 3 == 1 ? count / 2 + width / 3 : 0; // greedy's skip: 0 before it
            bandDistancesWith(kernel, tile);
            INFO(bandKernelName(kernel) << ", " << count << " rows, width " << width << ", " << features << " features");
            double worst = 0.0;
            std::size_t touched = 0;
            for (std::size_t p = 0; p < count; ++p)
                for (std::size_t o = 0; o < stride; ++o) {
                    const double value = e[p * stride + o];
                    if (o >= width) {
                        touched += value != sentinel;
                        continue;
                    }
                    const double direct = p + o < tile.from ? 0.0 : (a.row(Eigen::Index(p)) - b.row(Eigen::Index(p + o))).squaredNorm();
                    worst = std::max(worst, std::abs(value - direct) / (aNorms[Eigen::Index(p)] + bNorms[Eigen::Index(p + o)]));
                }
            CHECK(worst < 1e-14);
            CHECK(touched == 0);
            CHECK(e.back() == sentinel);
        }
    }
}
