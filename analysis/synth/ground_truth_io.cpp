// The demo ground truth on disk: truth.json (scalars, phrase tables, take randomisation) plus
// CSVs for every per-frame series. Format: docs/DEMO-CORPUS.md.
#include "analysis/synth/demo_corpus.h"
#include "analysis/synth/demo_corpus_io.h"

#include "analysis/core/puppet_layout.h"
#include "analysis/io/atomic_file.h"
#include "analysis/io/json_text.h"
#include "analysis/io/staged_folder.h"
#include "analysis/io/text_format.h"

#include <nlohmann/json.hpp>

#include <charconv>
#include <fstream>
#include <sstream>
#include <system_error>

namespace bunraku::analysis::synth {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

constexpr const char* kFormatName = "bunraku-demo-truth";
constexpr int kFormatVersion = 1;

/// Creates the file's folder, then writes it atomically (io::writeFileAtomically).
Status writeAtomically(const fs::path& file, const std::string& content)
{
    std::error_code ec;
    fs::create_directories(file.parent_path(), ec);
    if (ec) return makeError(ErrorCode::Io, file.parent_path().string() + ": cannot create folder: " + ec.message());
    return io::writeFileAtomically(file, content);
}

/// A CSV: header line `columns`, then one row per matrix row, first column the frame index.
std::string matrixCsv(const std::vector<std::string>& columns, const Eigen::MatrixXd& values)
{
    std::string text = "frame";
    for (const auto& c : columns) {
        text += ',';
        text += c;
    }
    text += "\n";
    for (Eigen::Index r = 0; r < values.rows(); ++r) {
        text += std::to_string(r);
        for (Eigen::Index c = 0; c < values.cols(); ++c) {
            text += ',';
            io::appendShortestNumber(text, values(r, c));
        }
        text += "\n";
    }
    return text;
}

Result<Eigen::MatrixXd> readMatrixCsv(const fs::path& file, const std::vector<std::string>& columns)
{
    auto text = io::readTextFile(file);
    if (!text) return text.error();
    std::istringstream in(*text);
    std::string expectedHeader = "frame";
    for (const auto& c : columns) {
        expectedHeader += ',';
        expectedHeader += c;
    }
    std::string line;
    long lineNumber = 0;
    std::vector<std::vector<double>> rows;
    while (std::getline(in, line)) {
        ++lineNumber;
        if (!line.empty() && line.back() == '\r') line.pop_back();
        if (lineNumber == 1) {
            if (line != expectedHeader) return parseError(file.string(), 1, "expected header '" + expectedHeader + "'");
            continue;
        }
        if (line.empty()) continue;
        std::vector<double> row;
        const char* p = line.data();
        const char* end = line.data() + line.size();
        bool first = true;
        while (p <= end) {
            const char* comma = std::find(p, end, ',');
            double value = 0.0;
            const auto [stop, ec] = std::from_chars(p, comma, value);
            if (ec != std::errc() || stop != comma || !std::isfinite(value))
                return parseError(file.string(), lineNumber,
                                  "expected a finite number in column " + std::to_string(row.size() + (first ? 1 : 2)));
            if (first) {
                if (value != double(rows.size()))
                    return parseError(file.string(), lineNumber, "expected frame " + std::to_string(rows.size()));
                first = false;
            } else {
                row.push_back(value);
            }
            p = comma + 1;
        }
        if (row.size() != columns.size())
            return parseError(file.string(), lineNumber,
                              "expected " + std::to_string(columns.size() + 1) + " columns, found " +
                                  std::to_string(row.size() + 1));
        rows.push_back(std::move(row));
    }
    if (rows.empty()) return parseError(file.string(), lineNumber, "expected at least one data row");
    Eigen::MatrixXd values(Eigen::Index(rows.size()), Eigen::Index(columns.size()));
    for (std::size_t r = 0; r < rows.size(); ++r)
        for (std::size_t c = 0; c < columns.size(); ++c) values(Eigen::Index(r), Eigen::Index(c)) = rows[r][c];
    return values;
}

std::vector<std::string> channelNames()
{
    std::vector<std::string> names;
    for (const auto& channel : puppetChannels()) names.push_back(channel.name());
    return names;
}

json matrixJson(const Eigen::MatrixXd& m)
{
    json rows = json::array();
    for (Eigen::Index r = 0; r < m.rows(); ++r) {
        json row = json::array();
        for (Eigen::Index c = 0; c < m.cols(); ++c) row.push_back(m(r, c));
        rows.push_back(std::move(row));
    }
    return rows;
}

Eigen::MatrixXd jsonMatrix(const json& rows, std::size_t columns)
{
    if (!rows.is_array()) throw std::runtime_error("expected an array of rows");
    Eigen::MatrixXd m(Eigen::Index(rows.size()), Eigen::Index(columns));
    for (std::size_t r = 0; r < rows.size(); ++r) {
        if (!rows[r].is_array() || rows[r].size() != columns)
            throw std::runtime_error("expected rows of " + std::to_string(columns) + " numbers");
        for (std::size_t c = 0; c < columns; ++c) m(Eigen::Index(r), Eigen::Index(c)) = rows[r][c].get<double>();
    }
    return m;
}

Eigen::VectorXd column(const Eigen::MatrixXd& m, Eigen::Index c) { return m.col(c); }

/// The sizes that must agree between the manifest and the CSVs.
Status checkShapes(const DemoGroundTruth& truth)
{
    const auto frames = Eigen::Index(truth.nominalFrames);
    for (const auto& f : truth.functions) {
        const auto phrases = Eigen::Index(f.phraseNames.size());
        if (f.phraseBoundaries.size() != f.phraseNames.size() + 1 || f.phraseDisplacements.rows() != phrases)
            return makeError(ErrorCode::Parse, "function " + f.function + ": expected phrases + 1 boundaries and one "
                                                   "displacement row per phrase");
        if (f.motion.rows() != frames)
            return makeError(ErrorCode::Parse, "function " + f.function + ": expected " + std::to_string(frames) +
                                                   " motion frames");
    }
    for (const auto& c : truth.cells) {
        const FunctionTruth* f = truth.function(c.function);
        if (!f) return makeError(ErrorCode::Parse, "cell " + c.function + "/" + c.emotion + ": unknown function");
        const auto phrases = Eigen::Index(f->phraseNames.size());
        if (c.phraseBoundaries.size() != f->phraseBoundaries.size() || c.phraseGains.rows() != phrases ||
            c.phraseOffsets.rows() != phrases)
            return makeError(ErrorCode::Parse, "cell " + c.function + "/" + c.emotion +
                                                   ": expected the function's phrase count in boundaries, gains, offsets");
        if (c.motion.rows() != frames || c.emotionComponent.rows() != frames || c.phaseWarp.size() != frames)
            return makeError(ErrorCode::Parse, "cell " + c.function + "/" + c.emotion + ": expected " +
                                                   std::to_string(frames) + " frames in every series");
    }
    for (const auto& t : truth.takes)
        if (!truth.cell(t.labels.function, t.labels.emotion))
            return makeError(ErrorCode::Parse, "take " + t.labels.function + "/" + t.labels.emotion + ": unknown cell");
    return okStatus();
}

/// Every file of the ground truth (relative path, content), truth.json last.
std::vector<std::pair<fs::path, std::string>> groundTruthFiles(const DemoGroundTruth& truth)
{
    const auto channels = channelNames();
    json manifest;
    manifest["format"] = kFormatName;
    manifest["version"] = kFormatVersion;
    manifest["seed"] = truth.seed;
    manifest["rate_hz"] = truth.rateHz;
    manifest["nominal_frames"] = truth.nominalFrames;
    manifest["position_noise_cm"] = truth.positionNoiseCm;
    manifest["angle_noise_deg"] = truth.angleNoiseDeg;
    manifest["neutral_emotion"] = truth.neutralEmotion;
    manifest["parameters"] = truth.parameterNames;
    manifest["channels"] = channels;

    std::vector<std::pair<fs::path, std::string>> files;
    manifest["functions"] = json::array();
    for (const auto& f : truth.functions) {
        const std::string file = "functions/" + io::fileSafeLabel(f.function) + "_y.csv";
        manifest["functions"].push_back({{"function", f.function},
                                         {"phrases", f.phraseNames},
                                         {"phrase_boundaries", f.phraseBoundaries},
                                         {"phrase_displacements", matrixJson(f.phraseDisplacements)},
                                         {"motion_file", file}});
        files.emplace_back(file, matrixCsv(channels, f.motion));
    }
    manifest["cells"] = json::array();
    for (const auto& c : truth.cells) {
        const std::string stem = "cells/" + io::fileSafeLabel(c.function) + "_" + io::fileSafeLabel(c.emotion);
        manifest["cells"].push_back({{"function", c.function},
                                     {"emotion", c.emotion},
                                     {"phrase_boundaries", c.phraseBoundaries},
                                     {"phrase_gains", matrixJson(c.phraseGains)},
                                     {"phrase_offsets", matrixJson(c.phraseOffsets)},
                                     {"motion_file", stem + "_x.csv"},
                                     {"emotion_file", stem + "_z.csv"},
                                     {"phase_file", stem + "_phase.csv"}});
        files.emplace_back(stem + "_x.csv", matrixCsv(channels, c.motion));
        files.emplace_back(stem + "_z.csv", matrixCsv(channels, c.emotionComponent));
        Eigen::MatrixXd phase(c.phaseWarp.size(), 2);
        phase << c.phaseWarp, c.functionalToEmotional;
        files.emplace_back(stem + "_phase.csv", matrixCsv({"phase_warp", "functional_to_emotional"}, phase));
    }
    manifest["takes"] = json::array();
    for (const auto& t : truth.takes) {
        const std::string file = "takes/" + io::fileSafeLabel(t.labels.function) + "_" + io::fileSafeLabel(t.labels.emotion) + "_" +
                                 std::to_string(t.labels.takeIndex) + "_warp.csv";
        manifest["takes"].push_back({{"function", t.labels.function},
                                     {"emotion", t.labels.emotion},
                                     {"take", t.labels.takeIndex},
                                     {"source", t.labels.source},
                                     {"frames", t.takeToCell.size()},
                                     {"late_start_frames", t.lateStartFrames},
                                     {"amplitude_gain", t.amplitudeGain},
                                     {"position_offset_cm", {t.positionOffset.x(), t.positionOffset.y(), t.positionOffset.z()}},
                                     {"yaw_offset_deg", t.yawOffsetDeg},
                                     {"yaw_wraps", t.yawWraps},
                                     {"warp_file", file}});
        files.emplace_back(file, matrixCsv({"cell_frame"}, t.takeToCell));
    }
    // The manifest last: a folder with truth.json is complete.
    files.emplace_back("truth.json", manifest.dump(2, ' ', false, json::error_handler_t::replace) + "\n");
    return files;
}

} // namespace

