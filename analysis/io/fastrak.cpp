#include "analysis/io/fastrak.h"

#include "analysis/core/puppet_layout.h"
#include "analysis/io/atomic_file.h"
#include "analysis/io/text_scan.h"

#include <cmath>

namespace bunraku::analysis::io {

namespace {

/// Station number of a record's first token: "N" or "0N" (record type 0 + station), N in 1..9.
std::optional<int> stationOf(std::string_view token)
{
    if (token.size() == 2 && token[0] == '0') token.remove_prefix(1);
    if (token.size() != 1 || token[0] < '1' || token[0] > '9') return std::nullopt;
    return token[0] - '0';
}

std::string missingStations(const std::array<int, 4>& stations, const std::array<bool, 4>& seen)
{
    std::string out;
    for (std::size_t p = 0; p < 4; ++p) {
        if (seen[p]) continue;
        if (!out.empty()) out += ", ";
        out += std::to_string(stations[p]);
    }
    return out;
}

} // namespace

RigidTransform fastrakToWorkbench(const Eigen::Vector3d& positionCm, double azimuthDeg, double elevationDeg, double rollDeg)
{
    const Eigen::Matrix3d C = Eigen::Vector3d(1.0, -1.0, -1.0).asDiagonal();
    const Eigen::Matrix3d fastrak_R_part =
        rotationFromYawPitchRoll(YawPitchRoll{azimuthDeg, elevationDeg, rollDeg}).toRotationMatrix();
    const Eigen::Matrix3d world_R_part = C * fastrak_R_part * C.transpose();
    return RigidTransform{Eigen::Quaterniond(world_R_part).normalized(), C * positionCm};
}

Result<Take> parseFastrak(const std::string& text, const std::string& sourceName, const FastrakOptions& options)
{
    if (!plausibleRate(options.rateHz))
        return makeError(ErrorCode::InvalidArgument, sourceName + ": the sample rate option: " + rateExpectation());
    for (std::size_t p = 0; p < 4; ++p)
        for (std::size_t q = p + 1; q < 4; ++q)
            if (options.stations[p] == options.stations[q])
                return makeError(ErrorCode::InvalidArgument, sourceName + ": station " + std::to_string(options.stations[p]) +
                                                                 " is mapped to two parts");
    const double scale = options.units == FastrakUnits::Inches ? 2.54 : 1.0;

    std::vector<std::array<RigidTransform, 4>> frames;
    std::array<RigidTransform, 4> current{};
    std::array<bool, 4> seen{false, false, false, false};
    int seenCount = 0;
    bool anyRecord = false;
    long lastLine = 0;
    for (const auto& line : detail::splitLines(text)) {
        const auto trimmed = detail::trim(line.text);
        if (trimmed.empty() || trimmed.front() == '#') continue;
        const auto tokens = detail::splitWhitespace(trimmed);
        const auto station = stationOf(tokens.front());
        if (!station) {
            if (!anyRecord) continue; // header lines before the first record
            return parseError(sourceName, line.number,
                                     "expected a record: station (N or 0N) then x y z azimuth elevation roll, found " +
                                         detail::quoted(tokens.front()));
        }
        anyRecord = true;
        lastLine = line.number;
        if (tokens.size() != 7)
            return parseError(sourceName, line.number,
                                     "expected 7 fields (station x y z azimuth elevation roll), found " + std::to_string(tokens.size()));
        double v[6];
        static constexpr const char* names[6] = {"x", "y", "z", "azimuth", "elevation", "roll"};
        for (std::size_t i = 0; i < 6; ++i) {
            const auto parsed = detail::parseNumber(tokens[i + 1]);
            if (parsed.status != detail::NumberStatus::Ok)
                return parseError(sourceName, line.number,
                                         std::string("field ") + names[i] + ": " +
                                             (parsed.status == detail::NumberStatus::NonFinite ? "non-finite value " : "expected a number, found ") +
                                             detail::quoted(tokens[i + 1]));
            v[i] = parsed.value;
            const double limit = i < 3 ? valueLimit("cm") / scale : valueLimit("deg");
            if (std::fabs(v[i]) > limit)
                return parseError(sourceName, line.number, std::string("field ") + names[i] + ": " + detail::quoted(tokens[i + 1]) +
                                                               " is beyond +-" + detail::shortText(limit) +
                                                               (i < 3 ? (scale == 1.0 ? " cm" : " in") : " deg"));
        }
        int part = -1;
        for (std::size_t p = 0; p < 4; ++p)
            if (options.stations[p] == *station) part = int(p);
        if (part < 0) continue; // a station not used by the puppet
        if (seen[std::size_t(part)])
            return parseError(sourceName, line.number,
                                     "station " + std::to_string(*station) + " repeated before frame " + std::to_string(frames.size()) +
                                         " was complete (missing stations " + missingStations(options.stations, seen) + ")");
        current[std::size_t(part)] = fastrakToWorkbench(scale * Eigen::Vector3d(v[0], v[1], v[2]), v[3], v[4], v[5]);
        seen[std::size_t(part)] = true;
        if (++seenCount == 4) {
            frames.push_back(current);
            seen = {false, false, false, false};
            seenCount = 0;
        }
    }
    if (seenCount != 0)
        return parseError(sourceName, lastLine, "the file ends in the middle of frame " + std::to_string(frames.size()) +
                                                           " (missing stations " + missingStations(options.stations, seen) + ")");
    if (frames.empty()) return parseError(sourceName, 0, "no FASTRAK records found (expected lines 'station x y z azimuth elevation roll')");

    Take take;
    take.channels = puppetChannels();
    take.rateHz = options.rateHz;
    take.values = Eigen::MatrixXd::Zero(Eigen::Index(frames.size()), kPuppetChannelCount);
    take.labels = options.labels;
    if (take.labels.source.empty()) take.labels.source = sourceName;
    for (std::size_t f = 0; f < frames.size(); ++f)
        for (int p = 0; p < kPuppetPartCount; ++p)
            setPartPose(take, Eigen::Index(f), Eigen::Index(p) * kDofCount, frames[f][std::size_t(p)]);
    if (auto valid = validateTake(take); !valid)
        return makeError(ErrorCode::Numerical, sourceName + ": the poses overflow (values too large?): " + valid.error().message);
    return take;
}

Result<Take> readFastrak(const std::filesystem::path& file, const FastrakOptions& options)
{
    auto text = readTextFile(file);
    if (!text) return text.error();
    return parseFastrak(*text, file.string(), options);
}

} // namespace bunraku::analysis::io
