#include "analysis/io/bvh.h"

#include "analysis/io/atomic_file.h"
#include "analysis/io/text_format.h"
#include "analysis/io/text_scan.h"

#include <cmath>

namespace bunraku::analysis::io {

namespace {

using detail::NumberStatus;

std::optional<BvhChannel> channelFromName(std::string_view name)
{
    static constexpr std::array<std::pair<std::string_view, BvhChannel>, 6> names{{
        {"Xposition", BvhChannel::Xposition}, {"Yposition", BvhChannel::Yposition}, {"Zposition", BvhChannel::Zposition},
        {"Xrotation", BvhChannel::Xrotation}, {"Yrotation", BvhChannel::Yrotation}, {"Zrotation", BvhChannel::Zrotation},
    }};
    for (const auto& [text, channel] : names) {
        if (text.size() != name.size()) continue;
        bool same = true;
        for (std::size_t i = 0; i < text.size() && same; ++i)
            same = std::tolower(static_cast<unsigned char>(text[i])) == std::tolower(static_cast<unsigned char>(name[i]));
        if (same) return channel;
    }
    return std::nullopt;
}

bool isPosition(BvhChannel c) { return c == BvhChannel::Xposition || c == BvhChannel::Yposition || c == BvhChannel::Zposition; }
int axisOf(BvhChannel c)
{
    switch (c) {
    case BvhChannel::Xposition: case BvhChannel::Xrotation: return 0;
    case BvhChannel::Yposition: case BvhChannel::Yrotation: return 1;
    default: return 2;
    }
}

/// Line-based parser state for the HIERARCHY section.
class HierarchyParser {
public:
    explicit HierarchyParser(std::string source) : m_source(std::move(source)) {}

    /// Consumes one trimmed, non-blank hierarchy line; returns an error or nothing.
    std::optional<Error> line(const detail::TextLine& line, std::string_view text)
    {
        const auto tokens = detail::splitWhitespace(text);
        const std::string_view keyword = tokens.front();
        if (keyword == "{") {
            if (!m_pendingOpen) return err(line, "unexpected '{': expected ROOT, JOINT, End Site, OFFSET, CHANNELS or '}'");
            m_pendingOpen = false;
            m_stack.push_back(int(m_skeleton.joints.size()) - 1);
            if (tokens.size() > 1) return err(line, "expected nothing after '{'");
            return std::nullopt;
        }
        if (m_pendingOpen) return err(line, "expected '{' after the joint name, found " + detail::quoted(keyword));
        if (keyword == "}") {
            if (m_stack.empty()) return err(line, "unbalanced '}'");
            m_stack.pop_back();
            return std::nullopt;
        }
        if (keyword == "ROOT" || keyword == "JOINT") {
            if (keyword == "ROOT" && !m_stack.empty()) return err(line, "ROOT inside another joint (expected JOINT)");
            if (keyword == "JOINT" && m_stack.empty()) return err(line, "JOINT outside a ROOT's braces");
            if (!m_stack.empty() && m_skeleton.joints[std::size_t(m_stack.back())].endSite)
                return err(line, "an End Site cannot have children");
            std::string_view name = detail::trim(text.substr(keyword.size()));
            bool open = false;
            if (!name.empty() && name.back() == '{') {
                name = detail::trim(name.substr(0, name.size() - 1));
                open = true;
            }
            if (name.empty()) return err(line, std::string(keyword) + " needs a name");
            if (m_skeleton.find(std::string(name)) >= 0) return err(line, "joint " + detail::quoted(name) + " is named twice");
            addJoint(std::string(name), false, open);
            return std::nullopt;
        }
        if (keyword == "End") {
            if (tokens.size() < 2 || tokens[1] != "Site") return err(line, "expected 'End Site'");
            if (m_stack.empty()) return err(line, "End Site outside a joint");
            if (m_skeleton.joints[std::size_t(m_stack.back())].endSite) return err(line, "an End Site cannot have children");
            const bool open = tokens.size() == 3 && tokens[2] == "{";
            if (tokens.size() > 2 && !open) return err(line, "expected nothing after 'End Site'");
            addJoint(m_skeleton.joints[std::size_t(m_stack.back())].name + "_End", true, open);
            return std::nullopt;
        }
        if (m_stack.empty()) return err(line, "expected ROOT or MOTION, found " + detail::quoted(keyword));
        BvhJoint& joint = m_skeleton.joints[std::size_t(m_stack.back())];
        if (keyword == "OFFSET") {
            if (tokens.size() != 4) return err(line, "OFFSET expects 3 numbers, found " + std::to_string(tokens.size() - 1));
            for (int i = 0; i < 3; ++i) {
                const auto parsed = detail::parseNumber(tokens[std::size_t(i) + 1]);
                if (parsed.status == NumberStatus::NonFinite)
                    return err(line, "non-finite OFFSET value " + detail::quoted(tokens[std::size_t(i) + 1]));
                if (parsed.status != NumberStatus::Ok)
                    return err(line, "OFFSET expects numbers, found " + detail::quoted(tokens[std::size_t(i) + 1]));
                joint.offset[i] = parsed.value;
            }
            return std::nullopt;
        }
        if (keyword == "CHANNELS") {
            if (joint.endSite) return err(line, "an End Site has no CHANNELS");
            if (!joint.channels.empty()) return err(line, "CHANNELS given twice for joint " + detail::quoted(joint.name));
            if (tokens.size() < 2) return err(line, "CHANNELS expects a count and channel names");
            const auto count = detail::parseInteger(tokens[1]);
            if (!count || *count < 0 || *count > 6)
                return err(line, "CHANNELS expects a count from 0 to 6, found " + detail::quoted(tokens[1]));
            if (long(tokens.size()) - 2 != *count)
                return err(line, "CHANNELS " + std::to_string(*count) + " lists " + std::to_string(tokens.size() - 2) + " names");
            for (std::size_t i = 2; i < tokens.size(); ++i) {
                const auto channel = channelFromName(tokens[i]);
                if (!channel)
                    return err(line, "unknown channel " + detail::quoted(tokens[i]) + " (expected X/Y/Z position or rotation)");
                for (BvhChannel existing : joint.channels)
                    if (existing == *channel) return err(line, "channel " + detail::quoted(tokens[i]) + " listed twice");
                joint.channels.push_back(*channel);
            }
            joint.firstChannel = m_skeleton.channelCount;
            m_skeleton.channelCount += int(joint.channels.size());
            return std::nullopt;
        }
        return err(line, "expected ROOT, JOINT, End Site, OFFSET, CHANNELS, '{' or '}', found " + detail::quoted(keyword));
    }

