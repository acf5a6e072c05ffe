// The thesis's multimodal display as a video (chapter 6): the arrangements, the moving cursor
// and the puppet region checked on pixels, the export from the main window (PNG, MP4, cancel)
// and `bunraku render --multimodal` against the plain render of the same frame.
#include "tests/app/video_export_support.h"
#include "tests/support/peer.h"

#include "app/multimodal_export.h"
#include "app/multimodal_export_controller.h"
#include "app/multimodal_export_dialog.h"
#include "app/offscreen_view.h"

#include "analysis/io/staged_folder.h"

#include "analysis/synth/demo_corpus.h"
#include "widgets/graph_panel.h"

#include <nlohmann/json.hpp>

#include <QComboBox>
#include <QImage>
#include <QLineEdit>
#include <QSpinBox>

#include <cstdlib>
#include <fstream>
#include <sstream>

using namespace bunraku;
using namespace bunraku::test::video;
using app::MultimodalFrame;
using app::MultimodalOptions;
using widgets::GraphLayout;

namespace {

std::shared_ptr<const analysis::Take> demoTake(const std::string& function, const std::string& emotion, int k)
{
    static const analysis::synth::DemoCorpus demo = analysis::synth::generateDemoCorpus();
    const analysis::Take* take = demo.corpus.find(function, emotion, k);
    REQUIRE(take != nullptr);
    return std::make_shared<const analysis::Take>(*take);
}

/// The column of `plot` holding the most pixels of the cursor's colour, -1 when none does.
int cursorColumnIn(const QImage& image, const QRect& plot, QColor cursor = app::MultimodalColours{}.cursor)
{
    int best = -1, bestCount = 0;
    for (int x = plot.left(); x <= plot.right(); ++x) {
        int count = 0;
        for (int y = plot.top(); y <= plot.bottom(); ++y) count += image.pixelColor(x, y) == cursor ? 1 : 0;
        if (count > bestCount) {
            best = x;
            bestCount = count;
        }
    }
    return bestCount >= plot.height() / 2 ? best : -1;
}

bool inside(const QRect& outer, const QRect& inner) { return outer.contains(inner); }

/// Largest channel difference between `image`'s region `rect` and `other` (same size as rect).
int largestDifference(const QImage& image, const QRect& rect, const QImage& other)
{
    int worst = 0;
    for (int y = 0; y < rect.height(); ++y)
        for (int x = 0; x < rect.width(); ++x) {
            const QColor a = image.pixelColor(rect.left() + x, rect.top() + y), b = other.pixelColor(x, y);
            worst = std::max({worst, std::abs(a.red() - b.red()), std::abs(a.green() - b.green()), std::abs(a.blue() - b.blue())});
        }
    return worst;
}

} // namespace

