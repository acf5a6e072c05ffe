// BVH text to BvhFile: one pass over the text, no per-value allocation. The hierarchy is read a
// line at a time (linear in the number of joints: names are checked with a hash set); the
// motion rows are scanned in place with std::from_chars straight into the frames x channels
// matrix, whose size is checked against the bytes left in the file before it is allocated.
#include "analysis/io/bvh.h"

#include "analysis/core/take.h"
#include "analysis/io/text_format.h"
#include "analysis/io/text_scan.h"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <memory>
#include <unordered_set>

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

/// Lines of a text one at a time (LF or CRLF), numbered from 1, without a vector of all lines.
class LineReader {
public:
    explicit LineReader(std::string_view text) : m_text(text) {}

    /// The next line, blank or not; false at the end of the text.
    bool next(detail::TextLine& line)
    {
        if (m_offset >= m_text.size()) return false;
        std::size_t end = m_text.find('\n', m_offset);
        if (end == std::string_view::npos) end = m_text.size();
        std::string_view text = m_text.substr(m_offset, end - m_offset);
        if (!text.empty() && text.back() == '\r') text.remove_suffix(1);
        line = detail::TextLine{++m_number, text};
        m_offset = end + 1;
        return true;
    }
    /// The next line that is not blank; false at the end of the text.
    bool nextContent(detail::TextLine& line)
    {
        while (next(line))
            if (!detail::trim(line.text).empty()) return true;
        return false;
    }
    /// Offset of the first byte after the last line returned, and that line's number.
    std::size_t offset() const { return std::min(m_offset, m_text.size()); }
    long number() const { return m_number; }

private:
    std::string_view m_text;
    std::size_t m_offset = 0;
    long m_number = 0;
};

/// Line-based parser state for the HIERARCHY section. Linear in the number of joints.
class HierarchyParser {
public:
    explicit HierarchyParser(const std::string& source) : m_source(source) {}

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
            if (!detail::isUtf8(name)) // the name goes into JSON skeleton files, which hold UTF-8 only
                return err(line, std::string(keyword) + " name " + detail::quoted(name) + " is not UTF-8 text");
            if (auto error = addJoint(line, std::string(name), false, open)) return error;
            return std::nullopt;
        }
        if (keyword == "End") {
            if (tokens.size() < 2 || tokens[1] != "Site") return err(line, "expected 'End Site'");
            if (m_stack.empty()) return err(line, "End Site outside a joint");
            if (m_skeleton.joints[std::size_t(m_stack.back())].endSite) return err(line, "an End Site cannot have children");
            const bool open = tokens.size() == 3 && tokens[2] == "{";
            if (tokens.size() > 2 && !open) return err(line, "expected nothing after 'End Site'");
            if (auto error = addJoint(line, m_skeleton.joints[std::size_t(m_stack.back())].name + "_End", true, open)) return error;
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
            joint.offsetLine = line.number; // lengths are checked once the units are known (checkBvhLengths)
            return std::nullopt;
        }
        if (keyword == "CHANNELS") {
            if (joint.endSite) return err(line, "an End Site has no CHANNELS");
            if (m_channelsGiven.size() > std::size_t(m_stack.back()) && m_channelsGiven[std::size_t(m_stack.back())])
                return err(line, "CHANNELS given twice for joint " + detail::quoted(joint.name));
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
            m_channelsGiven.resize(m_skeleton.joints.size(), false);
            m_channelsGiven[std::size_t(m_stack.back())] = true;
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

    std::optional<Error> addJoint(const detail::TextLine& line, std::string name, bool endSite, bool open)
    {
        if (!m_names.insert(name).second) return err(line, "joint " + detail::quoted(name) + " is named twice");
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
        return std::nullopt;
    }

    const std::string& m_source;
    BvhSkeleton m_skeleton;
    std::vector<int> m_stack;
    std::vector<bool> m_channelsGiven; ///< per joint: a CHANNELS line was read
    std::unordered_set<std::string> m_names;
    bool m_pendingOpen = false;
};

