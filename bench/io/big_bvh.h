#pragma once
/// Big BVH files for the benchmarks, made from a shared Bandai Namco take (never committed):
/// its hierarchy and its frames played forwards and backwards until the file has the frames
/// asked for (a 108,000-frame take is about 135 MB, an hour at 30 Hz).
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace bunraku::bench {

inline std::filesystem::path bandaiTake() { return std::filesystem::path(BUNRAKU_SHARED_DIR) / "data" / "bandai" / "wave-right-hand_active_001.bvh"; }

/// Writes (once) a `frames`-frame take into `folder`; empty path when the Bandai take is missing.
inline std::filesystem::path bigBandaiLikeTake(const std::filesystem::path& folder, long frames)
{
    const auto target = folder / ("bandai_like_" + std::to_string(frames) + ".bvh");
    if (std::filesystem::exists(target)) return target;
    std::ifstream in(bandaiTake(), std::ios::binary);
    if (!in) return {};
    std::vector<std::string> header, rows;
    std::string line;
    bool motion = false;
    while (std::getline(in, line)) {
        if (!motion) {
            header.push_back(line);
            if (line.rfind("Frame Time", 0) == 0) motion = true;
            continue;
        }
        if (line.find_first_not_of(" \t\r") != std::string::npos) rows.push_back(line);
    }
    std::filesystem::create_directories(folder);
    std::ofstream out(target, std::ios::binary);
    for (const auto& h : header) out << (h.rfind("Frames:", 0) == 0 ? "Frames:\t" + std::to_string(frames) : h) << "\n";
    const long n = long(rows.size());
    for (long f = 0; f < frames; ++f) {
        const long k = f % (2 * n - 2); // forwards, then backwards: no jump at the ends
        out << rows[std::size_t(k < n ? k : 2 * n - 2 - k)] << "\n";
    }
    return target;
}

} // namespace bunraku::bench