TEST_CASE("the multimodal arrangements follow the thesis for one take and for two", "[app][multimodal]")
{
    const auto take = demoTake("greeting", "none", 1);
    MultimodalOptions options;
    options.size = QSize(1920, 1080);
    const QRect frame(QPoint(0, 0), options.size);

    SECTION("one take, 24 graphs: two columns of 12 at the edges, the puppet between them")
    {
        const auto g = app::multimodalGeometry(take->channels, false, options);
        REQUIRE(g.graphs.size() == 24);
        CHECK(g.view == QRect(480, 0, 960, 1080));
        for (std::size_t i = 0; i < 24; ++i) {
            CHECK(inside(frame, g.graphs[i]));
            CHECK(inside(g.graphs[i], g.plots[i]));
            CHECK_FALSE(g.graphs[i].intersects(g.view));
            CHECK((g.cells[i].column == 0 ? g.graphs[i].right() < 480 : g.graphs[i].left() >= 1440));
        }
        CHECK(g.graphs[0].top() == 0);
        CHECK(g.graphs[11].bottom() == 1079);
    }
    SECTION("one take, one part's 6 or one DOF's 4: the right half")
    {
        for (auto [layout, count] : {std::pair{GraphLayout::OnePart, 6}, std::pair{GraphLayout::OneDof, 4}}) {
            options.layout = layout;
            const auto g = app::multimodalGeometry(take->channels, false, options);
            REQUIRE(int(g.graphs.size()) == count);
            CHECK(g.view == QRect(0, 0, 960, 1080));
            for (const QRect& graph : g.graphs) CHECK(graph.left() >= 960);
        }
    }
    SECTION("one take, a single graph: along the bottom")
    {
        options.layout = GraphLayout::Single;
        const auto g = app::multimodalGeometry(take->channels, false, options);
        REQUIRE(g.graphs.size() == 1);
        CHECK(g.graphs[0].top() == g.view.bottom() + 1);
        CHECK(g.graphs[0].width() == 1920);
    }
    SECTION("two takes: 48 / 12 / 8 / 2 graphs stacked under the puppets, each take under its own")
    {
        for (auto [layout, count, rows] : {std::tuple{GraphLayout::AllChannels, 48, 12}, std::tuple{GraphLayout::OnePart, 12, 6},
                                           std::tuple{GraphLayout::OneDof, 8, 4}, std::tuple{GraphLayout::Single, 2, 1}}) {
            options.layout = layout;
            const auto g = app::multimodalGeometry(take->channels, true, options);
            REQUIRE(int(g.graphs.size()) == count);
            CHECK(g.view.top() == 0);
            CHECK(g.view.width() == 1920);
            int maxRow = 0;
            for (std::size_t i = 0; i < g.graphs.size(); ++i) {
                CHECK(g.graphs[i].top() > g.view.bottom());
                CHECK(inside(frame, g.graphs[i]));
                const bool isB = g.cells[i].takes == widgets::GraphTakes::OnlyB;
                CHECK((isB ? g.graphs[i].left() >= 960 : g.graphs[i].right() < 960));
                maxRow = std::max(maxRow, g.cells[i].row);
                for (std::size_t j = i + 1; j < g.graphs.size(); ++j) CHECK_FALSE(g.graphs[i].intersects(g.graphs[j]));
            }
            CHECK(maxRow + 1 == rows);
        }
    }
    SECTION("too small a frame has no arrangement")
    {
        options.size = QSize(40, 40);
        CHECK(app::multimodalGeometry(take->channels, false, options).graphs.empty());
        CHECK_FALSE(MultimodalFrame::create(take, nullptr, options).ok());
    }
}

TEST_CASE("thesis ticks are every 10 units and every 2 s, automatic ticks round", "[app][multimodal]")
{
    const auto values = app::graphTicks(-23.0, 41.0, 10.0);
    CHECK(values == std::vector<double>{-20, -10, 0, 10, 20, 30, 40});
    const auto times = app::graphTicks(0.0, 21.0, 2.0);
    REQUIRE(times.size() == 11);
    CHECK(times.back() == 20.0);
    const auto automatic = app::graphTicks(0.0, 0.9, 0.0, 4);
    REQUIRE(automatic.size() == 5);
    for (std::size_t i = 0; i < automatic.size(); ++i) CHECK(automatic[i] == Approx(0.2 * double(i)).margin(1e-12));
    CHECK(app::graphTicks(-0.5, 0.5, 0.0, 4).at(2) == 0.0);
    CHECK(app::graphTicks(1.0, 1.0, 10.0).empty());
    // A graph whose range holds fewer than two thesis ticks (a head moving 5 cm, or -3..2 cm)
    // keeps two value labels: round ticks instead.
    CHECK(app::valueAxisTicks(-23.0, 41.0, true) == values);
    CHECK(app::graphTicks(-3.2, 2.1, 10.0).size() == 1);
    const auto small = app::valueAxisTicks(-3.2, 2.1, true);
    CHECK(small == std::vector<double>{-2, 0, 2});
    CHECK(app::valueAxisTicks(141.0, 144.0, true).size() >= 2); // no multiple of 10 at all
    CHECK(app::valueAxisTicks(-3.2, 2.1, false) == small);
}

