#pragma once
/// The Emotion dock (thesis ch. 4), a view of the pipeline's decompose stage: the input (the
/// chapter-3-normalised takes, the thesis's, or the preprocessed ones), the method (KM2O-Langevin
/// 4.4.4, the thesis's, or least squares 4.3.1) and KM2O's correlation length M (0: chosen by the
/// relative error P over 1..M_max as 4.4.4 does) are undoable parameters; a change re-decomposes
/// in the background. The emotion weight a (thesis eq. 4.45, x = y + a z) is a slider; the
/// AnalysisController re-synthesises the weighted take of take A's cell on every step (a few
/// microseconds) as the live take "weighted", so it plays as you drag; a spin box beside it
/// shows a and takes a typed value (2.00 exactly, where a drag lands on 2.03). A drag is one
/// undo step, and so are consecutive steps of M, of the slider or of the weight's spin box by
/// arrows, keys or wheel. The text names
/// the weighted cell, a, the method and M the shown result was computed with; a picker chooses
/// the emotion a neutral take is weighted against.

#include "app/document.h"

#include "analysis/pipeline/stages.h"

#include "widgets/bounded_spin_box.h"

#include <QWidget>

class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QSlider;
class QSpinBox;

namespace bunraku::app {

class AnalysisController;

class EmotionPanel : public QWidget {
    Q_OBJECT
public:
    EmotionPanel(Document& document, AnalysisController& analysis, QWidget* parent = nullptr);

    QSlider* weightSlider() const { return m_weight; }
    /// The emotion weight a as a number, beside the slider.
    QDoubleSpinBox* weightBox() const { return m_weightBox; }
    QComboBox* methodBox() const { return m_method; }
    QComboBox* inputBox() const { return m_input; }
    widgets::BoundedSpinBox* orderBox() const { return m_order; }
    /// Which emotion a neutral take A is weighted against (take A's own emotion otherwise).
    QComboBox* emotionBox() const { return m_emotion; }
    /// The method of the decomposition in use ("least-squares" | "km2o"), empty before the first.
    QString decomposedMethod() const;
    /// The M of the KM2O decomposition in use, 0 for least squares.
    int decomposedOrder() const;
    bool ready() const;
    /// The latest weighted take, null before the decomposition finished.
    TakePointer weightedTake() const;
    QString statusText() const;

private:
    void showParameters();
    void showResult();
    /// The emotion picker: take A's function's emotions, the weighted one current.
    void showEmotions();
    /// KM2O's notes on cells with one take as an HTML list, empty when there are none.
    static QString oneTakeNotes(const analysis::pipeline::DecomposeOutput& decomposed);

signals:
    /// A message for the status bar (a typed M clamped to its limits).
    void statusMessage(const QString& message);

private:

    Document& m_document;
    AnalysisController& m_analysis;
    QComboBox* m_input = nullptr;
    QComboBox* m_method = nullptr;
    widgets::BoundedSpinBox* m_order = nullptr;
    QComboBox* m_emotion = nullptr;
    QSlider* m_weight = nullptr;
    QDoubleSpinBox* m_weightBox = nullptr;
    QLabel* m_label = nullptr;
};

} // namespace bunraku::app
