#include "analysis/io/corpus_build_report.h"

#include <algorithm>
#include <iomanip>
#include <sstream>

namespace bunraku::analysis::io {

nlohmann::json corpusBuildFilesJson(const CorpusBuild& build)
{
    nlohmann::json takes = nlohmann::json::array();
    for (const auto& f : build.files)
        takes.push_back({{"file", f.file.string()},
                         {"function", f.labels.function},
                         {"emotion", f.labels.emotion},
                         {"take", f.labels.takeIndex},
                         {"frames", f.frames},
                         {"rate_hz", f.rateHz},
                         {"frames_in_corpus", f.framesInCorpus},
                         {"resampled", f.resampled},
                         {"part_map", f.partMap}});
    return takes;
}

std::string corpusBuildTable(const CorpusBuild& build)
{
    // Columns as wide as their longest entry (and two spaces apart), so long names never run together.
    std::size_t fileWidth = 4, functionWidth = 8, emotionWidth = 7;
    for (const auto& f : build.files) {
        fileWidth = std::max(fileWidth, f.file.filename().string().size());
        functionWidth = std::max(functionWidth, f.labels.function.size());
        emotionWidth = std::max(emotionWidth, f.labels.emotion.size());
    }
    const auto left = [](std::size_t width) { return std::setw(int(width + 2)); };
    std::ostringstream out;
    out << "  " << std::left << left(fileWidth) << "file" << left(functionWidth) << "function" << left(emotionWidth) << "emotion"
        << std::right << std::setw(4) << "take" << std::setw(8) << "frames" << std::setw(8) << "Hz" << "  part map\n";
    for (const auto& f : build.files)
        out << "  " << std::left << left(fileWidth) << f.file.filename().string() << left(functionWidth) << f.labels.function
            << left(emotionWidth) << f.labels.emotion << std::right << std::setw(4) << f.labels.takeIndex << std::setw(8) << f.frames
            << std::setw(8) << f.rateHz << "  " << (f.partMap.empty() ? std::string("-") : f.partMap) << (f.resampled ? "  (resampled)" : "")
            << "\n";
    for (const auto& note : build.notes) out << "note: " << note << "\n";
    return out.str();
}

} // namespace bunraku::analysis::io