Status writeGroundTruth(const DemoGroundTruth& truth, const std::filesystem::path& folder)
{
    for (const auto& [file, content] : groundTruthFiles(truth))
        if (Status s = writeAtomically(folder / file, content); !s) return s;
    return okStatus();
}

Status writeGroundTruthFiles(const DemoGroundTruth& truth, io::StagedFolder& folder, const std::filesystem::path& subfolder)
{
    for (const auto& [file, content] : groundTruthFiles(truth))
        if (Status s = folder.writeFile(subfolder / file, content); !s) return s;
    return okStatus();
}

Result<DemoGroundTruth> readGroundTruth(const std::filesystem::path& folder)
{
    const fs::path manifestFile = folder / "truth.json";
    auto text = io::readTextFile(manifestFile, io::kDocumentLimitBytes);
    if (!text) return text.error();
    auto parsed = io::parseJsonText(*text, manifestFile.string());
    if (!parsed) return parsed.error();
    const json manifest = std::move(parsed).value();
    const auto channels = channelNames();
    DemoGroundTruth truth;
    std::string where = "manifest";
    try {
        if (manifest.at("format").get<std::string>() != kFormatName || manifest.at("version").get<int>() != kFormatVersion)
            return parseError(manifestFile.string(), 0,
                              std::string("expected format '") + kFormatName + "' version " + std::to_string(kFormatVersion));
        truth.seed = manifest.at("seed").get<std::uint64_t>();
        truth.rateHz = manifest.at("rate_hz").get<double>();
        truth.nominalFrames = manifest.at("nominal_frames").get<int>();
        truth.positionNoiseCm = manifest.at("position_noise_cm").get<double>();
        truth.angleNoiseDeg = manifest.at("angle_noise_deg").get<double>();
        truth.neutralEmotion = manifest.at("neutral_emotion").get<std::string>();
        truth.parameterNames = manifest.at("parameters").get<std::vector<std::string>>();
        if (manifest.at("channels").get<std::vector<std::string>>() != channels)
            return parseError(manifestFile.string(), 0, "expected the 24 puppet channels head.x ... hand.roll");
        const std::size_t parameters = truth.parameterNames.size();

        for (const auto& f : manifest.at("functions")) {
            FunctionTruth function;
            function.function = f.at("function").get<std::string>();
            where = "function " + function.function;
            function.phraseNames = f.at("phrases").get<std::vector<std::string>>();
            function.phraseBoundaries = f.at("phrase_boundaries").get<std::vector<double>>();
            function.phraseDisplacements = jsonMatrix(f.at("phrase_displacements"), parameters);
            auto motion = readMatrixCsv(folder / f.at("motion_file").get<std::string>(), channels);
            if (!motion) return motion.error();
            function.motion = std::move(motion).value();
            truth.functions.push_back(std::move(function));
        }
        for (const auto& c : manifest.at("cells")) {
            CellTruth cell;
            cell.function = c.at("function").get<std::string>();
            cell.emotion = c.at("emotion").get<std::string>();
            where = "cell " + cell.function + "/" + cell.emotion;
            cell.phraseBoundaries = c.at("phrase_boundaries").get<std::vector<double>>();
            cell.phraseGains = jsonMatrix(c.at("phrase_gains"), parameters);
            cell.phraseOffsets = jsonMatrix(c.at("phrase_offsets"), parameters);
            auto motion = readMatrixCsv(folder / c.at("motion_file").get<std::string>(), channels);
            if (!motion) return motion.error();
            cell.motion = std::move(motion).value();
            auto emotion = readMatrixCsv(folder / c.at("emotion_file").get<std::string>(), channels);
            if (!emotion) return emotion.error();
            cell.emotionComponent = std::move(emotion).value();
            auto phase = readMatrixCsv(folder / c.at("phase_file").get<std::string>(),
                                       {"phase_warp", "functional_to_emotional"});
            if (!phase) return phase.error();
            cell.phaseWarp = column(*phase, 0);
            cell.functionalToEmotional = column(*phase, 1);
            truth.cells.push_back(std::move(cell));
        }
        for (const auto& t : manifest.at("takes")) {
            TakeTruth take;
            take.labels.function = t.at("function").get<std::string>();
            take.labels.emotion = t.at("emotion").get<std::string>();
            take.labels.takeIndex = t.at("take").get<int>();
            take.labels.source = t.value("source", std::string());
            where = "take " + take.labels.function + "/" + take.labels.emotion + "/" + std::to_string(take.labels.takeIndex);
            take.lateStartFrames = t.at("late_start_frames").get<int>();
            take.amplitudeGain = t.at("amplitude_gain").get<double>();
            const auto offset = t.at("position_offset_cm").get<std::vector<double>>();
            if (offset.size() != 3) throw std::runtime_error("position_offset_cm: expected 3 numbers");
            take.positionOffset = Eigen::Vector3d(offset[0], offset[1], offset[2]);
            take.yawOffsetDeg = t.at("yaw_offset_deg").get<double>();
            take.yawWraps = t.at("yaw_wraps").get<bool>();
            const fs::path warpFile = folder / t.at("warp_file").get<std::string>();
            auto warp = readMatrixCsv(warpFile, {"cell_frame"});
            if (!warp) return warp.error();
            take.takeToCell = column(*warp, 0);
            if (take.takeToCell.size() != t.at("frames").get<long>())
                return parseError(warpFile.string(), 0, "expected " + std::to_string(t.at("frames").get<long>()) + " frames");
            truth.takes.push_back(std::move(take));
        }
    } catch (const std::exception& e) {
        return parseError(manifestFile.string(), 0, where + ": " + e.what());
    }
    if (Status status = checkShapes(truth); !status)
        return parseError(manifestFile.string(), 0, status.error().message);
    return truth;
}

} // namespace bunraku::analysis::synth
