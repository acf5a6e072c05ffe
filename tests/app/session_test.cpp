// Sessions that cannot lose work: one autosave per running workbench, orphaned autosaves offered
// with their time and content, recovered work treated as unsaved, a drop that would replace the
// document asks first, and projects that reopen each import with the options it was made with.
#include "tests/app/app_test_support.h"

#include "app/autosave_session.h"
#include "app/commands.h"
#include "app/recovery_dialog.h"

#include "analysis/io/corpus_io.h"
#include "analysis/io/take_reader.h"

#include <catch2/catch.hpp>

#include <QApplication>
#include <QDropEvent>
#include <QFile>
#include <QFileInfo>
#include <QListWidget>
#include <QMessageBox>
#include <QMimeData>
#include <QPushButton>
#include <QTimer>
#include <QUrl>

#include <fstream>

#include <sys/wait.h>
#include <unistd.h>

using namespace bunraku;
using app::TakeSlot;

namespace {

/// A BVH with both arms: the built-in map takes the right one, "arm=LeftForeArm,hand=LeftHand"
/// the left one, which moves differently.
std::string twoArmedBvh()
{
    // Built stepwise: GCC 12 warns falsely (-Wrestrict) on chains of operator+.
    std::string text = "HIERARCHY\nROOT Hips\n{\n OFFSET 0 90 0\n CHANNELS 6 Xposition Yposition Zposition Zrotation Xrotation Yrotation\n"
                       " JOINT Chest\n {\n  OFFSET 0 20 0\n  CHANNELS 3 Zrotation Xrotation Yrotation\n"
                       "  JOINT Head\n  {\n   OFFSET 0 25 0\n   CHANNELS 3 Zrotation Xrotation Yrotation\n"
                       "   End Site\n   {\n    OFFSET 0 10 0\n   }\n  }\n";
    for (const char* side : {"Right", "Left"}) {
        const char* x = side[0] == 'R' ? "-15" : "15";
        for (const char* piece : {"  JOINT ", side, "ForeArm\n  {\n   OFFSET ", x, " 15 0\n   CHANNELS 3 Zrotation Xrotation Yrotation\n",
                                  "   JOINT ", side, "Hand\n   {\n    OFFSET ", x, " 0 0\n    CHANNELS 3 Zrotation Xrotation Yrotation\n",
                                  "    End Site\n    {\n     OFFSET 5 0 0\n    }\n   }\n  }\n"})
            text += piece;
    }
    text += " }\n}\nMOTION\nFrames: 12\nFrame Time: 0.04\n";
    for (int f = 0; f < 12; ++f) {
        const double t = f / 11.0;
        // hips (6), chest (3), head (3), right forearm and hand (6), left forearm and hand (6)
        const double values[24] = {2 * t, 90, -t, 0, 0, 0, 5 * t, 0, 0, 0, 10 * t, 0,
                                   30 * t, 0, 10, 0, 0, 20 * t, -70 * t, 15, 0, 45 * t, 0, -30};
        for (const double v : values) {
            text += std::to_string(v);
            text += ' ';
        }
        text += '\n';
    }
    return text;
}

/// An autosave left by a workbench that crashed: a child process takes a session in `folder`,
/// writes `state` as its autosave and dies without releasing its lock. Returns the file.
QString orphanedAutosave(const QString& folder, const app::ProjectState& state)
{
    int pipeFds[2];
    REQUIRE(::pipe(pipeFds) == 0);
    const pid_t child = ::fork();
    if (child == 0) {
        app::AutosaveSession session(folder);
        const bool written = bool(app::writeProject(state, session.path()));
        const QByteArray path = session.path().toUtf8() + "\n";
        if (::write(pipeFds[1], path.constData(), std::size_t(path.size())) < 0) ::_exit(2);
        ::_exit(written ? 0 : 1); // no destructors: the lock file stays, naming a dead process
    }
    ::close(pipeFds[1]);
    int status = 0;
    REQUIRE(::waitpid(child, &status, 0) == child);
    REQUIRE(WEXITSTATUS(status) == 0);
    char buffer[4096] = {};
    const auto got = ::read(pipeFds[0], buffer, sizeof buffer - 1);
    ::close(pipeFds[0]);
    REQUIRE(got > 0);
    return QString::fromUtf8(buffer).trimmed();
}

QString autosaveFolder(const app::MainWindow& window)
{
    return QFileInfo(const_cast<app::MainWindow&>(window).files().projects().autosavePath()).absolutePath();
}

} // namespace