/// The value after "Key:" on a line: "Frames: 10", "Frames:10", "Frame Time: 0.03".
std::optional<std::string_view> valueAfterColon(std::string_view text)
{
    const auto colon = text.find(':');
    if (colon == std::string_view::npos) return std::nullopt;
    return detail::trim(text.substr(colon + 1));
}

bool isBlank(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v'; }

/// Scans the MOTION rows in place: `frames` lines of `width` numbers each, blank lines allowed
/// anywhere, nothing after the last row but blank lines.
class MotionScanner {
public:
    MotionScanner(std::string_view text, std::size_t offset, long lineNumber, const std::string& source, const BvhSkeleton& skeleton)
        : m_begin(text.data()), m_p(text.data() + offset), m_end(text.data() + text.size()), m_line(lineNumber), m_source(source),
          m_skeleton(skeleton)
    {
        m_angle.assign(std::size_t(skeleton.channelCount), 0);
        for (const BvhJoint& joint : skeleton.joints)
            for (std::size_t k = 0; k < joint.channels.size(); ++k)
                m_angle[std::size_t(joint.firstChannel) + k] = isPositionChannel(joint.channels[k]) ? 0 : 1;
    }

    /// Reads values.rows() rows; `whole`: the text must end after them (else the rest is not read).
    /// Every kRowsPerReport rows the control is asked whether to stop and told the rows' fraction.
    std::optional<Error> scan(Eigen::MatrixXd& values, std::vector<std::pair<Eigen::Index, long>>& rowLines, bool whole,
                              const RunControl& control)
    {
        constexpr Eigen::Index kRowsPerReport = 4096;
        const double angleLimit = valueLimit("deg");
        const Eigen::Index frames = values.rows();
        const Eigen::Index width = values.cols();
        for (Eigen::Index row = 0; row < frames; ++row) {
            if (row % kRowsPerReport == 0 && row > 0) {
                if (control.cancelled()) return makeError(ErrorCode::Cancelled, m_source + ": reading stopped at frame " + std::to_string(row));
                control.report(double(row) / double(frames));
            }
            skipBlankLines();
            if (m_p == m_end)
                return parseError(m_source, lastLine(), "expected " + std::to_string(frames) + " motion rows (Frames), found " +
                                                            std::to_string(row) + " before the end of the file");
            if (rowLines.empty() || rowLines.back().second + (row - rowLines.back().first) != m_line) rowLines.emplace_back(row, m_line);
            for (Eigen::Index c = 0; c < width; ++c) {
                while (m_p != m_end && (*m_p == ' ' || *m_p == '\t')) ++m_p;
                if (m_p == m_end || *m_p == '\n' || *m_p == '\r')
                    return parseError(m_source, m_line, "frame " + std::to_string(row) + ": expected " + std::to_string(width) +
                                                            " channel values, found " + std::to_string(c));
                double value = 0.0;
                if (auto error = number(row, c, value)) return error;
                if (m_angle[std::size_t(c)] && std::fabs(value) > angleLimit)
                    return parseError(m_source, m_line, "frame " + std::to_string(row) + ", value " + std::to_string(c + 1) + " (" +
                                                            channelName(c) + "): " + shortestNumber(value) + " deg is beyond +-" +
                                                            detail::shortText(angleLimit) + " deg");
                values(row, c) = value;
            }
            while (m_p != m_end && isBlank(*m_p)) ++m_p;
            if (m_p != m_end && *m_p != '\n')
                return parseError(m_source, m_line, "frame " + std::to_string(row) + ": expected " + std::to_string(width) +
                                                        " channel values, found more (" + detail::quoted(token()) + ")");
            if (m_p != m_end) {
                ++m_p;
                ++m_line;
            }
        }
        if (!whole) return std::nullopt;
        skipBlankLines();
        if (m_p != m_end)
            return parseError(m_source, m_line, "more motion rows than 'Frames: " + std::to_string(frames) + "'");
        return std::nullopt;
    }

private:
    /// Skips lines holding only blanks; leaves m_p at the first character of a content line.
    void skipBlankLines()
    {
        const char* lineStart = m_p;
        while (m_p != m_end) {
            if (*m_p == '\n') {
                ++m_p;
                ++m_line;
                lineStart = m_p;
            } else if (isBlank(*m_p)) {
                ++m_p;
            } else {
                break;
            }
        }
        m_p = m_p == m_end ? m_end : lineStart;
    }

    /// The number of the file's last line (a final line end starts no new line).
    long lastLine() const { return m_p != m_begin && m_p[-1] == '\n' ? m_line - 1 : m_line; }

    /// "Joint Xrotation" for a column, for messages.
    std::string channelName(Eigen::Index column) const
    {
        for (const BvhJoint& joint : m_skeleton.joints)
            if (column >= joint.firstChannel && column < joint.firstChannel + Eigen::Index(joint.channels.size()))
                return detail::quoted(joint.name) + " " + bvhChannelName(joint.channels[std::size_t(column - joint.firstChannel)]);
        return "channel " + std::to_string(column + 1);
    }

    /// The whitespace-delimited token at m_p, for messages.
    std::string_view token() const
    {
        const char* e = m_p;
        while (e != m_end && !isBlank(*e) && *e != '\n') ++e;
        return std::string_view(m_p, std::size_t(e - m_p));
    }

    std::optional<Error> number(Eigen::Index row, Eigen::Index column, double& value)
    {
        const char* start = m_p;
        if (*start == '+') ++start;
        const auto [end, ec] = std::from_chars(start, m_end, value);
        const bool delimited = end == m_end || isBlank(*end) || *end == '\n';
        if (ec == std::errc() && delimited && std::isfinite(value)) {
            m_p = end;
            return std::nullopt;
        }
        // Rare paths: tiny values that underflow, non-finite values, junk.
        const std::string_view text = token();
        const auto parsed = detail::parseNumber(text);
        if (parsed.status == NumberStatus::Ok) {
            value = parsed.value;
            m_p += text.size();
            return std::nullopt;
        }
        return parseError(m_source, m_line,
                          "frame " + std::to_string(row) + ", value " + std::to_string(column + 1) + ": " +
                              (parsed.status == NumberStatus::NonFinite ? "non-finite value " : "expected a number, found ") +
                              detail::quoted(text));
    }

    const char* m_begin;
    const char* m_p;
    const char* m_end;
    long m_line;
    const std::string& m_source;
    const BvhSkeleton& m_skeleton;
    std::vector<char> m_angle; ///< per column: a rotation channel (degrees)
};

} // namespace

