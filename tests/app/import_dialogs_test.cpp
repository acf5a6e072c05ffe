// The joint dialog (automatic map preset, one joint per part, a preview of the mapped puppet)
// and File > New Corpus from Files (labels parsed and corrected in a table, files dropped, the
// corpus made and opened), driven as a user would under Xvfb.
#include "tests/app/app_test_support.h"

#include "app/file_dialogs.h"
#include "app/import_takes_dialog.h"
#include "app/joint_map_dialog.h"
#include "app/new_corpus_dialog.h"

#include "analysis/core/skeleton.h"
#include "analysis/io/bvh.h"
#include "analysis/io/corpus_io.h"
#include "tests/analysis/io/io_test_support.h"
#include "tests/support/bandai_files.h"
#include "tests/support/bvh_fixtures.h"

#include <catch2/catch.hpp>

#include <QApplication>
#include <QComboBox>
#include <QDialogButtonBox>
#include <QFileInfo>
#include <QInputDialog>
#include <QLabel>
#include <QSettings>
#include <QLineEdit>
#include <QMimeData>
#include <QPushButton>
#include <QTableWidget>
#include <QTimer>

using namespace bunraku;
namespace fs = std::filesystem;

namespace {

analysis::io::BvhFile fixtureFile(const std::string& id)
{
    for (const auto& family : test::bvhFamilies())
        if (family.id == id) {
            auto file = analysis::io::parseBvh(test::fixtureBvh(family), id + ".bvh");
            REQUIRE(file.ok());
            return std::move(file).value();
        }
    FAIL("no fixture family " << id);
    return {};
}

QPushButton* okButton(QDialog& dialog)
{
    auto* buttons = dialog.findChild<QDialogButtonBox*>();
    REQUIRE(buttons);
    return buttons->button(QDialogButtonBox::Ok);
}

/// Pixels of the image that are not the renderer's light background.
int drawnPixels(const QImage& image)
{
    int count = 0;
    for (int y = 0; y < image.height(); ++y)
        for (int x = 0; x < image.width(); ++x) {
            const QRgb p = image.pixel(x, y);
            if (qRed(p) < 200 || qGreen(p) < 200) ++count;
        }
    return count;
}

std::vector<fs::path> writeFixtures(const fs::path& dir, const std::vector<std::string>& names)
{
    const auto families = test::bvhFamilies();
    fs::create_directories(dir);
    std::vector<fs::path> files;
    for (const auto& name : names) files.push_back(test::writeText(dir / name, test::fixtureBvh(families[3])));
    return files;
}

} // namespace

TEST_CASE("the joint dialog presets the automatic map, refuses one joint for two parts and previews the puppet", "[app][import]")
{
    test::isolateSettings();
    app::JointMapDialog dialog(fixtureFile("classic"), QStringLiteral("classic.bvh"));
    CHECK(dialog.partBox(0)->currentText() == QStringLiteral("Head"));
    CHECK(dialog.partBox(1)->currentText() == QStringLiteral("Chest2"));
    CHECK(dialog.partBox(2)->currentText() == QStringLiteral("RightElbow"));
    CHECK(dialog.partBox(3)->currentText() == QStringLiteral("RightWrist"));
    CHECK(dialog.problem().isEmpty());
    CHECK(okButton(dialog)->isEnabled());
    REQUIRE_FALSE(dialog.preview().isNull());
    const int full = drawnPixels(dialog.preview());
    CHECK(full > 500);

    // The left side: the left arm and hand.
    dialog.sideBox()->setCurrentIndex(1);
    CHECK(dialog.partBox(2)->currentText() == QStringLiteral("LeftElbow"));
    CHECK(dialog.side() == analysis::BodySide::Left);

    // One joint for two parts: refused, OK disabled, no preview.
    dialog.partBox(0)->setCurrentText(QStringLiteral("Chest2"));
    CHECK_FALSE(okButton(dialog)->isEnabled());
    CHECK(dialog.problem().contains(QStringLiteral("Chest2 drives both the head and the shoulder")));
    CHECK(dialog.preview().isNull());
    dialog.partBox(0)->setCurrentText(QStringLiteral("Neck"));
    CHECK(okButton(dialog)->isEnabled());
    CHECK(dialog.jointMapText() == QStringLiteral("head=Neck,shoulder=Chest2,arm=LeftElbow,hand=LeftWrist"));
}

