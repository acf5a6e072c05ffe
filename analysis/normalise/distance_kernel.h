#pragma once
/// Internal: the innermost loops of matching after the band distances (band_distances.h): window
/// sums and the optimal path's dynamic programme, each with an AVX2 version chosen at run time
/// (simdLevel(), analysis/wavelet/simd_level.h) and a plain one that gives the same results
/// exactly (these loops only add, subtract and compare).

#include "analysis/wavelet/simd_level.h"

#include <cstddef>
#include <cstdint>

namespace bunraku::analysis::detail {

/// The window sums' and dynamic programme's kernel at a level: "plain" or "avx2" (AVX-512 runs
/// the AVX2 one).
const char* scanKernelName(SimdLevel level);

/// Window sums down the rows of e (each column is one diagonal of the band), one row at a time:
/// windowStart sets running[o] = sum_{s = 0 .. length - 1} rows[s][o] for o < columns, adding
/// the rows in order; windowSlide moves the window one row on: running = (running + entering) - leaving.
void windowStart(const double* const* rows, std::size_t length, std::size_t columns, double* running);
void windowSlide(double* running, const double* entering, const double* leaving, std::size_t columns);

/// The optimal path's dynamic programme over a band of `width` columns keeps its rows
/// interleaved: column c at entry dpEntry(c, S) = 4 (c mod S) + c / S, S = dpSegment(width) (a
/// multiple of 4 with 4 S > width), so the four quarters of a row run side by side in the
/// vector lanes and the prefix minimum needs no shuffles. Entries of columns >= width are
/// padding: infinity in D rows. Drop bits use the same order (dpWords(S) words a row).
inline constexpr std::size_t kDpLanes = 4;
std::size_t dpSegment(std::size_t width);
inline std::size_t dpEntry(std::size_t column, std::size_t segment) { return kDpLanes * (column % segment) + column / segment; }
inline std::size_t dpWords(std::size_t segment) { return (kDpLanes * segment + 63) / 64; }

/// A row's costs in column order, readable for 4 S entries, those >= width +infinity. With
/// `entering` and `leaving` (4 S entries, 0 past width) the costs are window sums slid one row
/// on first: running = (running + entering) - leaving, stored back.
struct DpCost {
    double* running = nullptr;
    const double* entering = nullptr;
    const double* leaving = nullptr;
};

/// Row 0: D = cost in low .. high, infinity elsewhere (interleaved), and the prefix minima of
/// D within each quarter (segmentPrefix[dpEntry(c)] = min D(c0 .. c), c0 the quarter's first column).
void dpFirstRow(const DpCost& cost, std::size_t width, std::size_t low, std::size_t high, double* d, double* segmentPrefix);

/// Row t from row t - 1's quarter prefix minima: with P(c) = min D_{t-1}(0 .. c),
/// D_t(c) = cost(c) + P(min(c + 1, width - 1)) for low <= c <= high and infinity elsewhere
/// (thesis 3.5.3's monotone path: the previous row's column c + 1 is the same sample frame);
/// `bits` gets row t - 1's drops (bit dpEntry(c) set where P strictly drops at c, so the first
/// minimum of D_{t-1}(0 .. c) is the highest set bit at or below c); d = D_t (skipped when null:
/// the next row needs only its quarter prefix minima) and nextSegmentPrefix those minima. Every
/// word of `bits` is written.
void dpRow(const double* segmentPrefix, const DpCost& cost, std::size_t width, std::size_t low, std::size_t high,
           std::uint64_t* bits, double* d, double* nextSegmentPrefix);

/// The drop bits of the row whose quarter prefix minima are given (the last row).
void dpDropBits(const double* segmentPrefix, std::size_t width, std::uint64_t* bits);

/// The highest column <= `column` whose drop bit is set in one row's bits: the first minimum
/// of that row's columns 0 .. column; -1 when there is none.
std::ptrdiff_t lastDropAtOrBelow(const std::uint64_t* bits, std::size_t column, std::size_t segment);

} // namespace bunraku::analysis::detail
