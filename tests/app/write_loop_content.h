#pragma once
/// The outputs of the kill test's child (write_loop.cpp), one version at a time, and the checks
/// that a file or folder on disk is exactly one complete version: a project save, a take export,
/// a corpus and a PNG frame sequence. Each version differs in size and content, so a file or
/// folder mixing two versions, cut short or empty is recognised.
#include "app/project_file.h"

#include "analysis/core/corpus.h"
#include "analysis/io/corpus_io.h"
#include "analysis/io/staged_folder.h"
#include "analysis/io/take_csv.h"

#include <QDir>
#include <QImage>

#include <cmath>
#include <filesystem>
#include <optional>
#include <string>

namespace bunraku::test::writeloop {

enum class Kind { Project, Take, Corpus, Frames };

inline std::optional<Kind> kindOf(const std::string& name)
{
    if (name == "project") return Kind::Project;
    if (name == "take") return Kind::Take;
    if (name == "corpus") return Kind::Corpus;
    if (name == "frames") return Kind::Frames;
    return std::nullopt;
}

inline double valueOf(int version, int take, Eigen::Index frame, Eigen::Index channel)
{
    return version + 0.25 * take + 0.001 * double(frame) + 1e-6 * double(channel);
}

/// Version `version`'s take: 24 channels, 2000 + 10 (version mod 7) frames (about 0.7 MB of CSV).
inline analysis::Take takeOf(int version, int take, Eigen::Index baseFrames = 2000)
{
    analysis::Take out;
    const char* parts[4] = {"head", "shoulder", "arm", "hand"};
    const char* dofs[6] = {"x", "y", "z", "yaw", "pitch", "roll"};
    for (const char* part : parts)
        for (const char* dof : dofs) out.channels.push_back(analysis::Channel{part, dof, std::string(dof).size() == 1 ? "cm" : "deg"});
    out.rateHz = 5.0;
    out.values.resize(baseFrames + 10 * (version % 7), 24);
    for (Eigen::Index f = 0; f < out.values.rows(); ++f)
        for (Eigen::Index c = 0; c < 24; ++c) out.values(f, c) = valueOf(version, take, f, c);
    out.labels = analysis::TakeLabels{"walk", take < 2 ? "none" : "joy", 1 + take % 2, ""};
    return out;
}

inline analysis::Corpus corpusOf(int version)
{
    analysis::Corpus corpus;
    corpus.name = std::to_string(version);
    corpus.name.insert(0, 1, 'v');
    corpus.rateHz = 5.0;
    for (int t = 0; t < 4; ++t) corpus.takes.push_back(takeOf(version, t, 300));
    return corpus;
}

/// A project of about 200 KB: imported takes, each version's count and paths its own.
inline int importsOf(int version) { return 300 + 10 * (version % 5); }
inline QString importPathOf(int version, int index)
{
    return QStringLiteral("/data/v%1/take_%2_with_a_long_name_to_make_the_project_file_large.csv").arg(version).arg(index);
}

inline app::ProjectState projectOf(int version)
{
    app::ProjectState state;
    state.corpus = QStringLiteral("demo");
    for (int i = 0; i < importsOf(version); ++i) state.imported.push_back({importPathOf(version, i), QStringLiteral("take"), {}});
    state.parameters.normalise.tau = 1 + version % 50;
    state.timeSeconds = version;
    return state;
}

inline int frameCountOf(int version) { return 6 + version % 5; }

inline QImage frameOf(int version, int index)
{
    QImage image(96, 64, QImage::Format_RGB32);
    image.fill(QColor((version * 37) % 256, (index * 11) % 256, 128));
    return image;
}

/// What is on disk at a target: nothing, one complete version, or a problem (a mix, a cut).
struct Verdict {
    bool exists = false;
    int version = -1;
    std::string problem; ///< empty when nothing or a complete version is there
};

inline std::optional<std::string> takeProblem(const analysis::Take& take, int version, int index)
{
    const analysis::Take expected = takeOf(version, index, take.frameCount() - 10 * (version % 7));
    if (take.frameCount() != expected.frameCount()) return "frame count of another version";
    if (take.values != expected.values) return "values of another version";
    return std::nullopt;
}

inline Verdict verify(Kind kind, const std::filesystem::path& target)
{
    Verdict verdict;
    std::error_code ec;
    verdict.exists = std::filesystem::exists(target, ec);
    if (!verdict.exists) return verdict;
    switch (kind) {
    case Kind::Take: {
        auto take = analysis::io::readTakeCsv(target);
        if (!take) return verdict.problem = take.error().message, verdict;
        verdict.version = int(std::floor(take->values(0, 0)));
        if (take->frameCount() != 2000 + 10 * (verdict.version % 7)) return verdict.problem = "cut short", verdict;
        if (auto problem = takeProblem(*take, verdict.version, 0)) verdict.problem = *problem;
        return verdict;
    }
    case Kind::Corpus: {
        auto corpus = analysis::io::readCorpus(target);
        if (!corpus) return verdict.problem = corpus.error().message, verdict;
        verdict.version = std::stoi(corpus->name.substr(1));
        if (corpus->takes.size() != 4) return verdict.problem = "takes missing", verdict;
        for (int t = 0; t < 4; ++t) {
            const analysis::Take& take = corpus->takes[std::size_t(t)];
            if (take.frameCount() != 300 + 10 * (verdict.version % 7)) return verdict.problem = "a take of another version", verdict;
            if (auto problem = takeProblem(take, verdict.version, t)) return verdict.problem = *problem, verdict;
        }
        if (!analysis::io::foreignFiles(target).empty()) verdict.problem = "files outside the manifest";
        return verdict;
    }
    case Kind::Project: {
        auto state = app::readProject(QString::fromStdString(target.string()));
        if (!state) return verdict.problem = state.error().message, verdict;
        verdict.version = int(state->timeSeconds);
        if (state->imported.size() != importsOf(verdict.version) || state->parameters.normalise.tau != 1 + verdict.version % 50)
            return verdict.problem = "content of another version", verdict;
        for (int i = 0; i < importsOf(verdict.version); ++i)
            if (state->imported[i].path != importPathOf(verdict.version, i)) return verdict.problem = "content of another version", verdict;
        return verdict;
    }
    case Kind::Frames: {
        if (!analysis::io::foreignFiles(target).empty()) return verdict.problem = "files outside the manifest", verdict;
        const QDir dir(QString::fromStdString(target.string()));
        const QStringList frames = dir.entryList({QStringLiteral("frame_*.png")}, QDir::Files, QDir::Name);
        if (frames.isEmpty()) return verdict.problem = "no frames", verdict;
        const QImage first(dir.filePath(frames.front()));
        if (first.isNull()) return verdict.problem = "a frame that does not decode", verdict;
        for (int v = 0; v < 256 * 5; ++v) // the version (mod 1280) whose first frame has this colour and count
            if (frameOf(v, 0).pixel(0, 0) == first.pixel(0, 0) && frameCountOf(v) == frames.size()) {
                verdict.version = v;
                break;
            }
        if (verdict.version < 0) return verdict.problem = "frames of two versions", verdict;
        for (int i = 0; i < frames.size(); ++i)
            if (QImage(dir.filePath(frames[i])).pixel(0, 0) != frameOf(verdict.version, i).pixel(0, 0))
                return verdict.problem = "frames of two versions", verdict;
        return verdict;
    }
    }
    return verdict;
}

} // namespace bunraku::test::writeloop