TEST_CASE("the joint dialog presets nothing for a skeleton the automatic map cannot read", "[app][import]")
{
    test::isolateSettings();
    auto file = analysis::io::parseBvh("HIERARCHY\nROOT Hips\n{\nOFFSET 0 0 0\nCHANNELS 3 Xposition Yposition Zposition\nJOINT b\n{\n"
                                       "OFFSET 0 1 0\nCHANNELS 0\n}\n}\nMOTION\nFrames: 1\nFrame Time: 0.1\n0 0 0\n",
                                       "stick.bvh");
    REQUIRE(file.ok());
    app::JointMapDialog dialog(*file, QStringLiteral("stick.bvh"));
    for (int part = 0; part < 4; ++part) CHECK(dialog.partBox(part)->currentIndex() == 0); // "(choose a joint)", not Hips
    CHECK_FALSE(okButton(dialog)->isEnabled());
    CHECK(dialog.problem().contains(QStringLiteral("Choose a joint for the head")));
}

TEST_CASE("a BVH file of any common skeleton imports without a map and keeps its skeleton", "[app][import]")
{
    auto window = test::demoWindow();
    REQUIRE(window);
    const auto dir = test::scratchDir("app_import_mixamo");
    const auto file = writeFixtures(dir, {"mixamo.bvh"}).front();
    REQUIRE(window->files().imports().importTakeFile(QString::fromStdString(file.string())));
    const auto& derived = window->document().derivedTakes();
    const auto imported = std::find_if(derived.begin(), derived.end(), [](const auto& d) { return !d.sourcePath.isEmpty(); });
    REQUIRE(imported != derived.end());
    REQUIRE(imported->take->skeleton);
    CHECK(imported->take->skeleton->skeleton->binding("arm")->joint ==
          imported->take->skeleton->skeleton->find("mixamorig:RightForeArm"));
}

TEST_CASE("new corpus from files: labels from the names, corrected in the table, made and opened", "[app][import]")
{
    auto window = test::demoWindow();
    REQUIRE(window);
    const auto dir = test::scratchDir("app_new_corpus");
    writeFixtures(dir / "in", {"dataset-2_wave_happy_001.bvh", "dataset-2_wave_happy_002.bvh", "dataset-2_wave_sad_001.bvh"});
    app::NewCorpusDialog dialog;
    dialog.addInputs({QString::fromStdString((dir / "in").string())});
    QTableWidget* table = dialog.table();
    REQUIRE(table->rowCount() == 3);
    // The default pattern reads these names wrongly; a pattern that does not match them at all
    // leaves the labels to type, and Create is disabled.
    CHECK(table->item(0, app::NewCorpusDialog::FunctionColumn)->text() == QStringLiteral("dataset-2"));
    dialog.setPattern(QStringLiteral("{function}.{emotion}"));
    CHECK(dialog.problem().contains(QStringLiteral("does not match the pattern")));
    dialog.setPattern(QStringLiteral("{any}_{function}_{emotion}_{take}"));
    CHECK(dialog.problem().isEmpty());
    CHECK(table->item(0, app::NewCorpusDialog::FunctionColumn)->text() == QStringLiteral("wave"));
    CHECK(table->item(2, app::NewCorpusDialog::EmotionColumn)->text() == QStringLiteral("sad"));
    CHECK(table->item(1, app::NewCorpusDialog::TakeColumn)->text() == QStringLiteral("2"));
    CHECK(table->item(0, app::NewCorpusDialog::MapColumn)->text().startsWith(QStringLiteral("head=mixamorig:Head (name)")));
    // A correction typed by the user: the third take is "calm", and stays so when the pattern changes.
    table->item(2, app::NewCorpusDialog::EmotionColumn)->setText(QStringLiteral("calm"));
    dialog.setPattern(QStringLiteral("dataset-2_{function}_{emotion}_{take}"));
    CHECK(table->item(2, app::NewCorpusDialog::EmotionColumn)->text() == QStringLiteral("calm"));
    // Two files with the same labels are refused.
    table->item(1, app::NewCorpusDialog::TakeColumn)->setText(QStringLiteral("1"));
    CHECK(dialog.problem().contains(QStringLiteral("both have the labels wave/happy/1")));
    table->item(1, app::NewCorpusDialog::TakeColumn)->setText(QStringLiteral("2"));
    dialog.neutralBox()->setCurrentText(QStringLiteral("calm"));
    const QString output = QString::fromStdString((dir / "made").string());
    dialog.setOutputFolder(output);
    REQUIRE(dialog.problem().isEmpty());
    const auto sources = dialog.sources();
    REQUIRE(sources.size() == 3);
    CHECK(sources[2].labels == analysis::TakeLabels{"wave", "calm", 1, ""});

    REQUIRE(window->files().corpora().createCorpusFromFiles(sources, dialog.buildOptions(), output));
    const auto& corpus = window->document().corpus();
    CHECK(window->document().corpusSource() == QFileInfo(output).absoluteFilePath());
    REQUIRE(corpus.takes.size() == 3);
    CHECK(corpus.neutralEmotion == "calm");
    CHECK(corpus.name == "made");
    for (const auto& take : corpus.takes) CHECK(take.skeleton);
    CHECK(analysis::io::isCorpusFolder(dir / "made"));
}

