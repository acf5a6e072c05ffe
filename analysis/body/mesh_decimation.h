#pragma once
/// Simplifying a closed triangle mesh by quadric error edge collapses (Garland and Heckbert
/// 1997), each collapse moving one vertex onto a neighbour so that the kept vertices keep their
/// attributes (normals, colours, skin weights) unchanged. Collapses that would fold a triangle
/// over, pinch the surface (the link condition) or move a locked vertex (e.g. one on a
/// material's border) are skipped.

#include <Eigen/Core>

#include <cstdint>
#include <functional>
#include <vector>

namespace bunraku::analysis {

struct DecimationOptions {
    std::size_t targetTriangles = 0; ///< stop at this many triangles
    /// Stop earlier when the cheapest collapse would move the surface further than this (cm):
    /// the quadric error's square root.
    double maxError = 0.05;
    /// No collapse makes an edge longer than this (cm): skinning bends the surface only at
    /// vertices, so a bending region keeps some.
    double maxEdge = 1e9;
};

/// Simplifies in place: returns, for every input vertex, the index of the vertex it became
/// (itself if kept), and rewrites `indices` to the kept triangles (old vertex numbering).
/// `difference(a, b)` (optional) measures how far two vertices' attributes differ (e.g. skin
/// weights): u moves onto v only when they differ by less than `tolerance`, and no edge from v
/// to u's other neighbours then spans more difference than u's did or `tolerance`.
std::vector<std::uint32_t> decimateMesh(const std::vector<Eigen::Vector3f>& positions, std::vector<std::uint32_t>& indices,
                                        const std::vector<char>& locked, const DecimationOptions& options,
                                        const std::function<float(std::uint32_t, std::uint32_t)>& difference = {},
                                        float tolerance = 0.0f);

} // namespace bunraku::analysis
