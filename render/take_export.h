#pragma once
/// Writing a take wherever a take can be written (File > Export Take A/B, `bunraku ... -o`), by
/// the file's extension: .csv (the take's channels), .bvh (on the take's own skeleton when it
/// has one, else the part layout) and .glb (glTF 2.0 binary: the skeleton with the performer's
/// body skinned to it, or, for a take without a skeleton, the modelled puppet's joints under a
/// root with its skinned surface, as the 3D view draws them). The geometry and the poses are the
/// 3D view's (analysis/body/performer_body.h, skeleton_geometry.h for a skeleton without a body;
/// analysis/body/puppet_model.h with puppetJointPoses; puppet_geometry.h for a body without the
/// puppet's parts), hence this lives beside the renderer.

#include "analysis/body/body_description.h"
#include "analysis/cloth/kimono_cloth.h"
#include "analysis/core/result.h"
#include "analysis/core/run_control.h"
#include "analysis/core/skeleton.h"
#include "analysis/core/take.h"
#include "analysis/io/gltf_export.h"

#include <filesystem>
#include <memory>
#include <string>
#include <vector>

namespace bunraku::render {

enum class TakeExportFormat { Csv, Bvh, Glb, Unknown };

/// By extension, case-insensitive: .csv, .bvh, .glb.
TakeExportFormat takeExportFormat(const std::filesystem::path& file);

/// "expected a .bvh, .glb or .csv file name", for error messages.
const char* takeExportExpectation();

/// A skeletal motion with the mesh skinned to it: what a .glb holds. Either rigid meshes, each
/// carried by one joint, or (when `meshes` is empty) one smoothly skinned mesh.
struct ExportRig {
    std::shared_ptr<const analysis::SkeletalMotion> motion;
    std::vector<analysis::io::JointMesh> meshes;
    analysis::io::SkinnedMesh skinned;
};

/// The take's own skeleton with its bone capsules and joint spheres (skeleton_geometry.h).
ExportRig skeletonRig(const std::shared_ptr<const analysis::SkeletalMotion>& motion);

/// The take's own skeleton with the performer's body skinned to it (analysis/body/performer_body.h,
/// the 3D view's "Body" figure; a vertex weighted to an End Site goes to its parent), or, for a
/// skeleton that has no body (performerBody's errors), skeletonRig's capsules.
ExportRig performerRig(const std::shared_ptr<const analysis::SkeletalMotion>& motion);

/// The puppet as a skeleton: a root joint "puppet" at the origin and, under it, for a body with
/// the modelled puppet's parts (bodyHasPuppetParts), the modelled puppet's joints
/// (analysis::kPuppetJointNames: the six parts, the kimono and the two sleeves) posed in every
/// frame as the 3D view poses them (worldPartPoses, then puppetJointPoses) with the puppet's
/// skinned surface (fittedPuppetMesh: its bind poses, its four weights per vertex, its colours)
/// in `skinned`; for another body, one joint per body part (named as the part) posed by
/// worldPartPoses, carrying that part's primitives in `meshes`. Errors when the take cannot
/// drive the body (bindBody). With `underCloth`, the modelled puppet's surface keeps only the
/// triangles the simulated kimono does not replace (analysis::puppetIndicesUnderCloth: without the
/// skinned skirt and long sleeves), so that a file with the cloth does not dress the puppet twice.
analysis::Result<ExportRig> puppetRig(const analysis::BodyDescription& body, const analysis::Take& take, bool underCloth = false);

/// The simulated kimono in a take's export (docs/KIMONO.md, "In a .glb"): the cloth's parameters,
/// how many key shapes a .glb keeps at most, and the simulation's progress and cancelling.
inline constexpr int kKimonoExportMaxKeys = 512;
struct KimonoExport {
    analysis::ClothParameters cloth;
    int maxKeys = kKimonoExportMaxKeys; ///< key shapes of the cloth in a .glb, at least 2
    analysis::RunControl control;       ///< the simulation's and the keys' progress, cancelling
};

/// The frames a .glb keeps the kimono's shape at: every frame of a take of at most `maxKeys`
/// frames, else `maxKeys` frames evenly spaced from the first to the last (frame
/// round(k (frames - 1) / (maxKeys - 1))); between them a client interpolates linearly.
std::vector<Eigen::Index> kimonoKeyFrames(Eigen::Index frames, int maxKeys = kKimonoExportMaxKeys);

/// The take whose kimono an export of `take` carries, as exportTake simulates it
/// (analysis::simulateKimono): the body's motion (analysis::bodyTake), on the performer's skeleton
/// when the file holds the performer, else the puppet's channels alone (the modelled puppet on the
/// default body, as the export poses it).
analysis::Take kimonoExportTake(const analysis::Take& take);

/// The simulated kimono as a mesh animated by morph targets (analysis/io/gltf_export.h): the
/// cloth's triangles, the kimono's colours (analysis::kimonoLook), its particles at
/// kimonoKeyFrames (positions from analysis::KimonoPlayer, world, cm) at frame / rate seconds, the
/// normals of the first key. `control` reports the keys' progress.
analysis::Result<analysis::io::MorphAnimatedMesh> kimonoMorphMesh(const std::shared_ptr<const analysis::KimonoSimulation>& simulation,
                                                                 const std::shared_ptr<const analysis::Take>& take,
                                                                 int maxKeys = kKimonoExportMaxKeys, const analysis::RunControl& control = {});

/// What a user must know about writing `take` to `file`: every format holds the take as one body
/// moves (analysis::bodyTake), and how far the thesis's per-channel result is from it - the
/// take's own values when they are not its body's, else `perChannel` (the per-channel result a
/// body take was made from, e.g. the workbench's ghost); empty when there is nothing to say.
std::string takeExportNote(const analysis::Take& take, const std::filesystem::path& file, const analysis::Take* perChannel = nullptr);

/// Writes the take by extension (atomic); the error names the file. `name` names a .glb's
/// animation, scene and mesh: short and stable (the workbench passes the take's name, e.g.
/// "bow designed"); empty: the take's displayName(). `description` (a derived take's recipe)
/// is kept in the file's metadata where its reader allows: a .glb's scene and animation
/// `extras.description`, a .csv's `#` comment lines; a .bvh has none (the BVH reader takes no
/// comments). With `kimono`, the take's kimono is simulated (analysis::simulateKimono on
/// kimonoExportTake) and written too: in a .glb as a mesh node "kimono_cloth" animated by morph targets
/// (kimonoMorphMesh) beside the figure, whose modelled puppet then leaves out the skinned skirt
/// and sleeves (puppetRig's `underCloth`); in a .csv as the kimono's 18 measured channels
/// (analysis::withKimonoChannels); a .bvh cannot hold it (an error). The cloth hangs on the body
/// simulateKimono chooses (the default puppet, or the puppet fitted to a performer's skeleton),
/// which is the figure's when `body` is analysis::defaultBodyDescription(), as every caller passes.
analysis::Status exportTake(const analysis::Take& take, const analysis::BodyDescription& body, const std::filesystem::path& file,
                            const std::string& name = {}, const std::string& description = {}, const KimonoExport* kimono = nullptr);

} // namespace bunraku::render
