#pragma once
/// The puppet's body: per part a set of solid primitives placed relative to the part's sensor,
/// with densities and display colours (thesis 5.2.1: part masses from volumes and a uniform
/// density). The motion axis samples mass points from it and the renderer builds the puppet's
/// meshes from the same description, so what is drawn is what the inertia is computed from.
/// File format: resources/puppet/bunraku_puppet.json (documented in docs/MOTION-AXIS.md).
///
/// Frames: a part frame sits at the part's sensor (x forward, y to the puppet's left, z up at
/// rest); `part_T_primitive` places a primitive in it. Lengths in cm, densities in g/cm^3,
/// masses in g.
///
/// Mirrored parts (the left arm and hand, which carry no sensor): `mirrored` is true and
/// `mirrorOf` names the source part. Their primitives are the source's primitives already
/// reflected in the part's y axis (position y negated, rotation R -> F R F with F = diag(1,-1,1));
/// every primitive shape is symmetric in its own y axis, so the reflected geometry is again a
/// list of ordinary primitives. A renderer therefore draws a mirrored part exactly like any
/// other: world_T_part (a proper rotation, from worldPartPoses) * part_T_primitive * mesh.

#include "analysis/core/pose.h"
#include "analysis/core/result.h"

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace bunraku::analysis {

enum class PrimitiveShape {
    Box,       ///< `size` = full edge lengths along the primitive's x, y, z
    Cylinder,  ///< `radius`, `length` along the primitive's z, centred on its origin
    Ellipsoid, ///< `size` = semi-axes (radii) along x, y, z
    Frustum,   ///< truncated cone along z: `radius` at z = -length/2, `topRadius` at +length/2
};

/// "box", "cylinder", "ellipsoid", "frustum".
std::string_view primitiveShapeName(PrimitiveShape shape);

struct Primitive {
    std::string name;
    PrimitiveShape shape = PrimitiveShape::Box;
    Eigen::Vector3d size = Eigen::Vector3d::Zero(); ///< cm: box edge lengths or ellipsoid radii
    double radius = 0.0;                            ///< cm: cylinder radius, frustum bottom radius
    double topRadius = 0.0;                         ///< cm: frustum top radius
    double length = 0.0;                            ///< cm: cylinder / frustum length along z
    RigidTransform part_T_primitive;                ///< placement in the part (sensor) frame
    double density = 1.0;                           ///< g/cm^3 (the part's unless overridden)
    Eigen::Vector3d colour{0.8, 0.8, 0.8};          ///< display RGB in [0, 1] (part's unless overridden)

    /// Analytic volume in cm^3.
    double volume() const;
    /// density * volume, in g.
    double mass() const { return density * volume(); }
    /// True when `point` (in the primitive's own frame, cm) lies inside or on the solid.
    bool containsLocal(const Eigen::Vector3d& point) const;
    /// Half extents (cm) of the primitive's own axis-aligned bounding box, centred on its origin.
    Eigen::Vector3d halfExtents() const;
};

struct BodyPart {
    std::string name;     ///< e.g. "head", "left_arm"
    std::string drivenBy; ///< the take part whose 6 channels pose it: "head", "shoulder", "arm", "hand"
    bool mirrored = false;
    std::string mirrorOf; ///< source part name when mirrored, else empty
    double density = 1.0; ///< g/cm^3, the default of its primitives
    Eigen::Vector3d colour{0.8, 0.8, 0.8};
    std::vector<Primitive> primitives; ///< mirrored parts: already reflected, see the file comment
    /// How this part's geometry was mapped from the shipped puppet's in the part frame
    /// (body_fit.h: p -> A_s + R S (p - A_p), reflected for a mirrored part); the identity for the
    /// shipped description. The modelled puppet (puppet_model.h) is fitted with it.
    Eigen::Affine3d fit = Eigen::Affine3d::Identity();

    /// Sum of the primitives' masses in g (overlaps counted twice, as the volumes are).
    double mass() const;
};

struct BodyDescription {
    std::string name;
    std::string source;          ///< file or name it was parsed from
    std::string mirrorFramePart; ///< the take part whose sagittal (x-z) plane mirrors, "shoulder"
    std::vector<BodyPart> parts; ///< in file order; the Bunraku puppet has 6

    /// Index of the part with this name, or -1.
    int partIndex(std::string_view partName) const;
    double mass() const;
};

/// Parses a body description (JSON). Errors name the source, the JSON path (e.g.
/// `parts[2].primitives[0].radius`) and what was expected.
Result<BodyDescription> parseBodyDescription(std::string_view jsonText, std::string_view sourceName);
/// Reads and parses a file.
Result<BodyDescription> loadBodyDescription(const std::filesystem::path& path);
/// The shipped description, resources/puppet/bunraku_puppet.json, embedded at build time so it
/// is available without the source tree.
const BodyDescription& defaultBodyDescription();

} // namespace bunraku::analysis
