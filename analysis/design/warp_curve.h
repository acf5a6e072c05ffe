#pragma once
/// The time-correspondence curve of a design (thesis Fig. 5.13, 5.5): for each output
/// (emotional) frame, the source (functional) frame it shows. Edited through control points and
/// evaluated by monotone cubic interpolation (Fritsch & Carlson 1980), so the curve never runs
/// backwards however the points are dragged (moveControlPoint clamps between the neighbours).

#include "analysis/core/result.h"

#include <Eigen/Core>

#include <filesystem>
#include <string>
#include <vector>

namespace bunraku::analysis {

struct WarpPoint {
    double output = 0.0; ///< frame of the designed (emotional) take
    double source = 0.0; ///< frame of the functional take it shows
    bool operator==(const WarpPoint&) const = default;
};

/// Control points with strictly increasing `output` and non-decreasing `source`.
struct WarpCurve {
    std::vector<WarpPoint> points;
    /// Frames of the designed take (the last output frame + 1 by default).
    Eigen::Index outputFrames = 0;
};

/// Checks at least 2 points, finite values, output strictly increasing, source non-decreasing.
Status validateWarpCurve(const WarpCurve& curve);

/// The identity curve over `frames` frames with a point every `spacing` frames.
WarpCurve identityWarp(Eigen::Index frames, int spacing = 8);

/// Source frame at output frame x: Fritsch-Carlson monotone cubic through the points, constant
/// beyond the first and last point.
double evaluateWarp(const WarpCurve& curve, double output);
/// Source frame for each output frame 0..outputFrames-1.
Eigen::VectorXd sampleWarp(const WarpCurve& curve);

/// The inverse of the monotone curve: the first output frame u (within the control points'
/// output range) with evaluateWarp(curve, u) >= source, to 1e-9 frames by bisection. Sources
/// below the first point's source give its output, above the last point's source the last
/// output; on a flat stretch (the curve holds a source frame) the stretch's first frame.
/// An invalid curve (validateWarpCurve) returns `source` unchanged (the identity).
double inverseWarp(const WarpCurve& curve, double source);

/// How a dragged point meets its neighbours' source frames.
enum class WarpMove {
    Clamp, ///< it stops at them
    Push,  ///< it pushes them (and theirs) along: one drag retimes a whole stretch
};

/// The curve with point `index` moved towards `proposed`, its output clamped strictly between
/// the neighbours' (by `minimumGap` frames; the first and last points keep their output frame).
/// Its source: Clamp keeps it between the neighbours' sources; Push takes it as proposed and
/// moves every earlier point's source down to it where above, every later point's up to it where
/// below, so the curve stays monotone. Points that do not block the move are never touched.
WarpCurve moveControlPoint(const WarpCurve& curve, std::size_t index, const WarpPoint& proposed, double minimumGap = 0.5,
                           WarpMove mode = WarpMove::Clamp);

/// Control points summarising a dense monotone map (one source frame per output frame): one
/// every `spacing` frames plus the last frame.
WarpCurve warpCurveFromSamples(const Eigen::VectorXd& sourceOfOutput, int spacing = 8);

/// The largest frame a warp CSV may name (output or source) and the most control points it may
/// hold: a curve past them would design takes of gigabytes (an output frame of 1e9).
inline constexpr double kWarpCsvMaxFrame = 1e6;
inline constexpr std::size_t kWarpCsvMaxPoints = 1'000'001;

/// CSV "output_frame,source_frame" with a header, one control point per line; written atomically.
Status writeWarpCsv(const WarpCurve& curve, const std::filesystem::path& file);
/// Parses warp CSV text: an optional UTF-8 byte order mark, an optional header line exactly
/// "output_frame,source_frame", then lines of exactly two numbers in [0, kWarpCsvMaxFrame] (blank
/// lines skipped, nothing after a number). Parse errors name `sourceName`, the line and what was
/// expected; the curve is validated (validateWarpCurve).
Result<WarpCurve> parseWarpCsv(const std::string& text, const std::string& sourceName);
/// parseWarpCsv of a file (a regular file of at most io::kDocumentLimitBytes).
Result<WarpCurve> readWarpCsv(const std::filesystem::path& file);

} // namespace bunraku::analysis
