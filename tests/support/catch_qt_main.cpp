// Catch2 main for Qt tests: a QApplication exists while tests run, but not while ctest lists
// the cases at build time (no display is needed to list them). The skip summary follows the run
// (tests/support/peer.h).
#define CATCH_CONFIG_RUNNER
#include <catch2/catch.hpp>

#include "tests/support/peer.h"

#include <QApplication>

int main(int argc, char** argv)
{
    Catch::Session session;
    if (const int rc = session.applyCommandLine(argc, argv); rc != 0) return rc;
    const auto& config = session.configData();
    if (config.listTests || config.listTestNamesOnly || config.listTags || config.listReporters)
        return session.run();
    QApplication app(argc, argv);
    const int failed = session.run();
    bunraku::test::printSkipSummary();
    return failed;
}
