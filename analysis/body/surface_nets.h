#pragma once
/// Polygonising a signed distance function by surface nets (Gibson 1998): one vertex per grid
/// cell the surface crosses, placed at the mean of the crossings on the cell's edges and then
/// projected onto the surface along the gradient, and one quad (two triangles) per crossed
/// grid edge joining the four cells around it. The result is a closed, watertight mesh wherever
/// the surface is resolved by the grid. Only blocks of cells near the surface are sampled finely
/// (a coarse pass on 4x4x4-cell blocks skips blocks the distance puts far from it), so the cost
/// grows with the surface's area rather than the volume of the box.

#include <Eigen/Core>

#include <cstdint>
#include <functional>
#include <vector>

namespace bunraku::analysis {

struct SurfaceNetsGrid {
    Eigen::Vector3f lower = Eigen::Vector3f::Zero(); ///< box corner, the first sample
    Eigen::Vector3f upper = Eigen::Vector3f::Zero(); ///< opposite box corner
    float cellSize = 0.5f;                           ///< edge of a grid cell (the units of the field)
    int threads = 1;                                 ///< threads sampling the field (it must be thread-safe)
};

struct SurfaceNetsMesh {
    std::vector<Eigen::Vector3f> positions; ///< on the surface
    std::vector<Eigen::Vector3f> normals;   ///< unit gradient of the field (outwards)
    std::vector<std::uint32_t> indices;     ///< 3 per triangle, counter-clockwise seen from outside
};

/// Polygonises the zero set of `distance` (negative inside, |gradient| <= ~1) over `grid`.
SurfaceNetsMesh surfaceNets(const std::function<float(const Eigen::Vector3f&)>& distance, const SurfaceNetsGrid& grid);

/// The triangles' connected components (by shared vertices): one component label per vertex.
std::vector<int> meshComponents(std::size_t vertexCount, const std::vector<std::uint32_t>& indices, int* componentCount);

} // namespace bunraku::analysis
