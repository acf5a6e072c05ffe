#include "analysis/synth/long_take.h"

#include "analysis/io/atomic_file.h"

#include <array>
#include <charconv>
#include <cmath>
#include <numbers>
#include <system_error>
#include <vector>

namespace bunraku::analysis::synth {
namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;

/// One joint of the hierarchy: its parent (index, -1 for the root), its rest offset in cm (Y up,
/// the performer facing +Z, their left at +X), and the End Site offset when it ends a chain.
struct JointSpec {
    const char* name;
    int parent;
    double offset[3];
    bool endSite;
    double endOffset[3];
    /// Per rotation channel (Z, X, Y): the mean angle and the swing's amplitude, degrees.
    double bias[3];
    double amplitude[3];
};

// clang-format off
constexpr std::array<JointSpec, kLongTakeJoints> kJoints{{
    {"joint_Root",  -1, {0, 0, 0},     false, {0, 0, 0},  {0, 0, 0},    {2, 2, 0}},
    {"Hips",         0, {0, 93, 0},    false, {0, 0, 0},  {0, 0, 0},    {4, 5, 10}},
    {"Spine",        1, {0, 12, 0},    false, {0, 0, 0},  {0, 3, 0},    {4, 6, 8}},
    {"Chest",        2, {0, 14, 0},    false, {0, 0, 0},  {0, 2, 0},    {4, 5, 8}},
    {"Neck",         3, {0, 22, 0},    false, {0, 0, 0},  {0, 0, 0},    {5, 8, 12}},
    {"Head",         4, {0, 8, 0},     true,  {0, 18, 0}, {0, -3, 0},   {6, 10, 20}},
    {"Shoulder_L",   3, {4, 18, 0},    false, {0, 0, 0},  {0, 0, 0},    {5, 3, 5}},
    {"UpperArm_L",   6, {14, 0, 0},    false, {0, 0, 0},  {-60, 0, 10}, {30, 25, 25}},
    {"LowerArm_L",   7, {28, 0, 0},    false, {0, 0, 0},  {0, 0, 40},   {10, 10, 35}},
    {"Hand_L",       8, {25, 0, 0},    true,  {18, 0, 0}, {0, 0, 0},    {20, 25, 15}},
    {"Shoulder_R",   3, {-4, 18, 0},   false, {0, 0, 0},  {0, 0, 0},    {5, 3, 5}},
    {"UpperArm_R",  10, {-14, 0, 0},   false, {0, 0, 0},  {60, 0, -10}, {30, 25, 25}},
    {"LowerArm_R",  11, {-28, 0, 0},   false, {0, 0, 0},  {0, 0, -40},  {10, 10, 35}},
    {"Hand_R",      12, {-25, 0, 0},   true,  {-18, 0, 0},{0, 0, 0},    {20, 25, 15}},
    {"UpperLeg_L",   1, {9, -5, 0},    false, {0, 0, 0},  {0, -5, 0},   {4, 18, 6}},
    {"LowerLeg_L",  14, {0, -42, 0},   false, {0, 0, 0},  {0, 15, 0},   {2, 15, 2}},
    {"Foot_L",      15, {0, -41, 0},   false, {0, 0, 0},  {0, 0, 0},    {3, 10, 3}},
    {"Toes_L",      16, {0, -6, 14},   true,  {0, 0, 6},  {0, 0, 0},    {0, 8, 0}},
    {"UpperLeg_R",   1, {-9, -5, 0},   false, {0, 0, 0},  {0, -5, 0},   {4, 18, 6}},
    {"LowerLeg_R",  18, {0, -42, 0},   false, {0, 0, 0},  {0, 15, 0},   {2, 15, 2}},
    {"Foot_R",      19, {0, -41, 0},   false, {0, 0, 0},  {0, 0, 0},    {3, 10, 3}},
    {"Toes_R",      20, {0, -6, 14},   true,  {0, 0, 6},  {0, 0, 0},    {0, 8, 0}},
}};
// clang-format on

/// splitmix64: the channels' frequencies and phases from the seed.
struct Random {
    std::uint64_t state;
    double uniform(double low, double high)
    {
        std::uint64_t z = (state += 0x9e3779b97f4a7c15ULL);
        z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
        z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
        z ^= z >> 31;
        return low + (high - low) * double(z >> 11) * 0x1p-53;
    }
};

/// One rotation channel: two sines, the amplitude drifting over minutes.
struct Swing {
    double bias = 0.0, amplitude = 0.0;
    double f1 = 0.0, p1 = 0.0, f2 = 0.0, p2 = 0.0, drift = 0.0, driftPhase = 0.0;
    double at(double t) const
    {
        const double envelope = 1.0 + 0.35 * std::sin(kTwoPi * t / drift + driftPhase);
        return bias + amplitude * envelope * (0.7 * std::sin(kTwoPi * f1 * t + p1) + 0.3 * std::sin(kTwoPi * f2 * t + p2));
    }
};

void appendNumber(std::string& text, double value, int digits)
{
    char buffer[32];
    const auto result = std::to_chars(buffer, buffer + sizeof buffer, value, std::chars_format::general, digits);
    text.append(buffer, result.ptr);
}

void appendHierarchy(std::string& text, int joint, int depth)
{
    const JointSpec& spec = kJoints[std::size_t(joint)];
    const std::string indent(std::size_t(2 * depth), ' ');
    text += indent + (spec.parent < 0 ? "ROOT " : "JOINT ") + spec.name + "\n" + indent + "{\n";
    text += indent + "  OFFSET";
    for (double value : spec.offset) {
        text += ' ';
        appendNumber(text, value, 6);
    }
    text += "\n" + indent + (spec.parent < 0 ? "  CHANNELS 6 Xposition Yposition Zposition Zrotation Xrotation Yrotation\n"
                                             : "  CHANNELS 3 Zrotation Xrotation Yrotation\n");
    for (int child = 0; child < kLongTakeJoints; ++child)
        if (kJoints[std::size_t(child)].parent == joint) appendHierarchy(text, child, depth + 1);
    if (spec.endSite) {
        text += indent + "  End Site\n" + indent + "  {\n" + indent + "    OFFSET";
        for (double value : spec.endOffset) {
            text += ' ';
            appendNumber(text, value, 6);
        }
        text += "\n" + indent + "  }\n";
    }
    text += indent + "}\n";
}

} // namespace

