#pragma once
/// The per-phrase gain table of a design (thesis 5.4): one row per phrase, one column per axis
/// DOF, each cell g0 over g1 (two lines, so six columns stay legible in a narrow dock); the selected cell's g0 and g1 are edited with two sliders on a
/// logarithmic scale (0.25 to 4). The table never changes its own gains: it proposes edits
/// (gainEdited) and shows what setGains gives it. The extracted gains (setExtracted) are shown
/// for comparison in each cell's tooltip and beside the selected cell's values; a cell whose
/// extracted g1 is ill-conditioned (analysis::DofGain::illConditioned) is shaded and its tooltip
/// says why.

#include "analysis/design/phrase_gains.h"

#include <QWidget>

class QLabel;
class QSlider;
class QTableWidget;

namespace bunraku::widgets {

class GainTable : public QWidget {
    Q_OBJECT
public:
    explicit GainTable(QWidget* parent = nullptr);

    void setGains(const analysis::GainSet& gains);
    const analysis::GainSet& gains() const { return m_gains; }
    /// The gains extracted from the emotional take for the same phrases (empty: none known).
    void setExtracted(const analysis::GainSet& extracted);
    const analysis::GainSet& extracted() const { return m_extracted; }
    /// The text under the table describing the selected cell.
    QString selectionText() const;
    /// Selects the cell of `phrase` and `dof` (binds the sliders to it).
    void selectCell(int phrase, int dof);
    QSlider* g0Slider() const { return m_g0; }
    QSlider* g1Slider() const { return m_g1; }
    QTableWidget* table() const { return m_table; }
    /// True when the extracted gain of `phrase` and `dof` (same phrase frames) is ill-conditioned.
    bool isIllConditioned(int phrase, int dof) const;
    /// True when every line of the cell's text fits its column width and row height unelided.
    bool cellTextFits(int phrase, int dof) const;
    /// A cell's text: g0 over g1, two decimals each.
    static QString cellText(const analysis::DofGain& gain);

    /// Slider position <-> gain: 2^(position / 100), position in [-200, 200].
    static double gainOfPosition(int position);
    static int positionOfGain(double gain);

signals:
    void dragStarted();
    void dragFinished();
    /// The user proposes g0 and g1 for one phrase and DOF.
    void gainEdited(int phrase, int dof, double g0, double g1);

private:
    /// Horizontal room an item needs beside its text, pixels: the style's text margins (2 x 3 in
    /// Fusion) and a pixel of grid line on each side.
    static constexpr int kCellMargin = 8;
    void fitColumns();
    void bindSliders();
    void updateTooltips();
    void sliderMoved();

    QTableWidget* m_table = nullptr;
    QSlider* m_g0 = nullptr;
    QSlider* m_g1 = nullptr;
    QLabel* m_label = nullptr;
    analysis::GainSet m_gains;
    analysis::GainSet m_extracted;
    bool m_binding = false;
};

} // namespace bunraku::widgets
