// Video export of the 3D view never loses the user's files: earlier frames and videos survive
// refused, failed and cancelled exports; errors name the take frame and the cause.
#include "tests/support/peer.h"
#include "tests/app/video_export_support.h"

using namespace bunraku;
using namespace bunraku::test::video;
using app::TakeSlot;
using app::VideoExportOptions;
using app::VideoFormat;

TEST_CASE("a PNG export never deletes or mixes with the frames of an earlier export", "[app][video]")
{
    auto window = exportWindow(0.0);
    REQUIRE(window);
    const auto folder = test::scratchDir("video-png-old-frames");
    writeOldFrames(folder, 10);
    VideoExportOptions options;
    options.format = VideoFormat::PngSequence;
    options.size = QSize(64, 48);
    options.firstFrame = 4;
    options.lastFrame = 6; // 3 frames
    options.output = QString::fromStdString(folder.string());
    const auto always = [](int, int) { return true; };

    SECTION("without overwrite the export is refused and the old frames stay")
    {
        const auto result = window->exportViewVideo(options, always);
        REQUIRE_FALSE(result.ok());
        REQUIRE_FALSE(result.cancelled);
        INFO(result.error.toStdString());
        REQUIRE(result.error.contains(QStringLiteral("already holds 10 frames")));
        REQUIRE(allEntries(folder).size() == 11); // with the manifest of the earlier export
        REQUIRE(oldFramesIntact(folder, 10));
    }
    SECTION("cancelled after 3 frames with overwrite, the old frames stay and nothing new remains")
    {
        options.overwrite = true;
        options.lastFrame = 12;
        const auto result = window->exportViewVideo(options, [](int done, int) { return done < 3; });
        REQUIRE(result.cancelled);
        REQUIRE(allEntries(folder).size() == 11); // no staging folder either
        REQUIRE(oldFramesIntact(folder, 10));
        REQUIRE(allEntries(folder.parent_path()).filter(QStringLiteral(".video-png-old-frames.bunraku-tmp")).isEmpty());
    }
    SECTION("a shorter export with overwrite leaves exactly its own frames")
    {
        options.overwrite = true;
        const auto result = window->exportViewVideo(options, always);
        INFO(result.error.toStdString());
        REQUIRE(result.ok());
        REQUIRE(result.frames == 3);
        REQUIRE(allEntries(folder) == QStringList{".bunraku-files.json", "frame_00000.png", "frame_00001.png", "frame_00002.png"});
        for (const QString& name : app::existingFrames(options.output))
            REQUIRE(QImage(QDir(options.output).filePath(name)).size() == QSize(64, 48)); // new images, not the old text
    }
}

TEST_CASE("a PNG export never replaces a folder holding the user's files, even when allowed to replace frames",
          "[app][video]")
{
    auto window = exportWindow(0.0);
    REQUIRE(window);
    const auto folder = test::scratchDir("video-png-user-files");
    writeOldFrames(folder, 3);
    {
        QFile notes(QString::fromStdString((folder / "notes.txt").string()));
        REQUIRE(notes.open(QIODevice::WriteOnly));
        notes.write("my notes");
    }
    VideoExportOptions options;
    options.format = VideoFormat::PngSequence;
    options.size = QSize(32, 24);
    options.lastFrame = 4;
    options.overwrite = true;
    options.output = QString::fromStdString(folder.string());
    const auto result = window->exportViewVideo(options, [](int, int) { return true; });
    REQUIRE_FALSE(result.ok());
    INFO(result.error.toStdString());
    REQUIRE(result.error.contains(QStringLiteral("notes.txt")));
    REQUIRE(oldFramesIntact(folder, 3));
    REQUIRE(allEntries(folder).size() == 5);
}

