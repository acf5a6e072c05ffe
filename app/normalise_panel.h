#pragma once
/// The Normalisation dock (thesis 3.5-3.8), a view of the pipeline's normalise stage (every cell
/// normalised by the AnalysisController's scheduler): take A's cell's reference (suggested by
/// thesis 3.6.1, a take, or the 3.7 average take), tau, T_cmp, the largest scale, the coupling
/// and the path; the variance table (before and after, per take), the correspondence curves and
/// the stage's errors. Take A normalised is the live take "normalised" (the controller's).
/// Consecutive steps of a spin box are one undo step.

#include "app/document.h"

#include <QWidget>

#include <memory>

class QComboBox;
class QCustomPlot;
class QLabel;
class QSpinBox;
class QTableWidget;

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
    QTableWidget* varianceTable() const { return m_table; }
    QSpinBox* tauSpin() const { return m_tau; }
    QSpinBox* searchBandSpin() const { return m_band; }

private:
    void refreshControls();
    void showResult();

    Document& m_document;
    AnalysisController& m_analysis;
    QComboBox* m_reference = nullptr;
    QSpinBox* m_tau = nullptr;
    QSpinBox* m_band = nullptr;
    QSpinBox* m_scales = nullptr;
    QComboBox* m_coupling = nullptr;
    QComboBox* m_path = nullptr;
    QLabel* m_summary = nullptr;
    QTableWidget* m_table = nullptr;
    QCustomPlot* m_curves = nullptr;
    bool m_updating = false;
};

} // namespace bunraku::app
