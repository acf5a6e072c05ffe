#include "analysis/io/take_csv.h"

#include "analysis/io/atomic_file.h"
#include "analysis/io/text_format.h"
#include "analysis/io/text_scan.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <set>

namespace bunraku::analysis::io {

namespace {

using detail::NumberStatus;

std::string unitForDof(std::string_view dof)
{
    if (dof == "x" || dof == "y" || dof == "z") return "cm";
    if (dof == "yaw" || dof == "pitch" || dof == "roll") return "deg";
    return "";
}

char detectSeparator(std::string_view header)
{
    // Separators inside double quotes (a quoted channel name) do not count.
    long commas = 0, semicolons = 0, tabs = 0;
    bool quoted = false;
    for (const char c : header) {
        if (c == '"') quoted = !quoted;
        else if (!quoted) {
            commas += c == ',';
            semicolons += c == ';';
            tabs += c == '\t';
        }
    }
    if (commas == 0 && semicolons == 0 && tabs == 0) return ' ';
    if (commas >= semicolons && commas >= tabs) return ',';
    return semicolons >= tabs ? ';' : '\t';
}

/// The header's names: fields split at the separator, a field in double quotes taken literally
/// ("" inside is one quote, RFC 4180). nullopt with `problem` set for an unterminated quote or
/// text after a closing quote.
std::optional<std::vector<std::string>> headerFields(std::string_view line, char separator, std::string& problem)
{
    std::vector<std::string> fields;
    if (separator == ' ' && line.find('"') == std::string_view::npos) {
        for (const auto token : detail::splitWhitespace(line)) fields.emplace_back(token);
        return fields;
    }
    const auto isSeparator = [&](char c) { return separator == ' ' ? (c == ' ' || c == '\t') : c == separator; };
    std::size_t i = 0;
    while (true) {
        while (i < line.size() && (line[i] == ' ' || line[i] == '\t') && !isSeparator(line[i])) ++i;
        if (separator == ' ') while (i < line.size() && isSeparator(line[i])) ++i;
        std::string field;
        if (i < line.size() && line[i] == '"') {
            ++i;
            bool closed = false;
            while (i < line.size()) {
                if (line[i] == '"') {
                    if (i + 1 < line.size() && line[i + 1] == '"') {
                        field += '"';
                        i += 2;
                        continue;
                    }
                    ++i;
                    closed = true;
                    break;
                }
                field += line[i++];
            }
            if (!closed) {
                problem = "a quoted name is not closed";
                return std::nullopt;
            }
            while (i < line.size() && (line[i] == ' ' || line[i] == '\t') && !isSeparator(line[i])) ++i;
            if (i < line.size() && !isSeparator(line[i])) {
                problem = "text after the closing quote of " + detail::quoted(field);
                return std::nullopt;
            }
        } else {
            const std::size_t start = i;
            while (i < line.size() && !isSeparator(line[i])) ++i;
            field = std::string(detail::trim(line.substr(start, i - start)));
        }
        fields.push_back(std::move(field));
        if (i >= line.size()) break;
        ++i; // the separator
        if (separator == ' ') {
            while (i < line.size() && isSeparator(line[i])) ++i;
            if (i >= line.size()) break;
        }
    }
    return fields;
}

/// A header name as written: in double quotes when it holds a separator, a quote or surrounding
/// spaces, so that any channel name reads back unchanged.
void appendHeaderName(std::string& out, const std::string& name)
{
    const bool plain = name.find_first_of(",;\t\"") == std::string::npos && !name.empty() && name.front() != ' ' &&
                       name.back() != ' ' && name.front() != '#';
    if (plain) {
        out += name;
        return;
    }
    out += '"';
    for (const char c : name) {
        if (c == '"') out += '"';
        out += c;
    }
    out += '"';
}

/// The largest |time_s| accepted (seconds): 31 years.
constexpr double kTimeLimitSeconds = 1e9;

std::vector<std::string_view> fieldsOf(std::string_view line, char separator)
{
    if (separator == ' ') return detail::splitWhitespace(line);
    return detail::splitFields(line, separator);
}

bool isTimeColumn(std::string_view name) { return name == "time_s" || name == "time" || name == "t"; }

} // namespace

Result<Take> parseTakeCsv(const std::string& text, const std::string& sourceName, const TakeCsvOptions& options)
{
    const auto lines = detail::splitLines(text);
    std::size_t index = 0;
    const auto skippable = [](std::string_view line) {
        const auto t = detail::trim(line);
        return t.empty() || t.front() == '#';
    };
    while (index < lines.size() && skippable(lines[index].text)) ++index;
    if (index == lines.size()) return parseError(sourceName, 0, "empty file, expected a header line `time_s,part.dof,...`");

    const detail::TextLine headerLine = lines[index++];
    const char separator = detectSeparator(headerLine.text);
    std::string headerProblem;
    const auto parsedHeader = headerFields(detail::trim(headerLine.text), separator, headerProblem);
    if (!parsedHeader) return parseError(sourceName, headerLine.number, "header: " + headerProblem);
    const std::vector<std::string>& header = *parsedHeader;
    const bool hasTime = !header.empty() && isTimeColumn(header.front());
    Take take;
    std::set<std::string> seen;
    for (std::size_t c = hasTime ? 1 : 0; c < header.size(); ++c) {
        const std::string_view name = header[c];
        const auto dot = name.rfind('.');
        const std::string where = "column " + std::to_string(c + 1) + " " + detail::quoted(name);
        if (dot == std::string_view::npos || dot == 0 || dot + 1 == name.size())
            return parseError(sourceName, headerLine.number,
                              where + ": expected a channel name `part.dof` (e.g. head.x)" +
                                  (isTimeColumn(name) ? " (the time column must come first)" : ""));
        if (name.find_first_of("\r\n") != std::string_view::npos)
            return parseError(sourceName, headerLine.number, where + ": a line break in a channel name");
        if (!seen.insert(std::string(name)).second)
            return parseError(sourceName, headerLine.number, where + ": channel named twice");
        const std::string dof(name.substr(dot + 1));
        take.channels.push_back(Channel{std::string(name.substr(0, dot)), dof, unitForDof(dof)});
    }
    if (take.channels.empty())
        return parseError(sourceName, headerLine.number, "expected at least one channel column `part.dof` in the header");

    std::vector<double> limits; // per column, by the channel's unit
    for (std::size_t c = 0; c < header.size(); ++c)
        limits.push_back(hasTime && c == 0 ? kTimeLimitSeconds : valueLimit(take.channels[c - (hasTime ? 1 : 0)].unit));
    std::vector<double> times;
    std::vector<long> rowLines;
    std::vector<double> data;
    const std::size_t width = header.size();
    for (; index < lines.size(); ++index) {
        const auto& line = lines[index];
        if (skippable(line.text)) continue;
        const auto fields = fieldsOf(detail::trim(line.text), separator);
        if (fields.size() != width)
            return parseError(sourceName, line.number,
                              "expected " + std::to_string(width) + " fields like the header, found " +
                                  std::to_string(fields.size()));
        for (std::size_t c = 0; c < width; ++c) {
            const auto parsed = detail::parseNumber(fields[c]);
            const std::string column = "column " + std::to_string(c + 1) + " (" + std::string(header[c]) + ")";
            if (parsed.status == NumberStatus::NotANumber)
                return parseError(sourceName, line.number, column + ": expected a number, found " + detail::quoted(fields[c]));
            if (parsed.status == NumberStatus::NonFinite)
                return parseError(sourceName, line.number, column + ": non-finite value " + detail::quoted(fields[c]) + " (NaN/Inf are not allowed)");
            if (std::fabs(parsed.value) > limits[c])
                return parseError(sourceName, line.number, column + ": " + detail::quoted(fields[c]) + " is beyond +-" +
                                                               detail::shortText(limits[c]) +
                                                               (hasTime && c == 0 ? " s" : " " + take.channels[c - (hasTime ? 1 : 0)].unit));
            if (hasTime && c == 0) times.push_back(parsed.value);
            else data.push_back(parsed.value);
        }
        rowLines.push_back(line.number);
    }
    const std::size_t frames = rowLines.size();
    if (frames == 0) return parseError(sourceName, headerLine.number, "expected data rows after the header, found none");

    double rate = options.rateHz.value_or(0.0);
    if (options.rateHz && !plausibleRate(*options.rateHz))
        return makeError(ErrorCode::InvalidArgument, sourceName + ": the sample rate option: " + rateExpectation());
    if (hasTime && frames >= 2) {
        for (std::size_t f = 1; f < frames; ++f)
            if (!(times[f] > times[f - 1]))
                return parseError(sourceName, rowLines[f], "time_s must increase from row to row: " + detail::shortText(times[f]) +
                                                               " s follows " + detail::shortText(times[f - 1]) + " s");
        const double step = (times.back() - times.front()) / double(frames - 1);
        for (std::size_t f = 1; f < frames; ++f) {
            const double d = times[f] - times[f - 1];
            if (std::fabs(d - step) > options.timeTolerance * step)
                return parseError(sourceName, rowLines[f],
                                  "time_s is not uniform: step " + detail::shortText(d) + " s, expected " +
                                      detail::shortText(step) + " s");
        }
        if (options.rateHz && options.timeMustMatchRate && std::fabs(step * *options.rateHz - 1.0) > options.timeTolerance)
            return parseError(sourceName, rowLines[1],
                              "time_s steps of " + detail::shortText(step) + " s are a rate of " + detail::shortText(1.0 / step) +
                                  " Hz, expected " + detail::shortText(*options.rateHz) + " Hz like the rest of the corpus");
        if (!options.rateHz) {
            rate = 1.0 / step;
            // Times written with finite precision: snap to a rate with few decimals when that close.
            const double snapped = std::round(rate * 1e6) / 1e6;
            if (std::fabs(snapped - rate) <= 1e-9 * rate) rate = snapped;
            if (!plausibleRate(rate))
                return parseError(sourceName, rowLines[1],
                                  "time_s steps of " + detail::shortText(step) + " s: " + rateExpectation());
        }
    } else if (!options.rateHz) {
        if (!hasTime) return parseError(sourceName, headerLine.number, "no time_s column: expected one, or a sample rate option");
        rate = 5.0; // one frame: the rate cannot be measured
    }

    take.rateHz = rate;
    take.values.resize(Eigen::Index(frames), Eigen::Index(take.channels.size()));
    for (std::size_t f = 0; f < frames; ++f)
        for (std::size_t c = 0; c < take.channels.size(); ++c)
            take.values(Eigen::Index(f), Eigen::Index(c)) = data[f * take.channels.size() + c];
    take.labels = options.labels;
    if (take.labels.source.empty()) take.labels.source = sourceName;
    return take;
}

Result<Take> readTakeCsv(const std::filesystem::path& file, const TakeCsvOptions& options)
{
    auto text = readTextFile(file, kTakeFileLimitBytes);
    if (!text) return text.error();
    return parseTakeCsv(*text, file.string(), options);
}

std::string formatTakeCsv(const Take& take, const std::string& comment)
{
    std::string out;
    if (!comment.empty()) {
        std::size_t start = 0;
        while (start <= comment.size()) {
            const std::size_t end = std::min(comment.find_first_of("\r\n", start), comment.size());
            out += "# " + comment.substr(start, end - start) + "\n";
            start = end + 1;
            if (end < comment.size() && comment[end] == '\r' && start < comment.size() && comment[start] == '\n') ++start;
        }
    }
    out += "time_s";
    for (const auto& channel : take.channels) {
        out += ',';
        appendHeaderName(out, channel.name());
    }
    out += "\n";
    for (Eigen::Index f = 0; f < take.frameCount(); ++f) {
        appendShortestNumber(out, take.timeOfFrame(f));
        for (Eigen::Index c = 0; c < take.channelCount(); ++c) {
            out += ',';
            appendShortestNumber(out, take.values(f, c));
        }
        out += '\n';
    }
    return out;
}

Status writeTakeCsv(const Take& take, const std::filesystem::path& file, const std::string& comment)
{
    if (auto valid = validateTake(take); !valid) return makeError(valid.error().code, file.string() + ": " + valid.error().message);
    for (const auto& channel : take.channels)
        if (channel.name().find_first_of("\r\n") != std::string::npos)
            return makeError(ErrorCode::InvalidArgument, file.string() + ": channel " + detail::quoted(channel.name()) +
                                                             " has a line break in its name, which CSV cannot hold");
    return writeFileAtomically(file, formatTakeCsv(take, comment));
}

} // namespace bunraku::analysis::io
