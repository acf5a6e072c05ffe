#include "analysis/preprocess/preprocess_report.h"

#include "analysis/core/puppet_layout.h"

#include <iomanip>
#include <sstream>

namespace bunraku::analysis::preprocess {

nlohmann::json preprocessReportJson(const PreprocessResult& result)
{
    using nlohmann::json;
    json takes = json::array();
    for (std::size_t i = 0; i < result.report.takes.size(); ++i) {
        const auto& r = result.report.takes[i];
        json offsets = json::array();
        const auto parts = sixDofParts(result.corpus.takes[i]);
        for (std::size_t p = 0; p < r.positionOffsets.size(); ++p)
            offsets.push_back(json{{"part", parts[p].part},
                                   {"offset_cm", json::array({r.positionOffsets[p].x(), r.positionOffsets[p].y(), r.positionOffsets[p].z()})}});
        takes.push_back({{"take", r.take},
                         {"frames_padded", r.framesPadded},
                         {"angles_unwrapped", r.anglesUnwrapped},
                         {"shift_frames", r.shiftFrames},
                         {"time_reference", r.isTimeReference},
                         {"position_reference", r.isPositionReference},
                         {"position_offsets", offsets},
                         {"branch_turns", r.branchTurns},
                         {"heading_offset_deg", r.headingOffsetDeg},
                         {"heading_reference", r.isHeadingReference}});
    }
    return takes;
}

std::string preprocessReportTable(const PreprocessReport& report)
{
    std::ostringstream out;
    out << "  " << std::left << std::setw(28) << "take" << std::right << std::setw(8) << "padded" << std::setw(10) << "unwraps"
        << std::setw(8) << "shift" << "  reference\n";
    for (const auto& r : report.takes)
        out << "  " << std::left << std::setw(28) << r.take << std::right << std::setw(8) << r.framesPadded << std::setw(10)
            << r.anglesUnwrapped << std::setw(8) << r.shiftFrames << "  " << (r.isTimeReference ? "time " : "")
            << (r.isPositionReference ? "position" : "") << "\n";
    return out.str();
}

} // namespace bunraku::analysis::preprocess
