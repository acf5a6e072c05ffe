#include "widgets/corpus_browser.h"

#include <catch2/catch.hpp>

#include <QSignalSpy>
#include <QTreeWidget>

using namespace bunraku;

namespace {

std::vector<widgets::BrowserEntry> entries()
{
    std::vector<widgets::BrowserEntry> list;
    int n = 0;
    for (const char* function : {"greeting", "serving-tea"})
        for (const char* emotion : {"none", "friendly", "hostile"})
            for (int k = 1; k <= 5; ++k)
                list.push_back({QStringLiteral("corpus/%1").arg(n++), function, emotion, k, {}, 100, false});
    list.push_back({QStringLiteral("live/designed"), {}, {}, 0, QStringLiteral("designed"), 106, true});
    return list;
}

} // namespace

TEST_CASE("the browser lists function x emotion x take and the derived takes", "[widgets][corpus_browser]")
{
    widgets::CorpusBrowser browser;
    browser.setEntries(entries());
    REQUIRE(browser.takeCount() == 31);
    REQUIRE(browser.tree()->topLevelItemCount() == 3); // greeting, serving-tea, derived
    REQUIRE(browser.tree()->topLevelItem(0)->childCount() == 3);
    REQUIRE(browser.tree()->topLevelItem(0)->child(1)->childCount() == 5);
}

TEST_CASE("choosing takes A and B emits their ids and marks them", "[widgets][corpus_browser]")
{
    widgets::CorpusBrowser browser;
    browser.setEntries(entries());
    QSignalSpy chosen(&browser, &widgets::CorpusBrowser::takeChosen);
    REQUIRE(browser.selectId(QStringLiteral("corpus/7")));
    emit browser.tree()->itemDoubleClicked(browser.tree()->currentItem(), 0);
    REQUIRE(chosen.count() == 1);
    REQUIRE(chosen[0][0].value<widgets::TakeSlot>() == widgets::TakeSlot::A);
    REQUIRE(chosen[0][1].toString() == QStringLiteral("corpus/7"));
    browser.setChosen(QStringLiteral("corpus/7"), QStringLiteral("live/designed"));
    REQUIRE(browser.tree()->currentItem()->text(2) == QStringLiteral("A"));
    REQUIRE(browser.selectId(QStringLiteral("live/designed")));
    REQUIRE(browser.tree()->currentItem()->text(2) == QStringLiteral("B"));
    REQUIRE_FALSE(browser.selectId(QStringLiteral("corpus/99")));
}
