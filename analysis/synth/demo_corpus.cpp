#include "analysis/synth/demo_corpus.h"

#include "analysis/core/puppet_layout.h"
#include "analysis/synth/demo_script.h"
#include "analysis/synth/motion_curves.h"
#include "analysis/synth/puppet_rig.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <numbers>
#include <sstream>

namespace bunraku::analysis::synth {
namespace {

constexpr double kLastNominalFrame = kDemoNominalFrames - 1;

/// Linear interpolation of samples at a fractional index, clamped to the ends.
double sampleAt(const Eigen::VectorXd& samples, double index)
{
    const Eigen::Index last = samples.size() - 1;
    if (index <= 0.0 || last == 0) return samples(0);
    if (index >= double(last)) return samples(last);
    const Eigen::Index k = Eigen::Index(std::floor(index));
    const double f = index - double(k);
    return f == 0.0 ? samples(k) : (1.0 - f) * samples(k) + f * samples(k + 1);
}

/// The fractional index where the non-decreasing `samples`, strictly increasing from `first`
/// on, reach `value` (linear between samples), clamped to [first, size-1].
double inverseAt(const Eigen::VectorXd& samples, Eigen::Index first, double value)
{
    const Eigen::Index last = samples.size() - 1;
    if (value <= samples(first)) return double(first);
    if (value >= samples(last)) return double(last);
    const double* begin = samples.data() + first;
    const double* it = std::upper_bound(begin, samples.data() + last + 1, value);
    const Eigen::Index k = Eigen::Index(it - samples.data()) - 1; // samples(k) <= value < samples(k+1)
    const double f = (value - samples(k)) / (samples(k + 1) - samples(k));
    return double(k) + f;
}

} // namespace

Eigen::Vector3d headingPivot(const CellTruth& cell)
{
    return cell.motion.row(0).segment<3>(puppetChannel(1, Dof::X)).transpose();
}

Eigen::Matrix3d headingTurn(const TakeTruth& take)
{
    return Eigen::AngleAxisd(take.yawOffsetDeg * std::numbers::pi / 180.0, Eigen::Vector3d::UnitZ()).toRotationMatrix();
}

namespace {

Eigen::MatrixXd noiselessValues(const CellTruth& cell, const TakeTruth& take)
{
    const Eigen::RowVectorXd start = cell.motion.row(0);
    const Eigen::Vector3d pivot = headingPivot(cell);
    const Eigen::Matrix3d turn = headingTurn(take);
    Eigen::MatrixXd values(take.takeToCell.size(), kPuppetChannelCount);
    for (Eigen::Index t = 0; t < values.rows(); ++t) {
        Eigen::RowVectorXd row = start + take.amplitudeGain * (interpolateMotion(cell.motion, take.takeToCell(t)) - start);
        // The whole puppet turned rigidly about the vertical through the shoulder's start
        // position (a turn about world z only adds to yaw), then moved by the position offset.
        for (int part = 0; part < kPuppetPartCount; ++part) {
            const Eigen::Vector3d position = row.segment<3>(part * kDofCount).transpose();
            row.segment<3>(part * kDofCount) = (turn * (position - pivot) + pivot + take.positionOffset).transpose();
            row(puppetChannel(part, Dof::Yaw)) += take.yawOffsetDeg;
        }
        values.row(t) = row;
    }
    return values;
}

void wrapAngles(Eigen::MatrixXd& values)
{
    for (Eigen::Index c = 0; c < values.cols(); ++c)
        if (isAngleDof(int(c % kDofCount)))
            for (Eigen::Index t = 0; t < values.rows(); ++t) values(t, c) = wrapDegrees(values(t, c));
}

/// A random smooth monotone warp: still until `lateStart`, then a speed exp(sum of two slow
/// sinusoids) of relative deviation up to `strength`, scaled so the last frame shows cell
/// frame 105. Simpson integration with 16 sub-steps per frame.
Eigen::VectorXd randomWarp(DemoRandom& random, int frames, int lateStart, double strength)
{
    struct Term {
        double amplitude, period, phase;
    };
    Term terms[2];
    for (Term& term : terms) {
        const double sign = random.uniform() < 0.5 ? -1.0 : 1.0;
        term.amplitude = sign * 0.5 * std::log1p(strength) * random.uniform(0.6, 1.0);
        term.period = random.uniform(25.0, 90.0);
        term.phase = random.uniform(0.0, 2.0 * std::numbers::pi);
    }
    auto speed = [&](double t) {
        double e = 0.0;
        for (const Term& term : terms) e += term.amplitude * std::sin(2.0 * std::numbers::pi * t / term.period + term.phase);
        return std::exp(e);
    };
    Eigen::VectorXd warp = Eigen::VectorXd::Zero(frames);
    constexpr int kSteps = 16;
    for (int t = lateStart + 1; t < frames; ++t) {
        const double h = 1.0 / kSteps;
        double sum = speed(t - 1) + speed(t);
        for (int i = 1; i < kSteps; ++i) sum += (i % 2 ? 4.0 : 2.0) * speed(t - 1 + i * h);
        warp(t) = warp(t - 1) + sum * h / 3.0;
    }
    warp *= kLastNominalFrame / warp(frames - 1);
    warp(frames - 1) = kLastNominalFrame;
    return warp;
}

CellTruth makeCell(const FunctionScript& script, const EmotionDesign& design, bool neutral)
{
    CellTruth cell;
    cell.function = script.function;
    cell.emotion = design.emotion;
    cell.phraseBoundaries = design.boundaries;
    cell.phraseGains = design.gains;
    cell.phraseOffsets = design.offsets;
    const Eigen::MatrixXd displacements = design.gains.cwiseProduct(script.displacements) + design.offsets;
    const MonotoneCubic phase(design.boundaries, script.boundaries); // cell frame -> functional frame
    cell.phaseWarp.resize(kDemoNominalFrames);
    cell.functionalToEmotional.resize(kDemoNominalFrames);
    cell.motion.resize(kDemoNominalFrames, kPuppetChannelCount);
    for (int u = 0; u < kDemoNominalFrames; ++u) {
        cell.phaseWarp(u) = neutral ? double(u) : phase(u);
        cell.functionalToEmotional(u) = neutral ? double(u) : phase.inverse(u);
        cell.motion.row(u) = rigChannels(scriptParameters(script, displacements, cell.phaseWarp(u)));
    }
    return cell;
}

} // namespace

const FunctionTruth* DemoGroundTruth::function(const std::string& name) const
{
    for (const auto& f : functions)
        if (f.function == name) return &f;
    return nullptr;
}

const CellTruth* DemoGroundTruth::cell(const std::string& functionName, const std::string& emotion) const
{
    for (const auto& c : cells)
        if (c.function == functionName && c.emotion == emotion) return &c;
    return nullptr;
}

const TakeTruth* DemoGroundTruth::take(const TakeLabels& labels) const
{
    for (const auto& t : takes)
        if (t.labels.function == labels.function && t.labels.emotion == labels.emotion &&
            t.labels.takeIndex == labels.takeIndex)
            return &t;
    return nullptr;
}

DemoCorpus generateDemoCorpus(const DemoOptions& options)
{
    DemoCorpus demo;
    DemoGroundTruth& truth = demo.truth;
    truth.seed = options.seed;
    truth.positionNoiseCm = options.positionNoiseCm;
    truth.angleNoiseDeg = options.angleNoiseDeg;
    for (auto name : kRigParameterNames) truth.parameterNames.emplace_back(name);

    const auto scripts = demoFunctionScripts();
    const auto emotions = demoEmotions();
    truth.neutralEmotion = emotions.front();
    for (const FunctionScript& script : scripts) {
        for (const std::string& emotion : emotions) {
            const bool neutral = emotion == truth.neutralEmotion;
            truth.cells.push_back(makeCell(script, demoEmotionDesign(script, emotion), neutral));
        }
        const CellTruth& neutralCell = truth.cells[truth.cells.size() - emotions.size()];
        truth.functions.push_back(FunctionTruth{script.function, script.phraseNames, script.boundaries,
                                                script.displacements, neutralCell.motion});
        for (std::size_t e = 0; e < emotions.size(); ++e) {
            CellTruth& cell = truth.cells[truth.cells.size() - emotions.size() + e];
            cell.emotionComponent = cell.motion - neutralCell.motion;
            if (e == 0) cell.emotionComponent.setZero();
        }
    }

    Corpus& corpus = demo.corpus;
    corpus.name = "Bunraku demo corpus (seed " + std::to_string(options.seed) + ")";
    corpus.rateHz = kDemoRateHz;
    corpus.neutralEmotion = truth.neutralEmotion;

    DemoRandom random(options.seed);
    const int K = std::max(1, options.takesPerCell);
    const int longest = random.uniformInt(0, int(truth.cells.size()) * K - 1);
    int globalIndex = 0;
    for (const CellTruth& cell : truth.cells) {
        const int lateTake = random.uniformInt(1, K);
        const int wrapTake = random.uniformInt(1, K);
        for (int k = 1; k <= K; ++k, ++globalIndex) {
            TakeTruth take;
            take.labels = TakeLabels{cell.function, cell.emotion, k, "demo seed " + std::to_string(options.seed)};
            take.lateStartFrames = k == lateTake ? random.uniformInt(5, 10) : 0;
            const int shortening = random.uniformInt(1, take.lateStartFrames > 0 ? 2 : 5);
            const int frames = globalIndex == longest ? kDemoNominalFrames : kDemoNominalFrames - shortening;
            take.takeToCell = randomWarp(random, frames, take.lateStartFrames, options.warpStrength);
            take.amplitudeGain = 1.0 + random.uniform(-1.0, 1.0) * options.amplitudeJitter;
            take.positionOffset = Eigen::Vector3d(random.uniform(-3.0, 3.0), random.uniform(-3.0, 3.0),
                                                  random.uniform(-1.5, 1.5));
            const double yawDraw = random.uniform(-1.0, 1.0);
            if (k == wrapTake) {
                // Put the shoulder's mean yaw within 1 degree of 180 so its sway crosses +-180.
                const Eigen::MatrixXd plain = noiselessValues(cell, take);
                const double meanYaw = plain.col(puppetChannel(1, Dof::Yaw)).mean();
                take.yawOffsetDeg = wrapDegrees(180.0 - meanYaw + yawDraw);
                take.yawWraps = true;
            } else {
                take.yawOffsetDeg = 4.0 * yawDraw;
            }
            Eigen::MatrixXd values = noiselessValues(cell, take);
            for (Eigen::Index t = 0; t < values.rows(); ++t)
                for (Eigen::Index c = 0; c < values.cols(); ++c)
                    values(t, c) += random.gaussian() *
                                    (isAngleDof(int(c % kDofCount)) ? options.angleNoiseDeg : options.positionNoiseCm);
            wrapAngles(values);

            Take out;
            out.values = std::move(values);
            out.rateHz = kDemoRateHz;
            out.channels = puppetChannels();
            out.labels = take.labels;
            corpus.takes.push_back(std::move(out));
            truth.takes.push_back(std::move(take));
        }
    }
    return demo;
}

Result<Eigen::MatrixXd> noiselessTake(const DemoGroundTruth& truth, const TakeLabels& labels)
{
    const TakeTruth* take = truth.take(labels);
    const CellTruth* cell = take ? truth.cell(labels.function, labels.emotion) : nullptr;
    if (!take || !cell)
        return makeError(ErrorCode::NotFound, "no demo take " + labels.function + "/" + labels.emotion + "/" +
                                                  std::to_string(labels.takeIndex) + " in the ground truth");
    Eigen::MatrixXd values = noiselessValues(*cell, *take);
    wrapAngles(values);
    return values;
}

Result<Eigen::VectorXd> trueCorrespondence(const DemoGroundTruth& truth, const TakeLabels& reference,
                                           const TakeLabels& sample)
{
    const TakeTruth* ref = truth.take(reference);
    const TakeTruth* smp = truth.take(sample);
    if (!ref || !smp) return makeError(ErrorCode::NotFound, "trueCorrespondence: take not in the ground truth");
    if (reference.function != sample.function)
        return makeError(ErrorCode::InvalidArgument, "trueCorrespondence: takes of different functions (" +
                                                         reference.function + ", " + sample.function + ")");
    const CellTruth* refCell = truth.cell(reference.function, reference.emotion);
    const CellTruth* smpCell = truth.cell(sample.function, sample.emotion);
    if (!refCell || !smpCell) return makeError(ErrorCode::NotFound, "trueCorrespondence: cell not in the ground truth");
    const bool sameCell = reference.emotion == sample.emotion;
    const int refLate = ref->lateStartFrames;
    const int smpLate = smp->lateStartFrames;
    const double lastSample = double(smp->takeToCell.size() - 1);

    Eigen::VectorXd result(ref->takeToCell.size());
    for (Eigen::Index t = 0; t < result.size(); ++t) {
        if (t <= refLate) { // both hold still: stretch the held interval, onset onto onset
            result(t) = refLate > 0 ? double(smpLate) * double(t) / double(refLate) : double(smpLate);
        } else {
            double u = ref->takeToCell(t);
            if (!sameCell) u = inverseAt(smpCell->phaseWarp, 0, sampleAt(refCell->phaseWarp, u));
            result(t) = inverseAt(smp->takeToCell, smpLate, u);
        }
        result(t) = std::clamp(result(t), 0.0, lastSample);
    }
    return result;
}

bool isDemoTakeName(const std::string& name) { return name.rfind("demo:", 0) == 0; }

Result<Take> demoTake(const std::string& name)
{
    std::vector<std::string> fields;
    std::stringstream stream(isDemoTakeName(name) ? name.substr(5) : std::string());
    for (std::string field; std::getline(stream, field, '/');) fields.push_back(field);
    int index = 0;
    if (fields.size() != 3 || (index = std::atoi(fields[2].c_str())) <= 0)
        return makeError(ErrorCode::InvalidArgument, "'" + name + "': expected demo:FUNCTION/EMOTION/K, e.g. demo:greeting/friendly/1");
    static const DemoCorpus demo = generateDemoCorpus();
    if (const Take* take = demo.corpus.find(fields[0], fields[1], index)) return *take;
    std::string functions, emotions;
    for (const auto& f : demo.corpus.functions()) functions += (functions.empty() ? "" : ", ") + f;
    for (const auto& e : demo.corpus.emotions()) emotions += (emotions.empty() ? "" : ", ") + e;
    const auto takes = demo.corpus.cell(demo.corpus.functions().front(), demo.corpus.emotions().front()).size();
    return makeError(ErrorCode::NotFound, "'" + name + "': no such demo take (functions: " + functions + "; emotions: " + emotions +
                                              "; K = 1.." + std::to_string(takes) + ")");
}

} // namespace bunraku::analysis::synth
