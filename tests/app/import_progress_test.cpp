// File > Import Take of a long BVH file: read and imported off the GUI thread behind a progress
// dialog whose Cancel changes nothing. The work is held at a known point through the controller's
// progress observer (no wall-clock window): the test presses Cancel while the file is half read.
#include "tests/app/app_test_support.h"

#include "app/joint_map_dialog.h"

#include "analysis/synth/long_take.h"

#include <catch2/catch.hpp>

#include <QApplication>
#include <QDialogButtonBox>
#include <QProgressDialog>
#include <QPushButton>
#include <QSemaphore>
#include <QTimer>

#include <atomic>
#include <vector>

using namespace bunraku;

namespace {

/// The imported takes among the derived ones (live results are published beside them).
std::vector<const app::DerivedTake*> importedTakes(const app::Document& document)
{
    std::vector<const app::DerivedTake*> out;
    for (const auto& derived : document.derivedTakes())
        if (derived.id.isImported()) out.push_back(&derived);
    return out;
}

constexpr Eigen::Index kFrames = 20000; // 4 progress reports while parsing, one per joint (and End Site) while importing

std::filesystem::path longTakeFile(const std::string& name)
{
    analysis::synth::LongTakeOptions options;
    options.frames = kFrames;
    auto file = analysis::synth::writeLongTake(options, test::scratchDir(name));
    REQUIRE(file.ok());
    return file.value();
}

/// Accepts the joint map dialog (the automatic map) whenever it is the active modal widget.
void acceptJointDialogWhenShown(bool& shown)
{
    QTimer::singleShot(0, [&shown] {
        auto* dialog = qobject_cast<app::JointMapDialog*>(QApplication::activeModalWidget());
        if (dialog == nullptr) return;
        shown = true;
        QTest::mouseClick(dialog->findChild<QDialogButtonBox*>()->button(QDialogButtonBox::Ok), Qt::LeftButton);
    });
}

/// Holds the work at its first progress report, presses the progress dialog's Cancel from the
/// GUI thread (which runs while the worker waits), then lets the work go on to see it.
class CancelAtFirstProgress {
public:
    explicit CancelAtFirstProgress(QWidget* window) : m_window(window)
    {
        QObject::connect(&m_poll, &QTimer::timeout, [this] { pressCancelWhenHeld(); });
    }
    ~CancelAtFirstProgress() { release(); }

    app::ProgressTaskOptions options()
    {
        app::ProgressTaskOptions options;
        options.showAfterMs = 0;
        options.observe = [this](double fraction) {
            if (fraction <= 0.0 || !m_first.exchange(false)) return;
            m_heldAt.store(fraction);
            m_reached.release();
            m_proceed.acquire(); // the worker waits here until the GUI thread has pressed Cancel
        };
        return options;
    }
    void start() { m_poll.start(5); }
    /// After the work returned: never leave the worker held, whatever happened.
    void release()
    {
        m_poll.stop();
        if (!m_released) m_proceed.release();
        m_released = true;
    }

    bool pressed = false;
    bool dialogVisible = false;
    QString label;
    double heldAt() const { return m_heldAt.load(); }

private:
    void pressCancelWhenHeld()
    {
        if (!m_reached.tryAcquire()) return;
        m_poll.stop();
        auto* progress = m_window->findChild<QProgressDialog*>();
        dialogVisible = progress != nullptr && progress->isVisible();
        if (progress != nullptr) {
            label = progress->labelText();
            for (auto* button : progress->findChildren<QPushButton*>())
                if (button->text() == QStringLiteral("Cancel")) {
                    QTest::mouseClick(button, Qt::LeftButton);
                    pressed = true;
                }
        }
        m_proceed.release();
        m_released = true;
    }

    QWidget* m_window;
    QTimer m_poll;
    QSemaphore m_reached, m_proceed;
    std::atomic<bool> m_first{true};
    std::atomic<double> m_heldAt{-1.0};
    bool m_released = false;
};

} // namespace