TEST_CASE("the multimodal cursor's column moves with the frame", "[app][multimodal][pixels]")
{
    const auto takeA = demoTake("serving-tea", "none", 2);
    const auto takeB = demoTake("serving-tea", "hostile", 2);
    for (bool two : {false, true}) {
        MultimodalOptions options;
        options.size = QSize(960, 540);
        options.layout = two ? GraphLayout::OnePart : GraphLayout::AllChannels;
        auto frame = MultimodalFrame::create(takeA, two ? takeB : nullptr, options);
        REQUIRE(frame.ok());
        QImage view(frame->geometry().view.size(), QImage::Format_ARGB32);
        view.fill(QColor(40, 60, 80));
        std::vector<int> columns;
        for (int f : {0, 20, 52, 90, int(takeA->frameCount()) - 1}) {
            const double seconds = f / takeA->rateHz;
            const QImage image = frame->compose(view, seconds);
            REQUIRE(image.size() == options.size);
            for (std::size_t g = 0; g < frame->geometry().plots.size(); ++g) {
                const QRect& plot = frame->geometry().plots[g];
                const int column = cursorColumnIn(image, plot);
                INFO("two takes " << two << ", frame " << f << ", graph " << g);
                CHECK(column == frame->cursorColumn(plot, seconds));
                // where the time axis puts it: 0 at the left edge, the duration at the right
                CHECK(column == plot.left() + int(std::lround(seconds / frame->duration() * (plot.width() - 1))));
                if (g == 0) columns.push_back(column);
            }
            // the view is untouched by the graphs
            CHECK(image.copy(frame->geometry().view) == view.convertToFormat(QImage::Format_RGB32));
        }
        for (std::size_t i = 1; i < columns.size(); ++i) CHECK(columns[i] > columns[i - 1]);
    }
}

TEST_CASE("the puppet region of a multimodal frame is the plain render of the same frame", "[app][multimodal][pixels]")
{
    const auto take = demoTake("greeting", "friendly", 3);
    MultimodalOptions options;
    options.size = QSize(800, 450);
    options.layout = GraphLayout::OnePart;
    auto frame = MultimodalFrame::create(take, nullptr, options);
    REQUIRE(frame.ok());
    const QSize viewSize = frame->geometry().view.size();
    render::SceneVisibility visibility;
    auto composer = app::OffscreenView::create({*take}, std::nullopt, visibility, viewSize);
    auto plain = app::OffscreenView::create({*take}, std::nullopt, visibility, viewSize);
    if (!composer.ok() || !plain.ok()) {
        FAIL("no OpenGL 3.3 context for the offscreen view: " << (composer.ok() ? plain.error().message : composer.error().message));
    }
    const app::ViewImage draw = [&composer](double seconds, QSize) -> analysis::Result<QImage> { return (*composer)->render(seconds); };
    for (int f : {0, 37, 80}) {
        const double seconds = f / take->rateHz;
        auto image = frame->render(draw, seconds);
        REQUIRE(image.ok());
        const QImage reference = (*plain)->render(seconds);
        REQUIRE(reference.size() == viewSize);
        INFO("frame " << f);
        CHECK(largestDifference(*image, frame->geometry().view, reference) <= 2);
    }
    // and a different frame differs: the region shows the pose of its own time
    auto later = frame->render(draw, 60 / take->rateHz);
    REQUIRE(later.ok());
    CHECK(largestDifference(*later, frame->geometry().view, (*plain)->render(0.0)) > 30);
}

