#include "analysis/synth/demo_script.h"

#include "analysis/synth/motion_curves.h"

#include <cassert>
#include <cmath>
#include <initializer_list>
#include <numbers>
#include <utility>

namespace bunraku::analysis::synth {
namespace {

using P = RigParameter;
using Settings = std::initializer_list<std::pair<P, double>>;

void set(Eigen::MatrixXd& matrix, int phrase, Settings values)
{
    for (const auto& [parameter, value] : values) matrix(phrase, rigIndex(parameter)) = value;
}

/// Gains of `phrase` chosen so that the net displacement over the whole cell reaches each
/// listed value: the phrase that "comes back" decides how far back the posture comes.
void balance(EmotionDesign& design, const FunctionScript& script, int phrase, Settings netTargets)
{
    for (const auto& [parameter, target] : netTargets) {
        const int q = rigIndex(parameter);
        const double own = script.displacements(phrase, q);
        assert(own != 0.0);
        double others = design.offsets(phrase, q);
        for (Eigen::Index p = 0; p < script.displacements.rows(); ++p)
            if (p != phrase) others += design.gains(p, q) * script.displacements(p, q) + design.offsets(p, q);
        design.gains(phrase, q) = (target - others) / own;
    }
}

std::vector<SwayTerm> swayTerms(double phaseShift, double periodScale)
{
    std::vector<SwayTerm> terms{
        {P::BodyX, 0.5, 53, 3.3},  {P::BodyY, 0.6, 61, 0.2},     {P::BodyZ, 0.4, 21, 0.3},
        {P::BodyYaw, 2.5, 47, 1.1}, {P::BodyRoll, 1.2, 33, 2.0},  {P::HeadYaw, 2.0, 29, 0.7},
        {P::HeadPitch, 1.5, 17, 2.6}, {P::HeadRoll, 2.0, 41, 4.0}, {P::ArmYaw, 1.5, 37, 5.1},
        {P::HandRoll, 3.0, 23, 1.7},
    };
    for (auto& term : terms) {
        term.phase += phaseShift;
        term.periodFrames *= periodScale;
    }
    return terms;
}

FunctionScript greetingScript()
{
    FunctionScript s;
    s.function = "greeting";
    s.phraseNames = {"rest", "prepare", "bow", "hold", "rise", "settle", "rest"};
    s.boundaries = {0, 10, 20, 40, 52, 72, 85, 105};
    s.displacements = Eigen::MatrixXd::Zero(7, kRigParameterCount);
    set(s.displacements, 1, {{P::BodyZ, 1.0}, {P::BodyPitch, -3}, {P::HeadPitch, -6}, {P::HandRoll, 5}});
    set(s.displacements, 2,
        {{P::BodyX, 2}, {P::BodyZ, -3}, {P::BodyPitch, 30}, {P::HeadPitch, 12}, {P::ArmPitch, -8}, {P::ArmReach, -1},
         {P::HandPitch, 5}});
    set(s.displacements, 3, {{P::BodyZ, -0.5}, {P::BodyPitch, 3}, {P::HeadPitch, 4}});
    // rise: back through the rest pose to a small overshoot that the settle phrase takes back.
    Eigen::RowVectorXd overshoot = Eigen::RowVectorXd::Zero(kRigParameterCount);
    overshoot(rigIndex(P::BodyPitch)) = -3;
    overshoot(rigIndex(P::HeadPitch)) = -3;
    overshoot(rigIndex(P::BodyZ)) = 0.5;
    s.displacements.row(4) = -s.displacements.topRows(4).colwise().sum() + overshoot;
    s.displacements.row(5) = -overshoot;
    s.sway = swayTerms(0.0, 1.0);
    return s;
}

FunctionScript teaScript()
{
    FunctionScript s;
    s.function = "serving-tea";
    s.phraseNames = {"rest", "travel", "offer", "release", "bow", "return", "rest"};
    s.boundaries = {0, 8, 30, 48, 58, 74, 92, 105};
    s.displacements = Eigen::MatrixXd::Zero(7, kRigParameterCount);
    set(s.displacements, 1,
        {{P::BodyX, 24}, {P::BodyZ, -1.5}, {P::BodyPitch, 6}, {P::HeadPitch, 4}, {P::ArmPitch, -10}, {P::ArmReach, 2}});
    set(s.displacements, 2,
        {{P::BodyX, 4}, {P::BodyZ, -2}, {P::BodyPitch, 6}, {P::HeadPitch, 5}, {P::ArmPitch, -22}, {P::ArmYaw, 12},
         {P::ArmReach, 5}, {P::HandPitch, 12}});
    set(s.displacements, 3, {{P::BodyZ, -0.5}, {P::HeadPitch, -6}, {P::ArmReach, -2}, {P::HandPitch, 10}, {P::HandRoll, 25}});
    set(s.displacements, 4,
        {{P::BodyZ, -2.5}, {P::BodyPitch, 20}, {P::HeadPitch, 15}, {P::ArmPitch, 20}, {P::ArmYaw, -12}, {P::ArmReach, -5},
         {P::HandPitch, -22}, {P::HandRoll, -25}});
    set(s.displacements, 5,
        {{P::BodyX, -8}, {P::BodyZ, 6.5}, {P::BodyPitch, -32}, {P::HeadPitch, -18}, {P::ArmPitch, 12}});
    s.sway = swayTerms(1.3, 1.1);
    return s;
}

EmotionDesign identityDesign(const FunctionScript& script, std::string emotion)
{
    const auto phrases = script.displacements.rows();
    return EmotionDesign{std::move(emotion), script.boundaries, Eigen::MatrixXd::Ones(phrases, kRigParameterCount),
                         Eigen::MatrixXd::Zero(phrases, kRigParameterCount)};
}

void designGreeting(EmotionDesign& d, const FunctionScript& s)
{
    if (d.emotion == "friendly") { // slower, deeper, warmer; lingers slightly bowed
        d.boundaries = {0, 12, 24, 50, 66, 88, 100, 105};
        set(d.gains, 1, {{P::BodyZ, 1.5}, {P::HeadPitch, 1.3}});
        set(d.gains, 2, {{P::BodyPitch, 1.35}, {P::HeadPitch, 1.3}, {P::BodyZ, 1.5}, {P::BodyX, 1.5}, {P::ArmPitch, 1.2}});
        set(d.gains, 3, {{P::BodyPitch, 1.6}, {P::HeadPitch, 1.5}, {P::BodyZ, 1.5}});
        set(d.offsets, 2, {{P::HeadRoll, 6}});
        set(d.offsets, 4, {{P::HeadRoll, -3}});
        balance(d, s, 4,
                {{P::BodyPitch, 2}, {P::HeadPitch, 3}, {P::BodyZ, -0.5}, {P::BodyX, 0}, {P::ArmPitch, 0}, {P::ArmReach, 0},
                 {P::HandPitch, 0}, {P::HandRoll, 0}});
    } else if (d.emotion == "hostile") { // quicker, shallow, head turned away, chin up
        d.boundaries = {0, 7, 14, 28, 34, 48, 58, 105};
        set(d.gains, 1, {{P::BodyZ, 0.5}, {P::BodyPitch, 0.5}, {P::HeadPitch, 0.5}, {P::HandRoll, 0.5}});
        set(d.gains, 2, {{P::BodyPitch, 0.45}, {P::HeadPitch, 0.4}, {P::BodyZ, 0.5}, {P::BodyX, 0.5}, {P::ArmPitch, 0.6}});
        set(d.gains, 3, {{P::BodyPitch, 0.3}, {P::HeadPitch, 0.3}, {P::BodyZ, 0.3}});
        set(d.offsets, 1, {{P::HeadYaw, 30}, {P::BodyYaw, 8}, {P::HeadRoll, -4}});
        set(d.offsets, 4, {{P::HeadYaw, -8}});
        balance(d, s, 4,
                {{P::BodyPitch, 0}, {P::HeadPitch, -4}, {P::BodyZ, 0}, {P::BodyX, 0}, {P::ArmPitch, 0}, {P::ArmReach, 0},
                 {P::HandPitch, 0}, {P::HandRoll, 0}});
    }
}

void designTea(EmotionDesign& d, const FunctionScript& s)
{
    if (d.emotion == "friendly") { // longer travel, larger up-down motion, stays low after offering
        d.boundaries = {0, 10, 38, 58, 70, 88, 102, 105};
        set(d.gains, 1, {{P::BodyX, 1.4}, {P::BodyZ, 1.6}, {P::BodyPitch, 1.3}});
        set(d.gains, 2, {{P::BodyX, 1.5}, {P::BodyPitch, 1.3}, {P::BodyZ, 1.5}, {P::ArmReach, 1.2}, {P::HeadPitch, 1.2}});
        set(d.gains, 3, {{P::HandRoll, 1.2}, {P::HeadPitch, 1.3}});
        set(d.gains, 4, {{P::BodyPitch, 1.35}, {P::HeadPitch, 1.3}, {P::BodyZ, 1.5}});
        set(d.gains, 5, {{P::BodyX, 0.4}});
        balance(d, s, 4, {{P::HandRoll, 0}});
        balance(d, s, 5,
                {{P::BodyPitch, 10}, {P::BodyZ, -3.5}, {P::HeadPitch, 6}, {P::ArmPitch, 0}});
    } else if (d.emotion == "hostile") { // shorter travel, quick, small bow, head turned away
        d.boundaries = {0, 6, 24, 36, 43, 55, 68, 105};
        set(d.gains, 1, {{P::BodyX, 0.7}, {P::BodyZ, 0.5}, {P::BodyPitch, 0.5}, {P::HeadPitch, 0.5}});
        set(d.gains, 2, {{P::BodyX, 0.5}, {P::BodyPitch, 0.5}, {P::BodyZ, 0.5}, {P::ArmReach, 1.4}, {P::ArmPitch, 1.1}});
        set(d.gains, 3, {{P::HandRoll, 1.3}, {P::HeadPitch, 0.5}});
        set(d.gains, 4, {{P::BodyPitch, 0.45}, {P::HeadPitch, 0.4}, {P::BodyZ, 0.5}});
        set(d.gains, 5, {{P::BodyX, 1.5}});
        set(d.offsets, 1, {{P::HeadYaw, 28}, {P::BodyYaw, 6}, {P::HeadRoll, -4}});
        set(d.offsets, 5, {{P::HeadYaw, -6}});
        balance(d, s, 4, {{P::HandRoll, 0}, {P::ArmReach, 0}, {P::HandPitch, 0}});
        balance(d, s, 5, {{P::BodyPitch, 0}, {P::BodyZ, 0}, {P::HeadPitch, -3}, {P::ArmPitch, 0}});
    }
}

} // namespace

std::vector<FunctionScript> demoFunctionScripts() { return {greetingScript(), teaScript()}; }

std::vector<std::string> demoEmotions() { return {"none", "friendly", "hostile"}; }

EmotionDesign demoEmotionDesign(const FunctionScript& script, const std::string& emotion)
{
    EmotionDesign design = identityDesign(script, emotion);
    if (script.function == "greeting")
        designGreeting(design, script);
    else
        designTea(design, script);
    return design;
}

Eigen::VectorXd scriptParameters(const FunctionScript& script, const Eigen::MatrixXd& displacements, double s)
{
    Eigen::VectorXd p = restParameters();
    for (Eigen::Index phrase = 0; phrase < displacements.rows(); ++phrase) {
        const double start = script.boundaries[std::size_t(phrase)];
        const double end = script.boundaries[std::size_t(phrase) + 1];
        p += displacements.row(phrase).transpose() * minimumJerk((s - start) / (end - start));
    }
    const double envelope = minimumJerk(s / 10.0);
    for (const SwayTerm& term : script.sway)
        p(rigIndex(term.parameter)) +=
            envelope * term.amplitude * std::sin(2.0 * std::numbers::pi * s / term.periodFrames + term.phase);
    return p;
}

} // namespace bunraku::analysis::synth
