#pragma once
/// The take model: one recording of a performer, frames x channels, with channel names, units
/// and labels. The puppet layout (4 parts x 6 DOF) is one layout among others: a BVH import may
/// keep more joints, a motion-axis take has its own 6 channels.

#include "analysis/core/result.h"

#include <Eigen/Core>

#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace bunraku::analysis {

struct SkeletalMotion; // analysis/core/skeleton.h

/// One column of a take: a part (head, Hand_R, axis...) and a degree of freedom of it.
struct Channel {
    std::string part; ///< e.g. "head"
    std::string dof;  ///< e.g. "x", "yaw"
    std::string unit; ///< e.g. "cm", "deg"

    /// "part.dof", the CSV header and the name used on the command line.
    std::string name() const { return part + "." + dof; }
    bool operator==(const Channel&) const = default;
};

/// What a take is an instance of. Emotion labels are data: nothing in analysis/ hard-codes them.
struct TakeLabels {
    std::string function;  ///< e.g. "greeting"
    std::string emotion;   ///< e.g. "none"
    int takeIndex = 0;     ///< 1-based index within its function x emotion cell, 0 when unknown
    std::string source;    ///< file it came from, or the recipe that derived it
    bool operator==(const TakeLabels&) const = default;
};

struct Take {
    /// frames x channels, rows = time; positions in cm, angles in degrees.
    Eigen::MatrixXd values;
    double rateHz = 5.0;
    std::vector<Channel> channels;
    TakeLabels labels;
    /// The performer's full skeleton and its motion, frame for frame with `values`, when the take
    /// came from (or was derived from) a file with a skeleton; null otherwise. Shared and
    /// immutable: a derived take builds a new one (analysis/core/skeleton.h).
    std::shared_ptr<const SkeletalMotion> skeleton;

    Eigen::Index frameCount() const { return values.rows(); }
    Eigen::Index channelCount() const { return values.cols(); }
    /// Seconds from the first to the last frame.
    double duration() const { return frameCount() > 1 ? double(frameCount() - 1) / rateHz : 0.0; }
    double timeOfFrame(Eigen::Index frame) const { return double(frame) / rateHz; }

    std::optional<Eigen::Index> channelIndex(std::string_view part, std::string_view dof) const;
    /// By "part.dof" name.
    std::optional<Eigen::Index> channelIndex(std::string_view name) const;
    /// Part names in the order of their first channel.
    std::vector<std::string> parts() const;
    /// "function/emotion/k" when labelled, else the source.
    std::string displayName() const;
};

/// Checks the shape (one Channel per column, at least one frame, positive rate) and that every
/// value is finite and within valueLimit of its unit; the error names the first offending frame
/// and channel.
Status validateTake(const Take& take);

/// The highest sample rate a take may have (Hz): well above any motion capture system, low
/// enough that a rate from a corrupt file (a BVH frame time of 1e-300 s) is refused.
inline constexpr double kMaxRateHz = 1e6;

/// True for a finite rate in (0, kMaxRateHz].
bool plausibleRate(double hz);

/// "expected a sample rate in (0, 1000000] Hz", for error messages.
std::string rateExpectation();

/// The largest magnitude a channel value may have, by unit: 1e7 for "cm" (100 km), 1e9 for
/// "deg" (unwrapped angles of hours of spinning), 1e12 for anything else. Far beyond any motion,
/// small enough that squares and sums over a take never overflow (positions of 1e308 would turn
/// variances and ARMA tables into inf). Readers refuse larger values with the line.
double valueLimit(std::string_view unit);

} // namespace bunraku::analysis
