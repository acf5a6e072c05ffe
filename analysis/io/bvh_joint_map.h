#pragma once
/// The automatic part map: which joints of any BVH skeleton drive the puppet's head, shoulder,
/// arm and hand. Joints are found by name synonyms first (case-insensitive; namespace prefixes
/// such as `mixamorig:`, 3ds Max's `Bip01 R `, side marks such as `R_`, `_L`, `.R`, `Left`,
/// and the single-letter `r`/`l` of CMU and Poser names), then by the skeleton's topology where
/// names fail. The rules are in docs/FORMATS.md ("Automatic part map").

#include "analysis/core/skeleton_anatomy.h"
#include "analysis/io/bvh.h"
#include "analysis/io/bvh_import.h"

#include <array>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace bunraku::analysis::io {

/// How a part's joint was chosen.
enum class MapMethod { Given, Name, Topology };
/// "given", "name", "topology".
const char* mapMethodName(MapMethod method);

/// What a joint's name says once decorations are removed: "mixamorig:RightForeArm" is
/// {Right, "forearm"}, "Bip01 L Hand" {Left, "hand"}, "rShldr" {Right, "shldr"}, "Head" {none, "head"}.
struct JointNameInfo {
    std::optional<BodySide> side;
    std::string term; ///< lower case, separators removed, digits kept ("spine2")
};
JointNameInfo jointNameInfo(std::string_view name);

/// The joints the puppet parts are bound to, and how each was found.
struct PartMap {
    JointMap names;
    PartJoints joints{-1, -1, -1, -1};
    std::array<MapMethod, 4> methods{MapMethod::Name, MapMethod::Name, MapMethod::Name, MapMethod::Name};
    BodySide side = BodySide::Right;

    /// "head=Head,shoulder=Chest,arm=LowerArm_R,hand=Hand_R", as --joints takes it.
    std::string text() const;
    /// "head=Head (name), shoulder=Chest (topology), ..." for reports.
    std::string describe() const;
};

struct PartMapOptions {
    BodySide side = BodySide::Right; ///< the limbs the arm and hand parts follow
};

/// Maps the four parts automatically (names, then topology), each part named in `given`
/// (non-empty names) taking that joint instead. `positions` (one per joint, workbench axes, at
/// the first frame) tell left from right where names cannot; without them the BVH custom (the
/// performer facing +Z of a Y-up file) is assumed. Errors name the part that found no joint and
/// list the skeleton's joints, or name a joint mapped to two parts.
Result<PartMap> mapPuppetParts(const BvhSkeleton& skeleton, const std::optional<JointMap>& given = std::nullopt,
                               const PartMapOptions& options = {}, const std::vector<Eigen::Vector3d>* positions = nullptr);
/// The same for a file, with the first frame's positions (bvh_import.h's axis conventions).
Result<PartMap> mapPuppetParts(const BvhFile& file, const std::optional<JointMap>& given = std::nullopt,
                               const PartMapOptions& options = {}, const BvhImportOptions& axes = {});

} // namespace bunraku::analysis::io