TEST_CASE("files and folders dropped on the new-corpus dialog join its table", "[app][import]")
{
    test::isolateSettings();
    QSettings().remove(QStringLiteral("folders"));
    const auto dir = test::scratchDir("app_new_corpus_drop");
    const auto files = writeFixtures(dir, {"walk_happy_1.bvh", "walk_sad_1.bvh"});
    app::NewCorpusDialog dialog;
    dialog.show();
    REQUIRE(QTest::qWaitForWindowExposed(&dialog));
    QMimeData mime;
    mime.setUrls({QUrl::fromLocalFile(QString::fromStdString(files[0].string())), QUrl::fromLocalFile(QString::fromStdString(files[1].string()))});
    QDragEnterEvent enter(QPoint(10, 10), Qt::CopyAction, &mime, Qt::LeftButton, Qt::NoModifier);
    QCoreApplication::sendEvent(&dialog, &enter);
    CHECK(enter.isAccepted());
    QDropEvent drop(QPointF(10, 10), Qt::CopyAction, &mime, Qt::LeftButton, Qt::NoModifier);
    QCoreApplication::sendEvent(&dialog, &drop);
    REQUIRE(dialog.table()->rowCount() == 2);
    CHECK(dialog.table()->item(1, app::NewCorpusDialog::EmotionColumn)->text() == QStringLiteral("sad"));
    CHECK(dialog.problem().isEmpty()); // the output folder defaults to "corpus" in the workbench's own folder
    CHECK(dialog.outputFolder() == app::unusedFolder(app::workbenchFolder(app::FilePurpose::NewCorpus), QStringLiteral("corpus")));
}

TEST_CASE("new corpus from files: a file that is not a take keeps the dialog open with all input, and rows are removed with Delete",
          "[app][import]")
{
    auto window = test::demoWindow();
    REQUIRE(window);
    const auto dir = test::scratchDir("app_new_corpus_error");
    const auto in = dir / "in";
    writeFixtures(in, {"walk_happy_1.bvh", "walk_sad_1.bvh"});
    // A text file whose name reads as a take but which holds none (a licence, say).
    const auto notTake = test::writeText(in / "walk_calm_1.txt", "This work is licensed under CC BY-NC 4.0.\n");
    // Corpora were last made in `corpora`: the new corpus is suggested there.
    const auto corpora = dir / "corpora";
    fs::create_directories(corpora);
    QSettings().setValue(app::purposeKey(app::FilePurpose::NewCorpus), QString::fromStdString(corpora.string()));
    const QString made = QString::fromStdString((dir / "made").string());

    int steps = 0;
    QTimer::singleShot(0, [&] {
        // (No REQUIRE in here: an exception must not cross Qt's event loop; a failed step rejects.)
        auto* dialog = qobject_cast<app::NewCorpusDialog*>(QApplication::activeModalWidget());
        CHECK(dialog);
        if (!dialog) return;
        QTableWidget* table = dialog->table();
        CHECK(table->rowCount() == 3);
        if (table->rowCount() != 3) return dialog->reject();
        CHECK(dialog->outputFolder() == QString::fromStdString((corpora / "corpus").string()));
        // The user's edits: a pattern, a corrected label and the folder.
        dialog->setPattern(QStringLiteral("{function}_{emotion}_{take}"));
        int bvhRow = -1, badRow = -1;
        for (int row = 0; row < 3; ++row) {
            if (table->item(row, app::NewCorpusDialog::FileColumn)->text() == QStringLiteral("walk_happy_1.bvh")) bvhRow = row;
            if (table->item(row, app::NewCorpusDialog::FileColumn)->text() == QStringLiteral("walk_calm_1.txt")) badRow = row;
        }
        CHECK(bvhRow >= 0);
        CHECK(badRow >= 0);
        if (bvhRow < 0 || badRow < 0) return dialog->reject();
        table->item(bvhRow, app::NewCorpusDialog::EmotionColumn)->setText(QStringLiteral("joyful"));
        dialog->setOutputFolder(made);
        CHECK(dialog->problem().isEmpty());
        QTest::mouseClick(dialog->createButton(), Qt::LeftButton);
        // The error is said in the dialog, which stays open with everything as it was.
        CHECK(dialog->isVisible());
        CHECK(dialog->messageText().contains(QStringLiteral("walk_calm_1.txt")));
        CHECK(table->rowCount() == 3);
        CHECK(table->item(bvhRow, app::NewCorpusDialog::EmotionColumn)->text() == QStringLiteral("joyful"));
        CHECK(dialog->outputFolder() == made);
        CHECK(table->selectionModel()->selectedRows().size() == 1);
        CHECK(table->currentRow() == badRow); // the row of the file the error names
        CHECK(dialog->removeButton()->isEnabled());
        // Delete removes the bad row; the others keep their labels.
        QTest::keyClick(table, Qt::Key_Delete);
        CHECK(table->rowCount() == 2);
        if (table->rowCount() != 2) return dialog->reject();
        for (int row = 0; row < 2; ++row) CHECK(table->item(row, app::NewCorpusDialog::FileColumn)->text() != QStringLiteral("walk_calm_1.txt"));
        CHECK(dialog->sources().size() == 2);
        CHECK(dialog->problem().isEmpty());
        ++steps;
        QTest::mouseClick(dialog->createButton(), Qt::LeftButton);
        CHECK_FALSE(dialog->isVisible()); // made: closed
        ++steps;
    });
    // The files picked one by one (a folder's .txt files are not collected as takes).
    QStringList picked;
    for (const char* name : {"walk_happy_1.bvh", "walk_sad_1.bvh", "walk_calm_1.txt"}) picked << QString::fromStdString((in / name).string());
    window->files().corpora().chooseFilesForCorpus(picked);
    REQUIRE(steps == 2);
    const auto& corpus = window->document().corpus();
    CHECK(window->document().corpusSource() == QFileInfo(made).absoluteFilePath());
    REQUIRE(corpus.takes.size() == 2);
    CHECK(std::any_of(corpus.takes.begin(), corpus.takes.end(), [](const auto& take) { return take.labels.emotion == "joyful"; }));
    CHECK(fs::exists(notTake)); // nothing deleted
    // The next new corpus is suggested beside this one (and File > Open Corpus opens there).
    CHECK(app::rememberedPurposeFolder(app::FilePurpose::NewCorpus) == QString::fromStdString(dir.string()));
    CHECK(app::rememberedPurposeFolder(app::FilePurpose::Corpus) == QString::fromStdString(dir.string()));
}

