#include "analysis/io/corpus_io.h"

#include "analysis/io/atomic_file.h"
#include "analysis/io/json_text.h"
#include "analysis/io/skeleton_io.h"
#include "analysis/io/staged_folder.h"
#include "analysis/io/text_format.h"
#include "analysis/io/text_scan.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <set>

namespace bunraku::analysis::io {

namespace {

namespace fs = std::filesystem;
using nlohmann::json;

/// A label usable in a file name; never empty.
std::string sanitise(const std::string& text)
{
    const std::string safe = fileSafeLabel(text);
    return safe.empty() ? std::string("take") : safe;
}

struct ManifestReader {
    std::string file;

    Error error(const std::string& where, const std::string& what) const
    {
        return makeError(ErrorCode::Parse, file + ": " + where + ": " + what);
    }
};

Result<std::string> stringField(const ManifestReader& reader, const json& object, const char* key, const std::string& where,
                                bool required = true)
{
    const auto it = object.find(key);
    if (it == object.end()) {
        if (!required) return std::string();
        return reader.error(where, std::string("missing \"") + key + "\" (a string)");
    }
    if (!it->is_string()) return reader.error(where, std::string("\"") + key + "\" must be a string");
    return it->get<std::string>();
}

Result<double> numberField(const ManifestReader& reader, const json& object, const char* key, const std::string& where)
{
    const auto it = object.find(key);
    if (it == object.end()) return reader.error(where, std::string("missing \"") + key + "\" (a number)");
    if (!it->is_number()) return reader.error(where, std::string("\"") + key + "\" must be a number");
    const double value = it->get<double>();
    if (!std::isfinite(value)) return reader.error(where, std::string("\"") + key + "\" must be finite");
    return value;
}

/// A plain file name inside the corpus folder, or an error.
Result<fs::path> fileInFolder(const ManifestReader& reader, const std::string& where, const char* key, const std::string& name,
                              const fs::path& folder)
{
    const fs::path relative(name);
    const bool climbs = std::any_of(relative.begin(), relative.end(), [](const fs::path& part) { return part == ".."; });
    if (relative.empty() || relative.is_absolute() || name.front() == '.' || climbs)
        return reader.error(where, std::string("\"") + key + "\" must be a file name inside the corpus folder, found \"" + name + "\"");
    std::error_code ec;
    if (!fs::is_regular_file(folder / relative, ec))
        return reader.error(where, std::string("\"") + key + "\": no such file \"" + name + "\" in " + folder.string());
    return folder / relative;
}

json manifestOf(const Corpus& corpus, const std::vector<std::string>& files)
{
    json channels = json::array();
    for (const auto& c : corpus.takes.front().channels)
        channels.push_back({{"name", c.name()}, {"part", c.part}, {"dof", c.dof}, {"unit", c.unit}});
    json takes = json::array();
    for (std::size_t i = 0; i < corpus.takes.size(); ++i) {
        const Take& take = corpus.takes[i];
        json entry = {{"function", take.labels.function},
                      {"emotion", take.labels.emotion},
                      {"take", take.labels.takeIndex},
                      {"file", files[i]},
                      {"frames", take.frameCount()}};
        if (take.skeleton) { // skeleton_io.h: beside the take's CSV
            const std::string stem = files[i].substr(0, files[i].size() - 4);
            entry["skeleton"] = stem + ".skeleton.json";
            entry["motion"] = stem + ".motion.csv";
        }
        if (!take.labels.source.empty()) entry["source"] = take.labels.source;
        takes.push_back(entry);
    }
    return json{{"format", kCorpusFormatName},
                {"version", kCorpusFormatVersion},
                {"name", corpus.name},
                {"rate_hz", corpus.rateHz},
                {"units", {{"position", "cm"}, {"angle", "deg"}, {"time", "s"}}},
                {"convention", corpus.convention},
                {"neutral_emotion", corpus.neutralEmotion},
                {"channels", channels},
                {"takes", takes}};
}

} // namespace

bool isCorpusFolder(const fs::path& folder)
{
    std::error_code ec;
    // Any corpus.json counts: reading it then says what is wrong (a folder, a device, a FIFO).
    return fs::is_directory(folder, ec) && fs::exists(fs::symlink_status(folder / "corpus.json", ec));
}

Result<CorpusManifest> parseCorpusManifest(const std::string& text, const std::string& sourceName)
{
    const ManifestReader reader{sourceName};
    auto parsed = parseJsonText(text, reader.file, "invalid JSON");
    if (!parsed) return parsed.error();
    const json manifest = std::move(parsed).value();
    if (!manifest.is_object()) return reader.error("top level", "expected a JSON object");
    auto format = stringField(reader, manifest, "format", "top level");
    if (!format) return format.error();
    if (*format != kCorpusFormatName)
        return reader.error("\"format\"", "expected \"" + std::string(kCorpusFormatName) + "\", found \"" + *format + "\"");
    auto version = numberField(reader, manifest, "version", "top level");
    if (!version) return version.error();
    if (*version != kCorpusFormatVersion)
        return makeError(ErrorCode::Unsupported, reader.file + ": corpus format version " + nlohmann::json(*version).dump() +
                                                     " is not supported (expected " + std::to_string(kCorpusFormatVersion) + ")");

    CorpusManifest result;
    auto name = stringField(reader, manifest, "name", "top level", false);
    if (!name) return name.error();
    result.name = *name;
    auto rate = numberField(reader, manifest, "rate_hz", "top level");
    if (!rate) return rate.error();
    if (!plausibleRate(*rate)) return reader.error("\"rate_hz\"", rateExpectation());
    result.rateHz = *rate;
    if (manifest.contains("convention")) {
        auto convention = stringField(reader, manifest, "convention", "top level");
        if (!convention) return convention.error();
        result.convention = *convention;
    }
    if (manifest.contains("neutral_emotion")) {
        auto neutral = stringField(reader, manifest, "neutral_emotion", "top level");
        if (!neutral) return neutral.error();
        result.neutralEmotion = *neutral;
    }

    const auto channelsIt = manifest.find("channels");
    if (channelsIt == manifest.end() || !channelsIt->is_array())
        return reader.error("top level", "missing \"channels\" (an array)");
    for (std::size_t i = 0; i < channelsIt->size(); ++i) {
        const json& entry = (*channelsIt)[i];
        const std::string where = "channels[" + std::to_string(i) + "]";
        if (!entry.is_object()) return reader.error(where, "expected an object {part, dof, unit}");
        auto part = stringField(reader, entry, "part", where);
        if (!part) return part.error();
        auto dof = stringField(reader, entry, "dof", where);
        if (!dof) return dof.error();
        auto unit = stringField(reader, entry, "unit", where, false);
        if (!unit) return unit.error();
        result.channels.push_back(Channel{*part, *dof, *unit});
    }

    const auto takesIt = manifest.find("takes");
    if (takesIt == manifest.end() || !takesIt->is_array()) return reader.error("top level", "missing \"takes\" (an array)");
    for (std::size_t i = 0; i < takesIt->size(); ++i) {
        const json& entry = (*takesIt)[i];
        const std::string where = "takes[" + std::to_string(i) + "]";
        if (!entry.is_object()) return reader.error(where, "expected an object {function, emotion, take, file, frames}");
        CorpusManifest::Entry item;
        auto function = stringField(reader, entry, "function", where);
        if (!function) return function.error();
        auto emotion = stringField(reader, entry, "emotion", where);
        if (!emotion) return emotion.error();
        auto index = numberField(reader, entry, "take", where);
        if (!index) return index.error();
        auto file = stringField(reader, entry, "file", where);
        if (!file) return file.error();
        auto source = stringField(reader, entry, "source", where, false);
        if (!source) return source.error();
        const fs::path relative(*file);
        const bool climbs = std::any_of(relative.begin(), relative.end(), [](const fs::path& part) { return part == ".."; });
        if (relative.empty() || relative.is_absolute() || *file.value().begin() == '.' || climbs)
            return reader.error(where, "\"file\" must be a file name inside the corpus folder, found \"" + *file + "\"");
        if (*index != std::floor(*index) || *index < 0.0 || *index > 1e9)
            return reader.error(where, "\"take\" must be a whole number from 0 (unknown) upwards");
        item.labels = TakeLabels{*function, *emotion, int(*index), *source};
        item.file = *file;
        if (entry.contains("frames")) {
            auto frames = numberField(reader, entry, "frames", where);
            if (!frames) return frames.error();
            if (*frames != std::floor(*frames) || *frames < 1.0 || *frames > double(kMaxCorpusTakeFrames))
                return reader.error(where, "\"frames\" must be a whole number from 1 to " + std::to_string(kMaxCorpusTakeFrames));
            item.frames = Eigen::Index(*frames);
        }
        if (entry.contains("skeleton") || entry.contains("motion")) { // skeleton_io.h: both or neither
            for (const char* key : {"skeleton", "motion"}) {
                auto named = stringField(reader, entry, key, where);
                if (!named) return named.error();
                const fs::path path(*named);
                const bool out = std::any_of(path.begin(), path.end(), [](const fs::path& part) { return part == ".."; });
                if (path.empty() || path.is_absolute() || named->front() == '.' || out)
                    return reader.error(where, std::string("\"") + key + "\" must be a file name inside the corpus folder, found \"" + *named + "\"");
                (std::string(key) == "skeleton" ? item.skeleton : item.motion) = *named;
            }
        }
        result.takes.push_back(std::move(item));
    }
    if (result.takes.empty()) return reader.error("\"takes\"", "expected at least one take");
    return result;
}

Result<Corpus> readCorpus(const fs::path& folder, const RunControl& control)
{
    std::error_code ec;
    if (!fs::is_directory(folder, ec)) return makeError(ErrorCode::NotFound, folder.string() + ": no such corpus folder");
    const fs::path manifestPath = folder / "corpus.json";
    auto text = readTextFile(manifestPath, kDocumentLimitBytes);
    if (!text) return text.error();
    auto manifest = parseCorpusManifest(*text, manifestPath.string());
    if (!manifest) return manifest.error();
    const ManifestReader reader{manifestPath.string()};

    Corpus corpus;
    corpus.name = manifest->name;
    corpus.rateHz = manifest->rateHz;
    corpus.convention = manifest->convention;
    corpus.neutralEmotion = manifest->neutralEmotion;
    const std::vector<Channel>& channels = manifest->channels;
    for (std::size_t i = 0; i < manifest->takes.size(); ++i) {
        if (control.cancelled()) return makeError(ErrorCode::Cancelled, folder.string() + ": reading stopped");
        control.report(double(i) / double(manifest->takes.size()));
        const CorpusManifest::Entry& entry = manifest->takes[i];
        const std::string where = "takes[" + std::to_string(i) + "]";
        const fs::path relative(entry.file);
        if (!fs::is_regular_file(folder / relative, ec))
            return reader.error(where, "\"file\": no such take file \"" + entry.file + "\" in " + folder.string());
        TakeCsvOptions options;
        options.rateHz = corpus.rateHz;
        options.timeMustMatchRate = true; // a 10 Hz take in a 5 Hz corpus is an error, not a silent resampling
        options.labels = entry.labels;
        auto take = readTakeCsv(folder / relative, options);
        if (!take) return take.error();
        if (entry.labels.source.empty()) take->labels.source = entry.file;
        if (take->channels.size() != channels.size())
            return makeError(ErrorCode::Parse, (folder / relative).string() + ": " + std::to_string(take->channels.size()) +
                                                   " channels, but corpus.json lists " + std::to_string(channels.size()));
        for (std::size_t c = 0; c < channels.size(); ++c) {
            if (take->channels[c].name() != channels[c].name())
                return makeError(ErrorCode::Parse, (folder / relative).string() + ":1: column " + std::to_string(c + 2) +
                                                       " is " + take->channels[c].name() + ", corpus.json expects " +
                                                       channels[c].name());
            take->channels[c].unit = channels[c].unit;
        }
        if (entry.frames && *entry.frames != take->frameCount())
            return makeError(ErrorCode::Parse, (folder / relative).string() + ": " + std::to_string(take->frameCount()) +
                                                   " frames, but corpus.json says " + std::to_string(*entry.frames));
        if (!entry.skeleton.empty()) {
            auto skeletonFile = fileInFolder(reader, where, "skeleton", entry.skeleton, folder);
            if (!skeletonFile) return skeletonFile.error();
            auto motionFile = fileInFolder(reader, where, "motion", entry.motion, folder);
            if (!motionFile) return motionFile.error();
            auto skeleton = readSkeletalMotion(*skeletonFile, *motionFile, corpus.rateHz);
            if (!skeleton) return skeleton.error();
            if ((**skeleton).frameCount() != take->frameCount())
                return makeError(ErrorCode::Parse, (folder / relative).string() + ": " + std::to_string(take->frameCount()) +
                                                       " frames, but its skeleton's motion has " + std::to_string((**skeleton).frameCount()));
            take->skeleton = *skeleton;
        }
        corpus.takes.push_back(std::move(*take));
    }
    if (auto valid = validateCorpus(corpus); !valid)
        return makeError(valid.error().code, folder.string() + ": " + valid.error().message);
    return corpus;
}

Status writeCorpusFiles(const Corpus& corpus, StagedFolder& folder)
{
    const fs::path& shown = folder.target();
    if (corpus.takes.empty()) return makeError(ErrorCode::InvalidArgument, shown.string() + ": the corpus has no takes");
    if (auto valid = validateCorpus(corpus); !valid)
        return makeError(valid.error().code, shown.string() + ": " + valid.error().message);
    std::vector<std::string> files;
    std::set<std::string> used;
    for (const Take& take : corpus.takes) {
        const std::string base = sanitise(take.labels.function) + "_" + sanitise(take.labels.emotion) + "_" +
                                 std::to_string(take.labels.takeIndex);
        std::string name = base + ".csv";
        for (int n = 2; used.count(name) != 0; ++n) name = base + "-" + std::to_string(n) + ".csv";
        used.insert(name);
        files.push_back(name);
        if (auto written = folder.writeFile(name, formatTakeCsv(take)); !written) return written;
        if (take.skeleton) { // skeleton_io.h: beside the take's CSV, named as manifestOf names them
            const std::string stem = name.substr(0, name.size() - 4);
            auto texts = formatSkeletalMotion(*take.skeleton, take.rateHz);
            if (!texts) return makeError(texts.error().code, (shown / name).string() + ": " + texts.error().message);
            if (auto written = folder.writeFile(stem + ".skeleton.json", texts->first); !written) return written;
            if (auto written = folder.writeFile(stem + ".motion.csv", texts->second); !written) return written;
        }
    }
    return folder.writeFile("corpus.json", manifestOf(corpus, files).dump(2, ' ', false, json::error_handler_t::replace) + "\n");
}

Status writeCorpus(const Corpus& corpus, const fs::path& folder)
{
    if (corpus.takes.empty()) return makeError(ErrorCode::InvalidArgument, folder.string() + ": the corpus has no takes");
    if (auto valid = validateCorpus(corpus); !valid)
        return makeError(valid.error().code, folder.string() + ": " + valid.error().message);
    auto staged = StagedFolder::begin(folder);
    if (!staged) return staged.error();
    if (auto written = writeCorpusFiles(corpus, *staged); !written) return written;
    return staged->commit();
}

} // namespace bunraku::analysis::io
