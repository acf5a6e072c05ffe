#pragma once
/// Internal: the innermost loops of matching, each with an AVX2/FMA version chosen at run time
/// when the CPU has it (the portable build targets baseline x86-64) and a plain fallback that
/// gives the same results up to rounding.

#include <cstddef>
#include <cstdint>

namespace bunraku::analysis::detail {

/// out[j] = sum_f (a[f] - rows[j][f])^2 for j < count; every vector has `features` entries.
void squaredDistances(const double* a, const double* const* rows, std::size_t count, std::size_t features, double* out);

/// The same for `count` consecutive rows starting at `first` (row j at first + j * features),
/// as |a|^2 + |b_j|^2 - 2 a.b_j (clamped at 0) from the squared norms aNorm and norms[j]: one
/// multiply-add per feature instead of two.
void squaredDistancesContiguous(const double* a, double aNorm, const double* first, const double* norms,
                                std::size_t count, std::size_t features, double* out);

/// Window sums down the rows of e (each column is one diagonal of the band), one row at a time:
/// windowStart sets running[o] = sum_{s = 0 .. length - 1} e[s * stride + o] for o < columns;
/// windowSlide moves the window one row on: running = (running + entering) - leaving.
void windowStart(const double* e, std::size_t length, std::size_t columns, std::size_t stride, double* running);
void windowSlide(double* running, const double* entering, const double* leaving, std::size_t columns);

/// One row of the optimal path's dynamic programme over a band of `width` cells.
/// prefix[k] = min(previous[0..k]); bits (one bit per column, 64 a word, (width + 63) / 64
/// words) get bit k set where the prefix minimum strictly drops at k, so the first minimum of
/// previous[0..k] is the highest set bit at or below k. Then
/// current[j] = cost[j] + prefix[min(j + 1, width - 1)] for low <= j <= high and infinity
/// elsewhere. `prefix` needs width + 4 entries of scratch.
void dynamicProgrammeRow(const double* previous, const double* cost, std::size_t width, std::size_t low,
                         std::size_t high, double* prefix, std::uint64_t* bits, double* current);

/// Just the prefix bits of `values` (as dynamicProgrammeRow), for the last row.
void prefixMinimumBits(const double* values, std::size_t width, double* prefix, std::uint64_t* bits);

} // namespace bunraku::analysis::detail