    bool balanced() const { return m_stack.empty() && !m_pendingOpen; }
    BvhSkeleton& skeleton() { return m_skeleton; }

private:
    Error err(const detail::TextLine& line, const std::string& what) const { return parseError(m_source, line.number, what); }

    void addJoint(std::string name, bool endSite, bool open)
    {
        BvhJoint joint;
        joint.name = std::move(name);
        joint.endSite = endSite;
        joint.parent = m_stack.empty() ? -1 : m_stack.back();
        joint.firstChannel = m_skeleton.channelCount;
        m_skeleton.joints.push_back(std::move(joint));
        m_pendingOpen = true;
        if (open) {
            m_pendingOpen = false;
            m_stack.push_back(int(m_skeleton.joints.size()) - 1);
        }
    }

    std::string m_source;
    BvhSkeleton m_skeleton;
    std::vector<int> m_stack;
    bool m_pendingOpen = false;
};

/// The value after "Key:" on a line: "Frames: 10", "Frames:10", "Frame Time: 0.03".
std::optional<std::string_view> valueAfterColon(std::string_view text)
{
    const auto colon = text.find(':');
    if (colon == std::string_view::npos) return std::nullopt;
    return detail::trim(text.substr(colon + 1));
}

} // namespace

const char* bvhChannelName(BvhChannel channel)
{
    switch (channel) {
    case BvhChannel::Xposition: return "Xposition";
    case BvhChannel::Yposition: return "Yposition";
    case BvhChannel::Zposition: return "Zposition";
    case BvhChannel::Xrotation: return "Xrotation";
    case BvhChannel::Yrotation: return "Yrotation";
    case BvhChannel::Zrotation: return "Zrotation";
    }
    return "";
}

int BvhSkeleton::find(const std::string& name) const
{
    for (std::size_t i = 0; i < joints.size(); ++i)
        if (joints[i].name == name) return int(i);
    return -1;
}

int BvhSkeleton::jointCount() const
{
    int count = 0;
    for (const auto& j : joints) count += j.endSite ? 0 : 1;
    return count;
}

int BvhSkeleton::endSiteCount() const { return int(joints.size()) - jointCount(); }

Result<BvhFile> parseBvh(const std::string& text, const std::string& sourceName)
{
    const auto lines = detail::splitLines(text);
    std::size_t i = 0;
    const auto nextContent = [&]() {
        while (i < lines.size() && detail::trim(lines[i].text).empty()) ++i;
        return i < lines.size();
    };
    if (!nextContent()) return parseError(sourceName, 0, "empty file, expected HIERARCHY");
    std::string_view first = detail::trim(lines[i].text);
    if (first.size() >= 3 && std::uint8_t(first[0]) == 0xEF && std::uint8_t(first[1]) == 0xBB && std::uint8_t(first[2]) == 0xBF)
        first.remove_prefix(3); // UTF-8 byte order mark
    if (first != "HIERARCHY") return parseError(sourceName, lines[i].number, "expected HIERARCHY, found " + detail::quoted(first));
    ++i;

    HierarchyParser hierarchy(sourceName);
    bool sawMotion = false;
    for (; nextContent(); ++i) {
        const std::string_view t = detail::trim(lines[i].text);
        if (t == "MOTION") {
            if (!hierarchy.balanced()) return parseError(sourceName, lines[i].number, "MOTION before the hierarchy's braces are closed");
            if (hierarchy.skeleton().joints.empty()) return parseError(sourceName, lines[i].number, "MOTION before any ROOT");
            sawMotion = true;
            ++i;
            break;
        }
        if (auto error = hierarchy.line(lines[i], t)) return *error;
    }
    if (!sawMotion) return parseError(sourceName, lines.empty() ? 0 : lines.back().number, "expected MOTION after the hierarchy, found the end of the file");

    BvhFile file;
    file.source = sourceName;
    file.skeleton = std::move(hierarchy.skeleton());

    if (!nextContent()) return parseError(sourceName, lines.back().number, "expected 'Frames: N' after MOTION");
    const auto framesLine = lines[i];
    const std::string_view framesText = detail::trim(framesLine.text);
    const auto framesValue = valueAfterColon(framesText);
    long frameCount = -1;
    if (framesValue)
        if (const auto parsed = detail::parseInteger(*framesValue)) frameCount = *parsed;
    const long* frames = &frameCount;
    if (framesText.rfind("Frames", 0) != 0 || frameCount < 0)
        return parseError(sourceName, framesLine.number, "expected 'Frames: N' with N a count, found " + detail::quoted(framesText));
    ++i;
    if (!nextContent()) return parseError(sourceName, framesLine.number, "expected 'Frame Time: seconds' after Frames");
    const auto timeLine = lines[i];
    const std::string_view timeText = detail::trim(timeLine.text);
    const auto timeValue = valueAfterColon(timeText);
    const auto frameTime = timeValue ? detail::parseNumber(*timeValue) : detail::ParsedNumber{};
    if (timeText.rfind("Frame Time", 0) != 0 || frameTime.status != NumberStatus::Ok || !(frameTime.value > 0.0))
        return parseError(sourceName, timeLine.number, "expected 'Frame Time: seconds' with a positive number, found " + detail::quoted(timeText));
    if (!plausibleRate(1.0 / frameTime.value))
        return parseError(sourceName, timeLine.number,
                          "'Frame Time: " + detail::shortText(frameTime.value) + "' s: " + rateExpectation()
                              + " (a frame time of at least 1e-6 s)");
    file.motion.frameTime = frameTime.value;
    ++i;

    const int width = file.skeleton.channelCount;
    // Never trust the count for the allocation: at most one row per remaining line.
    if (std::size_t(*frames) > lines.size() - i)
        return parseError(sourceName, framesLine.number, "'Frames: " + std::to_string(*frames) + "' but the file has only " +
                                                                    std::to_string(lines.size() - i) + " lines of motion");
    file.motion.values.resize(Eigen::Index(*frames), width);
    long row = 0;
    for (; nextContent(); ++i) {
        const auto tokens = detail::splitWhitespace(lines[i].text);
        if (row == *frames)
            return parseError(sourceName, lines[i].number, "more motion rows than 'Frames: " + std::to_string(*frames) + "'");
        if (long(tokens.size()) != width)
            return parseError(sourceName, lines[i].number, "frame " + std::to_string(row) + ": expected " + std::to_string(width) +
                                                               " channel values, found " + std::to_string(tokens.size()));
        for (int c = 0; c < width; ++c) {
            const auto parsed = detail::parseNumber(tokens[std::size_t(c)]);
            if (parsed.status != NumberStatus::Ok)
                return parseError(sourceName, lines[i].number,
                                  "frame " + std::to_string(row) + ", value " + std::to_string(c + 1) + ": " +
                                      (parsed.status == NumberStatus::NonFinite ? "non-finite value " : "expected a number, found ") +
                                      detail::quoted(tokens[std::size_t(c)]));
            file.motion.values(row, c) = parsed.value;
        }
        ++row;
    }
    if (row != *frames)
        return parseError(sourceName, lines.back().number, "expected " + std::to_string(*frames) + " motion rows (Frames), found " +
                                                               std::to_string(row));
    return file;
}

Result<BvhFile> readBvh(const std::filesystem::path& file)
{
    auto text = readTextFile(file);
    if (!text) return text.error();
    return parseBvh(*text, file.string());
}

std::vector<RigidTransform> bvhLocalPoses(const BvhFile& file, Eigen::Index frame, const BvhKinematicsOptions& options)
{
    assert(frame >= 0 && frame < file.motion.values.rows());
    std::vector<RigidTransform> local(file.skeleton.joints.size());
    for (std::size_t j = 0; j < file.skeleton.joints.size(); ++j) {
        const BvhJoint& joint = file.skeleton.joints[j];
        Eigen::Vector3d translation = joint.offset;
        Eigen::Vector3d channelsPosition = Eigen::Vector3d::Zero();
        bool replaced[3] = {false, false, false};
        Eigen::Quaterniond rotation = Eigen::Quaterniond::Identity();
        for (std::size_t k = 0; k < joint.channels.size(); ++k) {
            const double value = file.motion.values(frame, joint.firstChannel + Eigen::Index(k));
            const int axis = axisOf(joint.channels[k]);
            if (isPosition(joint.channels[k])) {
                channelsPosition[axis] = value;
                replaced[axis] = true;
            } else {
                rotation = rotation * Eigen::Quaterniond(Eigen::AngleAxisd(value * M_PI / 180.0, Eigen::Vector3d::Unit(axis)));
            }
        }
        for (int a = 0; a < 3; ++a) {
            if (!replaced[a]) continue;
            if (options.positionMode == BvhPositionMode::ReplaceOffset) translation[a] = channelsPosition[a];
            else translation[a] += channelsPosition[a];
        }
        local[j] = RigidTransform{rotation.normalized(), translation};
    }
    return local;
}

std::vector<RigidTransform> bvhWorldPoses(const BvhFile& file, Eigen::Index frame, const BvhKinematicsOptions& options)
{
    auto poses = bvhLocalPoses(file, frame, options);
    for (std::size_t j = 0; j < poses.size(); ++j) {
        const int parent = file.skeleton.joints[j].parent;
        if (parent >= 0) poses[j] = poses[std::size_t(parent)] * poses[j];
    }
    return poses;
}

std::string formatBvh(const BvhFile& file)
{
    std::string out = "HIERARCHY\n";
    const auto& joints = file.skeleton.joints;
    std::vector<int> depth(joints.size(), 0);
    std::vector<int> open; // indices whose braces are open
    const auto closeUntil = [&](int parent) {
        while (!open.empty() && open.back() != parent) {
            out += std::string(std::size_t(2 * (int(open.size()) - 1)), ' ') + "}\n";
            open.pop_back();
        }
    };
    for (std::size_t j = 0; j < joints.size(); ++j) {
        const BvhJoint& joint = joints[j];
        closeUntil(joint.parent);
        const std::string indent(std::size_t(2 * open.size()), ' ');
        if (joint.endSite) out += indent + "End Site\n";
        else out += indent + (joint.parent < 0 ? "ROOT " : "JOINT ") + joint.name + "\n";
        out += indent + "{\n";
        out += indent + "  OFFSET";
        for (int a = 0; a < 3; ++a) {
            out += ' ';
            appendShortestNumber(out, joint.offset[a]);
        }
        out += "\n";
        if (!joint.endSite) {
            out += indent + "  CHANNELS " + std::to_string(joint.channels.size());
            for (BvhChannel c : joint.channels) out += std::string(" ") + bvhChannelName(c);
            out += "\n";
        }
        open.push_back(int(j));
    }
    closeUntil(-1);
    out += "MOTION\nFrames: " + std::to_string(file.motion.values.rows()) + "\nFrame Time: ";
    appendShortestNumber(out, file.motion.frameTime);
    out += "\n";
    for (Eigen::Index f = 0; f < file.motion.values.rows(); ++f) {
        for (Eigen::Index c = 0; c < file.motion.values.cols(); ++c) {
            if (c > 0) out += ' ';
            appendShortestNumber(out, file.motion.values(f, c));
        }
        out += "\n";
    }
    return out;
}

} // namespace bunraku::analysis::io