TEST_CASE("two running workbenches keep separate autosaves", "[app][session]")
{
    auto first = test::demoWindow();
    auto second = test::demoWindow();
    REQUIRE(first);
    REQUIRE(second);
    REQUIRE(first->files().projects().autosavePath() != second->files().projects().autosavePath());
    app::changeStageParameters(first->document(), [](app::AnalysisParameters& p) { p.normalise.tau = 6; }, QStringLiteral("tau"));
    app::changeStageParameters(second->document(), [](app::AnalysisParameters& p) { p.normalise.tau = 7; }, QStringLiteral("tau"));
    REQUIRE(first->files().projects().autosave());
    REQUIRE(second->files().projects().autosave());
    first->files().projects().setUnsavedAnswerForTesting([] { return int(QMessageBox::Discard); });
    REQUIRE(first->close()); // discards its own work: its autosave goes, the other's stays
    REQUIRE_FALSE(QFile::exists(first->files().projects().autosavePath()));
    REQUIRE(QFile::exists(second->files().projects().autosavePath()));
    REQUIRE(app::readProject(second->files().projects().autosavePath())->parameters.normalise.tau == 7);
    // A running workbench's autosave is never offered as an orphan.
    for (const auto& orphan : first->files().projects().autosaveSession().orphans())
        REQUIRE(orphan.path != second->files().projects().autosavePath());
}

TEST_CASE("an orphaned autosave is offered with its time and content, and recovered as unsaved work", "[app][session]")
{
    auto window = test::demoWindow();
    REQUIRE(window);
    app::ProjectState state;
    state.corpus = QStringLiteral("demo");
    state.parameters.normalise.tau = 9;
    state.takeA = app::TakeId::corpus(5);
    const QString orphan = orphanedAutosave(autosaveFolder(*window), state);

    const auto orphans = window->files().projects().autosaveSession().orphans();
    const auto found = std::find_if(orphans.begin(), orphans.end(), [&](const app::OrphanedAutosave& o) { return o.path == orphan; });
    REQUIRE(found != orphans.end());
    CHECK(found->summary.contains(QStringLiteral("demo corpus")));
    CHECK(found->summary.contains(QStringLiteral("edited normalisation")));
    CHECK(std::abs(found->saved.secsTo(QDateTime::currentDateTime())) < 600);

    // The dialog lists it; Recover opens it into the window.
    window->files().setDialogsEnabled(true);
    QString listed;
    QTimer::singleShot(0, [&listed, orphan] {
        auto* dialog = qobject_cast<app::RecoveryDialog*>(QApplication::activeModalWidget());
        if (dialog == nullptr) return;
        for (int row = 0; row < dialog->list()->count(); ++row)
            if (dialog->list()->item(row)->data(Qt::UserRole).toString() == orphan) {
                dialog->list()->setCurrentRow(row);
                listed = dialog->list()->item(row)->text();
            }
        dialog->recoverButton()->click();
    });
    window->files().projects().offerRecovery();
    window->files().setDialogsEnabled(false);
    REQUIRE(listed.contains(QStringLiteral("demo corpus")));
    auto& document = window->document();
    REQUIRE(document.parameters().normalise.tau == 9);
    REQUIRE(document.selectedId(TakeSlot::A) == app::TakeId::corpus(5));
    // Unsaved work: the title is marked, the autosave is this window's and stays.
    REQUIRE_FALSE(document.undoStack()->isClean());
    REQUIRE(window->isWindowModified());
    REQUIRE(window->files().projects().autosavePath() == orphan);
    REQUIRE(window->files().projects().projectPath().isEmpty());

    // Quitting asks: Cancel keeps the window and the autosave.
    int asked = 0;
    window->files().projects().setUnsavedAnswerForTesting([&asked] {
        ++asked;
        return int(QMessageBox::Cancel);
    });
    REQUIRE_FALSE(window->close());
    REQUIRE(asked == 1);
    REQUIRE(QFile::exists(orphan));
    // Saving it removes the autosave; the window then closes without asking.
    REQUIRE(window->files().projects().saveProject(QString::fromStdString((test::scratchDir("recovered") / "r.bunraku.json").string())));
    REQUIRE_FALSE(QFile::exists(orphan));
    REQUIRE(window->close());
    REQUIRE(asked == 1);
}

