#pragma once
/// The Emotion dock (thesis ch. 4): the corpus is preprocessed (padded, unwrapped, aligned) and
/// decomposed by least squares into function y^i and emotion z^{ij} components in the
/// background; the emotion weight a (thesis eq. 4.45, x = y + a z) is a slider, and the weighted
/// take of take A's cell is re-synthesised on every slider step (a few microseconds) and
/// published as the live take "weighted", so it plays as you drag. A drag is one undo step.

#include "app/document.h"

#include <QWidget>

#include <memory>

class QComboBox;
class QLabel;
class QSlider;

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
    bool ready() const { return m_model != nullptr; }
    /// The latest weighted take, null before the decomposition finished.
    TakePointer weightedTake() const { return m_weighted; }

private:
    void resolveCell();
    void synthesise();

    Document& m_document;
    Recomputer* m_recomputer = nullptr;
    std::shared_ptr<const EmotionModel> m_model;
    TakePointer m_weighted;
    std::string m_function;
    std::string m_emotion;
    QComboBox* m_method = nullptr;
    QSlider* m_weight = nullptr;
    QLabel* m_label = nullptr;
    quint64 m_corpusSerial = 0;
};

} // namespace bunraku::app
