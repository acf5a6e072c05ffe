#pragma once
/// Internal: the table of orthogonal wavelet filters behind waveletByName.

#include <string>
#include <vector>

namespace bunraku::analysis::detail {

struct NamedFilter {
    std::string name;
    std::vector<double> reconstructionLowPass;
};

/// db1..db8 and sym2..sym8, rec_lo.
const std::vector<NamedFilter>& orthogonalFilters();

} // namespace bunraku::analysis::detail
