#pragma once
/// A corpus: takes labelled function x emotion x take index, as the thesis's 2 x 3 x 5 design,
/// with any labels (they are data). Files: see analysis/io/corpus_io.h.

#include "analysis/core/take.h"

#include <string>
#include <vector>

namespace bunraku::analysis {

struct Corpus {
    std::string name;
    double rateHz = 5.0;
    /// Coordinate convention, written into corpus.json.
    std::string convention = "right-handed, z up, x towards the partner; cm; degrees, intrinsic Z-Y'-X''";
    /// The emotion label meaning "no emotion" (thesis hypothesis 4: z^{i1} = 0).
    std::string neutralEmotion = "none";
    std::vector<Take> takes;

    /// Function labels in order of first appearance.
    std::vector<std::string> functions() const;
    /// Emotion labels in order of first appearance (the neutral one first when present).
    std::vector<std::string> emotions() const;
    /// The takes of one function x emotion cell, sorted by take index.
    std::vector<const Take*> cell(const std::string& function, const std::string& emotion) const;
    const Take* find(const std::string& function, const std::string& emotion, int takeIndex) const;
};

/// Checks every take (validateTake), that all share the corpus rate and channel layout, and that
/// (function, emotion, takeIndex) labels are unique.
Status validateCorpus(const Corpus& corpus);

} // namespace bunraku::analysis