Status validateLongTakeOptions(const LongTakeOptions& options)
{
    if (options.frames < 2 || options.frames > 100'000'000)
        return makeError(ErrorCode::InvalidArgument, "a long take has 2 to 100,000,000 frames, got " + std::to_string(options.frames));
    if (!(options.rateHz > 0.0) || !(options.rateHz <= 1000.0))
        return makeError(ErrorCode::InvalidArgument, "a long take's rate is in (0, 1000] Hz, got " + std::to_string(options.rateHz));
    return okStatus();
}

Result<std::string> longTakeBvh(const LongTakeOptions& options)
{
    if (auto status = validateLongTakeOptions(options); !status.ok()) return status.error();
    std::string text = "HIERARCHY\n";
    appendHierarchy(text, 0, 0);
    text += "MOTION\nFrames: " + std::to_string(options.frames) + "\nFrame Time: ";
    appendNumber(text, 1.0 / options.rateHz, 9);
    text += '\n';

    Random random{options.seed};
    std::vector<Swing> swings; // joint by joint, Z X Y
    for (const JointSpec& joint : kJoints)
        for (int axis = 0; axis < 3; ++axis) {
            Swing swing;
            swing.bias = joint.bias[axis];
            swing.amplitude = joint.amplitude[axis];
            swing.f1 = random.uniform(0.1, 0.8);
            swing.p1 = random.uniform(0.0, kTwoPi);
            swing.f2 = random.uniform(0.5, 1.6);
            swing.p2 = random.uniform(0.0, kTwoPi);
            swing.drift = random.uniform(60.0, 300.0);
            swing.driftPhase = random.uniform(0.0, kTwoPi);
            swings.push_back(swing);
        }
    double phases[5];
    for (double& phase : phases) phase = random.uniform(0.0, kTwoPi);

    text.reserve(text.size() + std::size_t(options.frames) * std::size_t(kLongTakeChannels) * 10);
    for (Eigen::Index frame = 0; frame < options.frames; ++frame) {
        const double t = double(frame) / options.rateHz;
        // The root wanders over a 2 m floor, turns slowly and bounces a little.
        const double position[3] = {60.0 * std::sin(kTwoPi * t / 97.0 + phases[0]) + 20.0 * std::sin(kTwoPi * t / 23.0 + phases[1]),
                                    1.5 * std::sin(kTwoPi * 1.3 * t),
                                    60.0 * std::sin(kTwoPi * t / 131.0 + phases[2]) + 20.0 * std::sin(kTwoPi * t / 29.0 + phases[3])};
        for (double value : position) {
            appendNumber(text, value, 6);
            text += ' ';
        }
        const double heading = 90.0 * std::sin(kTwoPi * t / 173.0 + phases[4]);
        for (std::size_t channel = 0; channel < swings.size(); ++channel) {
            double angle = swings[channel].at(t);
            if (channel == 2) angle += heading; // the root's Y rotation
            appendNumber(text, angle, 6);
            text += channel + 1 == swings.size() ? '\n' : ' ';
        }
    }
    return text;
}

std::string longTakeFileName() { return "long_none_001.bvh"; }

Result<std::filesystem::path> writeLongTake(const LongTakeOptions& options, const std::filesystem::path& folder)
{
    auto text = longTakeBvh(options);
    if (!text) return text.error();
    std::error_code error;
    std::filesystem::create_directories(folder, error);
    if (error) return makeError(ErrorCode::Io, folder.string() + ": cannot create the folder: " + error.message());
    const std::filesystem::path file = folder / longTakeFileName();
    if (auto status = io::writeFileAtomically(file, *text); !status.ok()) return status.error();
    return file;
}

} // namespace bunraku::analysis::synth
