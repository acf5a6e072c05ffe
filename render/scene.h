#pragma once
/// What the 3D view shows (thesis 6): up to two takes, each with a puppet built from the body
/// description, its motion axis and the orbits of its sensors, plus a floor grid and a marker
/// for the partner. Plain data and the CPU-side layout rules; the Renderer uploads it.

#include "analysis/body/body_description.h"
#include "analysis/cloth/kimono_cloth.h"
#include "analysis/core/pose.h"
#include "analysis/core/result.h"
#include "analysis/core/take.h"
#include "render/camera.h"
#include "render/mesh.h"

#include <glm/glm.hpp>

#include <array>
#include <map>
#include <memory>
#include <optional>
#include <utility>
#include <string>
#include <string_view>
#include <vector>

namespace bunraku::render {

inline constexpr int kMaxTakeSlots = 2;
/// Body parts the picking IDs can tell apart (renderer.h).
inline constexpr std::size_t kMaxBodyParts = 31;

/// One take on stage.
struct TakeSlot {
    analysis::Take take;
    /// world_T_axis per frame (one per take frame): the motion axis, origin at the centre of
    /// mass, x front-back, z the long axis (thesis 5.2.1). Empty: no axis for this take.
    std::vector<analysis::RigidTransform> world_T_axis;
    /// This take's own body, with the same parts as SceneContent::body (the puppet fitted to the
    /// take's skeleton, analysis/body/body_fit.h); null: SceneContent::body. Drawn from its
    /// primitives (SceneContent::partMeshes replace the shared body's only).
    std::shared_ptr<const analysis::BodyDescription> body = nullptr;
    /// The take's kimono simulated as cloth (analysis/cloth) on the body the take is drawn with:
    /// the modelled puppet is then dressed in it (its skinned skirt and sleeves left out) and the
    /// orbits show the sleeve tips and the hem. Null, or simulated for another take or body: the
    /// skinned kimono.
    std::shared_ptr<const analysis::KimonoSimulation> kimono = nullptr;
    /// What the slot is made from, as the caller holds it (the document's take, its axis, body
    /// and kimono), compared by address: a slot whose sources are those of the same slot of the
    /// scene before, in a scene of the same body source, no part meshes and the same layout,
    /// keeps what the renderer built for it (its posed take, binding, orbits, bounds and
    /// figures), so a scene replaced on every step of a drag of take A rebuilds A alone. The
    /// caller vouches that equal sources mean equal content. Empty: the slot is always built.
    std::vector<std::shared_ptr<const void>> sources = {};
};

struct SceneContent {
    analysis::BodyDescription body;
    /// What `body` is, as the caller holds it (for TakeSlot::sources); null: slots are always built.
    std::shared_ptr<const void> bodySource = nullptr;
    /// Meshes loaded from files (mesh_file.h) that replace a body part's primitives, by body
    /// part name; vertices in the part (sensor) frame, cm.
    std::map<std::string, Mesh> partMeshes;
    /// One or two takes: two are placed side by side (see slotRoot).
    std::vector<TakeSlot> takes;
};

/// How a take's figure is drawn: the puppet, the performer's skeleton (a take that carries one,
/// analysis/core/skeleton.h; a take without one shows its puppet), both overlaid, the
/// performer's body (a smooth mannequin skinned to the skeleton, analysis/body/performer_body.h;
/// its capsules for a skeleton of more joints than a body is made for), or the file's own mesh
/// (the skinned mesh an FBX/glTF/Collada file carries for its skeleton, Skeleton::mesh; the
/// skeleton's capsules for a take without one: takeHasFileMesh).
enum class FigureStyle { Puppet, Skeleton, PuppetAndSkeleton, Body, FileMesh };

/// The figure styles by their command-line names ("puppet", "skeleton", "both", "body", "mesh"),
/// as `bunraku render --figure` and the workbench's `--figure` spell them; nullopt for others.
std::optional<FigureStyle> figureStyleFromName(std::string_view name);
/// True when the take carries a skinned mesh of its file that fits its skeleton (the "File's
/// mesh" figure can show it).
bool takeHasFileMesh(const analysis::Take& take);

enum class OrbitVisibility {
    WhenPuppetHidden, ///< as in the thesis: orbits replace the puppet
    Always,
};

/// Which objects are drawn; any combination.
struct SceneVisibility {
    bool puppet = true;
    bool axis = true;
    bool orbits = true;
    bool grid = true;    ///< the floor and its grid
    bool shadows = true; ///< the figures' shadows on the floor (drawn with it)
    bool partner = true;
    OrbitVisibility orbitVisibility = OrbitVisibility::WhenPuppetHidden;
    /// Per take slot, what `puppet` (the figure) shows.
    std::array<FigureStyle, kMaxTakeSlots> figures{FigureStyle::Puppet, FigureStyle::Puppet};

