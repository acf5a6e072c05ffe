// Catch2 main of the tests without Qt: runs the cases, then prints the skip summary
// (tests/support/peer.h).
#define CATCH_CONFIG_RUNNER
#include <catch2/catch.hpp>

#include "tests/support/peer.h"

int main(int argc, char** argv)
{
    const int failed = Catch::Session().run(argc, argv);
    bunraku::test::printSkipSummary();
    return failed;
}
