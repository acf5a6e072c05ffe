// Video export of the 3D view from the real main window: MP4 frames and size checked by ffprobe,
// PNG sequences, cancel, missing or failing ffmpeg, and the dialog's remembered choices.
#include "tests/support/peer.h"
#include "tests/app/video_export_support.h"

using namespace bunraku;
using namespace bunraku::test::video;
using app::TakeSlot;
using app::VideoExportOptions;
using app::VideoFormat;

TEST_CASE("the planned export frames cover the range at the take's or a chosen rate", "[app][video]")
{
    const auto own = app::planFrames(5.0, 3, 9, 0.0);
    REQUIRE(own.times.size() == 7);
    REQUIRE(own.fps == 5.0);
    REQUIRE(own.times.front() == Approx(0.6));
    REQUIRE(own.times.back() == Approx(1.8));
    const auto resampled = app::planFrames(5.0, 0, 10, 12.0); // 2 s at 12 fps, both ends
    REQUIRE(resampled.times.size() == 25);
    REQUIRE(resampled.fps == 12.0);
    REQUIRE(resampled.times[1] == Approx(1.0 / 12.0));
    REQUIRE(resampled.times.back() == Approx(2.0));
    REQUIRE(app::planFrames(5.0, 0, 10, 7.0).times.size() == 15); // 2 s * 7 = 14 steps
    REQUIRE(app::planFrames(5.0, 4, 3, 0.0).times.empty());
}

TEST_CASE("an MP4 of the 3D view has the frames and size asked for, and the time is restored", "[app][video][ffmpeg]")
{
    if (!test::requirePeer(ffmpegInstalled(), "ffmpeg and ffprobe on PATH (MP4 export)", "apt-get install ffmpeg")) return;
    auto window = exportWindow(1.0);
    REQUIRE(window);
    const auto folder = test::scratchDir("video-mp4");
    const auto take = window->document().selectedTake(TakeSlot::A);

    SECTION("at a chosen size, drawn offscreen")
    {
        VideoExportOptions options;
        options.firstFrame = 3;
        options.lastFrame = 9;
        options.size = QSize(160, 96);
        options.output = QString::fromStdString((folder / "range.mp4").string());
        const auto result = window->exportViewVideo(options, [](int, int) { return true; });
        INFO(result.error.toStdString());
        REQUIRE(result.ok());
        REQUIRE(result.frames == 7);
        const auto probed = probe(folder / "range.mp4");
        REQUIRE(probed);
        REQUIRE(probed->frames == 7);
        REQUIRE(probed->width == 160);
        REQUIRE(probed->height == 96);
    }
    SECTION("at the view's size, resampled to a chosen rate")
    {
        VideoExportOptions options;
        options.firstFrame = 0;
        options.lastFrame = 2;
        options.fps = 2.0 * take->rateHz; // two video frames per take frame
        options.output = QString::fromStdString((folder / "view.mp4").string());
        REQUIRE(test::waitUntilIdle(*window)); // the view keeps its size during the export
        const auto result = window->exportViewVideo(options, [](int, int) { return true; });
        INFO(result.error.toStdString());
        REQUIRE(result.ok());
        auto* view = window->viewportPanel()->viewport();
        const QSize pixels = view->size() * view->devicePixelRatio();
        const auto probed = probe(folder / "view.mp4");
        REQUIRE(probed);
        REQUIRE(probed->frames == 5);
        REQUIRE(probed->width == (pixels.width() & ~1));
        REQUIRE(probed->height == (pixels.height() & ~1));
    }
    REQUIRE(fileCount(folder) == 1); // no temporary file left
    REQUIRE(window->document().currentTime() == Approx(1.0));
}

TEST_CASE("a PNG sequence of the 3D view has one image per planned frame", "[app][video]")
{
    auto window = exportWindow(0.0);
    REQUIRE(window);
    const auto folder = test::scratchDir("video-png");
    VideoExportOptions options;
    options.format = VideoFormat::PngSequence;
    options.firstFrame = 2;
    options.lastFrame = 6;
    options.size = QSize(64, 48);
    options.output = QString::fromStdString(folder.string());
    const auto result = window->exportViewVideo(options, [](int, int) { return true; });
    INFO(result.error.toStdString());
    REQUIRE(result.ok());
    REQUIRE(result.frames == 5);
    REQUIRE(fileCount(folder) == 6); // and the manifest of the files written
    const QImage first(QString::fromStdString((folder / "frame_00000.png").string()));
    const QImage last(QString::fromStdString((folder / "frame_00004.png").string()));
    REQUIRE(first.size() == QSize(64, 48));
    REQUIRE(first != last); // the puppet moved between frames 2 and 6
}

