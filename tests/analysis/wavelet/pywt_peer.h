#pragma once
/// Runs a short script under Debian's /usr/bin/python3 (which has python3-pywt) and reads the
/// whitespace-separated numbers it prints. Empty optional when python or pywt is missing, so
/// the calling test can WARN and skip; a failing script throws (the test fails).

#include "tests/support/test_paths.h"

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace bunraku::test {

inline bool pywtAvailable()
{
    static const bool available = std::filesystem::exists("/usr/bin/python3")
                                  && std::system("/usr/bin/python3 -c 'import pywt' >/dev/null 2>&1") == 0;
    return available;
}

inline std::optional<std::vector<double>> runPywt(const std::string& name, const std::string& script)
{
    if (!pywtAvailable()) return std::nullopt;
    const auto dir = scratchDir("pywt-" + name);
    const auto path = dir / "script.py";
    {
        std::ofstream file(path);
        file << "import numpy as np\nimport pywt\nimport sys\n" << script << "\n";
    }
    const std::string command = "/usr/bin/python3 " + path.string() + " 2>&1";
    FILE* pipe = popen(command.c_str(), "r");
    if (!pipe) return std::nullopt;
    std::string output;
    char buffer[4096];
    while (std::size_t got = std::fread(buffer, 1, sizeof buffer, pipe)) output.append(buffer, got);
    if (pclose(pipe) != 0) throw std::runtime_error("python3 peer script failed:\n" + output);
    std::istringstream in(output);
    std::vector<double> values;
    std::string token;
    while (in >> token) values.push_back(std::stod(token));
    return values;
}

/// Python literal for a vector: "np.array([...])" with round-trip precision.
inline std::string pythonArray(const std::vector<double>& values)
{
    std::ostringstream out;
    out.precision(17);
    out << "np.array([";
    for (std::size_t i = 0; i < values.size(); ++i) out << (i ? "," : "") << values[i];
    out << "])";
    return out.str();
}

} // namespace bunraku::test