TEST_CASE("new corpus from files: the Remove button removes the selected rows and renumbers takes", "[app][import]")
{
    test::isolateSettings();
    QSettings().remove(QStringLiteral("folders"));
    const auto dir = test::scratchDir("app_new_corpus_remove");
    writeFixtures(dir, {"a_walk_happy.bvh", "b_walk_happy.bvh", "c_walk_happy.bvh"});
    app::NewCorpusDialog dialog;
    dialog.addInputs({QString::fromStdString(dir.string())});
    dialog.setPattern(QStringLiteral("{any}_{function}_{emotion}"));
    QTableWidget* table = dialog.table();
    REQUIRE(table->rowCount() == 3);
    CHECK(table->item(2, app::NewCorpusDialog::TakeColumn)->text() == QStringLiteral("3"));
    CHECK_FALSE(dialog.removeButton()->isEnabled()); // nothing selected
    table->selectRow(0);
    REQUIRE(dialog.removeButton()->isEnabled());
    QTest::mouseClick(dialog.removeButton(), Qt::LeftButton);
    REQUIRE(table->rowCount() == 2);
    CHECK(table->item(0, app::NewCorpusDialog::FileColumn)->text() == QStringLiteral("b_walk_happy.bvh"));
    // Takes numbered in file order within their cell: 1 and 2 again.
    CHECK(table->item(0, app::NewCorpusDialog::TakeColumn)->text() == QStringLiteral("1"));
    CHECK(table->item(1, app::NewCorpusDialog::TakeColumn)->text() == QStringLiteral("2"));
    REQUIRE(dialog.sources().size() == 2);
    CHECK(dialog.sources()[1].file.filename() == "c_walk_happy.bvh");
    // No folder remembered for new corpora: the workbench's own.
    CHECK(dialog.outputFolder() == app::unusedFolder(app::workbenchFolder(app::FilePurpose::NewCorpus), QStringLiteral("corpus")));
}

