#pragma once
/// The orbits of the sensors (thesis 6: the path of each sensor over a take) as tubes: a line
/// one pixel wide disappears beside the puppet (OpenGL core has no wide lines), a tube has a
/// size in the scene and is shaded like the puppet.

#include "render/mesh.h"

#include <glm/glm.hpp>

#include <cstddef>
#include <vector>

namespace bunraku::render {

/// A tube of `radius` cm through `points` (`sides` vertices around each ring), coloured
/// `colour`. Paths longer than `maxPoints` are sampled evenly (always keeping the last point),
/// so a 100,000-frame take costs no more than a short one. Fewer than 2 points: an empty mesh.
Mesh orbitTubeMesh(const std::vector<glm::vec3>& points, float radius, const glm::vec3& colour, std::size_t maxPoints = 4000,
                   int sides = 6);

/// The tube radius (cm) for orbits whose points span `extent` cm (their box's longest side):
/// a hundredth of it, between 0.4 and 5 cm.
float orbitTubeRadius(float extent);

} // namespace bunraku::render
