#include "analysis/preprocess/preprocess.h"

#include "analysis/core/angle_channels.h"
#include "analysis/core/puppet_layout.h"
#include "analysis/skeleton/puppet_rig_fit.h"
#include "analysis/skeleton/skeleton_resample.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>

namespace bunraku::analysis::preprocess {

namespace {

bool isAngleChannel(const Channel& channel) { return channel.unit == "deg"; }

/// Index into corpus.takes of the reference take of the cell (function, emotion), -1 if empty.
int cellReference(const Corpus& corpus, const std::string& function, const std::string& emotion, int referenceIndex)
{
    int best = -1;
    for (std::size_t i = 0; i < corpus.takes.size(); ++i) {
        const auto& labels = corpus.takes[i].labels;
        if (labels.function != function || labels.emotion != emotion) continue;
        if (labels.takeIndex == referenceIndex) return int(i);
        if (best < 0 || labels.takeIndex < corpus.takes[std::size_t(best)].labels.takeIndex) best = int(i);
    }
    return best;
}

/// Index of the position reference of a function: the reference take of its reference emotion.
int functionReference(const Corpus& corpus, const std::string& function, const PreprocessOptions& options)
{
    std::vector<std::string> candidates;
    if (!options.referenceEmotion.empty()) candidates.push_back(options.referenceEmotion);
    candidates.push_back(corpus.neutralEmotion);
    for (const auto& emotion : corpus.emotions()) candidates.push_back(emotion);
    for (const auto& emotion : candidates) {
        const int index = cellReference(corpus, function, emotion, options.referenceTakeIndex);
        if (index >= 0) return index;
    }
    return -1;
}

/// The heading part of a take as a 6-DOF part, when it is one.
std::optional<SixDofPart> headingSixDof(const Take& take, const std::string& headingPart)
{
    for (const SixDofPart& part : sixDofParts(take))
        if (part.part == headingPart) return part;
    return std::nullopt;
}

/// Index of the heading reference of a function: among its takes with a yaw channel on the
/// heading part, the one whose start heading is nearest (summed circular distance) to all the
/// others', so that a reference take that is itself turned (e.g. by 180 deg) cannot turn the
/// whole function; ties keep `fallback` (the function's position reference). -1 without such
/// takes. Headings differ by startHeadingDifference.
int headingReference(const Corpus& corpus, const std::string& function, const std::string& headingPart, int fallback)
{
    std::vector<int> candidates;
    for (std::size_t i = 0; i < corpus.takes.size(); ++i) {
        const Take& take = corpus.takes[i];
        if (take.labels.function != function || take.frameCount() == 0) continue;
        if (!take.channelIndex(headingPart, "yaw")) continue;
        candidates.push_back(int(i));
    }
    int best = -1;
    double bestSpread = std::numeric_limits<double>::infinity();
    for (int a : candidates) {
        double spread = 0.0;
        for (int other : candidates)
            spread += std::fabs(startHeadingDifference(corpus.takes[std::size_t(other)], corpus.takes[std::size_t(a)], headingPart));
        const bool better = spread < bestSpread - 1e-9 || (std::fabs(spread - bestSpread) <= 1e-9 && a == fallback);
        if (better) {
            bestSpread = spread;
            best = a;
        }
    }
    return best;
}

/// Onset of a take (fractional frame): departureOnset of its departure signal, with the noise
/// floor of its activity (both are distances between two noisy samples when the take is still).
double startOnset(const Take& take, const PreprocessOptions& options)
{
    const double noise = noiseFloor(activitySignal(take, options.activity), options.quietFraction);
    return departureOnset(departureSignal(take, options.activity), noise, options.onsetFraction, options.noiseBand);
}

/// Signal the CrossCorrelation method correlates: the start edge of the take's departure,
/// clipped at 2 * noiseBand * noise (twice the onset band; noiseless takes: the onset threshold
/// noise + onsetFraction * (peak - noise), whichever is lower), so the correlation aligns the
/// rise from the start pose rather than the whole motion, whose tempo differs between takes.
Eigen::VectorXd xcorrSignal(const Take& take, const PreprocessOptions& options)
{
    const double noise = noiseFloor(activitySignal(take, options.activity), options.quietFraction);
    const Eigen::VectorXd departure = departureSignal(take, options.activity);
    if (departure.size() == 0) return departure;
    double ceiling = noise + options.onsetFraction * (departure.maxCoeff() - noise);
    if (noise > 0.0) ceiling = std::min(ceiling, 2.0 * options.noiseBand * noise);
    return startEdge(departure, ceiling);
}

/// Step (3): per cell, choose the time reference (named or automatic) and shift every other
/// take by its estimated start shift; shifts are estimated on the unshifted takes.
void alignStartTimes(Corpus& out, const std::vector<Eigen::Index>& originalFrames, const PreprocessOptions& options,
                     PreprocessReport& report)
{
    const std::vector<Take> before = out.takes;
    std::vector<Eigen::VectorXd> signals;
    for (std::size_t i = 0; i < before.size(); ++i) {
        report.takes[i].onsetFrame = startOnset(before[i], options);
        if (options.alignMethod == StartAlignMethod::CrossCorrelation) signals.push_back(xcorrSignal(before[i], options));
    }
    for (const auto& function : out.functions())
        for (const auto& emotion : out.emotions()) {
            std::vector<std::size_t> members;
            std::vector<ReferenceCandidate> candidates;
            int ref = -1;
            for (std::size_t i = 0; i < before.size(); ++i) {
                const auto& labels = before[i].labels;
                if (labels.function != function || labels.emotion != emotion) continue;
                if (options.referenceTakeIndex > 0 && labels.takeIndex == options.referenceTakeIndex) ref = int(i);
                members.push_back(i);
                candidates.push_back({originalFrames[i], report.takes[i].onsetFrame});
            }
            if (members.empty()) continue;
            const bool automatic = ref < 0;
            if (automatic) ref = int(members[std::size_t(chooseTimeReference(candidates, options.longTakeFraction))]);
            const auto r = std::size_t(ref);
            report.timeReferences.push_back({function, emotion, before[r].labels.takeIndex, automatic, report.takes[r].onsetFrame});
            report.takes[r].isTimeReference = true;
            for (std::size_t i : members) {
                if (i == r) continue;
                const int shift = options.alignMethod == StartAlignMethod::Onset
                                      ? int(std::lround(report.takes[i].onsetFrame - report.takes[r].onsetFrame))
                                      : crossCorrelationShift(signals[i], signals[r], options.maxShiftFrames);
                shiftTake(out.takes[i], shift);
                report.takes[i].shiftFrames = shift;
            }
        }
}

Error cancelled() { return makeError(ErrorCode::Cancelled, "preprocessing cancelled"); }

} // namespace

Eigen::Index padToLength(Take& take, Eigen::Index frames)
{
    const Eigen::Index old = take.frameCount();
    if (old >= frames || old == 0) return 0;
    Eigen::MatrixXd padded(frames, take.channelCount());
    padded.topRows(old) = take.values;
    padded.bottomRows(frames - old) = take.values.row(old - 1).replicate(frames - old, 1);
    take.values = std::move(padded);
    if (take.skeleton) take.skeleton = resampleSkeletalMotion(*take.skeleton, shiftedFrames(old, frames, 0));
    return frames - old;
}

int unwrapDegrees(Eigen::Ref<Eigen::VectorXd> column)
{
    int wraps = 0;
    double offset = 0.0;
    for (Eigen::Index t = 1; t < column.size(); ++t) {
        const double raw = column[t] + offset;
        const double step = raw - column[t - 1];
        const double turns = std::round(step / 360.0);
        if (turns != 0.0) {
            offset -= 360.0 * turns;
            wraps += int(std::fabs(turns));
        }
        column[t] += offset;
    }
    return wraps;
}

int unwrapAngles(Take& take)
{
    // 6-DOF parts: the Euler filter (whole turns and the mirrored triple, nearest the previous
    // frame); lone angle channels: whole turns.
    std::vector<bool> inPart(std::size_t(take.channelCount()), false);
    for (const SixDofPart& part : sixDofParts(take))
        for (Eigen::Index c = part.firstChannel + 3; c < part.firstChannel + 6; ++c) inPart[std::size_t(c)] = true;
    int wraps = filterEulerAngles(take);
    for (Eigen::Index c = 0; c < take.channelCount(); ++c)
        if (isAngleChannel(take.channels[std::size_t(c)]) && !inPart[std::size_t(c)]) wraps += unwrapDegrees(take.values.col(c));
    return wraps;
}

int estimateStartShift(const Take& take, const Take& reference, const PreprocessOptions& options)
{
    if (options.alignMethod == StartAlignMethod::Onset)
        return int(std::lround(startOnset(take, options) - startOnset(reference, options)));
    return crossCorrelationShift(xcorrSignal(take, options), xcorrSignal(reference, options), options.maxShiftFrames);
}

int matchAngleBranches(Take& take, const Take& reference)
{
    int turns = 0;
    for (Eigen::Index c = 0; c < take.channelCount(); ++c) {
        const Channel& channel = take.channels[std::size_t(c)];
        if (!isAngleChannel(channel) || take.frameCount() == 0) continue;
        const auto r = reference.channelIndex(channel.part, channel.dof);
        if (!r || reference.frameCount() == 0) continue;
        const double k = std::round((reference.values(0, *r) - take.values(0, c)) / 360.0);
        if (k == 0.0) continue;
        take.values.col(c).array() += 360.0 * k;
        turns += int(std::abs(k));
    }
    return turns;
}

double startHeadingDifference(const Take& reference, const Take& take, const std::string& headingPart)
{
    if (take.frameCount() == 0 || reference.frameCount() == 0) return 0.0;
    const auto own = headingSixDof(take, headingPart);
    const auto ref = headingSixDof(reference, headingPart);
    if (own && ref) {
        // The turn taking the take's start orientation to the reference's, in world axes, and
        // of it the twist about the vertical (swing-twist decomposition).
        const Eigen::Quaterniond q = (partPose(reference, 0, ref->firstChannel).rotation *
                                      partPose(take, 0, own->firstChannel).rotation.conjugate()).normalized();
        if (std::hypot(q.w(), q.z()) > 1e-9) return std::remainder(2.0 * std::atan2(q.z(), q.w()) * 180.0 / std::numbers::pi, 360.0);
        return 0.0; // a half turn about a horizontal axis: no heading to speak of
    }
    const auto yaw = take.channelIndex(headingPart, "yaw");
    const auto refYaw = reference.channelIndex(headingPart, "yaw");
    if (!yaw || !refYaw) return 0.0;
    return std::remainder(reference.values(0, *refYaw) - take.values(0, *yaw), 360.0);
}

double alignStartHeading(Take& take, const Take& reference, const std::string& headingPart)
{
    const auto own = take.channelIndex(headingPart, "yaw");
    const auto ref = reference.channelIndex(headingPart, "yaw");
    if (!own || !ref || take.frameCount() == 0 || reference.frameCount() == 0) return 0.0;
    // The physical turn, within (-180, 180]: the branch is matched afterwards by whole turns.
    const double offset = startHeadingDifference(reference, take, headingPart);
    // A rigid turn about the vertical through the heading part's start position: a rotation
    // about world z adds to every yaw (Rz(a) Rz(y) Ry(p) Rx(r) = Rz(a + y) Ry(p) Rx(r)) and
    // turns every position about the pivot.
    const auto pivotColumn = take.channelIndex(headingPart, "x");
    const bool hasPivot = pivotColumn && take.channelIndex(headingPart, "y") == *pivotColumn + 1;
    const Eigen::Vector2d pivot =
        hasPivot ? Eigen::Vector2d(take.values(0, *pivotColumn), take.values(0, *pivotColumn + 1)) : Eigen::Vector2d::Zero();
    const Eigen::Matrix2d turn = Eigen::Rotation2Dd(offset * std::numbers::pi / 180.0).toRotationMatrix();
    std::vector<SixDofPart> carried = sixDofParts(take);
    for (const SixDofPart& point : pointParts(take)) carried.push_back(point); // carried by the body (the kimono's points)
    for (const SixDofPart& part : carried) {
        if (!hasPivot) break;
        for (Eigen::Index f = 0; f < take.frameCount(); ++f) {
            const Eigen::Vector2d xy(take.values(f, part.firstChannel), take.values(f, part.firstChannel + 1));
            const Eigen::Vector2d turned = turn * (xy - pivot) + pivot;
            take.values(f, part.firstChannel) = turned.x();
            take.values(f, part.firstChannel + 1) = turned.y();
        }
    }
    for (Eigen::Index c = 0; c < take.channelCount(); ++c)
        if (take.channels[std::size_t(c)].dof == "yaw" && isAngleChannel(take.channels[std::size_t(c)]))
            take.values.col(c).array() += offset;
    if (take.skeleton && offset != 0.0) {
        // The same rigid turn of the whole skeleton: about the vertical through the pivot.
        RigidTransform turnAbout;
        turnAbout.rotation = Eigen::Quaterniond(Eigen::AngleAxisd(offset * std::numbers::pi / 180.0, Eigen::Vector3d::UnitZ()));
        const Eigen::Vector3d pivot3(pivot.x(), pivot.y(), 0.0);
        turnAbout.translation = pivot3 - turnAbout.rotation * pivot3;
        take.skeleton = moveSkeletalMotion(*take.skeleton, turnAbout);
    }
    return offset;
}

Result<PreprocessResult> preprocessCorpus(const Corpus& corpus, const PreprocessOptions& options, const RunControl& control)
{
    if (auto valid = validateCorpus(corpus); !valid) return valid.error();
    if (!(options.onsetFraction > 0.0 && options.onsetFraction <= 1.0))
        return makeError(ErrorCode::InvalidArgument, "onset fraction must be in (0, 1]");
    if (options.maxShiftFrames < 0) return makeError(ErrorCode::InvalidArgument, "the maximum shift must not be negative");
    if (!(options.quietFraction >= 0.0 && options.quietFraction <= 1.0))
        return makeError(ErrorCode::InvalidArgument, "quiet fraction must be in [0, 1]");
    if (!(options.longTakeFraction >= 0.0 && options.longTakeFraction <= 1.0))
        return makeError(ErrorCode::InvalidArgument, "long-take fraction must be in [0, 1]");
    if (!(options.activity.cmPerDegree >= 0.0) || !std::isfinite(options.activity.cmPerDegree))
        return makeError(ErrorCode::InvalidArgument, "the angle weight (cm per degree) must be finite and not negative");
    if (options.referenceTakeIndex < 0)
        return makeError(ErrorCode::InvalidArgument, "the reference take index must be 0 (automatic) or a take index");
    std::vector<Eigen::Index> originalFrames;
    for (const Take& take : corpus.takes) originalFrames.push_back(take.frameCount());
    PreprocessResult result{corpus, {}};
    Corpus& out = result.corpus;
    // One body per take: puppet-channel takes without a skeleton get the puppet's rig fitted to
    // the whole corpus (one puppet), which every step below moves as one body.
    if (auto rig = attachPuppetRig(out.takes); !rig) return rig.error();
    auto& reports = result.report.takes;
    for (const Take& take : out.takes) {
        TakeReport report;
        report.take = take.displayName();
        report.positionOffsets.assign(sixDofParts(take).size(), Eigen::Vector3d::Zero());
        reports.push_back(report);
    }

    if (options.unwrap)
        for (std::size_t i = 0; i < out.takes.size(); ++i) reports[i].anglesUnwrapped = unwrapAngles(out.takes[i]);
    if (control.cancelled()) return cancelled();
    control.report(0.25);

    if (options.pad) {
        Eigen::Index longest = 0;
        for (const Take& take : out.takes) longest = std::max(longest, take.frameCount());
        for (std::size_t i = 0; i < out.takes.size(); ++i) reports[i].framesPadded = padToLength(out.takes[i], longest);
        result.report.paddedFrames = longest;
    }
    if (control.cancelled()) return cancelled();
    control.report(0.5);

    if (options.alignStart) alignStartTimes(out, originalFrames, options, result.report);
    if (control.cancelled()) return cancelled();
    control.report(0.75);

    if (options.unwrap || options.alignHeading) {
        for (const auto& function : out.functions()) {
            const int positionRef = functionReference(out, function, options);
            const int headingRef = headingReference(out, function, options.headingPart, positionRef);
            const int ref = headingRef >= 0 ? headingRef : positionRef;
            if (ref < 0) continue;
            const Take reference = out.takes[std::size_t(ref)];
            if (options.alignHeading && headingRef >= 0) reports[std::size_t(ref)].isHeadingReference = true;
            for (std::size_t i = 0; i < out.takes.size(); ++i) {
                Take& take = out.takes[i];
                if (take.labels.function != function || int(i) == ref) continue;
                // Heading first, then whole turns: every angle channel ends within 180 deg of the
                // reference's, whichever branch the turn left it on.
                if (options.alignHeading)
                    reports[i].headingOffsetDeg = alignStartHeading(take, reference, options.headingPart);
                if (options.unwrap) {
                    reports[i].branchTurns = matchPartBranches(take, reference) + matchAngleBranches(take, reference);
                }
            }
        }
    }

    if (options.alignPosition) {
        for (const auto& function : out.functions()) {
            const int ref = functionReference(out, function, options);
            if (ref < 0) continue;
            const Take reference = out.takes[std::size_t(ref)];
            for (std::size_t i = 0; i < out.takes.size(); ++i) {
                Take& take = out.takes[i];
                if (take.labels.function != function) continue;
                reports[i].isPositionReference = int(i) == ref;
                if (int(i) == ref) continue;
                reports[i].positionOffsets = alignStartPosition(take, reference, options.positionAlignment);
                // The skeleton is one rigid body: it moves by the heading part's offset (every
                // part's under the default rigid alignment).
                const auto parts = sixDofParts(take);
                std::optional<Eigen::Vector3d> bodyOffset;
                for (std::size_t p = 0; p < parts.size() && p < reports[i].positionOffsets.size(); ++p)
                    if (parts[p].part == options.headingPart || !bodyOffset) bodyOffset = reports[i].positionOffsets[p];
                // A performer stands on the floor: the body moves across it, never into or above
                // it (the thesis's channels still move up or down; the puppet's rig, held by its
                // puppeteers, follows them).
                if (take.skeleton && bodyOffset && !isPuppetRig(*take.skeleton->skeleton)) bodyOffset->z() = 0.0;
                if (take.skeleton && bodyOffset && !bodyOffset->isZero())
                    take.skeleton = moveSkeletalMotion(*take.skeleton, RigidTransform{Eigen::Quaterniond::Identity(), *bodyOffset});
            }
        }
    }
    control.report(1.0);
    return result;
}

} // namespace bunraku::analysis::preprocess
