// Measurements Google Benchmark does not make (docs/PERFORMANCE.md):
//   bench_normalise_extras memory N   peak RSS of normalising one N-frame x 24-channel pair
//                                     (T_cmp 240, scales 1..16, method 2, optimal path)
//   bench_normalise_extras pywt       our CWT of 100,000 samples at scales 1..16 against Debian
//                                     python3-pywt's, measured in the same run, as ratios of
//                                     wall and of CPU time
//   bench_normalise_extras digest     a hash of every correspondence and the summed costs of the
//                                     30 demo-corpus normalisations and of a 30,000-frame pair,
//                                     greedy and optimal: two builds that print the same digest
//                                     chose the same frames
#include "analysis/normalise/take_normalisation.h"
#include "analysis/synth/demo_corpus.h"
#include "analysis/wavelet/cwt.h"
#include "bench/normalise/kernels_in_use.h"
#include "bench/normalise/long_takes.h"

#include <algorithm>
#include <chrono>
#include <ctime>
#include <functional>
#include <cstdio>
#include <cstdint>
#include <cstdlib>
#include <fstream>
#include <map>
#include <random>
#include <sstream>
#include <string>
#include <vector>

using namespace bunraku::analysis;

namespace {

long statusKilobytes(const std::string& key)
{
    std::ifstream status("/proc/self/status");
    std::string line;
    while (std::getline(status, line))
        if (line.rfind(key + ":", 0) == 0) return std::stol(line.substr(key.size() + 1));
    return -1;
}

double seconds(const std::chrono::steady_clock::time_point& start)
{
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

int memory(long frames)
{
    const Take reference = bunraku::bench::longTake(frames, 0.0, 1.0, 1);
    const Take sample = bunraku::bench::longTake(frames, 190.0, 7919.0, 2);
    const long before = statusKilobytes("VmHWM");
    NormaliseOptions options;
    options.match.searchBand = 240;
    options.match.path = PathMethod::Optimal;
    const auto start = std::chrono::steady_clock::now();
    const std::clock_t cpuStart = std::clock();
    auto result = normaliseTake(reference, sample, options);
    const double cpu = double(std::clock() - cpuStart) / CLOCKS_PER_SEC;
    const double wall = seconds(start);
    if (!result) {
        std::fprintf(stderr, "%s\n", result.error().message.c_str());
        return 1;
    }
    std::printf("kernels: %s\n", bunraku::bench::kernelsInUse().c_str());
    std::printf("frames %ld: wall %.3f s, cpu %.3f s, peak RSS %ld kB (inputs alone %ld kB)\n", frames, wall, cpu,
                statusKilobytes("VmHWM"), before);
    return 0;
}

// FNV-1a over the correspondences; costs summed.
struct Digest {
    std::uint64_t hash = 1469598103934665603ull;
    double cost = 0.0;
    void add(const TakeNormalisation& result)
    {
        for (Eigen::Index i = 0; i < result.correspondence.size(); ++i) {
            hash ^= std::uint64_t(std::uint32_t(result.correspondence.data()[i]));
            hash *= 1099511628211ull;
        }
        cost += result.cost;
    }
};

int digest()
{
    const auto demo = synth::generateDemoCorpus();
    const Take reference = bunraku::bench::longTake(30000, 0.0, 1.0, 1);
    const Take sample = bunraku::bench::longTake(30000, 190.0, 7919.0, 2);
    for (const PathMethod path : {PathMethod::Greedy, PathMethod::Optimal}) {
        NormaliseOptions options;
        options.match.path = path;
        Digest corpus;
        for (const auto& function : demo.corpus.functions())
            for (const auto& emotion : demo.corpus.emotions()) {
                const auto takes = demo.corpus.cell(function, emotion);
                auto results = normaliseTakes(*takes[0], takes, options);
                if (!results) {
                    std::fprintf(stderr, "%s\n", results.error().message.c_str());
                    return 1;
                }
                for (const auto& result : *results) corpus.add(result);
            }
        options.match.searchBand = 240;
        auto pair = normaliseTake(reference, sample, options);
        if (!pair) {
            std::fprintf(stderr, "%s\n", pair.error().message.c_str());
            return 1;
        }
        Digest long_;
        long_.add(*pair);
        std::printf("%s: demo corpus %016llx cost %.17g; 30,000-frame pair %016llx cost %.17g\n",
                    path == PathMethod::Greedy ? "greedy" : "optimal", static_cast<unsigned long long>(corpus.hash), corpus.cost,
                    static_cast<unsigned long long>(long_.hash), long_.cost);
    }
    return 0;
}

double threadSeconds()
{
    timespec now{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &now);
    return double(now.tv_sec) + 1e-9 * double(now.tv_nsec);
}

struct Timing {
    double wall = 0.0;
    double cpu = 0.0;
};

// Medians of wall and CPU (this thread) time over the repeats.
Timing medianTimes(const std::function<void()>& work, int repeats)
{
    std::vector<double> walls, cpus;
    for (int i = 0; i < repeats; ++i) {
        const auto start = std::chrono::steady_clock::now();
        const double cpu = threadSeconds();
        work();
        cpus.push_back(threadSeconds() - cpu);
        walls.push_back(seconds(start));
    }
    std::sort(walls.begin(), walls.end());
    std::sort(cpus.begin(), cpus.end());
    return {walls[walls.size() / 2], cpus[cpus.size() / 2]};
}

int pywt()
{
    std::mt19937 random(5);
    std::normal_distribution<double> normal;
    Eigen::VectorXd signal(100000);
    for (auto& v : signal) v = normal(random);
    std::map<std::string, Timing> ours;
    for (const std::string name : {"sym3", "mexh"}) {
        CwtOptions options;
        options.wavelet = *waveletByName(name);
        for (auto method : {CwtMethod::Direct, CwtMethod::Fft}) {
            options.method = method;
            const CwtFilterBank bank = *makeCwtFilterBank(integerScales(16), options);
            ours[name + (method == CwtMethod::Direct ? "-direct" : "-fft")] = medianTimes([&] { auto r = cwt(signal, bank); (void)r; }, 7);
        }
    }
    const std::string script = std::string(BUNRAKU_SOURCE_DIR) + "/scripts/bench_pywt_cwt.py";
    FILE* pipe = popen(("/usr/bin/python3 " + script + " 100000 7").c_str(), "r");
    if (!pipe) return 1;
    std::map<std::string, Timing> theirs;
    char name[64];
    Timing value;
    while (std::fscanf(pipe, "%63s %lf %lf", name, &value.wall, &value.cpu) == 3) theirs[name] = value;
    if (pclose(pipe) != 0 || theirs.empty()) {
        std::fprintf(stderr, "/usr/bin/python3 %s failed (python3-pywt missing?)\n", script.c_str());
        return 1;
    }
    std::printf("kernels: %s\n", bunraku::bench::kernelsInUse().c_str());
    std::printf("CWT of 100,000 samples, scales 1..16, medians of 7 (seconds): wall, CPU\n");
    for (const auto& [key, time] : ours) std::printf("  ours %-12s %.4f %.4f\n", key.c_str(), time.wall, time.cpu);
    for (const auto& [key, time] : theirs) std::printf("  pywt %-12s %.4f %.4f\n", key.c_str(), time.wall, time.cpu);
    // sym3: pywt's legacy steps against our direct transform; mexh: pywt's best method against ours.
    auto ratios = [&](double Timing::*field) {
        const double mexhTheirs = std::min(theirs["mexh-conv"].*field, theirs["mexh-fft"].*field);
        const double mexhOurs = std::min(ours["mexh-direct"].*field, ours["mexh-fft"].*field);
        return std::pair{theirs["sym3-legacy"].*field / (ours["sym3-direct"].*field), mexhTheirs / mexhOurs};
    };
    const auto [sym3Wall, mexhWall] = ratios(&Timing::wall);
    const auto [sym3Cpu, mexhCpu] = ratios(&Timing::cpu);
    std::printf("ratio pywt/ours, wall: sym3 legacy %.2f (vs our direct), mexh %.2f (pywt's best vs our best)\n", sym3Wall, mexhWall);
    std::printf("ratio pywt/ours, CPU:  sym3 legacy %.2f (vs our direct), mexh %.2f (pywt's best vs our best)\n", sym3Cpu, mexhCpu);
    return 0;
}

} // namespace

int main(int argc, char** argv)
{
    const std::string command = argc > 1 ? argv[1] : "";
    if (command == "memory" && argc > 2) return memory(std::atol(argv[2]));
    if (command == "pywt") return pywt();
    if (command == "digest") return digest();
    std::fprintf(stderr, "usage: %s memory FRAMES | pywt | digest\n", argv[0]);
    return 2;
}