TEST_CASE("an orphan discarded from the dialog is removed, one kept for later stays", "[app][session]")
{
    auto window = test::demoWindow();
    REQUIRE(window);
    app::ProjectState state;
    state.corpus = QStringLiteral("demo");
    const QString kept = orphanedAutosave(autosaveFolder(*window), state);
    const QString dropped = orphanedAutosave(autosaveFolder(*window), state);
    app::RecoveryDialog dialog(window->files().projects().autosaveSession().orphans(),
                               [&](const QString& path) { return window->files().projects().autosaveSession().discardOrphan(path); });
    for (int row = 0; row < dialog.list()->count(); ++row)
        if (dialog.list()->item(row)->data(Qt::UserRole).toString() == dropped) dialog.list()->setCurrentRow(row);
    dialog.discardButton()->click();
    REQUIRE_FALSE(QFile::exists(dropped));
    REQUIRE_FALSE(QFile::exists(dropped + QStringLiteral(".lock")));
    REQUIRE(QFile::exists(kept));
    window->files().projects().autosaveSession().discardOrphan(kept); // tidy: other tests share the folder
}

TEST_CASE("dropping a corpus folder or project on unsaved work asks first", "[app][session]")
{
    auto window = test::demoWindow();
    REQUIRE(window);
    const auto dir = test::scratchDir("drop-asks");
    REQUIRE(analysis::io::writeCorpus(window->document().corpus(), dir / "corpus").ok());
    app::changeStageParameters(window->document(), [](app::AnalysisParameters& p) { p.normalise.tau = 6; }, QStringLiteral("tau"));
    REQUIRE(window->files().projects().autosave());
    const QString autosave = window->files().projects().autosavePath();

    const auto drop = [&](const QString& path) {
        QMimeData mime;
        mime.setUrls({QUrl::fromLocalFile(path)});
        QDragEnterEvent enter(QPoint(100, 100), Qt::CopyAction, &mime, Qt::LeftButton, Qt::NoModifier);
        QApplication::sendEvent(window.get(), &enter);
        REQUIRE(enter.isAccepted());
        QDropEvent event(QPointF(100, 100), Qt::CopyAction, &mime, Qt::LeftButton, Qt::NoModifier);
        QApplication::sendEvent(window.get(), &event);
        REQUIRE(event.isAccepted());
    };
    int asked = 0;
    window->files().projects().setUnsavedAnswerForTesting([&asked] {
        ++asked;
        return int(QMessageBox::Cancel);
    });
    drop(QString::fromStdString((dir / "corpus").string()));
    REQUIRE(QTest::qWaitFor([&] { return asked == 1; }, 5000)); // the drop opens once the event is over
    REQUIRE(window->document().corpusSource() == QStringLiteral("demo")); // not replaced
    REQUIRE(window->document().parameters().normalise.tau == 6);
    REQUIRE(QFile::exists(autosave));

    window->files().projects().setUnsavedAnswerForTesting([&asked] {
        ++asked;
        return int(QMessageBox::Discard);
    });
    drop(QString::fromStdString((dir / "corpus").string()));
    REQUIRE(QTest::qWaitFor([&] { return asked == 2; }, 5000));
    REQUIRE(window->document().corpusSource().endsWith(QStringLiteral("corpus")));
    REQUIRE_FALSE(QFile::exists(autosave)); // discarded: nothing left to recover
}

