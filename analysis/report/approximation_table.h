#pragma once
/// Thesis 5.4.1 (eq. 5.18, Fig. 5.16): the axis stage's approximation error per emotional cell,
/// largest scale c and axis DOF, as CSV, JSON and text (`bunraku experiment approximation`).

#include "analysis/pipeline/stages.h"

#include <nlohmann/json.hpp>

#include <string>

namespace bunraku::analysis::report {

/// Figure 5.16 is printed as a plot only: no value of it is legible in the text.
inline constexpr const char* kApproximationThesisFigure =
    "Fig. 5.16 (no emotion vs friendly, per axis DOF): plotted only, no values printed";

/// function,emotion,scale,dof,relative_error,thesis: a row per cell, scale and DOF, and the
/// mean over the DOF ("mean"); the thesis column is empty (kApproximationThesisFigure).
std::string approximationCsv(const pipeline::AxisOutput& axes);
/// Per cell: function, emotion, scales, relative_error per DOF, mean_relative_error (null for a
/// value that is not finite) and thesis (null).
nlohmann::json approximationJson(const pipeline::AxisOutput& axes);
/// The table for a person: what it measures, kApproximationThesisFigure, then per cell a row per
/// largest scale c with the error per DOF and their mean (4 decimals).
std::string approximationText(const pipeline::AxisOutput& axes);

} // namespace bunraku::analysis::report
