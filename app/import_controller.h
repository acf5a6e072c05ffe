#pragma once
/// File > Import Take...: a take file (CSV, BVH with its joint map dialog, FBX, glTF, Collada,
/// FASTRAK) imported into the document as an undoable command, read off the GUI thread behind a
/// progress dialog that can cancel it. Errors are told by the FileController.

#include "analysis/io/take_reader.h"

#include <QObject>
#include <QString>
#include <QStringList>

#include <optional>

class QAction;

namespace bunraku::app {

class Document;
class FileController;

class ImportController : public QObject {
    Q_OBJECT
public:
    ImportController(Document& document, FileController& files);

    /// Imports a take; `jointMap` ("head=Head,...", may be empty) applies to BVH files (with
    /// dialogs and no map, the joint map dialog asks first, from the file's first pose). With
    /// dialogs the file is read and imported off the GUI thread behind a progress dialog that
    /// can cancel it; a cancelled import changes nothing.
    bool importTakeFile(const QString& file, const QString& jointMap = {});
    /// Imports several take files: with dialogs and more than one BVH file, one dialog
    /// (import_takes_dialog.h) chooses the joints, side and units of all of them first. Stops at
    /// the first failure (FileController::lastError); returns how many were imported.
    int importTakeFiles(const QStringList& files);

    QAction* importAction() const { return m_import; }

private:
    /// importTakeFile, with the BVH options `preset` chosen in a dialog for several files (no
    /// joint dialog then).
    bool importTake(const QString& file, const std::optional<analysis::io::BvhImportOptions>& preset, const QString& jointMap = {});
    void chooseAndImport();

    Document& m_document;
    FileController& m_files;
    QAction* m_import = nullptr;
};

} // namespace bunraku::app
