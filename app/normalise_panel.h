#pragma once
/// The Normalisation dock (thesis 3.5-3.8), a view of the pipeline's normalise stage (every cell
/// normalised by the AnalysisController's scheduler): take A's cell's reference (suggested by
/// thesis 3.6.1, a take, or the 3.7 average take), tau, T_cmp, the largest scale, the coupling
/// and the path (their limits in their tool tips; a typed value beyond them is clamped and said
/// in the status bar); the variance table (before and after, per take, DOF family and part, in
/// cm^2 and deg^2, worse rows marked), the correspondence curves with a legend and the stage's
/// errors; the summary names the reference and the parameters the result was computed with. Take A normalised is the live take "normalised" (the controller's).
/// Consecutive steps of a spin box are one undo step.

#include "app/document.h"

#include "widgets/bounded_spin_box.h"

#include <QWidget>

#include <memory>

class QComboBox;
class QCustomPlot;
class QLabel;
class QSpinBox;
class QTreeWidget;

namespace bunraku::app {

class AnalysisController;

class NormalisePanel : public QWidget {
    Q_OBJECT
public:
    NormalisePanel(Document& document, AnalysisController& analysis, QWidget* parent = nullptr);
    ~NormalisePanel() override;

    /// Take A normalised by the latest result, null before one arrived.
    TakePointer normalisedTake() const;
    /// The summary line (the cell, its reference, or the stage's error).
    QString summaryText() const;
    /// The variance table (app/variance_tree.h): per take, DOF family and part.
    QTreeWidget* varianceTree() const { return m_table; }
    /// The correspondence curves (one per take, named in the legend).
    QCustomPlot* correspondencePlot() const { return m_curves; }
    widgets::BoundedSpinBox* tauSpin() const { return m_tau; }
    widgets::BoundedSpinBox* searchBandSpin() const { return m_band; }
    widgets::BoundedSpinBox* maxScaleSpin() const { return m_scales; }

signals:
    /// A message for the status bar (a typed value clamped to its limits).
    void statusMessage(const QString& message);

private:
    void refreshControls();
    void showResult();
    /// The cell shown: take A's, or the last one while A is a derived take.
    std::pair<std::string, std::string> shownCell() const;

    Document& m_document;
    AnalysisController& m_analysis;
    QComboBox* m_reference = nullptr;
    widgets::BoundedSpinBox* m_tau = nullptr;
    widgets::BoundedSpinBox* m_band = nullptr;
    widgets::BoundedSpinBox* m_scales = nullptr;
    QComboBox* m_coupling = nullptr;
    QComboBox* m_path = nullptr;
    QLabel* m_summary = nullptr;
    QTreeWidget* m_table = nullptr;
    QCustomPlot* m_curves = nullptr;
    bool m_updating = false;
};

} // namespace bunraku::app