TEST_CASE("cancelling a video export leaves no file behind", "[app][video][ffmpeg]")
{
    auto window = exportWindow(0.5);
    REQUIRE(window);
    const auto folder = test::scratchDir("video-cancel");
    VideoExportOptions options;
    options.size = QSize(64, 48);
    options.lastFrame = 8;
    const auto cancelAtThree = [](int done, int) { return done < 3; };

    SECTION("a PNG sequence")
    {
        options.format = VideoFormat::PngSequence;
        options.output = QString::fromStdString((folder / "frames").string());
        const auto result = window->exportViewVideo(options, cancelAtThree);
        REQUIRE(result.cancelled);
        REQUIRE(fileCount(folder / "frames") == 0);
    }
    if (!test::requirePeer(ffmpegInstalled(), "ffmpeg and ffprobe on PATH (MP4 cancel)", "apt-get install ffmpeg")) return;
    SECTION("an MP4 through the callback")
    {
        options.output = QString::fromStdString((folder / "cancelled.mp4").string());
        const auto result = window->exportViewVideo(options, cancelAtThree);
        REQUIRE(result.cancelled);
        REQUIRE(result.error.isEmpty());
        REQUIRE(fileCount(folder) == 0);
    }
    SECTION("an MP4 through the progress dialog's Cancel button")
    {
        options.output = QString::fromStdString((folder / "cancelled.mp4").string());
        QTimer cancel;
        cancel.setInterval(0);
        QObject::connect(&cancel, &QTimer::timeout, [&window] {
            if (auto* dialog = window->findChild<QProgressDialog*>("videoExportProgress"); dialog && dialog->value() >= 2)
                dialog->cancel();
        });
        cancel.start();
        const auto result = window->exportViewVideo(options);
        REQUIRE(result.cancelled);
        REQUIRE(fileCount(folder) == 0);
    }
    REQUIRE(window->document().currentTime() == Approx(0.5));
}

TEST_CASE("an MP4 export without ffmpeg, or with a failing one, says why and writes nothing", "[app][video][ffmpeg]")
{
    auto window = exportWindow(0.0);
    REQUIRE(window);
    const auto folder = test::scratchDir("video-no-ffmpeg");
    const auto bin = test::scratchDir("video-fake-bin");
    VideoExportOptions options;
    options.size = QSize(64, 48);
    options.lastFrame = 3;
    options.output = QString::fromStdString((folder / "out.mp4").string());

    SECTION("ffmpeg missing")
    {
        app::VideoExportResult result;
        {
            const ScopedPath path(bin); // an empty folder: no ffmpeg
            result = window->exportViewVideo(options, [](int, int) { return true; });
        }
        REQUIRE_FALSE(result.ok());
        REQUIRE_FALSE(result.cancelled);
        REQUIRE(result.error.contains(QStringLiteral("ffmpeg")));
        REQUIRE(result.error.contains(QStringLiteral("apt-get install ffmpeg")));
    }
    SECTION("ffmpeg failing: its error output is shown")
    {
        const QString script = QString::fromStdString((bin / "ffmpeg").string());
        QFile file(script);
        REQUIRE(file.open(QIODevice::WriteOnly));
        file.write("#!/bin/sh\ncat > /dev/null\necho \"Unknown encoder 'libx264'\" >&2\nexit 1\n");
        file.close();
        file.setPermissions(QFileDevice::ReadOwner | QFileDevice::WriteOwner | QFileDevice::ExeOwner);
        app::VideoExportResult result;
        {
            const ScopedPath path(bin.string() + ":/usr/bin:/bin"); // the fake first, sh and cat after
            result = window->exportViewVideo(options, [](int, int) { return true; });
        }
        REQUIRE_FALSE(result.ok());
        REQUIRE(result.error.contains(QStringLiteral("exit code 1")));
        REQUIRE(result.error.contains(QStringLiteral("Unknown encoder 'libx264'")));
    }
    REQUIRE(fileCount(folder) == 0);
}