TEST_CASE("new corpus from files suggests the workbench's own folder, never the data folder the files are in", "[app][import]")
{
    // It used to suggest "corpus" beside the files, or beside the corpus last opened: the
    // user's data folder (the Bandai files' folder is read-only shared data).
    test::isolateSettings();
    QSettings().remove(QStringLiteral("folders"));
    const auto dir = test::scratchDir("app_new_corpus_own_folder");
    const auto data = dir / "data";
    const auto files = writeFixtures(data / "takes", {"walk_happy_1.bvh", "walk_sad_1.bvh"});
    // A corpus opened from the data folder: File > Open Corpus remembers it for opening.
    app::rememberFolder(app::FilePurpose::Corpus, QString::fromStdString((data / "takes").string()));
    app::NewCorpusDialog dialog;
    dialog.addInputs({QString::fromStdString(files[0].string()), QString::fromStdString(files[1].string())});
    const QString suggested = dialog.outputFolder();
    CHECK_FALSE(suggested.startsWith(QString::fromStdString(data.string())));
    const QString own = app::workbenchFolder(app::FilePurpose::NewCorpus);
    CHECK(own.endsWith(QStringLiteral("Bunraku/corpora")));
    CHECK(QFileInfo(suggested).absolutePath() == QFileInfo(own).absoluteFilePath());
    CHECK(QFileInfo(suggested).fileName().startsWith(QStringLiteral("corpus")));
    CHECK_FALSE(QFileInfo::exists(suggested)); // never an existing folder

    // Remembered per purpose, as exports are: the folder the last corpus was made in.
    const auto made = dir / "made";
    fs::create_directories(made);
    app::rememberFolder(app::FilePurpose::NewCorpus, QString::fromStdString((made / "first").string()));
    app::NewCorpusDialog next;
    next.addInputs({QString::fromStdString(files[0].string())});
    CHECK(next.outputFolder() == QString::fromStdString((made / "corpus").string()));
    fs::create_directories(made / "corpus");
    app::NewCorpusDialog third;
    third.addInputs({QString::fromStdString(files[0].string())});
    CHECK(third.outputFolder() == QString::fromStdString((made / "corpus-2").string()));
}

TEST_CASE("new corpus from the bandai files in the workbench", "[app][import]")
{
    const auto files = test::bandaiFilesOrSkip();
    if (files.empty()) return;
    auto window = test::demoWindow();
    REQUIRE(window);
    app::NewCorpusDialog dialog;
    dialog.addInputs({QString::fromStdString(test::bandaiDir().string())});
    REQUIRE(dialog.table()->rowCount() == int(files.size()));
    const QString output = QString::fromStdString((test::scratchDir("app_new_corpus_bandai") / "bandai").string());
    dialog.setOutputFolder(output);
    REQUIRE(dialog.problem().isEmpty());
    REQUIRE(window->files().corpora().createCorpusFromFiles(dialog.sources(), dialog.buildOptions(), output));
    const auto& corpus = window->document().corpus();
    CHECK(corpus.takes.size() == files.size());
    CHECK(corpus.neutralEmotion == "normal");
    CHECK(corpus.rateHz == 30.0);
    CHECK(corpus.takes.front().channels.size() == 24);

    // Channels: every joint of the skeleton - the whole body, 22 joints x 6 channels.
    REQUIRE(dialog.channelsBox());
    dialog.channelsBox()->setCurrentIndex(1);
    CHECK(dialog.buildOptions().import.bvhLayout == analysis::io::BvhTakeLayout::AllJoints);
    const QString whole = QString::fromStdString((test::scratchDir("app_new_corpus_bandai_joints") / "bandai").string());
    dialog.setOutputFolder(whole);
    REQUIRE(window->files().corpora().createCorpusFromFiles(dialog.sources(), dialog.buildOptions(), whole));
    const auto& joints = window->document().corpus();
    CHECK(joints.takes.size() == files.size());
    CHECK(joints.takes.front().channels.size() == 132);
    REQUIRE(joints.takes.front().skeleton);
}

TEST_CASE("File > Import Take of a BVH file takes the map chosen in the joint dialog", "[app][import]")
{
    auto window = test::demoWindow();
    REQUIRE(window);
    const auto dir = test::scratchDir("app_import_dialog");
    const auto file = writeFixtures(dir, {"mixamo.bvh"}).front();
    window->files().setDialogsEnabled(true);
    bool shown = false;
    // When the dialog opens: the left side, then OK, as a user would.
    QTimer::singleShot(0, [&] {
        auto* dialog = qobject_cast<app::JointMapDialog*>(QApplication::activeModalWidget());
        if (dialog == nullptr) return;
        shown = true;
        dialog->sideBox()->setCurrentIndex(1);
        QTest::mouseClick(okButton(*dialog), Qt::LeftButton);
    });
    const bool imported = window->files().imports().importTakeFile(QString::fromStdString(file.string()));
    window->files().setDialogsEnabled(false);
    REQUIRE(shown);
    REQUIRE(imported);
    const auto take = window->document().selectedTake(app::TakeSlot::A);
    REQUIRE(take->skeleton);
    const auto& skeleton = *take->skeleton->skeleton;
    CHECK(skeleton.binding("arm")->joint == skeleton.find("mixamorig:LeftForeArm"));
    CHECK(skeleton.binding("hand")->joint == skeleton.find("mixamorig:LeftHand"));
}