TEST_CASE("File > Import Take reads a long BVH off the GUI thread, and Cancel half way changes nothing", "[app][import][progress]")
{
    auto window = test::demoWindow();
    REQUIRE(window);
    REQUIRE(test::waitUntilIdle(*window));
    const auto file = longTakeFile("app_import_cancel");
    const app::TakeId shownBefore = window->document().selectedId(app::TakeSlot::A);
    const auto takesBefore = importedTakes(window->document()).size();
    const int undoBefore = window->document().undoStack()->count();

    CancelAtFirstProgress cancel(window.get());
    window->files().setProgressOptionsForTesting(cancel.options());
    window->files().setDialogsEnabled(true);
    QString lastStatus;
    QObject::connect(&window->files(), &app::FileController::statusMessage, [&](const QString& text) { lastStatus = text; });
    bool jointDialog = false;
    acceptJointDialogWhenShown(jointDialog);
    cancel.start();
    const bool imported = window->files().imports().importTakeFile(QString::fromStdString(file.string()));
    cancel.release();
    window->files().setDialogsEnabled(false);

    CHECK(jointDialog);
    CHECK(cancel.dialogVisible);
    CHECK(cancel.pressed);
    CHECK(cancel.heldAt() > 0.0);
    CHECK(cancel.heldAt() < 0.5); // held while the file was being parsed (the first half)
    CHECK(cancel.label.contains(QString::fromStdString(analysis::synth::longTakeFileName())));
    CHECK_FALSE(imported);
    CHECK(window->files().lastError().isEmpty());
    CHECK(lastStatus.contains(QStringLiteral("cancelled")));
    CHECK(window->document().selectedId(app::TakeSlot::A) == shownBefore);
    CHECK(importedTakes(window->document()).size() == takesBefore);
    CHECK(window->document().undoStack()->count() == undoBefore);
    CHECK(window->findChild<QProgressDialog*>() == nullptr);
}

TEST_CASE("File > Import Take of a long BVH reports its progress to the end and imports every frame", "[app][import][progress]")
{
    auto window = test::demoWindow();
    REQUIRE(window);
    const auto file = longTakeFile("app_import_progress");
    std::vector<double> fractions;
    QMutex guard;
    app::ProgressTaskOptions options;
    options.observe = [&](double fraction) {
        QMutexLocker lock(&guard);
        fractions.push_back(fraction);
    };
    window->files().setProgressOptionsForTesting(options);
    window->files().setDialogsEnabled(true);
    bool jointDialog = false;
    acceptJointDialogWhenShown(jointDialog);
    const bool imported = window->files().imports().importTakeFile(QString::fromStdString(file.string()));
    window->files().setDialogsEnabled(false);

    CHECK(jointDialog);
    REQUIRE(imported);
    const auto take = window->document().selectedTake(app::TakeSlot::A);
    REQUIRE(take);
    CHECK(take->frameCount() == kFrames);
    REQUIRE(take->skeleton);
    CHECK(take->skeleton->skeleton->joints.size() >= std::size_t(analysis::synth::kLongTakeJoints));
    // Reading: rows 4096 ... 16384 of 20000 (0.5 x 0.2 ... 0.82); importing: 22 joints.
    REQUIRE(fractions.size() >= 4 + std::size_t(analysis::synth::kLongTakeJoints));
    for (std::size_t i = 1; i < fractions.size(); ++i) CHECK(fractions[i] >= fractions[i - 1]);
    CHECK(fractions.front() == Approx(0.5 * 4096.0 / double(kFrames)));
    CHECK(fractions.back() > 0.9);
    CHECK(fractions.back() <= 1.0);
}

TEST_CASE("a project holding a long imported take reopens behind the progress dialog, and Cancel changes nothing", "[app][import][progress]")
{
    auto window = test::demoWindow();
    REQUIRE(window);
    const auto file = longTakeFile("app_project_cancel");
    REQUIRE(window->files().imports().importTakeFile(QString::fromStdString(file.string())));
    const auto project = test::scratchDir("app_project_cancel_file") / "long.bunraku.json";
    REQUIRE(window->files().projects().saveProject(QString::fromStdString(project.string())));
    REQUIRE(window->files().corpora().openDemoCorpus());
    REQUIRE(importedTakes(window->document()).empty());
    const app::TakeId shownBefore = window->document().selectedId(app::TakeSlot::A);

    CancelAtFirstProgress cancel(window.get());
    window->files().setProgressOptionsForTesting(cancel.options());
    window->files().setDialogsEnabled(true);
    cancel.start();
    const bool opened = window->files().projects().openProject(QString::fromStdString(project.string()));
    cancel.release();
    window->files().setDialogsEnabled(false);

    CHECK(cancel.pressed);
    CHECK(cancel.dialogVisible);
    CHECK_FALSE(opened);
    CHECK(window->files().lastError().isEmpty());
    CHECK(importedTakes(window->document()).empty());
    CHECK(window->document().selectedId(app::TakeSlot::A) == shownBefore);
    CHECK(window->files().projects().projectPath().isEmpty());

    // Not cancelled, the same project brings the take back.
    window->files().setProgressOptionsForTesting({});
    REQUIRE(window->files().projects().openProject(QString::fromStdString(project.string())));
    const auto imported = importedTakes(window->document());
    REQUIRE(imported.size() == 1);
    CHECK(imported.front()->take->frameCount() == kFrames);
}