TEST_CASE("a failed PNG export names the take frame and removes only what it wrote", "[app][video]")
{
    const auto folder = test::scratchDir("video-png-no-image");
    writeOldFrames(folder, 2);
    VideoExportOptions options;
    options.format = VideoFormat::PngSequence;
    options.output = QString::fromStdString(folder.string());
    options.overwrite = true;
    const auto plan = app::planFrames(5.0, 5, 9, 0.0); // take frames 5..9
    int calls = 0;
    const app::FrameRenderer render = [&calls](double) -> analysis::Result<QImage> {
        if (++calls == 3) return analysis::makeError(analysis::ErrorCode::Io, "the view went away");
        QImage image(32, 24, QImage::Format_RGB32);
        image.fill(Qt::darkCyan);
        return image;
    };
    const auto result = app::exportFrames(options, plan, render);
    INFO(result.error.toStdString());
    REQUIRE_FALSE(result.ok());
    REQUIRE(result.error.contains(QStringLiteral("take A frame 7"))); // the third planned frame
    REQUIRE(result.error.contains(QStringLiteral("1.400 s")));
    REQUIRE(result.error.contains(QStringLiteral("the view went away")));
    REQUIRE(allEntries(folder).size() == 3);
    REQUIRE(oldFramesIntact(folder, 2));
}

TEST_CASE("hiding the 3D view during an export at its size stops with the cause", "[app][video]")
{
    auto window = exportWindow(0.0);
    REQUIRE(window);
    const auto folder = test::scratchDir("video-view-hidden");
    VideoExportOptions options;
    options.format = VideoFormat::PngSequence;
    options.firstFrame = 10;
    options.lastFrame = 15;
    options.output = QString::fromStdString((folder / "frames").string());
    auto* viewDock = window->dock("viewDock");
    REQUIRE(viewDock != nullptr);
    const auto result = window->exportViewVideo(options, [viewDock](int done, int) {
        if (done == 2) viewDock->hide(); // before the third frame (take frame 12)
        return true;
    });
    INFO(result.error.toStdString());
    REQUIRE_FALSE(result.ok());
    REQUIRE(result.error.contains(QStringLiteral("take A frame 12")));
    REQUIRE(result.error.contains(QStringLiteral("no longer shown")));
    REQUIRE(allEntries(folder).isEmpty()); // the folder it made is gone again
}

TEST_CASE("a cancelled MP4 export leaves an existing MP4 of the same name untouched", "[app][video][ffmpeg]")
{
    if (!test::requirePeer(ffmpegInstalled(), "ffmpeg and ffprobe on PATH (MP4 cancel)", "apt-get install ffmpeg")) return;
    auto window = exportWindow(0.0);
    REQUIRE(window);
    const auto folder = test::scratchDir("video-mp4-existing");
    const QString output = QString::fromStdString((folder / "take.mp4").string());
    {
        QFile earlier(output);
        REQUIRE(earlier.open(QIODevice::WriteOnly));
        earlier.write("an earlier video");
    }
    VideoExportOptions options;
    options.size = QSize(64, 48);
    options.lastFrame = 8;
    options.output = output;
    const auto result = window->exportViewVideo(options, [](int done, int) { return done < 3; });
    REQUIRE(result.cancelled);
    REQUIRE(allEntries(folder) == QStringList{"take.mp4"});
    QFile earlier(output);
    REQUIRE(earlier.open(QIODevice::ReadOnly));
    REQUIRE(earlier.readAll() == QByteArray("an earlier video"));
}

