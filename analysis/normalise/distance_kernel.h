#pragma once
/// Internal: the innermost loop of matching - squared distances from one feature vector to a
/// run of others - with an AVX2/FMA version chosen at run time when the CPU has it (the
/// portable build targets baseline x86-64) and a plain fallback.

#include <cstddef>

namespace bunraku::analysis::detail {

/// out[j] = sum_f (a[f] - rows[j][f])^2 for j < count; every vector has `features` entries.
void squaredDistances(const double* a, const double* const* rows, std::size_t count, std::size_t features, double* out);

/// The same for `count` consecutive rows starting at `first` (row j at first + j * features),
/// as |a|^2 + |b_j|^2 - 2 a.b_j (clamped at 0) from the squared norms aNorm and norms[j]: one
/// multiply-add per feature instead of two.
void squaredDistancesContiguous(const double* a, double aNorm, const double* first, const double* norms,
                                std::size_t count, std::size_t features, double* out);

} // namespace bunraku::analysis::detail
