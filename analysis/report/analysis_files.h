#pragma once
/// The data files of an analysed corpus (what `bunraku analyse -o DIR` writes beside the HTML
/// report): every stage's results as CSV and JSON with shortest round-trip numbers, so a value
/// read back is the bit-identical double the pipeline computed. Names (f = function,
/// e = emotion, k = take index, made file-safe):
///   parameters.json, summary.json,
///   preprocessed_f_e_k.csv, normalised_f_e_k.csv, correspondence_f_e_k.csv,
///   reference_f_e.csv, average_f_e.csv, variance_f_e.csv        (thesis 2.2, 3.6-3.8)
///   y_f.csv, z_f_e.csv, km2o_by_M.csv, km2o_errors.csv           (4.3.1, 4.4.4, Table 4.5)
///   spectra.csv, arma_table.csv                                  (4.3.2, Table 4.1)
///   axis_functional_f.csv, axis_emotional_f_e.csv, warp_f_e.csv, phase_f_e.csv, gains_f_e.csv (5)
/// Formats: docs/FORMATS.md.

#include "analysis/core/result.h"
#include "analysis/decompose/arma.h"
#include "analysis/pipeline/chain.h"
#include "analysis/synth/demo_corpus.h"

#include <nlohmann/json.hpp>

#include <filesystem>
#include <string>
#include <vector>

namespace bunraku::analysis::report {

struct OutputFile {
    std::string name;    ///< file name inside the output folder
    std::string content;
};

/// Every data file's text, computed before anything is written (needs every stage's result).
Result<std::vector<OutputFile>> analysisDataFiles(const pipeline::ChainResult& chain, const pipeline::ChainParameters& parameters);

/// Writes the files as one folder output (io/staged_folder.h): built beside `folder` and swapped
/// in whole, refused when `folder` holds files this program did not write there; Io errors name
/// the file.
Status writeOutputFiles(const std::filesystem::path& folder, const std::vector<OutputFile>& files);

// The writers of each stage's files, one per file, shared by `bunraku analyse` (above) and the
// stage's own command (`normalise`, `decompose`), so both write the same bytes.

/// variance_f_e.csv (`normalise`: variance.csv): thesis 3.8's variance of each take to the
/// reference, raw and normalised, per channel and in total.
std::string varianceCsv(const pipeline::CellNormalisation& cell);
/// correspondence_f_e_k.csv (`normalise`: k_correspondence.csv): each coupling set's reference
/// frame to take frame, for the reference's `frames` frames.
std::string correspondenceCsv(const TakeNormalisation& normalisation, Eigen::Index frames);
/// y_f.csv (a pose), z_f_e.csv (rotation coordinates), and with KM2O km2o_by_M.csv and
/// km2o_errors.csv (Table 4.5's layout).
Result<std::vector<OutputFile>> decompositionFiles(const pipeline::DecomposeOutput& decomposed);
/// eta_f_e_k.csv: each take's fluctuation (`decompose` only).
Result<std::vector<OutputFile>> fluctuationTakeFiles(const Decomposition& decomposition);
/// spectra.csv (each cell's Welch spectra of eta, averaged over its takes) and arma_table.csv
/// (Table 4.1: ARMA(p,q) averaged per cell).
std::vector<OutputFile> fluctuationFiles(const pipeline::FluctuationOutput& fluctuations);

/// What `decompose` writes of each take's fluctuation beyond `analyse`'s files, for every take of
/// a cell of two or more (one take has no fluctuation, eq. 4.24):
///   spectra_periodogram.csv, spectra_welch.csv   eta's spectra (Welch segments of `welchSegment` frames)
///   arma_takes.csv                               each channel's ARMA order chosen by FPE, up to `armaMaxOrder`
struct TakeFluctuationOptions {
    int welchSegment = 32;
    ArmaOrderSearch search = ArmaOrderSearch::EqualOrders;
    int armaMaxOrder = 4;
};
Result<std::vector<OutputFile>> takeFluctuationFiles(const Decomposition& decomposition, const TakeFluctuationOptions& options);

/// The decomposition against a synthetic corpus's ground truth (`decompose` on a demo corpus):
/// {"y": {f: {"relative_error_percent", "rms"}}, "z": {"f/e": {"rms"}}}; y compared as a pose
/// (angles modulo 360), z as rotation coordinates about the function's chart on both sides.
Result<nlohmann::json> groundTruthErrorsJson(const Decomposition& decomposition, const synth::DemoGroundTruth& truth);

/// What KM2O did per cell, for summary.json and the CLI's --json summaries (docs/FORMATS.md):
/// {"estimable", "outcome", "notes", "cells": [{"function", "emotion", "takes", "gamma": "own
/// takes" | "pooled" | "least squares"}]} (docs/KM2O.md, "Cells with one take").
nlohmann::json km2oOutcomeJson(const Km2oDecomposition& km2o);

/// File-safe "f_e" / "f_e_k" stems used above.
std::string cellStem(const std::string& function, const std::string& emotion);
std::string takeStem(const TakeLabels& labels);

} // namespace bunraku::analysis::report
