#pragma once
/// The Emotion dock (thesis ch. 4): the corpus is preprocessed (padded, unwrapped, aligned) and
/// decomposed into function y^i and emotion z^{ij} components in the background, by least
/// squares (thesis 4.3.1) or by the KM2O-Langevin equation with correlation length M (thesis
/// 4.4.4; the method and M are undoable parameters and a change re-decomposes); the emotion weight a (thesis eq. 4.45, x = y + a z) is a slider, and the weighted
/// take of take A's cell is re-synthesised on every slider step (a few microseconds) and
/// published as the live take "weighted", so it plays as you drag. A drag is one undo step, and
/// so are consecutive steps of M or of the slider by arrows, keys or wheel (commands.h stepParameter).

#include "app/document.h"

#include <QWidget>

#include <memory>

class QComboBox;
class QLabel;
class QSlider;
class QSpinBox;

namespace bunraku::app {

class Recomputer;
struct EmotionModel;

class EmotionPanel : public QWidget {
    Q_OBJECT
public:
    explicit EmotionPanel(Document& document, QWidget* parent = nullptr);
    ~EmotionPanel() override;

    Recomputer* recomputer() const { return m_recomputer; }
    QSlider* weightSlider() const { return m_weight; }
    QComboBox* methodBox() const { return m_method; }
    QSpinBox* orderBox() const { return m_order; }
    /// The method of the decomposition in use ("least-squares" | "km2o"), empty before the first.
    QString decomposedMethod() const;
    /// The M of the KM2O decomposition in use, 0 for least squares.
    int decomposedOrder() const;
    bool ready() const { return m_model != nullptr; }
    /// The latest weighted take, null before the decomposition finished.
    TakePointer weightedTake() const { return m_weighted; }

private:
    void resolveCell();
    void synthesise();
    void showParameters();

    Document& m_document;
    Recomputer* m_recomputer = nullptr;
    std::shared_ptr<const EmotionModel> m_model;
    TakePointer m_weighted;
    std::string m_function;
    std::string m_emotion;
    QComboBox* m_method = nullptr;
    QSpinBox* m_order = nullptr;
    QSlider* m_weight = nullptr;
    QLabel* m_label = nullptr;
    quint64 m_inputSerial = 0; ///< bumped when the corpus, method or M change
};

} // namespace bunraku::app