namespace {

/// parseBvh, reading at most `rowLimit` motion rows when given.
Result<BvhFile> parse(std::string_view text, const std::string& sourceName, std::optional<long> rowLimit, const RunControl& control)
{
    LineReader reader(text);
    detail::TextLine line;
    if (!reader.nextContent(line)) return parseError(sourceName, 0, "empty file, expected HIERARCHY");
    std::string_view first = detail::trim(line.text);
    if (first.size() >= 3 && std::uint8_t(first[0]) == 0xEF && std::uint8_t(first[1]) == 0xBB && std::uint8_t(first[2]) == 0xBF)
        first.remove_prefix(3); // UTF-8 byte order mark
    if (first != "HIERARCHY") return parseError(sourceName, line.number, "expected HIERARCHY, found " + detail::quoted(first));

    HierarchyParser hierarchy(sourceName);
    bool sawMotion = false;
    while (reader.nextContent(line)) {
        const std::string_view t = detail::trim(line.text);
        if (t == "MOTION") {
            if (!hierarchy.balanced()) return parseError(sourceName, line.number, "MOTION before the hierarchy's braces are closed");
            if (hierarchy.skeleton().joints.empty()) return parseError(sourceName, line.number, "MOTION before any ROOT");
            sawMotion = true;
            break;
        }
        if (auto error = hierarchy.line(line, t)) return *error;
    }
    if (!sawMotion)
        return parseError(sourceName, std::max(reader.number(), 1L), "expected MOTION after the hierarchy, found the end of the file");

    BvhFile file;
    file.source = sourceName;
    file.skeleton = std::move(hierarchy.skeleton());

    const long motionLine = line.number;
    if (!reader.nextContent(line)) return parseError(sourceName, motionLine, "expected 'Frames: N' after MOTION");
    const detail::TextLine framesLine = line;
    const std::string_view framesText = detail::trim(framesLine.text);
    const auto framesValue = valueAfterColon(framesText);
    long frames = -1;
    if (framesValue)
        if (const auto parsed = detail::parseInteger(*framesValue)) frames = *parsed;
    if (framesText.rfind("Frames", 0) != 0 || frames < 0)
        return parseError(sourceName, framesLine.number, "expected 'Frames: N' with N a count, found " + detail::quoted(framesText));
    if (!reader.nextContent(line)) return parseError(sourceName, framesLine.number, "expected 'Frame Time: seconds' after Frames");
    const detail::TextLine timeLine = line;
    const std::string_view timeText = detail::trim(timeLine.text);
    const auto timeValue = valueAfterColon(timeText);
    const auto frameTime = timeValue ? detail::parseNumber(*timeValue) : detail::ParsedNumber{};
    if (timeText.rfind("Frame Time", 0) != 0 || frameTime.status != NumberStatus::Ok || !(frameTime.value > 0.0))
        return parseError(sourceName, timeLine.number, "expected 'Frame Time: seconds' with a positive number, found " + detail::quoted(timeText));
    if (!plausibleRate(1.0 / frameTime.value))
        return parseError(sourceName, timeLine.number,
                          "'Frame Time: " + detail::shortText(frameTime.value) + "' s: " + rateExpectation() +
                              " (a frame time of at least 1e-6 s)");
    if (frameTime.value > kMaxBvhFrameTime)
        return parseError(sourceName, timeLine.number,
                          "'Frame Time: " + detail::shortText(frameTime.value) + "' s: expected at most " +
                              detail::shortText(kMaxBvhFrameTime) + " s per frame");
    file.motion.frameTime = frameTime.value;

    const long width = file.skeleton.channelCount;
    if (width == 0 && frames > 0)
        return parseError(sourceName, framesLine.number, "'Frames: " + std::to_string(frames) +
                                                             "' but the hierarchy has no channels (expected CHANNELS lines)");
    // Never trust the count for the allocation: every value takes at least one byte, so the
    // bytes left bound the rows the file can hold (and the matrix to 8 times the file's size).
    const std::size_t left = text.size() - reader.offset();
    const std::size_t fit = width > 0 ? left / std::size_t(width) : 0;
    if (std::size_t(frames) > fit)
        return parseError(sourceName, framesLine.number,
                          "'Frames: " + std::to_string(frames) + "' but the " + std::to_string(left) + " bytes after 'Frame Time' hold at most " +
                              std::to_string(fit) + " rows of " + std::to_string(width) + " values");
    const long rows = rowLimit ? std::min(frames, *rowLimit) : frames;
    file.motion.values.resize(Eigen::Index(rows), Eigen::Index(width));
    MotionScanner scanner(text, reader.offset(), timeLine.number + 1, sourceName, file.skeleton);
    if (auto error = scanner.scan(file.motion.values, file.motion.rowLines, !rowLimit, control)) return *error;
    return file;
}

/// The bytes of a regular file of at most kMaxBvhFileBytes, read in one piece into a buffer that
/// is not zero-filled first (a 135 MB take would be written twice).
struct FileBytes {
    std::unique_ptr<char[]> data;
    std::size_t size = 0;
    std::string_view view() const { return std::string_view(data.get(), size); }
};

Result<FileBytes> readBvhBytes(const std::filesystem::path& path)
{
    namespace fs = std::filesystem;
    const std::string name = path.string();
    std::error_code ec;
    const auto status = fs::status(path, ec);
    if (ec || !fs::exists(status)) return makeError(ErrorCode::NotFound, name + ": no such file");
    if (fs::is_directory(status)) return makeError(ErrorCode::Io, name + ": is a folder, expected a BVH file");
    if (!fs::is_regular_file(status)) return makeError(ErrorCode::Io, name + ": not a regular file (a device or pipe?), expected a BVH file");
    const auto size = fs::file_size(path, ec);
    if (ec) return makeError(ErrorCode::Io, name + ": cannot read its size: " + ec.message());
    if (size > kMaxBvhFileBytes)
        return makeError(ErrorCode::Io, name + ": " + std::to_string(size) + " bytes, more than the " +
                                            std::to_string(kMaxBvhFileBytes) + " a BVH file may have");
    std::FILE* stream = std::fopen(name.c_str(), "rb");
    if (stream == nullptr) return makeError(ErrorCode::Io, name + ": cannot open for reading");
    FileBytes bytes{std::unique_ptr<char[]>(new char[std::max<std::size_t>(std::size_t(size), 1)]), 0};
    bytes.size = std::fread(bytes.data.get(), 1, std::size_t(size), stream); // a file that shrank is parsed as it was read
    const bool failed = std::ferror(stream) != 0;
    std::fclose(stream);
    if (failed) return makeError(ErrorCode::Io, name + ": read error");
    return bytes;
}

} // namespace