TEST_CASE("a BVH imported with a non-default joint map reopens from its project identically", "[app][session]")
{
    const auto dir = test::scratchDir("project-import-options");
    const QString bvh = QString::fromStdString((dir / "arms.bvh").string());
    {
        std::ofstream out(bvh.toStdString());
        out << twoArmedBvh();
    }
    const QString map = QStringLiteral("arm=LeftForeArm,hand=LeftHand");
    const QString project = QString::fromStdString((dir / "p.bunraku.json").string());
    app::TakePointer imported;
    {
        auto window = test::demoWindow();
        REQUIRE(window);
        REQUIRE(window->files().imports().importTakeFile(bvh, map));
        imported = window->document().selectedTake(TakeSlot::A);
        REQUIRE(window->files().projects().saveProject(project));
    }
    // The map matters: the default one takes the other arm.
    const auto byDefault = analysis::io::readTakeFile(bvh.toStdString());
    REQUIRE(byDefault.ok());
    REQUIRE((byDefault->values - imported->values).cwiseAbs().maxCoeff() > 1.0);

    auto window = test::demoWindow();
    REQUIRE(window);
    REQUIRE(window->files().projects().openProject(project));
    const auto& derived = window->document().derivedTakes();
    const auto found = std::find_if(derived.begin(), derived.end(), [](const app::DerivedTake& d) { return !d.sourcePath.isEmpty(); });
    REQUIRE(found != derived.end());
    const auto& reopened = *found->take;
    REQUIRE(reopened.channels == imported->channels);
    REQUIRE(reopened.rateHz == imported->rateHz);
    REQUIRE(reopened.frameCount() == imported->frameCount());
    REQUIRE((reopened.values - imported->values).cwiseAbs().maxCoeff() <= 1e-12);
}

TEST_CASE("a corpus, project or take that cannot be read is an error in the workbench, not an abort", "[app][session]")
{
    auto window = test::demoWindow();
    REQUIRE(window);
    const auto dir = test::scratchDir("workbench-bad-inputs");
    REQUIRE(analysis::io::writeCorpus(window->document().corpus(), dir / "corpus").ok());
    std::string manifest;
    {
        std::ifstream in(dir / "corpus" / "corpus.json");
        manifest.assign(std::istreambuf_iterator<char>(in), {});
    }
    manifest.replace(manifest.find("\"rate_hz\": 5.0"), 14, "\"rate_hz\": 1e400");
    {
        std::ofstream out(dir / "corpus" / "corpus.json");
        out << manifest;
    }
    REQUIRE_FALSE(window->files().corpora().openCorpusFolder(QString::fromStdString((dir / "corpus").string())));
    REQUIRE(window->files().lastError().contains(QStringLiteral("corpus.json")));
    // A take's skeleton file holding an offset of 1e400 (used to abort with exit 134).
    {
        analysis::io::ImportOptions allJoints;
        allJoints.bvhLayout = analysis::io::BvhTakeLayout::AllJoints;
        auto joints = analysis::io::readTakeFile(test::sourceDir() / "tests" / "data" / "io" / "two_joint_chain.bvh", allJoints);
        REQUIRE(joints.ok());
        joints->labels = analysis::TakeLabels{"greeting", "none", 1, ""};
        analysis::Corpus corpus;
        corpus.rateHz = joints->rateHz;
        corpus.takes.push_back(*joints);
        REQUIRE(analysis::io::writeCorpus(corpus, dir / "skeletal").ok());
        const auto skeleton = dir / "skeletal" / "greeting_none_1.skeleton.json";
        std::string text;
        {
            std::ifstream in(skeleton);
            text.assign(std::istreambuf_iterator<char>(in), {});
        }
        const auto at = text.find("10.0");
        REQUIRE(at != std::string::npos);
        text.replace(at, 4, "1e400");
        {
            std::ofstream out(skeleton);
            out << text;
        }
        REQUIRE_FALSE(window->files().corpora().openCorpusFolder(QString::fromStdString((dir / "skeletal").string())));
        REQUIRE(window->files().lastError().contains(QStringLiteral("greeting_none_1.skeleton.json:")));
    }
    REQUIRE_FALSE(window->files().projects().openProject(QStringLiteral("/dev/zero")));
    REQUIRE(window->files().lastError().contains(QStringLiteral("/dev/zero")));
    std::filesystem::create_symlink("/dev/urandom", dir / "noise.csv");
    REQUIRE_FALSE(window->files().imports().importTakeFile(QString::fromStdString((dir / "noise.csv").string())));
    REQUIRE(window->files().lastError().contains(QStringLiteral("device")));
    REQUIRE(window->document().corpus().takes.size() == 30); // still the demo corpus
}