    /// True when orbits are drawn given the puppet's visibility.
    bool orbitsDrawn() const { return orbits && (orbitVisibility == OrbitVisibility::Always || !puppet); }
};
/// The objects' names (`bunraku render --show`), one per switch of SceneVisibility.
inline constexpr std::pair<const char*, bool SceneVisibility::*> kSceneObjects[] = {
    {"puppet", &SceneVisibility::puppet}, {"axis", &SceneVisibility::axis},       {"orbits", &SceneVisibility::orbits},
    {"grid", &SceneVisibility::grid},     {"shadows", &SceneVisibility::shadows}, {"partner", &SceneVisibility::partner}};

struct LayoutOptions {
    float separation = 70.0f;      ///< cm between the two puppets' centres, along the screen's right
    bool centreTakes = true;       ///< move each take's centre (takeCentre) to the origin
    /// cm from a take's centre along +x (towards the partner); further for a take that travels
    /// that way (the partner keeps 60 cm clear of its furthest reach)
    float partnerDistance = 110.0f;
    float gridHalfExtent = 200.0f; ///< cm, at least (the floor grows with a take's path)
    float gridSpacing = 20.0f;     ///< cm
    float axisBarLength = 30.0f;   ///< cm, each bar from the centre of mass along +x, +y, +z
    float axisBarThickness = 1.6f; ///< cm
    float orbitPointRadius = 1.6f; ///< cm, the moving point on each orbit
    bool operator==(const LayoutOptions&) const = default;
};

/// Checks 1..2 takes, a body of 1..kMaxBodyParts parts, every take valid and able to drive its body (bindBody, through
/// drawnTake), a take's own body with the scene body's parts, axis poses one per frame when given, part meshes named
/// after body parts. `drawn` (optional) receives each slot's drawnTake, so a caller poses them
/// without making them again. Slots whose `kept` entry is true are not checked again (a renderer
/// keeps what it built for them); `drawn` receives an empty take for each.
analysis::Status validateScene(const SceneContent& scene, std::vector<analysis::Take>* drawn = nullptr,
                               const std::vector<bool>& kept = {});

/// The take a slot draws: `take` itself when it has the parts that drive `body`; else, for a take
/// of a skeleton's joints (the whole body, every joint a part) whose skeleton binds the puppet's
/// four parts, the puppet take its skeleton poses (analysis/core/skeleton_take.h,
/// puppetTakeFromSkeleton: the same motion, the puppet, skeleton and performer figures on it).
/// Otherwise bindBody's error.
analysis::Result<analysis::Take> drawnTake(const analysis::BodyDescription& body, const analysis::Take& take);
/// True for a take the 3D view can pose: the puppet's 24 channels, or a skeleton that binds the
/// puppet's four parts (drawnTake).
bool drawableTake(const analysis::Take& take);

/// Where a take stands: the mean position over the take of `centrePart`'s sensor (the puppet's
/// shoulder: its mirror frame) in x and y, z = 0. Without that part, the mean of every 6-DOF
/// part's sensor.
glm::vec3 takeCentre(const analysis::Take& take, std::string_view centrePart = "shoulder");

/// world_T_take for take `slotIndex` of `slotCount`: the take's centre (when centring) moved to
/// the origin, then, with two takes, the first shifted half the separation to the screen's left
/// and the second to its right, whatever the camera's angle (thesis Fig. 6.18).
glm::mat4 slotRoot(const glm::vec3& centre, int slotIndex, int slotCount, const Camera& camera,
                   const LayoutOptions& options);

/// The frame shown at `seconds` (nearest, clamped to the take).
Eigen::Index frameAtTime(const analysis::Take& take, double seconds);

/// The 4x4 matrix of a rigid transform (cm).
glm::mat4 toMatrix(const analysis::RigidTransform& a_T_b);

/// Display colour of the orbit of sensor `sensorIndex` (0..) of take `slotIndex`.
glm::vec3 orbitColour(int slotIndex, int sensorIndex);

/// Display colour of the orbit of the kimono's measured point `point` (analysis::KimonoPoint) of
/// take `slotIndex`: the sleeve tips crimson, the hem's points plum.
glm::vec3 kimonoOrbitColour(int slotIndex, int point);

/// Colours of the motion axis bars: x red, y green, z blue.
glm::vec3 axisColour(int axis);

} // namespace bunraku::render
