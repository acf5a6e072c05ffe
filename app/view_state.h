#pragma once
/// The view a project keeps (the "view" object of the project file, app/project_file.h): what
/// MainWindow::viewState gathers from the docks and restoreViewState gives back. Every value is
/// optional: one a project does not hold (written before it existed, or a window layout that
/// could not be read) leaves the view as it is.

#include "analysis/cloth/kimono_cloth.h"

#include <QByteArray>
#include <QString>

#include <array>
#include <optional>
#include <utility>

namespace bunraku::app {

/// The 3D view's camera (render::Camera): degrees and centimetres.
struct CameraState {
    double angle = 0.0;
    double elevation = 0.0;
    double distance = 0.0;
    std::array<double, 3> target{};
    double fov = 35.0;
};

/// The 3D view's boxes of what it draws and Follow, each kept when the project holds it.
struct ShownObjects {
    std::optional<bool> puppet;
    std::optional<bool> axis;
    std::optional<bool> orbits;
    std::optional<bool> grid;
    std::optional<bool> shadows;
    std::optional<bool> partner;
    std::optional<bool> follow;
};
/// Their keys in the project file's "view"."show" object, one table for the file and the view.
inline constexpr std::pair<const char*, std::optional<bool> ShownObjects::*> kShownObjectKeys[] = {
    {"puppet", &ShownObjects::puppet}, {"axis", &ShownObjects::axis},       {"orbits", &ShownObjects::orbits},
    {"grid", &ShownObjects::grid},     {"shadows", &ShownObjects::shadows}, {"partner", &ShownObjects::partner},
    {"follow", &ShownObjects::follow}};

struct ViewState {
    // The Graphs dock: widgets::GraphLayout, TwoTakeMode, ValueScale and AngleDisplay as numbers,
    // the thesis's ticks, the part and DOF selected.
    std::optional<int> graphLayout;
    std::optional<int> twoTakeMode;
    std::optional<int> valueScale;
    std::optional<int> angleDisplay;
    std::optional<bool> thesisTicks;
    std::optional<QString> part;
    std::optional<QString> dof;
    // The 3D view: its camera, each take's figure (the boxes' indices), the kimono as cloth and
    // its settings.
    std::optional<CameraState> camera;
    ShownObjects shown;
    std::optional<int> figureA;
    std::optional<int> figureB;
    std::optional<bool> cloth;
    std::optional<analysis::ClothParameters> clothParameters;
    /// The emotion a neutral take A is weighted against.
    std::optional<QString> weightEmotion;
    /// The cell (function, emotion) the live results were computed for (AnalysisController's):
    /// a project reopened on a live take A recomputes it for this cell.
    std::optional<QString> cellFunction;
    std::optional<QString> cellEmotion;
    /// Playback speed.
    std::optional<double> speed;
    /// The docks' places and sizes (QMainWindow::saveState) and the left column's width.
    std::optional<QByteArray> windowState;
    std::optional<int> leftWidth;
    /// The window's width the layout was saved in.
    std::optional<int> windowWidth;
};

} // namespace bunraku::app
