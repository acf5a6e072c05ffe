#pragma once
/// The kimono simulated over every take of a corpus and measured (analysis/cloth/kimono_cloth.h;
/// docs/KIMONO.md): per take and per function and emotion, the sleeves' and the hem's own swing
/// and the sleeve's lag behind the hand, as JSON, as text and as an SVG figure (`bunraku experiment kimono`).

#include "analysis/cloth/kimono_cloth.h"
#include "analysis/core/corpus.h"
#include "analysis/core/result.h"

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace bunraku::analysis::report {

/// One take's measures.
struct KimonoTakeMeasures {
    std::string take, function, emotion;
    KimonoMeasures measures;
};

/// The measures of one function and emotion's takes, summed: `mean` of a sum is its mean.
struct KimonoCellMeans {
    std::string function, emotion;
    int takes = 0;
    double swingRight = 0.0, swingLeft = 0.0, lag = 0.0, hem = 0.0, hand = 0.0;
    double mean(double sum) const { return sum / double(takes); }
    /// The right sleeve's own swing per cm of the hand's (0 when the hand does not swing).
    double sleevePerHand() const { return hand > 0.0 ? swingRight / hand : 0.0; }
};

/// Every take's kimono simulated with `cloth` and measured, in the corpus's order; an error names the take.
Result<std::vector<KimonoTakeMeasures>> measureKimonos(const Corpus& corpus, const ClothParameters& cloth);
/// The means per function and emotion, in the order the takes first name them.
std::vector<KimonoCellMeans> kimonoCellMeans(const std::vector<KimonoTakeMeasures>& takes);
/// The means per cell as a table for a person: a header line, then a row per cell.
std::string kimonoCellMeansText(const std::vector<KimonoCellMeans>& cells);
/// {"takes": [...], "cells": [...]}: every take's measures and the means per cell.
nlohmann::json kimonoMeasuresJson(const std::vector<KimonoTakeMeasures>& takes, const std::vector<KimonoCellMeans>& cells);
/// Two scatter plots side by side, one dot per take coloured by its function and emotion: the
/// right sleeve's own swing against the hand's (the line where they are equal drawn dashed), and
/// the sleeve's lag behind the hand against the hand's swing. An SVG document.
std::string kimonoFigureSvg(const std::vector<KimonoTakeMeasures>& takes);

} // namespace bunraku::analysis::report
