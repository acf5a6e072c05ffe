#pragma once
/// The puppet's meshes, built from the body description (the same primitives the motion axis
/// integrates over, thesis 5.2.1 and 6): one mesh per body part in the part (sensor) frame, so a
/// frame places each with its world_T_part alone (thesis 6.4.1: position at the sensor,
/// orientation on the part).

#include "analysis/body/body_description.h"
#include "render/mesh.h"

#include <map>
#include <string>
#include <vector>

namespace bunraku::render {

/// Tessellation of one primitive in its own frame (cm), painted in its colour.
Mesh primitiveMesh(const analysis::Primitive& primitive);

/// One triangle mesh per body part (same order as body.parts), in the part frame: the part's
/// primitives placed by part_T_primitive, or the part's entry of `partMeshes` when it has one
/// (a scanned mesh loaded from a file, coloured as loaded).
std::vector<Mesh> buildPuppetMeshes(const analysis::BodyDescription& body,
                                    const std::map<std::string, Mesh>& partMeshes = {});

} // namespace bunraku::render
