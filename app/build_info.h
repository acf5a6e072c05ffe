#pragma once
/// What both programs say about themselves: the project version, the commit they were built
/// from and the `--version` text. Plain C++ (no Qt), shared by `bunraku` and
/// `bunraku-workbench`; the commit comes from a file generated at every build
/// (cmake/BunrakuCommit.cmake).

#include <string>
#include <string_view>

namespace bunraku::app {

/// The project version (CMake's PROJECT_VERSION), e.g. "0.1.0".
std::string_view projectVersion();
/// The git commit the programs were built from (12 hex digits, "-dirty" appended when tracked
/// files differed from it), the -DBUNRAKU_COMMIT= given to CMake, or "unknown".
std::string_view buildCommit();
/// The commit's date (YYYY-MM-DD), empty when unknown.
std::string_view buildCommitDate();
/// The project's licence as an SPDX expression: "GPL-3.0-or-later".
std::string_view projectLicense();
/// The text `PROGRAM --version` prints, GNU style (help2man reads it): "PROGRAM VERSION" on the
/// first line, then the commit, the copyright and the licence with its warranty disclaimer.
std::string versionText(std::string_view program);

} // namespace bunraku::app
