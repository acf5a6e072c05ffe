#include "tests/support/peer.h"

#include <catch2/catch.hpp>

#include <cstdlib>
#include <iostream>
#include <string_view>
#include <vector>

namespace bunraku::test {
namespace {

std::vector<std::string>& skips()
{
    static std::vector<std::string> recorded;
    return recorded;
}

} // namespace

bool runningInCi()
{
    const char* ci = std::getenv("CI");
    return ci != nullptr && (std::string_view(ci) == "true" || std::string_view(ci) == "1");
}

bool requirePeer(bool available, const std::string& what, const std::string& howToGet)
{
    if (available) return true;
    if (runningInCi()) FAIL("missing peer (CI=true): " << what << "; " << howToGet);
    const std::string test = Catch::getResultCapture().getCurrentTestName();
    skips().push_back(test + ": " + what);
    std::cout << kSkipMarker << " " << test << ": " << what << " is missing (" << howToGet << ")" << std::endl;
    return false;
}

int skippedCount() { return int(skips().size()); }

void printSkipSummary()
{
    if (skips().empty()) return;
    std::cout << skips().size() << (skips().size() == 1 ? " test case" : " test cases") << " skipped, not passed:" << std::endl;
    for (const std::string& skip : skips()) std::cout << "  " << skip << std::endl;
}

} // namespace bunraku::test
