// The menu paths docs/TUTORIAL.md tells a reader to choose (**File > New Corpus from Files...**,
// **Help > User Guide**...) exist, word for word, in the running window's menus. The page's
// Blender section (its menus are Blender's) is left out: it starts at the heading naming Blender.
#include "app_test_support.h"

#include "tests/cli/cli_files.h"

#include <catch2/catch.hpp>

#include <QMenu>
#include <QMenuBar>

#include <regex>

using namespace bunraku;

namespace {

/// "&Export Take A..." as the reader sees it: "Export Take A...".
QString shownText(const QAction* action)
{
    QString text = action->text();
    text.remove(QLatin1Char('&'));
    return text;
}

/// True when `path` (["File", "Export Take A..."], or deeper through submenus) is a chain of
/// menu items from the menu bar's `actions`.
bool hasMenuPath(const QList<QAction*>& actions, const QStringList& path)
{
    if (path.isEmpty()) return true;
    for (const QAction* action : actions) {
        if (shownText(action) != path.front()) continue;
        if (path.size() == 1) return true;
        if (action->menu() && hasMenuPath(action->menu()->actions(), path.mid(1))) return true;
    }
    return false;
}

} // namespace

TEST_CASE("every menu path of the tutorial is in the workbench's menus", "[app][tutorial]")
{
    auto window = test::demoWindow();
    REQUIRE(window);
    QStringList menuTitles;
    for (const QAction* menu : window->menuBar()->actions()) menuTitles << shownText(menu);
    REQUIRE(menuTitles.contains(QStringLiteral("File")));

    std::string page = test::readTextFile(test::sourceDir() / "docs" / "TUTORIAL.md");
    const std::size_t blender = page.find("\n## 8. Open it in Blender");
    REQUIRE(blender != std::string::npos);
    page.resize(blender);

    // Bold text with " > " whose first step is one of the window's menus.
    const std::regex bold(R"(\*\*([^*]+ > [^*]+)\*\*)");
    int checked = 0;
    for (auto it = std::sregex_iterator(page.begin(), page.end(), bold); it != std::sregex_iterator(); ++it) {
        const QStringList path = QString::fromStdString((*it)[1].str()).split(QStringLiteral(" > "));
        if (!menuTitles.contains(path.front())) continue;
        INFO(path.join(QStringLiteral(" > ")).toStdString());
        CHECK(hasMenuPath(window->menuBar()->actions(), path));
        ++checked;
    }
    CHECK(checked >= 8); // New Corpus from Files, Open Corpus Folder, the exports, the report, the guide
}
