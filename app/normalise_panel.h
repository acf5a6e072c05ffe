#pragma once
/// The Normalisation dock (thesis 3.5-3.8): the takes of take A's function x emotion cell are
/// normalised to a reference take (chosen, or suggested by thesis 3.6.1) with the parameters
/// tau, T_cmp, the largest scale, the coupling and the path method. Recomputed in the
/// background on every parameter change; the results update live: the variance table (before
/// and after, per take), the correspondence curves, and take A normalised, published as the
/// live take "normalised" with A as its ghost. Consecutive steps of a spin box are one undo step.

#include "app/document.h"

#include <QWidget>

#include <memory>

class QComboBox;
class QCustomPlot;
class QLabel;
class QSpinBox;
class QTableWidget;

namespace bunraku::app {

class Recomputer;
struct NormaliseOutput;

class NormalisePanel : public QWidget {
    Q_OBJECT
public:
    explicit NormalisePanel(Document& document, QWidget* parent = nullptr);
    ~NormalisePanel() override;

    Recomputer* recomputer() const { return m_recomputer; }
    /// Take A normalised by the latest result, null before one arrived.
    TakePointer normalisedTake() const;
    QTableWidget* varianceTable() const { return m_table; }
    QSpinBox* tauSpin() const { return m_tau; }
    QSpinBox* searchBandSpin() const { return m_band; }

private:
    void refreshControls();
    void accept(std::shared_ptr<const NormaliseOutput> output);

    Document& m_document;
    Recomputer* m_recomputer = nullptr;
    std::shared_ptr<const NormaliseOutput> m_output;
    QComboBox* m_reference = nullptr;
    QSpinBox* m_tau = nullptr;
    QSpinBox* m_band = nullptr;
    QSpinBox* m_scales = nullptr;
    QComboBox* m_coupling = nullptr;
    QComboBox* m_path = nullptr;
    QLabel* m_summary = nullptr;
    QTableWidget* m_table = nullptr;
    QCustomPlot* m_curves = nullptr;
    QString m_cellKey;
    bool m_updating = false;
};

} // namespace bunraku::app
