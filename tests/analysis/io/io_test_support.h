#pragma once
/// Small helpers of the io tests: write a text file into a scratch folder, check an error
/// message mentions the expected places.
#include "tests/support/test_paths.h"

#include <filesystem>
#include <fstream>
#include <string>

namespace bunraku::test {

inline std::filesystem::path writeText(const std::filesystem::path& file, const std::string& text)
{
    std::ofstream out(file, std::ios::binary);
    out << text;
    return file;
}

inline std::filesystem::path ioDataDir() { return sourceDir() / "tests" / "data" / "io"; }

} // namespace bunraku::test
