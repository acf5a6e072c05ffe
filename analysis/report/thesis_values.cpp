#include "analysis/report/thesis_values.h"

#include <limits>
#include <map>

namespace bunraku::analysis::report {
namespace {

constexpr double kDash = std::numeric_limits<double>::quiet_NaN();

} // namespace

const std::array<ThesisVarianceRow, 5>& thesisVarianceTable(int method)
{
    static const std::array<ThesisVarianceRow, 5> method1{{
        {1, {3.0077, 2.4348, 2.4151, 1.6071, 3.1817, 2.7875}},
        {2, {1.0492, 0.5795, 0.7919, 0.2605, 0.7819, 0.2720}},
        {3, {2.2888, 0.5526, 2.1837, 0.4749, 1.9348, 0.2750}},
        {4, {kDash, kDash, 0.2341, 0.2126, 0.1897, 0.1705}},
        {5, {1.1202, 0.5632, 0.8681, 0.3299, 0.7631, 0.2573}},
    }};
    static const std::array<ThesisVarianceRow, 5> method2{{
        {1, {3.0077, 2.4147, 2.4177, 1.6123, 3.1847, 2.7925}},
        {2, {1.0492, 0.6088, 0.7849, 0.2653, 0.7739, 0.2688}},
        {3, {2.2888, 0.5551, 2.1759, 0.4597, 1.9301, 0.2969}},
        {4, {kDash, kDash, 0.2427, 0.2247, 0.1990, 0.1872}},
        {5, {1.1202, 0.5905, 0.8721, 0.3218, 0.7660, 0.2568}},
    }};
    return method == 1 ? method1 : method2;
}

const std::array<double, 5>& thesisArmaHeadX(int function, int emotion)
{
    static const std::array<std::array<double, 5>, 6> rows{{
        {-1.8290, 0.8586, 0.2125, 0.5891, 0.0035},
        {-1.4239, 0.5201, 0.2414, 0.6818, 0.0486},
        {-1.2734, 0.3064, 0.2164, 0.6834, 0.0309},
        {-1.8791, 0.9090, 0.3267, 0.6809, -0.0197},
        {-1.7569, 0.7812, 0.1484, 0.6383, 0.0056},
        {-1.4880, 0.5361, 0.1371, 0.6121, -0.0085},
    }};
    static const std::array<double, 5> none{kDash, kDash, kDash, kDash, kDash};
    if (function < 1 || function > 2 || emotion < 1 || emotion > 3) return none;
    return rows[std::size_t((function - 1) * 3 + (emotion - 1))];
}

double thesisCellErrorPercent(const std::string& channel, int function, int emotion)
{
    // Table 4.5, columns P^11 P^12 P^13 P^21 P^22 P^23.
    static const std::map<std::string, std::array<double, 6>> table{
        {"head.x", {0.05, 0.22, 5.32, 0.01, 2.77, 0.95}},       {"head.y", {1.09, 2.16, 0.57, 0.10, 0.67, 0.44}},
        {"head.z", {0.05, 1.06, 49.91, 0.31, 0.36, 0.11}},      {"head.yaw", {0.64, 0.05, 0.20, 6.53, 0.72, 0.05}},
        {"head.pitch", {0.02, 0.19, 0.11, 3.99, 0.22, 0.25}},   {"head.roll", {1.56, 0.91, 0.73, 1.33, 0.35, 0.38}},
        {"shoulder.x", {0.31, 0.12, 2.18, 0.04, 2.77, 0.76}},   {"shoulder.y", {0.46, 0.70, 0.31, 0.08, 1.49, 0.37}},
        {"shoulder.z", {0.09, 2.57, 31.70, 0.25, 0.48, 0.12}},  {"shoulder.yaw", {8.94, 0.17, 0.61, 1.25, 0.72, 0.33}},
        {"shoulder.pitch", {0.62, 1.74, 9.92, 2.34, 1.75, 0.20}}, {"shoulder.roll", {0.12, 1.94, 6.46, 0.48, 0.31, 1.19}},
        {"arm.x", {0.43, 0.14, 1.56, 0.03, 2.86, 0.08}},        {"arm.y", {0.08, 0.27, 0.65, 0.21, 0.99, 0.09}},
        {"arm.z", {0.07, 1.21, 15.91, 0.89, 0.04, 0.32}},       {"arm.yaw", {0.19, 3.89, 0.70, 2.52, 1.01, 0.21}},
        {"arm.pitch", {0.58, 0.47, 7.27, 0.23, 1.01, 1.08}},    {"arm.roll", {2.05, 1.17, 8.12, 0.13, 0.88, 0.41}},
        {"hand.x", {0.49, 0.14, 1.70, 0.04, 3.16, 0.07}},       {"hand.y", {0.07, 0.49, 0.53, 0.20, 0.85, 0.11}},
        {"hand.z", {0.09, 1.75, 15.47, 0.70, 0.08, 0.20}},      {"hand.yaw", {0.33, 1.65, 1.03, 1.99, 5.31, 17.52}},
        {"hand.pitch", {2.50, 1.90, 1.34, 4.89, 9.91, 14.16}},  {"hand.roll", {2.36, 1.42, 14.43, 0.10, 0.40, 0.50}},
    };
    const auto found = table.find(channel);
    if (found == table.end() || function < 1 || function > 2 || emotion < 1 || emotion > 3) return kDash;
    return found->second[std::size_t((function - 1) * 3 + (emotion - 1))];
}

int thesisFunctionIndex(const std::string& function)
{
    if (function == "greeting") return 1;
    if (function == "serving-tea" || function == "serving tea") return 2;
    return 0;
}

int thesisEmotionIndex(const std::string& emotion)
{
    if (emotion == "none") return 1;
    if (emotion == "friendly") return 2;
    if (emotion == "hostile") return 3;
    return 0;
}

} // namespace bunraku::analysis::report
