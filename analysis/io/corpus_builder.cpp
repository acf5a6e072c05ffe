#include "analysis/io/corpus_builder.h"

#include "analysis/core/pose.h"
#include "analysis/core/puppet_layout.h"
#include "analysis/core/skeleton_take.h"
#include "analysis/io/bvh_joint_map.h"
#include "analysis/io/text_scan.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <map>
#include <set>

namespace bunraku::analysis::io {
namespace {

namespace fs = std::filesystem;

enum class Field { Literal, Function, Emotion, Take, Any };

struct PatternToken {
    Field field = Field::Literal;
    std::string text; ///< the literal
};

Result<std::vector<PatternToken>> tokenise(std::string_view pattern)
{
    std::vector<PatternToken> tokens;
    const auto fail = [&](const std::string& what) {
        return makeError(ErrorCode::InvalidArgument, "file-name pattern '" + std::string(pattern) + "': " + what);
    };
    for (std::size_t i = 0; i < pattern.size();) {
        if (pattern[i] != '{') {
            if (tokens.empty() || tokens.back().field != Field::Literal) tokens.push_back({});
            tokens.back().text += pattern[i++];
            continue;
        }
        const std::size_t close = pattern.find('}', i);
        if (close == std::string_view::npos) return fail("a '{' without its '}'");
        const std::string_view name = pattern.substr(i + 1, close - i - 1);
        Field field;
        if (name == "function") field = Field::Function;
        else if (name == "emotion") field = Field::Emotion;
        else if (name == "take") field = Field::Take;
        else if (name == "any" || name == "*") field = Field::Any;
        else return fail("unknown placeholder {" + std::string(name) + "} (expected {function}, {emotion}, {take} or {any})");
        if (!tokens.empty() && tokens.back().field != Field::Literal)
            return fail("two placeholders need something between them, such as '_'");
        tokens.push_back({field, {}});
        i = close + 1;
    }
    const auto count = [&](Field f) { return std::count_if(tokens.begin(), tokens.end(), [&](const PatternToken& t) { return t.field == f; }); };
    if (count(Field::Function) != 1) return fail("expected {function} exactly once");
    if (count(Field::Emotion) > 1 || count(Field::Take) > 1) return fail("{emotion} and {take} may appear once each");
    return tokens;
}

bool matchFrom(const std::vector<PatternToken>& tokens, std::size_t t, std::string_view stem, std::size_t at, TakeLabels& labels)
{
    if (t == tokens.size()) return at == stem.size();
    const PatternToken& token = tokens[t];
    if (token.field == Field::Literal) {
        if (stem.substr(at, token.text.size()) != token.text) return false;
        return matchFrom(tokens, t + 1, stem, at + token.text.size(), labels);
    }
    for (std::size_t length = 1; at + length <= stem.size(); ++length) {
        const std::string_view value = stem.substr(at, length);
        if (token.field == Field::Take && !std::isdigit(static_cast<unsigned char>(value.back()))) break;
        if (token.field == Field::Take && length > 9) break;
        if (!matchFrom(tokens, t + 1, stem, at + length, labels)) continue;
        if (token.field == Field::Function) labels.function = std::string(value);
        if (token.field == Field::Emotion) labels.emotion = std::string(value);
        if (token.field == Field::Take) labels.takeIndex = std::stoi(std::string(value));
        return true;
    }
    return false;
}

std::string shortRate(double hz) { return detail::shortText(hz); }

} // namespace

Status checkLabelPattern(std::string_view pattern)
{
    auto tokens = tokenise(pattern);
    if (!tokens) return tokens.error();
    return okStatus();
}

std::optional<TakeLabels> parseTakeLabels(std::string_view stem, std::string_view pattern)
{
    auto tokens = tokenise(pattern);
    if (!tokens) return std::nullopt;
    TakeLabels labels;
    if (!matchFrom(*tokens, 0, stem, 0, labels)) return std::nullopt;
    return labels;
}

Result<std::vector<fs::path>> collectTakeFiles(const std::vector<fs::path>& inputs)
{
    std::vector<fs::path> files;
    for (const fs::path& input : inputs) {
        std::error_code ec;
        if (fs::is_directory(input, ec)) {
            // One format per folder, so that a README.txt beside BVH files is not read as FASTRAK.
            std::map<TakeFileFormat, std::vector<fs::path>> byFormat;
            for (const auto& entry : fs::directory_iterator(input, ec))
                if (entry.is_regular_file(ec) && takeFileFormat(entry.path()) != TakeFileFormat::Unknown)
                    byFormat[takeFileFormat(entry.path())].push_back(entry.path());
            if (ec) return makeError(ErrorCode::Io, input.string() + ": cannot list the folder: " + ec.message());
            std::vector<fs::path> found;
            for (const TakeFileFormat format : {TakeFileFormat::Bvh, TakeFileFormat::Scene, TakeFileFormat::Csv, TakeFileFormat::Fastrak})
                if (found.empty() && byFormat.count(format)) found = byFormat[format];
            if (found.empty())
                return makeError(ErrorCode::NotFound, input.string() + ": no take files (.bvh, .fbx, .glb, .gltf, .dae, .csv, .txt, .fastrak, .fst) in the folder");
            std::sort(found.begin(), found.end());
            files.insert(files.end(), found.begin(), found.end());
        } else if (fs::exists(input, ec)) {
            if (takeFileFormat(input) == TakeFileFormat::Unknown)
                return makeError(ErrorCode::Unsupported,
                                 input.string() + ": not a take file (expected .bvh, .fbx, .glb, .gltf, .dae, .csv, .txt, .fastrak or .fst)");
            files.push_back(input);
        } else {
            return makeError(ErrorCode::NotFound, input.string() + ": no such file or folder");
        }
    }
    if (files.empty()) return makeError(ErrorCode::InvalidArgument, "no take files given");
    return files;
}

Result<std::vector<CorpusSource>> labelTakeFiles(const std::vector<fs::path>& files, std::string_view pattern)
{
    if (auto ok = checkLabelPattern(pattern); !ok) return ok.error();
    std::vector<CorpusSource> sources;
    for (const fs::path& file : files) {
        auto labels = parseTakeLabels(file.stem().string(), pattern);
        if (!labels)
            return makeError(ErrorCode::InvalidArgument,
                             file.string() + ": the file name does not match the pattern '" + std::string(pattern) + "'");
        if (labels->emotion.empty()) labels->emotion = "none";
        sources.push_back({file, *labels});
    }
    // Takes without an index: 1, 2, ... in file order within their cell, after the cell's given indices.
    std::map<std::pair<std::string, std::string>, int> next;
    for (const auto& s : sources) {
        int& n = next[{s.labels.function, s.labels.emotion}];
        n = std::max(n, s.labels.takeIndex);
    }
    for (auto& s : sources)
        if (s.labels.takeIndex == 0) s.labels.takeIndex = ++next[{s.labels.function, s.labels.emotion}];
    return sources;
}

Result<Take> resampleTake(const Take& take, double toHz)
{
    if (!plausibleRate(toHz)) return makeError(ErrorCode::InvalidArgument, "resampling to " + shortRate(toHz) + " Hz: " + rateExpectation());
    if (take.rateHz == toHz) return take;
    if (take.skeleton && hasPuppetLayout(take)) {
        bool bound = true;
        for (const auto part : kPuppetParts) bound = bound && take.skeleton->skeleton->binding(part) != nullptr;
        if (bound) {
            auto motion = std::make_shared<const SkeletalMotion>(resampleSkeletalMotion(*take.skeleton, take.rateHz, toHz));
            return puppetTakeFromSkeleton(std::move(motion), toHz, take.labels);
        }
    }
    const double duration = take.duration();
    const Eigen::Index frames = Eigen::Index(std::floor(duration * toHz + 1e-9)) + 1;
    Take out;
    out.channels = take.channels;
    out.labels = take.labels;
    out.rateHz = toHz;
    out.values.resize(frames, take.channelCount());
    for (Eigen::Index f = 0; f < frames; ++f) {
        const double at = std::min(double(f) / toHz * take.rateHz, double(take.frameCount() - 1));
        const Eigen::Index a = Eigen::Index(std::floor(at));
        const Eigen::Index b = std::min(a + 1, take.frameCount() - 1);
        const double t = at - double(a);
        out.values.row(f) = (1.0 - t) * take.values.row(a) + t * take.values.row(b);
    }
    if (take.skeleton) {
        // Parts named after joints (the all-joints layout) are posed again from the skeleton.
        auto motion = std::make_shared<const SkeletalMotion>(resampleSkeletalMotion(*take.skeleton, take.rateHz, toHz));
        const auto parts = sixDofParts(out);
        for (Eigen::Index f = 0; f < frames; ++f) {
            const auto poses = motion->worldPoses(f);
            for (const auto& part : parts) {
                const int joint = motion->skeleton->find(part.part);
                if (joint >= 0) setPartPose(out, f, part.firstChannel, poses[std::size_t(joint)]);
            }
        }
        out.skeleton = std::move(motion);
    }
    if (auto valid = validateTake(out); !valid) return valid.error();
    return out;
}

Result<CorpusBuild> buildCorpus(const std::vector<CorpusSource>& sources, const CorpusBuildOptions& options, const RunControl& control)
{
    if (sources.empty()) return makeError(ErrorCode::InvalidArgument, "a corpus needs at least one take file");
    CorpusBuild build;
    std::map<std::tuple<std::string, std::string, int>, fs::path> seen;
    for (std::size_t i = 0; i < sources.size(); ++i) {
        if (control.cancelled()) return makeError(ErrorCode::Cancelled, "building the corpus was cancelled");
        const CorpusSource& source = sources[i];
        const auto key = std::make_tuple(source.labels.function, source.labels.emotion, source.labels.takeIndex);
        if (const auto it = seen.find(key); it != seen.end())
            return makeError(ErrorCode::InvalidArgument, source.file.string() + ": the labels " + source.labels.function + "/" +
                                                             source.labels.emotion + "/" + std::to_string(source.labels.takeIndex) +
                                                             " are also those of " + it->second.string());
        seen.emplace(key, source.file);
        CorpusFileReport report;
        report.file = source.file;
        report.labels = source.labels;
        Result<Take> take = makeError(ErrorCode::InvalidArgument, "");
        const TakeFileFormat format = takeFileFormat(source.file);
        if ((format == TakeFileFormat::Bvh || format == TakeFileFormat::Scene) && options.import.bvhLayout == BvhTakeLayout::PuppetParts) {
            // Half of a file's share of the progress for reading it, half for its import.
            const double share = 0.9 / double(sources.size());
            auto bvh = readSkeletalFile(source.file, options.import, control.step(share * double(i), share * (double(i) + 0.5)));
            if (!bvh) return bvh.error();
            const BvhImportOptions bvhOptions = format == TakeFileFormat::Scene ? sceneBvhOptions(options.import.bvh) : options.import.bvh;
            auto imported = importBvhPuppet(*bvh, bvhOptions, control.step(share * (double(i) + 0.5), share * double(i + 1)));
            if (!imported) return imported.error();
            report.partMap = imported->map->describe();
            take = std::move(imported->take);
        } else {
            take = readTakeFile(source.file, options.import);
            if (!take) return take.error();
        }
        take->labels = source.labels;
        take->labels.source = source.file.string();
        report.rateHz = take->rateHz;
        report.frames = take->frameCount();
        build.files.push_back(report);
        build.corpus.takes.push_back(std::move(take).value());
        control.report(0.9 * double(i + 1) / double(sources.size()));
    }

    // One rate: the given one, else the rate most files have (the highest of a tie).
    std::map<double, int> rates;
    for (const auto& report : build.files) ++rates[report.rateHz];
    double rate = options.rateHz;
    if (rate == 0.0) {
        int best = 0;
        for (const auto& [hz, count] : rates)
            if (count >= best) {
                best = count;
                rate = hz;
            }
    }
    if (!plausibleRate(rate)) return makeError(ErrorCode::InvalidArgument, "corpus rate " + shortRate(rate) + " Hz: " + rateExpectation());
    std::vector<std::string> resampled;
    for (std::size_t i = 0; i < build.corpus.takes.size(); ++i) {
        Take& take = build.corpus.takes[i];
        if (take.rateHz != rate) {
            auto converted = resampleTake(take, rate);
            if (!converted) return makeError(converted.error().code, build.files[i].file.string() + ": " + converted.error().message);
            take = std::move(converted).value();
            build.files[i].resampled = true;
            resampled.push_back(build.files[i].file.filename().string() + " (" + shortRate(build.files[i].rateHz) + " Hz)");
        }
        build.files[i].framesInCorpus = take.frameCount();
    }
    build.corpus.rateHz = rate;
    if (rates.size() > 1 || options.rateHz != 0.0) {
        std::string note = "corpus rate " + shortRate(rate) + " Hz (" + (options.rateHz != 0.0 ? "given" : "the rate most files have") + ")";
        if (!resampled.empty()) {
            note += "; resampled to it: ";
            for (std::size_t k = 0; k < resampled.size(); ++k) {
                if (k > 0) note += ", ";
                note += resampled[k];
            }
        }
        build.notes.push_back(note);
    }

    const auto emotions = build.corpus.emotions();
    if (!options.neutralEmotion.empty()) {
        if (std::find(emotions.begin(), emotions.end(), options.neutralEmotion) == emotions.end()) {
            std::string list;
            for (const auto& e : emotions) {
                if (!list.empty()) list += ", ";
                list += e;
            }
            return makeError(ErrorCode::InvalidArgument, "the neutral emotion '" + options.neutralEmotion + "' is none of the files' emotions (" + list + ")");
        }
        build.corpus.neutralEmotion = options.neutralEmotion;
    } else {
        std::string neutral;
        for (const char* candidate : {"neutral", "normal", "none"})
            if (neutral.empty() && std::find(emotions.begin(), emotions.end(), candidate) != emotions.end()) neutral = candidate;
        build.notes.push_back(neutral.empty() ? "neutral emotion '" + emotions.front() + "' (the first; give --neutral to choose)"
                                              : "neutral emotion '" + neutral + "'");
        build.corpus.neutralEmotion = neutral.empty() ? emotions.front() : neutral;
    }
    build.corpus.name = options.name.empty() ? std::string("corpus") : options.name;
    if (auto valid = validateCorpus(build.corpus); !valid) return valid.error();
    control.report(1.0);
    return build;
}

} // namespace bunraku::analysis::io