TEST_CASE("File > Import Take of an inch-unit BVH stands at a person's height when the dialog says Inches", "[app][import][units]")
{
    auto window = test::demoWindow();
    REQUIRE(window);
    const auto dir = test::scratchDir("app_import_inches");
    test::BvhFamily family = test::bvhFamilies()[3];
    family.unitsPerCm = 1.0 / 2.54; // the 172 cm performer written in inches: 68 units tall
    const auto file = test::writeText(dir / "inches.bvh", test::fixtureBvh(family));
    window->files().setDialogsEnabled(true);
    QString guessed, chosen;
    QTimer::singleShot(0, [&] {
        auto* dialog = qobject_cast<app::JointMapDialog*>(QApplication::activeModalWidget());
        if (dialog == nullptr) return;
        // Guessed (a standing take: centimetres), with the hint; then Inches, as a user would.
        guessed = dialog->findChild<QLabel*>("height")->text();
        QComboBox* units = dialog->unitsBox();
        units->setCurrentIndex(units->findText(QStringLiteral("Inches")));
        chosen = dialog->findChild<QLabel*>("height")->text();
        QTest::mouseClick(okButton(*dialog), Qt::LeftButton);
    });
    const bool imported = window->files().imports().importTakeFile(QString::fromStdString(file.string()));
    window->files().setDialogsEnabled(false);
    INFO("guessed: " << guessed.toStdString() << "; chosen: " << chosen.toStdString());
    REQUIRE(imported);
    CHECK(guessed.contains(QStringLiteral("0.6")));
    CHECK(guessed.contains(QStringLiteral("choose Inches")));
    CHECK(chosen.startsWith(QStringLiteral("1.7")));
    const auto take = window->document().selectedTake(app::TakeSlot::A);
    REQUIRE(take->skeleton);
    // The joints span the performer's height in cm at the first frame.
    double low = 1e9, high = -1e9;
    for (const auto& pose : take->skeleton->worldPoses(0)) {
        low = std::min(low, pose.translation.z());
        high = std::max(high, pose.translation.z());
    }
    CHECK(high - low == Approx(170.0).margin(8.0));

    // New Corpus from Files has the same box, its choice reaches the corpus's import, and each
    // file's row says the height it gives.
    app::NewCorpusDialog corpus;
    corpus.addInputs({QString::fromStdString(file.string())});
    REQUIRE(corpus.unitsBox());
    CHECK(corpus.buildOptions().import.bvh.guessUnits);
    auto* table = corpus.findChild<QTableWidget*>();
    REQUIRE(table);
    const auto rowText = [table] {
        QString text;
        for (int column = 0; column < table->columnCount(); ++column)
            if (table->item(0, column)) text += table->item(0, column)->text() + QStringLiteral(" | ");
        return text;
    };
    INFO(rowText().toStdString());
    CHECK(rowText().contains(QStringLiteral("0.6")));
    corpus.unitsBox()->setCurrentIndex(corpus.unitsBox()->findText(QStringLiteral("Inches")));
    CHECK_FALSE(corpus.buildOptions().import.bvh.guessUnits);
    CHECK(corpus.buildOptions().import.bvh.unitScale == 2.54);
    INFO(rowText().toStdString());
    CHECK(rowText().contains(QStringLiteral("1.7")));
}

TEST_CASE("six BVH files imported at once ask one dialog for all of them and import every one", "[app][import]")
{
    auto window = test::demoWindow();
    REQUIRE(window);
    const auto dir = test::scratchDir("app_import_six");
    QStringList files;
    for (const auto& path : writeFixtures(dir, {"w1.bvh", "w2.bvh", "w3.bvh", "w4.bvh", "w5.bvh", "w6.bvh"}))
        files << QString::fromStdString(path.string());
    const auto importedCount = [&window] {
        return std::count_if(window->document().derivedTakes().begin(), window->document().derivedTakes().end(),
                             [](const app::DerivedTake& take) { return take.id.isImported(); });
    };
    const auto importedBefore = importedCount();
    window->files().setDialogsEnabled(true);
    int dialogs = 0, jointDialogs = 0, rows = 0;
    QString heights;
    // Every modal dialog that opens is counted; the one for all files: the left side, then OK.
    QTimer watcher;
    watcher.setInterval(10);
    QObject::connect(&watcher, &QTimer::timeout, [&] {
        QWidget* modal = QApplication::activeModalWidget();
        if (auto* joints = qobject_cast<app::JointMapDialog*>(modal)) {
            ++jointDialogs;
            joints->reject();
        } else if (auto* all = qobject_cast<app::ImportTakesDialog*>(modal)) {
            ++dialogs;
            rows = all->table()->rowCount();
            heights = all->table()->item(0, 2)->text();
            all->sideBox()->setCurrentIndex(1);
            REQUIRE(all->problem().isEmpty());
            QTest::mouseClick(okButton(*all), Qt::LeftButton);
        }
    });
    watcher.start();
    const int imported = window->files().imports().importTakeFiles(files);
    watcher.stop();
    window->files().setDialogsEnabled(false);
    CHECK(dialogs == 1);
    CHECK(jointDialogs == 0);
    CHECK(rows == 6);
    CHECK(heights.endsWith(QStringLiteral(" m")));
    REQUIRE(imported == 6);
    CHECK(importedCount() == importedBefore + 6);
    // Every take follows the left arm chosen for all of them.
    const auto take = window->document().selectedTake(app::TakeSlot::A);
    REQUIRE(take->skeleton);
    CHECK(take->skeleton->skeleton->binding("arm")->joint == take->skeleton->skeleton->find("mixamorig:LeftForeArm"));
}

