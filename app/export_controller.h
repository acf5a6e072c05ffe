#pragma once
/// File > Export Take A / Export Take B: writes the take shown as A or B as BVH (on the take's
/// own skeleton when it has one: the performer's hierarchy, names, offsets and channel order),
/// glTF binary (the skeleton, or the puppet for a take without one, as a skinned mesh with one
/// animation) or CSV, chosen by the file's extension. The same writer as `bunraku ... -o`
/// (render/take_export.h). Writes are atomic; errors name the file and what went wrong.
/// The save dialog also offers the take with its kimono simulated as cloth (`bunraku ... --kimono`):
/// a .glb with the cloth as a mesh moving by morph targets (the figure without its skinned skirt
/// and sleeves), a .csv with the kimono's 18 measured channels; the simulation runs off the GUI
/// thread behind a progress dialog with Cancel.

#include "app/document.h"

#include "analysis/cloth/kimono_cloth.h"

#include <QObject>
#include <QString>

class QAction;
class QWidget;

namespace bunraku::app {

class ExportController : public QObject {
    Q_OBJECT
public:
    ExportController(Document& document, QWidget* window);

    /// With dialogs off (tests, --screenshot) errors go to lastError() and the status signal.
    void setDialogsEnabled(bool enabled) { m_dialogs = enabled; }
    QString lastError() const { return m_lastError; }
    /// What the last export said of a derived take's skeleton and channels (render::takeExportNote).
    QString lastNote() const { return m_lastNote; }

    /// Writes the take shown in `slot` to `file` (.bvh, .glb or .csv); false on failure. With
    /// `kimono`, the take's kimono simulated with clothParameters() goes into the file too (a .glb
    /// or a .csv; a .bvh is refused).
    bool exportTake(TakeSlot slot, const QString& file, bool kimono = false);

    /// The cloth parameters a kimono export simulates with: ClothParameters{} (the command line's
    /// defaults) until set, e.g. from the 3D view's cloth settings.
    void setClothParameters(const analysis::ClothParameters& parameters) { m_cloth = parameters; }
    const analysis::ClothParameters& clothParameters() const { return m_cloth; }

    /// "Export Take A..." / "Export Take B...": a save dialog offering BVH, glTF and CSV.
    QAction* exportAction(TakeSlot slot) const { return slot == TakeSlot::A ? m_exportA : m_exportB; }

signals:
    void statusMessage(const QString& message);

private:
    void chooseAndExport(TakeSlot slot);
    void report(const QString& message);

    Document& m_document;
    QWidget* m_window;
    bool m_dialogs = true;
    QString m_lastError;
    QString m_lastNote;
    analysis::ClothParameters m_cloth;
    QAction* m_exportA = nullptr;
    QAction* m_exportB = nullptr;
};

} // namespace bunraku::app
