#include "analysis/body/surface_nets.h"

#include "analysis/core/parallel.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>

namespace bunraku::analysis {
namespace {

constexpr int kBlock = 4; ///< cells per coarse block edge

Eigen::Vector3f gradient(const std::function<float(const Eigen::Vector3f&)>& distance, const Eigen::Vector3f& p, float h)
{
    Eigen::Vector3f g;
    for (int a = 0; a < 3; ++a) {
        Eigen::Vector3f e = Eigen::Vector3f::Zero();
        e[a] = h;
        g[a] = distance(p + e) - distance(p - e);
    }
    return g / (2.0f * h);
}

} // namespace

SurfaceNetsMesh surfaceNets(const std::function<float(const Eigen::Vector3f&)>& distance, const SurfaceNetsGrid& grid)
{
    SurfaceNetsMesh mesh;
    const float h = grid.cellSize;
    if (!(h > 0.0f)) return mesh;
    const Eigen::Vector3f extent = grid.upper - grid.lower;
    // Samples per axis, rounded up to whole blocks.
    std::array<int, 3> blocks{};
    std::array<int, 3> n{};
    for (int a = 0; a < 3; ++a) {
        blocks[std::size_t(a)] = std::max(1, int(std::ceil(extent[a] / (h * kBlock))));
        n[std::size_t(a)] = blocks[std::size_t(a)] * kBlock + 1;
    }
    const auto sampleIndex = [&](int i, int j, int k) { return (std::size_t(k) * std::size_t(n[1]) + std::size_t(j)) * std::size_t(n[0]) + std::size_t(i); };
    const auto at = [&](int i, int j, int k) { return Eigen::Vector3f(grid.lower + h * Eigen::Vector3f(float(i), float(j), float(k))); };
    std::vector<float> field(static_cast<std::size_t>(n[0]) * static_cast<std::size_t>(n[1]) * static_cast<std::size_t>(n[2]), 0.0f);

    // Coarse pass by slabs of blocks along z: a block far from the surface takes its centre's
    // value everywhere (the sign is all surface nets reads there), a near block is sampled.
    const float blockRadius = 0.5f * std::sqrt(3.0f) * h * kBlock;
    const int threads = std::max(1, grid.threads);
    std::vector<std::vector<char>> near(static_cast<std::size_t>(blocks[2]));
    (void)parallelFor(std::size_t(blocks[2]), threads, [&](std::size_t bk) {
        std::vector<char>& slab = near[bk];
        slab.assign(std::size_t(blocks[0]) * std::size_t(blocks[1]), 0);
        for (int bj = 0; bj < blocks[1]; ++bj)
            for (int bi = 0; bi < blocks[0]; ++bi) {
                const Eigen::Vector3f centre = at(bi * kBlock, bj * kBlock, int(bk) * kBlock) + Eigen::Vector3f::Constant(0.5f * h * kBlock);
                const float d = distance(centre);
                const bool isNear = std::abs(d) <= 1.25f * blockRadius + h;
                slab[std::size_t(bj) * std::size_t(blocks[0]) + std::size_t(bi)] = isNear ? 1 : 0;
                // Samples on the block's lower faces belong to it; the last layer to the next
                // block or the box's end.
                const int kEnd = int(bk) == blocks[2] - 1 ? kBlock : kBlock - 1;
                const int jEnd = bj == blocks[1] - 1 ? kBlock : kBlock - 1;
                const int iEnd = bi == blocks[0] - 1 ? kBlock : kBlock - 1;
                for (int k = 0; k <= kEnd; ++k)
                    for (int j = 0; j <= jEnd; ++j)
                        for (int i = 0; i <= iEnd; ++i) {
                            const int si = bi * kBlock + i, sj = bj * kBlock + j, sk = int(bk) * kBlock + k;
                            field[sampleIndex(si, sj, sk)] = isNear ? distance(at(si, sj, sk)) : d;
                        }
            }
        return okStatus();
    });
    // A near block's samples on its upper faces belong to the next blocks: where such an owner
    // is far, it wrote its centre's value there, so sample them exactly. Even slabs, then odd
    // ones: two slabs one apart share no sample.
    const auto ownerNear = [&](int si, int sj, int sk) {
        const int bi = std::min(si / kBlock, blocks[0] - 1), bj = std::min(sj / kBlock, blocks[1] - 1);
        const int bk = std::min(sk / kBlock, blocks[2] - 1);
        return near[std::size_t(bk)][std::size_t(bj) * std::size_t(blocks[0]) + std::size_t(bi)] != 0;
    };
    for (int parity = 0; parity < 2; ++parity) {
        const std::size_t slabs = std::size_t((blocks[2] - parity + 1) / 2);
        (void)parallelFor(slabs, threads, [&](std::size_t s) {
            const int bk = int(2 * s) + parity;
            for (int bj = 0; bj < blocks[1]; ++bj)
                for (int bi = 0; bi < blocks[0]; ++bi) {
                    if (!near[std::size_t(bk)][std::size_t(bj) * std::size_t(blocks[0]) + std::size_t(bi)]) continue;
                    for (int k = 0; k <= kBlock; ++k)
                        for (int j = 0; j <= kBlock; ++j)
                            for (int i = 0; i <= kBlock; ++i) {
                                if (i < kBlock && j < kBlock && k < kBlock) continue;
                                const int si = bi * kBlock + i, sj = bj * kBlock + j, sk = bk * kBlock + k;
                                if (ownerNear(si, sj, sk)) continue;
                                field[sampleIndex(si, sj, sk)] = distance(at(si, sj, sk));
                            }
                }
            return okStatus();
        });
    }

    // One vertex per crossed cell.
    const int cx = n[0] - 1, cy = n[1] - 1, cz = n[2] - 1;
    const auto cellIndex = [&](int i, int j, int k) { return (std::size_t(k) * std::size_t(cy) + std::size_t(j)) * std::size_t(cx) + std::size_t(i); };
    std::vector<std::int32_t> cellVertex(static_cast<std::size_t>(cx) * static_cast<std::size_t>(cy) * static_cast<std::size_t>(cz), -1);
    static constexpr std::array<std::array<int, 2>, 12> kEdges{{{0, 1}, {2, 3}, {4, 5}, {6, 7}, {0, 2}, {1, 3}, {4, 6}, {5, 7}, {0, 4}, {1, 5}, {2, 6}, {3, 7}}};
    for (int k = 0; k < cz; ++k)
        for (int j = 0; j < cy; ++j)
            for (int i = 0; i < cx; ++i) {
                std::array<float, 8> v{};
                int inside = 0;
                for (int c = 0; c < 8; ++c) {
                    v[std::size_t(c)] = field[sampleIndex(i + (c & 1), j + ((c >> 1) & 1), k + ((c >> 2) & 1))];
                    if (v[std::size_t(c)] < 0.0f) ++inside;
                }
                if (inside == 0 || inside == 8) continue;
                Eigen::Vector3f sum = Eigen::Vector3f::Zero();
                int count = 0;
                for (const auto& e : kEdges) {
                    const float a = v[std::size_t(e[0])], b = v[std::size_t(e[1])];
                    if ((a < 0.0f) == (b < 0.0f)) continue;
                    const float t = a / (a - b);
                    const Eigen::Vector3f pa(float(e[0] & 1), float((e[0] >> 1) & 1), float((e[0] >> 2) & 1));
                    const Eigen::Vector3f pb(float(e[1] & 1), float((e[1] >> 1) & 1), float((e[1] >> 2) & 1));
                    sum += pa + t * (pb - pa);
                    ++count;
                }
                cellVertex[cellIndex(i, j, k)] = std::int32_t(mesh.positions.size());
                mesh.positions.push_back(at(i, j, k) + h * sum / float(count));
            }
    // Projected onto the surface (two Newton steps, each move bounded by the cell), with the
    // field's gradient as the normal.
    mesh.normals.resize(mesh.positions.size());
    const float step = 0.1f * h;
    (void)parallelFor(std::size_t(threads), threads, [&](std::size_t part) {
        const std::size_t count = mesh.positions.size();
        for (std::size_t v = part * count / std::size_t(threads); v < (part + 1) * count / std::size_t(threads); ++v) {
            Eigen::Vector3f p = mesh.positions[v];
            const Eigen::Vector3f start = p;
            for (int iteration = 0; iteration < 2; ++iteration) {
                const Eigen::Vector3f g = gradient(distance, p, step);
                const float g2 = g.squaredNorm();
                if (g2 < 1e-8f) break;
                p -= distance(p) * g / g2;
                const Eigen::Vector3f moved = p - start;
                if (moved.norm() > h) p = start + moved.normalized() * h;
            }
            mesh.positions[v] = p;
            Eigen::Vector3f g = gradient(distance, p, step);
            mesh.normals[v] = g.norm() > 1e-8f ? Eigen::Vector3f(g.normalized()) : Eigen::Vector3f::UnitZ();
        }
        return okStatus();
    });

    // One quad per crossed edge, around it the four cells sharing it.
    const auto quad = [&](std::int32_t a, std::int32_t b, std::int32_t c, std::int32_t d, bool flip) {
        if (a < 0 || b < 0 || c < 0 || d < 0) return;
        if (flip) std::swap(b, d);
        // Split along the shorter diagonal.
        const float ac = (mesh.positions[std::size_t(a)] - mesh.positions[std::size_t(c)]).squaredNorm();
        const float bd = (mesh.positions[std::size_t(b)] - mesh.positions[std::size_t(d)]).squaredNorm();
        const std::array<std::int32_t, 6> t = ac <= bd ? std::array<std::int32_t, 6>{a, b, c, a, c, d}
                                                       : std::array<std::int32_t, 6>{a, b, d, b, c, d};
        for (const std::int32_t i : t) mesh.indices.push_back(std::uint32_t(i));
    };
    for (int k = 0; k < cz; ++k)
        for (int j = 0; j < cy; ++j)
            for (int i = 0; i < cx; ++i) {
                const bool inside = field[sampleIndex(i, j, k)] < 0.0f;
                // Edge along x from sample (i, j, k): cells (i, j-1..j, k-1..k).
                if (j > 0 && k > 0 && i + 1 < n[0] && inside != (field[sampleIndex(i + 1, j, k)] < 0.0f))
                    quad(cellVertex[cellIndex(i, j - 1, k - 1)], cellVertex[cellIndex(i, j, k - 1)], cellVertex[cellIndex(i, j, k)],
                         cellVertex[cellIndex(i, j - 1, k)], !inside);
                // Edge along y: cells (i-1..i, j, k-1..k).
                if (i > 0 && k > 0 && j + 1 < n[1] && inside != (field[sampleIndex(i, j + 1, k)] < 0.0f))
                    quad(cellVertex[cellIndex(i - 1, j, k - 1)], cellVertex[cellIndex(i - 1, j, k)], cellVertex[cellIndex(i, j, k)],
                         cellVertex[cellIndex(i, j, k - 1)], !inside);
                // Edge along z: cells (i-1..i, j-1..j, k).
                if (i > 0 && j > 0 && k + 1 < n[2] && inside != (field[sampleIndex(i, j, k + 1)] < 0.0f))
                    quad(cellVertex[cellIndex(i - 1, j - 1, k)], cellVertex[cellIndex(i, j - 1, k)], cellVertex[cellIndex(i, j, k)],
                         cellVertex[cellIndex(i - 1, j, k)], !inside);
            }
    // Orientation: the winding above follows one convention; make the triangles face along the
    // field's gradient whatever it was (checked on the sum over the mesh).
    double agreement = 0.0;
    for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
        const Eigen::Vector3f& a = mesh.positions[mesh.indices[t]];
        const Eigen::Vector3f& b = mesh.positions[mesh.indices[t + 1]];
        const Eigen::Vector3f& c = mesh.positions[mesh.indices[t + 2]];
        agreement += double((b - a).cross(c - a).dot(mesh.normals[mesh.indices[t]]));
    }
    if (agreement < 0.0)
        for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) std::swap(mesh.indices[t + 1], mesh.indices[t + 2]);
    return mesh;
}

std::vector<int> meshComponents(std::size_t vertexCount, const std::vector<std::uint32_t>& indices, int* componentCount)
{
    std::vector<int> parent(vertexCount);
    std::iota(parent.begin(), parent.end(), 0);
    const auto find = [&](int x) {
        while (parent[std::size_t(x)] != x) {
            parent[std::size_t(x)] = parent[std::size_t(parent[std::size_t(x)])];
            x = parent[std::size_t(x)];
        }
        return x;
    };
    for (std::size_t t = 0; t + 2 < indices.size(); t += 3)
        for (int e = 1; e < 3; ++e) {
            const int a = find(int(indices[t])), b = find(int(indices[t + std::size_t(e)]));
            if (a != b) parent[std::size_t(std::max(a, b))] = std::min(a, b);
        }
    std::vector<int> label(vertexCount, -1), rootLabel(vertexCount, -1);
    int count = 0;
    for (std::size_t v = 0; v < vertexCount; ++v) {
        const int root = find(int(v));
        if (rootLabel[std::size_t(root)] < 0) rootLabel[std::size_t(root)] = count++;
        label[v] = rootLabel[std::size_t(root)];
    }
    if (componentCount) *componentCount = count;
    return label;
}

} // namespace bunraku::analysis
