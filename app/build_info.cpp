#include "app/build_info.h"

namespace bunraku::app {

std::string_view projectVersion() { return BUNRAKU_VERSION; }

std::string_view projectLicense() { return "GPL-3.0-or-later"; }

std::string versionText(std::string_view program)
{
    std::string text;
    text += program;
    text += ' ';
    text += projectVersion();
    text += "\ncommit ";
    text += buildCommit();
    if (!buildCommitDate().empty()) {
        text += " (";
        text += buildCommitDate();
        text += ')';
    }
    text += "\nCopyright (C) 2026 The Bunraku Motion Workbench authors.\n"
            "License GPL-3.0-or-later: GNU GPL version 3 or later <https://www.gnu.org/licenses/gpl.html>.\n"
            "This is free software: you are free to change and redistribute it.\n"
            "There is NO WARRANTY, to the extent permitted by law.";
    return text;
}

} // namespace bunraku::app
