#pragma once
/// The masses of the motion axis taken from the modelled puppet (thesis 5.2.1: part masses from
/// the measured volumes of the parts at a uniform density; issue "a puppet worth looking at",
/// item 5). The thesis scanned its puppet's parts and measured their volumes; here the parts are
/// the modelled puppet's solid (puppet_model.h), cut into the six parts by the skin: a point of
/// the solid belongs to the part its surface moves with (the kimono below the dō-wa to the
/// shoulder, a sleeve to its arm).
///
/// Sampling: the solid is sampled once per lattice step on a regular lattice in model space
/// (points where the signed distance is negative), each point carried into its part's frame at
/// rest. For a body description the points are then placed by each part's `fit` (body_fit.h), as
/// the drawn puppet is, and a point's mass is the volume of its lattice cell (scaled by the fit's
/// volume change) times the density of the description's primitive of that part that holds it
/// (else the primitive nearest it), so the densities stay the description's (documented in
/// docs/MOTION-AXIS.md) while the volumes, centres and shapes are the model's.

#include "analysis/body/body_description.h"
#include "analysis/body/body_pose.h"

#include <Eigen/Core>

#include <array>
#include <vector>

namespace bunraku::analysis {

/// The modelled solid's lattice points in the frames of the six parts (head, shoulder, right
/// arm, right hand, left arm, left hand: PuppetJoint order), at rest, cm.
struct PuppetSolidSample {
    double spacing = 1.0;                           ///< cm, the lattice step
    std::array<Eigen::Matrix3Xd, 6> partPoints;     ///< 3 x K per part, in the part's frame
    double cellVolume() const { return spacing * spacing * spacing; }
};

/// The sample for a lattice step (cm, clamped to [0.25, 100]), computed once per step per process
/// (thread-safe).
const PuppetSolidSample& puppetSolidSample(double spacing);

/// Mass points of every part of `body` (body order) from the modelled solid; the error when the
/// body lacks one of the six parts the puppet's joints move with (bodyHasPuppetParts).
Result<std::vector<MassPoints>> modelMassPoints(const BodyDescription& body, const MassPointOptions& options = {});

/// Mass points as `options.source` says: the model's when the body has the puppet's six parts,
/// else (or for MassSource::Primitives) the primitives' (sampleMassPoints). `used` (optional)
/// gets the source that was used.
std::vector<MassPoints> bodyMassPoints(const BodyDescription& body, const MassPointOptions& options, MassSource* used = nullptr);

} // namespace bunraku::analysis
