#pragma once
/// The Design dock: the warp curve editor over the extracted correspondence, the per-phrase
/// gain table (with the gains extracted for the phrase boundaries in use), and buttons to show
/// the designed take (with its original as a ghost), to use the extracted gains, and to add a
/// phrase boundary at the time cursor or remove the one nearest to it (so the phrase structure
/// is editable without the mouse; the timeline's ticks do the same by mouse), and under them the
/// per-scale approximation error of the extracted cell (thesis 5.4.1, Fig. 5.16). A notice over
/// the editors names the phrases and DOF whose extracted g1 is ill-conditioned and why (their
/// cells are shaded in the gain table, with the reason in the tooltip).

#include <QWidget>

class QLabel;

namespace bunraku::widgets {
class GainTable;
class ScaleErrorPlot;
class WarpCurveEditor;
} // namespace bunraku::widgets

namespace bunraku::app {

class DesignController;
class Document;

class DesignPanel : public QWidget {
    Q_OBJECT
public:
    DesignPanel(Document& document, DesignController& controller, QWidget* parent = nullptr);

    widgets::WarpCurveEditor* editor() const { return m_editor; }
    widgets::GainTable* gainTable() const { return m_gains; }
    /// Fig. 5.16 of the emotional cell the phase was extracted from.
    widgets::ScaleErrorPlot* scaleErrorPlot() const { return m_scaleError; }

    /// The status line under the editors (synthesis time, why extracted gains are missing).
    QString statusText() const;
    /// The ill-conditioned-gains notice ("" when every extracted g1 is well conditioned).
    QString illConditionedNotice() const;
    /// Whether the notice is shown (not hidden; the panel itself may be hidden).
    bool illConditionedNoticeShown() const;

private:
    void refresh();
    void showStatus();
    void showConditioning();
    /// The functional frame under the time cursor on take A.
    double cursorFrame() const;

    Document& m_document;
    DesignController& m_controller;
    widgets::WarpCurveEditor* m_editor = nullptr;
    widgets::GainTable* m_gains = nullptr;
    widgets::ScaleErrorPlot* m_scaleError = nullptr;
    QLabel* m_inputs = nullptr;
    QLabel* m_timing = nullptr;
    QLabel* m_conditioning = nullptr;
};

} // namespace bunraku::app
