#pragma once
/// The Design dock: the warp curve editor over the extracted correspondence, the per-phrase
/// gain table, and buttons to show the designed take (with its original as a ghost).

#include <QWidget>

class QLabel;

namespace bunraku::widgets {
class GainTable;
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

private:
    void refresh();

    Document& m_document;
    DesignController& m_controller;
    widgets::WarpCurveEditor* m_editor = nullptr;
    widgets::GainTable* m_gains = nullptr;
    QLabel* m_inputs = nullptr;
    QLabel* m_timing = nullptr;
};

} // namespace bunraku::app