TEST_CASE("exporting the whole take gives take A's frames even when take B is longer", "[app][video]")
{
    auto window = exportWindow(0.0);
    REQUIRE(window);
    auto& document = window->document();
    const auto full = document.take(app::TakeId::corpus(2));
    REQUIRE(full);
    REQUIRE(full->frameCount() > 12);
    auto shorter = std::make_shared<analysis::Take>(*full);
    shorter->values = full->values.topRows(12).eval();
    document.setLiveTake(QStringLiteral("short"), QStringLiteral("first 12 frames"), shorter);
    document.selectTake(TakeSlot::A, app::TakeId::live(QStringLiteral("short")));
    document.selectTake(TakeSlot::B, app::TakeId::corpus(2));
    REQUIRE(document.selectedTake(TakeSlot::A)->frameCount() == 12);
    REQUIRE(document.duration() > document.selectedTake(TakeSlot::A)->duration()); // B is the longer one

    const auto folder = test::scratchDir("video-whole-take-a");
    VideoExportOptions options;
    options.format = VideoFormat::PngSequence;
    options.size = QSize(32, 24);
    options.output = QString::fromStdString(folder.string());
    const auto result = window->exportViewVideo(options, [](int, int) { return true; });
    INFO(result.error.toStdString());
    REQUIRE(result.ok());
    REQUIRE(result.frames == 12);
    REQUIRE(fileCount(folder) == 13); // and the manifest

    VideoExportOptions beyond = options; // a frame of B past A's end is refused, naming A's range
    beyond.output = QString::fromStdString((folder / "beyond").string());
    beyond.firstFrame = 0;
    beyond.lastFrame = 12;
    const auto refused = window->exportViewVideo(beyond, [](int, int) { return true; });
    REQUIRE_FALSE(refused.ok());
    REQUIRE(refused.error.contains(QStringLiteral("take A has frames 0 to 11")));
}

TEST_CASE("the video export dialog asks before replacing the frames of a folder", "[app][video]")
{
    test::isolateSettings();
    const auto folder = test::scratchDir("video-dialog-replace");
    writeOldFrames(folder, 4);
    app::VideoExportDialog dialog(app::VideoExportLimits{20, 5.0, QSize(640, 480)});
    VideoExportOptions png;
    png.format = VideoFormat::PngSequence;
    png.output = QString::fromStdString(folder.string());
    dialog.setOptions(png);

    const auto answer = [](QMessageBox::StandardButton button, QString* asked) {
        QTimer::singleShot(0, [button, asked] { // the question runs its own event loop
            auto* box = qobject_cast<QMessageBox*>(QApplication::activeModalWidget());
            if (box == nullptr || box->objectName() != QStringLiteral("replaceFramesQuestion")) return;
            *asked = box->text();
            box->button(button)->click();
        });
    };
    QString asked;
    answer(QMessageBox::No, &asked);
    dialog.accept();
    REQUIRE(asked.contains(QStringLiteral("already holds 4 frames")));
    REQUIRE(dialog.result() != QDialog::Accepted);
    REQUIRE_FALSE(dialog.options().overwrite);

    asked.clear();
    answer(QMessageBox::Yes, &asked);
    dialog.accept();
    REQUIRE_FALSE(asked.isEmpty());
    REQUIRE(dialog.result() == QDialog::Accepted);
    REQUIRE(dialog.options().overwrite);
    REQUIRE(oldFramesIntact(folder, 4)); // asking removes nothing
}

TEST_CASE("destroying the main window with unsaved changes does not update it half-destroyed", "[app][video][window]")
{
    /// Counts the window's "modified" changes (MainWindow::updateTitle's setWindowModified).
    class ModifiedCounter : public QObject {
    public:
        int count = 0;
        bool eventFilter(QObject*, QEvent* event) override
        {
            if (event->type() == QEvent::ModifiedChange) ++count;
            return false;
        }
    };
    ModifiedCounter counter;
    auto window = exportWindow(0.0);
    REQUIRE(window);
    window->installEventFilter(&counter);
    QUndoStack* stack = window->document().undoStack();
    stack->push(new QUndoCommand(QStringLiteral("a change")));
    REQUIRE_FALSE(stack->isClean());
    REQUIRE(counter.count == 1); // the title follows the stack while the window lives
    bool stackCleaned = false;
    QObject::connect(stack, &QUndoStack::cleanChanged, [&stackCleaned](bool clean) { stackCleaned = stackCleaned || clean; });
    window.reset(); // the stack's destructor clears it: its cleanChanged(true) must not reach the window
    REQUIRE(stackCleaned);
    REQUIRE(counter.count == 1);
}
