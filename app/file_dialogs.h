#pragma once
/// The workbench's file dialogs: each purpose (open a corpus, save a project, a screenshot, the
/// report, a video...) opens in the folder last chosen for it - else the folder last chosen for
/// anything, else the open project's folder, else the home folder (never a folder such as
/// ~/Videos the person never went to) - and save dialogs suggest a name made of what is shown
/// ("demo-greeting-none-2.png"). Folders are kept in QSettings ("folders/<purpose>").
///
/// Tests (and scripted runs) replace the dialogs with setFileChooser: it receives the purpose
/// and the path the dialog would have started at, and returns the chosen path ("" = cancel).

#include <QString>

#include <functional>

class QWidget;

namespace bunraku::app {

class Document;

/// NewCorpus: where File > New Corpus from Files writes corpora (not where corpora are opened
/// from: that is often the user's data folder, never the place to write into).
enum class FilePurpose { Corpus, NewCorpus, Project, ImportTake, ExportTake, Screenshot, Report, Video, VideoFrames };

/// The settings key of a purpose's folder: "folders/screenshot".
QString purposeKey(FilePurpose purpose);
/// The folder a dialog for `purpose` starts in (see the file comment); `projectFile` is the open
/// project, if any.
QString rememberedFolder(FilePurpose purpose, const QString& projectFile = {});
/// The folder last chosen for `purpose` itself (no fallback), empty when none exists.
QString rememberedPurposeFolder(FilePurpose purpose);
/// The workbench's own folder for what it writes for `purpose` when the person has chosen none
/// yet: "<Documents>/Bunraku/corpora" for NewCorpus (it need not exist yet).
QString workbenchFolder(FilePurpose purpose);
/// A name for a new folder in `parent` that does not exist yet: `name`, else "name-2", "name-3"...
QString unusedFolder(const QString& parent, const QString& name);
/// Remembers the folder holding `path` (a file, or a chosen folder: its parent, where its
/// siblings are) for `purpose` and as the last folder of all.
void rememberFolder(FilePurpose purpose, const QString& path);

/// What a suggested name is made of.
enum class NameParts { CorpusAndTakeA, CorpusAndTakeB, Corpus };
/// A file name (without folder) for what the document shows: the corpus ("demo" or the corpus
/// folder's name) and take A's (or B's) name (Document::takeName), made safe for file
/// systems, then `suffix` (".png").
QString suggestedFileName(const Document& document, const QString& suffix, NameParts parts = NameParts::CorpusAndTakeA);

/// Replaces the dialogs (null restores them).
using FileChooser = std::function<QString(FilePurpose purpose, const QString& start)>;
void setFileChooser(FileChooser chooser);

/// A save dialog starting at rememberedFolder/`suggestedName`; remembers the chosen folder.
/// `selectedFilter`, when given, is the filter shown first and receives the one chosen.
QString chooseSaveFile(QWidget* parent, FilePurpose purpose, const QString& title, const QString& suggestedName,
                       const QString& filter, const QString& projectFile = {}, QString* selectedFilter = nullptr);
/// An open dialog starting in rememberedFolder; remembers the chosen folder.
QString chooseOpenFile(QWidget* parent, FilePurpose purpose, const QString& title, const QString& filter,
                       const QString& projectFile = {});
/// A folder dialog starting in rememberedFolder; remembers the chosen folder's parent.
QString chooseFolder(QWidget* parent, FilePurpose purpose, const QString& title, const QString& projectFile = {});

} // namespace bunraku::app
