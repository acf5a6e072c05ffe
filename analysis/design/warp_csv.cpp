// The warp curve's CSV file: "output_frame,source_frame", one control point per line.
#include "analysis/design/warp_curve.h"

#include "analysis/io/atomic_file.h"
#include "analysis/io/text_format.h"
#include "analysis/io/text_scan.h"

#include <cmath>

namespace bunraku::analysis {

namespace {

namespace detail = io::detail;

constexpr std::string_view kHeader = "output_frame,source_frame";
constexpr std::string_view kByteOrderMark = "\xEF\xBB\xBF";

} // namespace

Status writeWarpCsv(const WarpCurve& curve, const std::filesystem::path& file)
{
    std::string text(kHeader);
    text += '\n';
    for (const WarpPoint& p : curve.points) {
        io::appendShortestNumber(text, p.output);
        text += ',';
        io::appendShortestNumber(text, p.source);
        text += '\n';
    }
    return io::writeFileAtomically(file, text);
}

Result<WarpCurve> parseWarpCsv(const std::string& text, const std::string& sourceName)
{
    std::string_view body = text;
    if (body.substr(0, kByteOrderMark.size()) == kByteOrderMark) body.remove_prefix(kByteOrderMark.size());
    WarpCurve curve;
    bool first = true;
    for (const detail::TextLine& line : detail::splitLines(body)) {
        const std::string_view trimmed = detail::trim(line.text);
        if (trimmed.empty()) continue;
        if (first && trimmed == kHeader) {
            first = false;
            continue;
        }
        first = false;
        const auto fields = detail::splitFields(trimmed, ',');
        if (fields.size() != 2)
            return parseError(sourceName, line.number,
                              "expected \"output_frame,source_frame\" (two numbers), found " + std::to_string(fields.size()) +
                                  (fields.size() == 1 ? " field" : " fields"));
        WarpPoint point;
        double* values[2] = {&point.output, &point.source};
        static constexpr const char* names[2] = {"output_frame", "source_frame"};
        for (int i = 0; i < 2; ++i) {
            const auto parsed = detail::parseNumber(fields[std::size_t(i)]);
            if (parsed.status != detail::NumberStatus::Ok)
                return parseError(sourceName, line.number,
                                  std::string(names[i]) + ": expected a finite number, found " + detail::quoted(fields[std::size_t(i)]));
            if (parsed.value < 0.0 || parsed.value > kWarpCsvMaxFrame)
                return parseError(sourceName, line.number,
                                  std::string(names[i]) + ": " + detail::quoted(fields[std::size_t(i)]) + " is outside [0, " +
                                      detail::shortText(kWarpCsvMaxFrame) + "] frames");
            *values[i] = parsed.value;
        }
        if (curve.points.size() == kWarpCsvMaxPoints)
            return parseError(sourceName, line.number, "more than " + std::to_string(kWarpCsvMaxPoints) + " control points");
        if (!curve.points.empty() && point.output <= curve.points.back().output)
            return parseError(sourceName, line.number, "output_frame must increase from line to line");
        if (!curve.points.empty() && point.source < curve.points.back().source)
            return parseError(sourceName, line.number, "source_frame must not decrease (time cannot run backwards)");
        curve.points.push_back(point);
    }
    if (!curve.points.empty()) curve.outputFrames = Eigen::Index(std::floor(curve.points.back().output)) + 1;
    if (Status valid = validateWarpCurve(curve); !valid.ok())
        return makeError(ErrorCode::Parse, sourceName + ": " + valid.error().message);
    return curve;
}

Result<WarpCurve> readWarpCsv(const std::filesystem::path& file)
{
    auto text = io::readTextFile(file, io::kDocumentLimitBytes);
    if (!text) return text.error();
    return parseWarpCsv(*text, file.string());
}

} // namespace bunraku::analysis