namespace {

/// A Mixamo-named fixture BVH imported in `window` and exported from take A as glTF binary (the
/// skeleton with the 3D view's geometry): an FBX/glTF/Collada take of a known skeleton.
fs::path mixamoGlb(app::MainWindow& window, const fs::path& dir, const std::string& name)
{
    const auto bvh = writeFixtures(dir, {name + ".bvh"}).front();
    REQUIRE(window.files().imports().importTakeFile(QString::fromStdString(bvh.string())));
    const fs::path glb = dir / (name + ".glb");
    REQUIRE(window.exports().exportTake(app::TakeSlot::A, QString::fromStdString(glb.string())));
    return glb;
}

} // namespace

TEST_CASE("File > Import Take and drag and drop of a glTF take keep its skeleton and show the joint dialog on it", "[app][import][scene]")
{
    auto window = test::demoWindow();
    REQUIRE(window);
    const auto dir = test::scratchDir("app_import_glb");
    const fs::path glb = mixamoGlb(*window, dir, "mixamo");
    const auto source = window->document().selectedTake(app::TakeSlot::A);
    window->files().setDialogsEnabled(true);
    bool shown = false;
    // The file is read behind a progress dialog first: the joint dialog is waited for.
    QTimer poll;
    QObject::connect(&poll, &QTimer::timeout, [&] {
        auto* dialog = qobject_cast<app::JointMapDialog*>(QApplication::activeModalWidget());
        if (dialog == nullptr || shown) return;
        shown = true;
        QTest::mouseClick(okButton(*dialog), Qt::LeftButton);
    });
    poll.start(20);
    const bool imported = window->files().imports().importTakeFile(QString::fromStdString(glb.string()));
    poll.stop();
    window->files().setDialogsEnabled(false);
    REQUIRE(shown);
    REQUIRE(imported);
    const auto take = window->document().selectedTake(app::TakeSlot::A);
    REQUIRE(take != source);
    REQUIRE(take->skeleton);
    const auto& skeleton = *take->skeleton->skeleton;
    CHECK(skeleton.binding("hand")->joint == skeleton.find("mixamorig:RightHand"));
    REQUIRE(take->frameCount() == source->frameCount());
    for (Eigen::Index f = 0; f < take->frameCount(); ++f) {
        const auto ours = take->skeleton->worldPoses(f), theirs = source->skeleton->worldPoses(f);
        for (std::size_t j = 0; j < source->skeleton->skeleton->joints.size(); ++j) {
            const auto& joint = source->skeleton->skeleton->joints[j];
            if (joint.endSite) continue;
            const int k = skeleton.find(joint.name);
            REQUIRE(k >= 0);
            CHECK((ours[std::size_t(k)].translation - theirs[j].translation).norm() < 1e-3);
        }
    }
    // Dropped on the window: imported the same way (no dialog when dialogs are off).
    CHECK(window->files().openDroppedPaths({QString::fromStdString(glb.string())}) == 1);
    CHECK(window->document().selectedTake(app::TakeSlot::A)->frameCount() == source->frameCount());
    // A project keeps the imported glTF takes and reads them again when reopened.
    const QString project = QString::fromStdString((dir / "glb.bunraku.json").string());
    REQUIRE(window->files().projects().saveProject(project));
    auto reopened = test::demoWindow();
    REQUIRE(reopened);
    REQUIRE(reopened->files().projects().openProject(project));
    int fromGlb = 0;
    for (const auto& derived : reopened->document().derivedTakes()) {
        if (!derived.sourcePath.endsWith(QStringLiteral(".glb"))) continue;
        ++fromGlb;
        REQUIRE(derived.take);
        REQUIRE(derived.take->skeleton);
        CHECK(derived.take->skeleton->skeleton->find("mixamorig:RightHand") >= 0);
        CHECK(derived.take->frameCount() == source->frameCount());
    }
    CHECK(fromGlb == 2);
}

