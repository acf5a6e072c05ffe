// The video export runs beside the event loop: the GUI thread renders a frame per turn of the
// loop while a worker encodes and writes, so timers, repaints and Cancel keep working; ffmpeg
// writes into a private folder of its own, and the finished file is moved into place.
#include "tests/support/peer.h"
#include "tests/app/video_export_support.h"

#include "app/video_export_job.h"

#include <sys/stat.h>

using namespace bunraku;
using namespace bunraku::test::video;
using app::VideoExportOptions;
using app::VideoFormat;

TEST_CASE("the event loop serves a timer during a long export", "[app][video]")
{
    auto window = exportWindow(0.0);
    REQUIRE(window);
    const auto folder = test::scratchDir("video-event-loop");
    VideoExportOptions options;
    options.format = VideoFormat::PngSequence;
    options.size = QSize(320, 240);
    options.firstFrame = 0;
    options.lastFrame = 59;
    options.output = QString::fromStdString((folder / "frames").string());
    int ticks = 0;
    QTimer timer;
    timer.setInterval(10);
    QObject::connect(&timer, &QTimer::timeout, [&ticks] { ++ticks; });
    timer.start();
    std::vector<int> ticksSeen;
    const auto result = window->exportViewVideo(options, [&](int, int) {
        ticksSeen.push_back(ticks);
        return true;
    });
    INFO(result.error.toStdString());
    REQUIRE(result.ok());
    REQUIRE(result.frames == 60);
    REQUIRE(ticksSeen.size() == 61);
    CHECK(ticksSeen.back() > ticksSeen.front()); // the timer fired between frames, during the export
    CHECK(fileCount(folder / "frames") == 61);  // 60 frames and the manifest
}

TEST_CASE("a job renders on the GUI thread and reports progress, results and cancel once", "[app][video]")
{
    test::isolateSettings();
    const auto folder = test::scratchDir("video-job");
    VideoExportOptions options;
    options.format = VideoFormat::PngSequence;
    options.output = QString::fromStdString((folder / "frames").string());
    const auto plan = app::planFrames(5.0, 0, 19, 0.0);
    const Qt::HANDLE gui = QThread::currentThreadId();
    bool renderedElsewhere = false;
    const app::FrameRenderer render = [&](double) -> analysis::Result<QImage> {
        renderedElsewhere = renderedElsewhere || QThread::currentThreadId() != gui;
        QImage image(48, 32, QImage::Format_RGB32);
        image.fill(Qt::darkGreen);
        return image;
    };
    app::VideoExportJob job(options, plan, render);
    int finished = 0;
    app::VideoExportResult result;
    QObject::connect(&job, &app::VideoExportJob::finished, [&](const app::VideoExportResult& r) {
        ++finished;
        result = r;
    });
    QObject::connect(&job, &app::VideoExportJob::progress, [&](int done, int) {
        if (done == 7) job.cancel();
    });
    job.start();
    REQUIRE(job.running());
    REQUIRE(QTest::qWaitFor([&] { return finished == 1; }, 20000));
    CHECK_FALSE(renderedElsewhere);
    CHECK(result.cancelled);
    CHECK_FALSE(std::filesystem::exists(folder / "frames"));
    CHECK(allEntries(folder).isEmpty()); // the staging folder is gone too
    QTest::qWait(20);
    CHECK(finished == 1);
}

TEST_CASE("ffmpeg writes into a private folder of its own, moved into place when it succeeds", "[app][video][ffmpeg]")
{
    if (!test::requirePeer(ffmpegInstalled(), "ffmpeg and ffprobe on PATH (MP4 export)", "apt-get install ffmpeg")) return;
    auto window = exportWindow(0.0);
    REQUIRE(window);
    const auto folder = test::scratchDir("video-mp4-private");
    VideoExportOptions options;
    options.size = QSize(64, 48);
    options.lastFrame = 9;
    options.output = QString::fromStdString((folder / "take.mp4").string());
    QStringList during;
    mode_t mode = 0;
    const auto result = window->exportViewVideo(options, [&](int done, int) {
        if (done == 5) {
            during = allEntries(folder);
            struct stat info {};
            if (!during.isEmpty() && ::stat((folder / during.front().toStdString()).c_str(), &info) == 0) mode = info.st_mode;
        }
        return true;
    });
    INFO(result.error.toStdString());
    REQUIRE(result.ok());
    REQUIRE(during.size() == 1); // nothing under the output's name while it is being written
    CHECK(during.front().startsWith(QStringLiteral(".take.mp4.bunraku-tmp-")));
    CHECK(S_ISDIR(mode));
    CHECK((mode & 0777) == 0700);
    CHECK(allEntries(folder) == QStringList{QStringLiteral("take.mp4")});
    const auto probed = probe(folder / "take.mp4");
    REQUIRE(probed);
    CHECK(probed->frames == 10);
}
