#pragma once
/// A synthetic long take for benchmarks and batch tests: one performer with a 22-joint skeleton
/// (joint names like the Bandai Namco files, so the automatic part map finds head, chest, the
/// forearms and hands) moving for any number of frames, written as BVH text - the format users
/// bring hour-long captures in. Nothing large is kept in the repository: `bunraku demo --long N`
/// writes the file on demand (docs/PERFORMANCE.md).
///
/// The motion is deterministic in (seed, frame): every rotation channel is a sum of two sines
/// whose frequencies (0.1-1.6 Hz) and phases come from the seed, their amplitude drifting over
/// minutes, and the root wanders over a 2 m floor, so no stretch of an hour repeats another.

#include "analysis/core/result.h"

#include <Eigen/Core>

#include <cstdint>
#include <filesystem>
#include <string>

namespace bunraku::analysis::synth {

struct LongTakeOptions {
    Eigen::Index frames = 432000; ///< an hour at 120 Hz
    double rateHz = 120.0;
    std::uint64_t seed = 1;
};

/// Joints (22, End Sites not counted) and motion channels (root: 3 positions + 3 rotations,
/// every other joint 3 rotations) of the long take's skeleton.
inline constexpr int kLongTakeJoints = 22;
inline constexpr int kLongTakeChannels = 6 + 3 * (kLongTakeJoints - 1);

/// Checks frames in [2, 100,000,000] and a rate in (0, 1000] Hz.
Status validateLongTakeOptions(const LongTakeOptions& options);

/// The whole BVH text (HIERARCHY, then MOTION with options.frames rows): Y up, centimetres,
/// rotations Z X Y in degrees with 6 significant digits (about 640 bytes a frame).
Result<std::string> longTakeBvh(const LongTakeOptions& options);

/// The file name `long_none_001.bvh`: function "long", emotion "none", take 1, so a corpus can be
/// made from it with the pattern {function}_{emotion}_{take}.
std::string longTakeFileName();

/// Writes longTakeBvh(options) to `folder / longTakeFileName()` (the folder is created;
/// the file is written atomically). Returns the file's path.
Result<std::filesystem::path> writeLongTake(const LongTakeOptions& options, const std::filesystem::path& folder);

} // namespace bunraku::analysis::synth
