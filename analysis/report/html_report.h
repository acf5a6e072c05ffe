#pragma once
/// The analysis report: one self-contained HTML file (inline CSS and SVG figures drawn here, no
/// script, no network) that a researcher can read and send. Sections, each with the thesis's
/// published values beside the project's where the thesis gives them (thesis_values.h):
///   #overview     corpus, parameters, stage keys
///   #preprocess   thesis 2.2, per take
///   #normalise    per cell: raw and normalised takes overlaid, the variance table (3.6-3.8)
///   #average      per cell: the average take over its members (3.7)
///   #spectra      eta spectra per cell (4.3.2)
///   #arma         ARMA(p,q) per cell (Table 4.1)
///   #km2o         KM2O's P by M and P^{ij} per channel (4.4.4, Table 4.5)
///   #axes         motion axes of the functional and emotional average takes (5.2.1)
///   #warps        phase: warp curves emotional -> functional frame (5.3)
///   #gains        amplitude: gains per phrase and axis DOF (5.4), design error (5.5)
/// Every number in a table carries its exact value and where it comes from
/// (data-source="variance_f_e.csv" data-row="1,raw" data-column="total" data-value="..."),
/// the data file of the same name written by analysisDataFiles.

#include "analysis/pipeline/chain.h"

#include <string>

namespace bunraku::analysis::report {

struct ReportOptions {
    std::string title = "Bunraku motion analysis";
    std::string corpusSource; ///< shown in the overview (folder or "demo")
    std::string generator;    ///< e.g. "bunraku analyse 0.1.0"
};

/// The ids of the sections above, in order.
const std::vector<std::string>& reportSections();

/// The report's HTML. InvalidArgument when a stage's result is missing.
Result<std::string> htmlReport(const pipeline::ChainResult& chain, const pipeline::ChainParameters& parameters,
                               const ReportOptions& options = {});

} // namespace bunraku::analysis::report
