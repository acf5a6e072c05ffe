#pragma once
/// The demo's choreography: each function as a sequence of phrases (thesis 5.2.2) with the
/// change of every rig parameter over each phrase, plus a slow "life" sway; and each emotion as
/// a design applied to the function (thesis hypotheses of 5.2.2-5.4): new phrase boundaries
/// (phase), per-phrase gains on the displacements (amplitude) and added part-relative
/// displacements. Deterministic: the seed only randomises the takes.

#include "analysis/synth/puppet_rig.h"

#include <Eigen/Core>

#include <string>
#include <vector>

namespace bunraku::analysis::synth {

/// A slow sinusoid added to one parameter in functional time (breathing, balance, gaze),
/// faded in over the first 10 functional frames so every motion starts at rest.
struct SwayTerm {
    RigParameter parameter = RigParameter::BodyZ;
    double amplitude = 0.0;    ///< cm or degrees
    double periodFrames = 1.0; ///< frames at 5 Hz
    double phase = 0.0;        ///< radians
};

struct FunctionScript {
    std::string function;
    std::vector<std::string> phraseNames;
    /// Functional frames, phrases + 1 values from 0 to 105.
    std::vector<double> boundaries;
    /// Phrases x kRigParameterCount: change of each parameter over each phrase.
    Eigen::MatrixXd displacements;
    std::vector<SwayTerm> sway;
};

struct EmotionDesign {
    std::string emotion;
    /// Cell frames of the phrase boundaries (same count as the function's, 0 and 105 at the ends).
    std::vector<double> boundaries;
    /// Phrases x kRigParameterCount gains on the function's displacements.
    Eigen::MatrixXd gains;
    /// Phrases x kRigParameterCount displacements added after the gains.
    Eigen::MatrixXd offsets;
};

/// greeting and serving-tea, in that order.
std::vector<FunctionScript> demoFunctionScripts();
/// The emotions of the demo, the neutral one first: none, friendly, hostile.
std::vector<std::string> demoEmotions();
/// The design of `emotion` for `script`; "none" is the identity design (gains 1, offsets 0,
/// the function's own boundaries).
EmotionDesign demoEmotionDesign(const FunctionScript& script, const std::string& emotion);

/// Rig parameters at functional time s (frames): rest + sum_p D_p minimumJerk over phrase p +
/// sway, where D = `displacements` (phrases x parameters) is the design's effective
/// displacement matrix (gains .* function displacements + offsets).
Eigen::VectorXd scriptParameters(const FunctionScript& script, const Eigen::MatrixXd& displacements, double s);

} // namespace bunraku::analysis::synth