long BvhMotion::lineOfRow(Eigen::Index row) const
{
    const auto after = std::upper_bound(rowLines.begin(), rowLines.end(), row,
                                        [](Eigen::Index r, const std::pair<Eigen::Index, long>& entry) { return r < entry.first; });
    if (after == rowLines.begin()) return 0;
    const auto& entry = *std::prev(after);
    return entry.second + long(row - entry.first);
}

Status checkBvhLengths(const BvhFile& file, double cmPerUnit)
{
    const double limit = valueLimit("cm");
    const auto beyond = [&](double value) { return !(std::fabs(value * cmPerUnit) <= limit); };
    const auto length = [&](double value) {
        return cmPerUnit == 1.0 ? detail::shortText(value) + " cm"
                                : detail::shortText(value) + " file units (" + detail::shortText(value * cmPerUnit) + " cm)";
    };
    for (const BvhJoint& joint : file.skeleton.joints)
        for (int i = 0; i < 3; ++i)
            if (beyond(joint.offset[i]))
                return parseError(file.source, joint.offsetLine,
                                  "OFFSET of joint " + detail::quoted(joint.name) + ": " + length(joint.offset[i]) +
                                      " is beyond +-" + detail::shortText(limit) + " cm");
    const Eigen::MatrixXd& values = file.motion.values;
    for (const BvhJoint& joint : file.skeleton.joints)
        for (std::size_t k = 0; k < joint.channels.size(); ++k) {
            if (!isPositionChannel(joint.channels[k])) continue;
            const Eigen::Index column = joint.firstChannel + Eigen::Index(k);
            for (Eigen::Index row = 0; row < values.rows(); ++row)
                if (beyond(values(row, column)))
                    return parseError(file.source, file.motion.lineOfRow(row),
                                      "frame " + std::to_string(row) + ", value " + std::to_string(column + 1) + " (" +
                                          detail::quoted(joint.name) + " " + bvhChannelName(joint.channels[k]) + "): " +
                                          length(values(row, column)) + " is beyond +-" +
                                          detail::shortText(limit) + " cm");
        }
    return okStatus();
}

Result<BvhFile> parseBvh(const std::string& text, const std::string& sourceName, const RunControl& control)
{
    return parse(text, sourceName, std::nullopt, control);
}

Result<BvhFile> readBvh(const std::filesystem::path& path, const RunControl& control)
{
    auto bytes = readBvhBytes(path);
    if (!bytes) return bytes.error();
    if (control.cancelled()) return makeError(ErrorCode::Cancelled, path.string() + ": reading stopped");
    return parse(bytes->view(), path.string(), std::nullopt, control);
}

Result<BvhFile> readBvhStart(const std::filesystem::path& path, Eigen::Index frames)
{
    auto bytes = readBvhBytes(path);
    if (!bytes) return bytes.error();
    return parse(bytes->view(), path.string(), long(std::max<Eigen::Index>(frames, 0)), {});
}

} // namespace bunraku::analysis::io