TEST_CASE("File > Export Multimodal Video writes PNG frames, cancels without a trace and makes MP4s", "[app][multimodal]")
{
    auto window = exportWindow(0.0);
    REQUIRE(window);
    window->document().selectTake(app::TakeSlot::B, app::TakeId::corpus(8));
    auto& controller = window->multimodalExport();
    REQUIRE(controller.action()->objectName() == "exportMultimodalVideo");
    // the graph dock's choices are the default layout
    window->graphPanel()->setGraphLayout(GraphLayout::OneDof);
    window->graphPanel()->setThesisTicks(true);
    MultimodalOptions layout = controller.graphDockLayout(QSize(480, 320));
    CHECK(layout.layout == GraphLayout::OneDof);
    CHECK(layout.thesisTicks);
    const auto folder = test::scratchDir("multimodal-png");
    app::VideoExportOptions options;
    options.format = app::VideoFormat::PngSequence;
    options.firstFrame = 10;
    options.lastFrame = 14;
    options.output = QString::fromStdString((folder / "frames").string());

    SECTION("PNG frames: one per planned frame, at the asked size, the cursor moving")
    {
        const auto result = controller.exportVideo(layout, options, [](int, int) { return true; });
        INFO(result.error.toStdString());
        REQUIRE(result.ok());
        REQUIRE(result.frames == 5);
        const auto frames = app::existingFrames(options.output);
        REQUIRE(frames.size() == 5);
        auto made = MultimodalFrame::create(window->document().selectedTake(app::TakeSlot::A),
                                            window->document().selectedTake(app::TakeSlot::B), layout);
        REQUIRE(made.ok());
        REQUIRE(made->geometry().graphs.size() == 8); // one DOF of 4 parts, for A and B
        int previous = -1;
        for (int i = 0; i < 5; ++i) {
            const QImage image(QDir(options.output).filePath(frames[i]));
            REQUIRE(image.size() == QSize(480, 320));
            const QRect plot = made->geometry().plots[0];
            const int column = cursorColumnIn(image, plot);
            CHECK(column == made->cursorColumn(plot, (10 + i) / window->document().selectedTake(app::TakeSlot::A)->rateHz));
            CHECK(column > previous);
            previous = column;
        }
        // The five frames and the list of what was written (analysis/io/staged_folder.h), no
        // staging folder left.
        auto entries = allEntries(folder / "frames");
        CHECK(entries.size() == 6);
        CHECK(entries.contains(QString::fromLatin1(analysis::io::kWrittenFilesManifest)));
    }
    SECTION("cancelled half way: nothing is left")
    {
        const auto result = controller.exportVideo(layout, options, [](int done, int) { return done < 3; });
        CHECK(result.cancelled);
        CHECK(result.frames == 0);
        CHECK_FALSE(QDir(options.output).exists());
        CHECK(allEntries(folder).isEmpty());
    }
    SECTION("MP4: the frames and size asked for")
    {
        if (!bunraku::test::requirePeer(ffmpegInstalled(), "ffmpeg and ffprobe (the multimodal MP4 export)", "apt-get install ffmpeg"))
            return;
        options.format = app::VideoFormat::Mp4;
        options.output = QString::fromStdString((folder / "multimodal.mp4").string());
        options.fps = 10.0; // two video frames per take frame
        const auto result = controller.exportVideo(layout, options, [](int, int) { return true; });
        INFO(result.error.toStdString());
        REQUIRE(result.ok());
        const auto probed = probe(folder / "multimodal.mp4");
        REQUIRE(probed);
        CHECK(probed->frames == 9);
        CHECK(probed->width == 480);
        CHECK(probed->height == 320);
        CHECK(fileCount(folder) == 1);
    }
    SECTION("a range outside take A is refused before anything is written")
    {
        options.lastFrame = 100000;
        const auto result = controller.exportVideo(layout, options, [](int, int) { return true; });
        CHECK_FALSE(result.ok());
        CHECK(result.error.contains("take A has frames 0 to"));
        CHECK(allEntries(folder).isEmpty());
    }
}