TEST_CASE("new corpus from glTF files lists each file's animation and part map and makes the corpus", "[app][import][scene]")
{
    auto window = test::demoWindow();
    REQUIRE(window);
    const auto dir = test::scratchDir("app_new_corpus_glb");
    mixamoGlb(*window, dir / "made", "walk_happy_1");
    mixamoGlb(*window, dir / "made", "walk_sad_1");
    fs::create_directories(dir / "in");
    for (const std::string name : {"walk_happy_1.glb", "walk_sad_1.glb"}) fs::copy_file(dir / "made" / name, dir / "in" / name);
    app::NewCorpusDialog dialog;
    dialog.addInputs({QString::fromStdString((dir / "in").string())});
    QTableWidget* table = dialog.table();
    REQUIRE(table->rowCount() == 2);
    const QString map = table->item(0, app::NewCorpusDialog::MapColumn)->text();
    INFO(map.toStdString());
    CHECK(map.startsWith(QStringLiteral("animation 0 of 1")));
    CHECK(map.contains(QStringLiteral("hand=mixamorig:RightHand")));
    // An animation the files do not have: the row says so and Create is refused.
    dialog.animationEdit()->setText(QStringLiteral("run"));
    CHECK(table->item(0, app::NewCorpusDialog::MapColumn)->text().contains(QStringLiteral("no animation 'run'")));
    CHECK(!dialog.problem().isEmpty());
    dialog.animationEdit()->setText(QStringLiteral("0"));
    const QString output = QString::fromStdString((dir / "corpus").string());
    dialog.setOutputFolder(output);
    REQUIRE(dialog.problem().isEmpty());
    REQUIRE(window->files().corpora().createCorpusFromFiles(dialog.sources(), dialog.buildOptions(), output));
    const auto& corpus = window->document().corpus();
    REQUIRE(corpus.takes.size() == 2);
    for (const auto& take : corpus.takes) {
        REQUIRE(take.skeleton);
        CHECK(take.skeleton->skeleton->find("mixamorig:RightHand") >= 0);
    }
}

TEST_CASE("File > Import Take of a glTF file with two animations lists them before the joint dialog", "[app][import][scene]")
{
    auto window = test::demoWindow();
    REQUIRE(window);
    const auto dir = test::scratchDir("app_import_animations");
    // Two nodes; animation "walk" turns root, "idle" holds its translation (keys in the buffer).
    const fs::path file = test::writeText(dir / "two.gltf", R"({"asset":{"version":"2.0"},"scene":0,"scenes":[{"nodes":[0]}],
"nodes":[{"name":"root","translation":[0,1,0],"children":[1]},{"name":"tip","translation":[0.1,0,0]}],
"buffers":[{"byteLength":72,"uri":"data:application/octet-stream;base64,AAAAAM3MzD0AAAAAAAAAAAAAAAAAAIA/AAAAAAAAAAAV78M+XoNsPwAAAAAAAAA/AAAAAAAAgD8AAAAAAAAAAAAAgD8AAAAA"}],
"bufferViews":[{"buffer":0,"byteOffset":0,"byteLength":8},{"buffer":0,"byteOffset":8,"byteLength":32},{"buffer":0,"byteOffset":40,"byteLength":8},{"buffer":0,"byteOffset":48,"byteLength":24}],
"accessors":[{"bufferView":0,"componentType":5126,"count":2,"type":"SCALAR","min":[0],"max":[0.1]},{"bufferView":1,"componentType":5126,"count":2,"type":"VEC4"},
{"bufferView":2,"componentType":5126,"count":2,"type":"SCALAR","min":[0],"max":[0.5]},{"bufferView":3,"componentType":5126,"count":2,"type":"VEC3"}],
"animations":[{"name":"walk","channels":[{"sampler":0,"target":{"node":0,"path":"rotation"}}],"samplers":[{"input":0,"output":1}]},
{"name":"idle","channels":[{"sampler":0,"target":{"node":0,"path":"translation"}}],"samplers":[{"input":2,"output":3}]}]})");
    window->files().setDialogsEnabled(true);
    QStringList listed;
    bool jointDialog = false;
    QTimer poll;
    QObject::connect(&poll, &QTimer::timeout, [&] {
        QWidget* modal = QApplication::activeModalWidget();
        if (auto* input = qobject_cast<QInputDialog*>(modal); input && listed.isEmpty()) {
            listed = input->comboBoxItems();
            input->setTextValue(listed.value(1));
            input->accept();
        } else if (auto* joints = qobject_cast<app::JointMapDialog*>(modal); joints && !jointDialog) {
            jointDialog = true; // two joints cannot carry the puppet's four parts: cancelled
            joints->reject();
        }
    });
    poll.start(20);
    const bool imported = window->files().imports().importTakeFile(QString::fromStdString(file.string()));
    poll.stop();
    window->files().setDialogsEnabled(false);
    CHECK(listed == QStringList({QStringLiteral("0: walk"), QStringLiteral("1: idle")}));
    CHECK(jointDialog);
    CHECK_FALSE(imported);
}