TEST_CASE("the video export dialog remembers the last choices", "[app][video]")
{
    auto window = exportWindow(0.0);
    REQUIRE(window);
    REQUIRE(window->findChild<QAction*>("exportViewVideoAction") != nullptr);
    const app::VideoExportLimits limits{20, 5.0, QSize(640, 480)};
    const auto folder = test::scratchDir("video-dialog");
    {
        app::VideoExportDialog dialog(limits, window.get());
        VideoExportOptions chosen;
        chosen.format = VideoFormat::Mp4;
        chosen.firstFrame = 4;
        chosen.lastFrame = 12;
        chosen.fps = 24.0;
        chosen.size = QSize(1280, 720);
        chosen.output = QString::fromStdString((folder / "take").string()); // no suffix yet
        dialog.setOptions(chosen);
        dialog.accept();
        REQUIRE(dialog.result() == QDialog::Accepted);
    }
    app::VideoExportDialog again(limits, window.get());
    const auto remembered = again.options();
    REQUIRE(remembered.format == VideoFormat::Mp4);
    REQUIRE(remembered.firstFrame == 4);
    REQUIRE(remembered.lastFrame == 12);
    REQUIRE(remembered.fps == Approx(24.0));
    REQUIRE(remembered.size == QSize(1280, 720));
    REQUIRE(remembered.output == QString::fromStdString((folder / "take.mp4").string()));

    VideoExportOptions whole; // the whole take at its own rate and the view's size
    whole.format = VideoFormat::PngSequence;
    whole.output = QString::fromStdString(folder.string());
    again.setOptions(whole);
    const auto shown = again.options();
    REQUIRE(shown.format == VideoFormat::PngSequence);
    REQUIRE(shown.lastFrame == -1);
    REQUIRE(shown.fps == 0.0);
    REQUIRE(shown.size.isEmpty());
    REQUIRE(shown.output == whole.output);
}

TEST_CASE("the video export dialog refuses MP4 and says how to install ffmpeg when it is missing", "[app][video]")
{
    test::isolateSettings();
    const auto bin = test::scratchDir("video-dialog-no-ffmpeg");
    const ScopedPath path(bin);
    app::VideoExportDialog dialog(app::VideoExportLimits{20, 5.0, QSize(640, 480)});
    VideoExportOptions mp4;
    mp4.output = QStringLiteral("/tmp/unused.mp4");
    dialog.setOptions(mp4);
    auto* exportButton = dialog.findChild<QDialogButtonBox*>()->button(QDialogButtonBox::Ok);
    REQUIRE_FALSE(exportButton->isEnabled());
    bool told = false;
    for (auto* label : dialog.findChildren<QLabel*>()) told = told || label->text().contains(QStringLiteral("apt-get install ffmpeg"));
    REQUIRE(told);
    VideoExportOptions png = mp4;
    png.format = VideoFormat::PngSequence;
    png.output = QStringLiteral("/tmp/unused-frames");
    dialog.setOptions(png);
    REQUIRE(exportButton->isEnabled()); // PNG needs no ffmpeg
}

TEST_CASE("File > Export 3D View Video exports what the dialog was given", "[app][video]")
{
    auto window = exportWindow(0.0);
    REQUIRE(window);
    const auto folder = test::scratchDir("video-menu");
    auto* action = window->findChild<QAction*>("exportViewVideoAction");
    REQUIRE(action != nullptr);
    bool answered = false;
    QTimer::singleShot(0, [&] { // the dialog runs its own event loop: fill it in from there
        auto* dialog = qobject_cast<app::VideoExportDialog*>(QApplication::activeModalWidget());
        if (dialog == nullptr) return;
        VideoExportOptions options;
        options.format = VideoFormat::PngSequence;
        options.firstFrame = 1;
        options.lastFrame = 3;
        options.size = QSize(48, 32);
        options.output = QString::fromStdString(folder.string());
        dialog->setOptions(options);
        dialog->accept();
        answered = true;
    });
    action->trigger();
    REQUIRE(answered);
    REQUIRE(fileCount(folder) == 4); // and the manifest
    REQUIRE(QImage(QString::fromStdString((folder / "frame_00002.png").string())).size() == QSize(48, 32));
}