TEST_CASE("bunraku render --multimodal: the view region is the plain render, the cursor where the frame is",
          "[app][multimodal][cli]")
{
    const auto folder = test::scratchDir("multimodal-cli");
    const std::string cli = BUNRAKU_CLI;
    const auto run = [&](const std::string& arguments, const std::string& out) {
        const std::string command =
            "'" + cli + "' " + arguments + " > '" + (folder / out).string() + "' 2> '" + (folder / (out + ".err")).string() + "'";
        return std::system(command.c_str());
    };
    const std::string take = "demo:serving-tea/friendly/2";
    REQUIRE(run("render " + take + " --multimodal --graphs part --part arm --frame 40 --size 800x450 --samples 0 -o '" +
                    (folder / "multimodal.png").string() + "' --json",
                "multimodal.json") == 0);
    std::ifstream in(folder / "multimodal.json");
    std::stringstream text;
    text << in.rdbuf();
    const auto summary = nlohmann::json::parse(text.str());
    const auto view = summary["view"];
    REQUIRE(view.size() == 4);
    const QRect viewRect(view[0].get<int>(), view[1].get<int>(), view[2].get<int>(), view[3].get<int>());
    REQUIRE(summary["graphs"].size() == 6);
    CHECK(summary["graphs"][0]["part"] == "arm");
    CHECK(summary["thesis_ticks"] == true);
    const std::string size = std::to_string(viewRect.width()) + "x" + std::to_string(viewRect.height());
    REQUIRE(run("render " + take + " --frame 40 --size " + size + " --samples 0 -o '" + (folder / "plain.png").string() + "'",
                "plain.txt") == 0);
    const QImage composed(QString::fromStdString((folder / "multimodal.png").string()));
    const QImage plain(QString::fromStdString((folder / "plain.png").string()));
    REQUIRE(composed.size() == QSize(800, 450));
    REQUIRE(plain.size() == viewRect.size());
    CHECK(largestDifference(composed, viewRect, plain) == 0);
    const auto& plot = summary["graphs"][0]["plot"];
    const QRect plotRect(plot[0].get<int>(), plot[1].get<int>(), plot[2].get<int>(), plot[3].get<int>());
    const double duration = summary["duration_s"].get<double>();
    CHECK(cursorColumnIn(composed, plotRect) == plotRect.left() + int(std::lround(8.0 / duration * (plotRect.width() - 1))));

    // a sequence of PNG frames through the video export (atomic), and a refused --mp4
    REQUIRE(run("render " + take + " --multimodal --frames 0:3 --size 320x240 --samples 0 -o '" + (folder / "seq").string() + "'",
                "seq.txt") == 0);
    CHECK(app::existingFrames(QString::fromStdString((folder / "seq").string())).size() == 4);
    CHECK(run("render " + take + " --multimodal --frames 0:3 --size 320x240 -o '" + (folder / "seq").string() + "'", "again.txt") != 0);
    CHECK(run("render " + take + " --multimodal --frames 0:3 --mp4 x.mp4 -o '" + (folder / "seq2").string() + "'", "mp4.txt") != 0);
}

TEST_CASE("File > Export Multimodal Video exports what the dialog was given", "[app][multimodal]")
{
    auto window = exportWindow(0.0);
    REQUIRE(window);
    window->graphPanel()->setGraphLayout(GraphLayout::Single);
    const auto folder = test::scratchDir("multimodal-menu");
    QAction* action = nullptr;
    for (auto* candidate : window->findChildren<QAction*>())
        if (candidate->objectName() == "exportMultimodalVideo") action = candidate;
    REQUIRE(action != nullptr);
    bool answered = false;
    QTimer::singleShot(0, [&] { // the dialog runs its own event loop: fill it in from there
        auto* dialog = qobject_cast<app::MultimodalExportDialog*>(QApplication::activeModalWidget());
        if (dialog == nullptr) return;
        // it starts from the graph dock's layout
        auto* layout = dialog->findChild<QComboBox*>("layout");
        REQUIRE(layout);
        CHECK(widgets::GraphLayout(layout->currentData().toInt()) == GraphLayout::Single);
        layout->setCurrentIndex(layout->findData(int(GraphLayout::OneDof)));
        auto* format = dialog->findChild<QComboBox*>("format");
        format->setCurrentIndex(format->findData(int(app::VideoFormat::PngSequence)));
        dialog->findChild<QSpinBox*>("firstFrame")->setValue(2);
        dialog->findChild<QSpinBox*>("lastFrame")->setValue(4);
        auto* size = dialog->findChild<QComboBox*>("size");
        size->setCurrentIndex(size->findData(QSize(1280, 720)));
        dialog->findChild<QLineEdit*>("output")->setText(QString::fromStdString((folder / "frames").string()));
        const app::MultimodalExportChoice choice = dialog->choice();
        CHECK(choice.layout.layout == GraphLayout::OneDof);
        CHECK(choice.video.firstFrame == 2);
        CHECK(choice.video.lastFrame == 4);
        dialog->accept();
        answered = true;
    });
    action->trigger();
    REQUIRE(answered);
    const auto frames = app::existingFrames(QString::fromStdString((folder / "frames").string()));
    REQUIRE(frames.size() == 3);
    CHECK(QImage(QDir(QString::fromStdString((folder / "frames").string())).filePath(frames[2])).size() == QSize(1280, 720));
}
