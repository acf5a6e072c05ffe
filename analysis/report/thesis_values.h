#pragma once
/// The values the thesis publishes for its (lost) recordings, shown in the report beside the
/// project's: Tables 3.4/3.5 (variances of greeting/none, x 10^5), Table 4.1 (ARMA(2,2) of
/// head-x), 4.4.4's chosen M and mean P, Table 4.5 (P^{ij} per DOF). Chapter 5 publishes no
/// numbers. Cells are indexed i = function (1 greeting, 2 serving tea), j = emotion (1 none,
/// 2 friendly, 3 hostile) as in the thesis.

#include <array>
#include <string>

namespace bunraku::analysis::report {

/// One row of Table 3.4 or 3.5: take x_k's variance before ("sample") and after normalisation
/// to each reference; NaN where the thesis prints a dash.
struct ThesisVarianceRow {
    int take = 0;
    std::array<double, 6> values; ///< x4: sample, normalised; 5ave: ...; 4ave: ...
};
/// method 1 (Table 3.4) or method 2 (Table 3.5), rows x_1..x_5, x 10^5.
const std::array<ThesisVarianceRow, 5>& thesisVarianceTable(int method);

/// Table 4.1 row (i, j): a1, a2, b0, b1, b2 of ARMA(2, 2), head-x.
const std::array<double, 5>& thesisArmaHeadX(int function, int emotion);

/// 4.4.4: M = 2 was best; the mean P over 24 DOF x 6 motions was 2.32 %.
inline constexpr int kThesisCorrelationLength = 2;
inline constexpr double kThesisMeanErrorPercent = 2.32;

/// Table 4.5: P^{ij} [%] of the channel "part.dof" (head.x ... hand.roll), NaN when unknown.
double thesisCellErrorPercent(const std::string& channel, int function, int emotion);

/// 1-based thesis index of the demo corpus's labels (greeting 1, serving-tea 2; none 1, friendly
/// 2, hostile 3), 0 when the label is not one of the thesis's.
int thesisFunctionIndex(const std::string& function);
int thesisEmotionIndex(const std::string& emotion);

} // namespace bunraku::analysis::report
