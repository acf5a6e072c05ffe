#include "analysis/body/mesh_decimation.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>
#include <iterator>
#include <queue>

namespace bunraku::analysis {
namespace {

using Quadric = Eigen::Matrix4d;

double error(const Quadric& q, const Eigen::Vector3f& p)
{
    const Eigen::Vector4d v(p.x(), p.y(), p.z(), 1.0);
    return std::max(0.0, v.dot(q * v));
}

struct Candidate {
    double cost;
    std::uint32_t from, to;
    std::uint32_t fromStamp, toStamp;
    bool operator<(const Candidate& other) const { return cost > other.cost; } // min-heap
};

} // namespace

std::vector<std::uint32_t> decimateMesh(const std::vector<Eigen::Vector3f>& positions, std::vector<std::uint32_t>& indices,
                                        const std::vector<char>& locked, const DecimationOptions& options,
                                        const std::function<float(std::uint32_t, std::uint32_t)>& difference, float tolerance)
{
    const std::size_t n = positions.size();
    const std::size_t faceCount = indices.size() / 3;
    std::vector<std::uint32_t> into(n);
    for (std::size_t v = 0; v < n; ++v) into[v] = std::uint32_t(v);
    std::vector<std::array<std::uint32_t, 3>> faces(faceCount);
    std::vector<char> alive(faceCount, 1);
    std::vector<std::vector<std::uint32_t>> facesOf(n);
    std::vector<Quadric> quadric(n, Quadric::Zero());
    for (std::size_t f = 0; f < faceCount; ++f) {
        faces[f] = {indices[3 * f], indices[3 * f + 1], indices[3 * f + 2]};
        for (const std::uint32_t v : faces[f]) facesOf[v].push_back(std::uint32_t(f));
        const Eigen::Vector3d a = positions[faces[f][0]].cast<double>(), b = positions[faces[f][1]].cast<double>(),
                              c = positions[faces[f][2]].cast<double>();
        Eigen::Vector3d normal = (b - a).cross(c - a);
        const double area = normal.norm();
        if (area < 1e-12) continue;
        normal /= area;
        const Eigen::Vector4d plane(normal.x(), normal.y(), normal.z(), -normal.dot(a));
        const Quadric q = 0.5 * area * plane * plane.transpose();
        for (const std::uint32_t v : faces[f]) quadric[v] += q;
    }
    std::vector<std::uint32_t> stamp(n, 0);
    std::priority_queue<Candidate> heap;
    const auto neighbours = [&](std::uint32_t v) {
        std::vector<std::uint32_t> out;
        for (const std::uint32_t f : facesOf[v])
            if (alive[f])
                for (const std::uint32_t w : faces[f])
                    if (w != v) out.push_back(w);
        std::sort(out.begin(), out.end());
        out.erase(std::unique(out.begin(), out.end()), out.end());
        return out;
    };
    const auto push = [&](std::uint32_t from, std::uint32_t to) {
        if (locked[from] || (difference && difference(from, to) >= tolerance)) return;
        const double cost = error(quadric[from] + quadric[to], positions[to]);
        heap.push(Candidate{cost, from, to, stamp[from], stamp[to]});
    };
    for (std::size_t f = 0; f < faceCount; ++f)
        for (int e = 0; e < 3; ++e) {
            const std::uint32_t a = faces[f][std::size_t(e)], b = faces[f][std::size_t((e + 1) % 3)];
            push(a, b);
            push(b, a);
        }
    std::size_t triangles = faceCount;
    const double maxCost = options.maxError * options.maxError;
    while (triangles > options.targetTriangles && !heap.empty()) {
        const Candidate c = heap.top();
        heap.pop();
        if (c.fromStamp != stamp[c.from] || c.toStamp != stamp[c.to] || into[c.from] != c.from || into[c.to] != c.to) continue;
        if (c.cost > maxCost) break;
        const std::uint32_t u = c.from, v = c.to;
        // Still an edge, and the link condition: exactly two shared neighbours.
        const std::vector<std::uint32_t> nu = neighbours(u), nv = neighbours(v);
        if (!std::binary_search(nu.begin(), nu.end(), v)) continue;
        std::vector<std::uint32_t> shared;
        std::set_intersection(nu.begin(), nu.end(), nv.begin(), nv.end(), std::back_inserter(shared));
        if (shared.size() != 2) continue;
        // No triangle around u turns over (or collapses) when u moves to v.
        bool ok = true;
        for (const std::uint32_t f : facesOf[u]) {
            if (!alive[f]) continue;
            const auto& t = faces[f];
            if (t[0] == v || t[1] == v || t[2] == v) continue;
            std::array<Eigen::Vector3f, 3> p{positions[t[0]], positions[t[1]], positions[t[2]]};
            const Eigen::Vector3f before = (p[1] - p[0]).cross(p[2] - p[0]);
            for (int k = 0; k < 3; ++k)
                if (t[std::size_t(k)] == u) p[std::size_t(k)] = positions[v];
            const Eigen::Vector3f after = (p[1] - p[0]).cross(p[2] - p[0]);
            if (after.norm() < 1e-9f || before.normalized().dot(after.normalized()) < 0.3f) {
                ok = false;
                break;
            }
        }
        for (const std::uint32_t w : nu) {
            if ((positions[w] - positions[v]).norm() > options.maxEdge) ok = false;
            if (difference && w != v && difference(v, w) > std::max(difference(u, w), tolerance)) ok = false;
        }
        if (!ok) continue;
        // Collapse u into v.
        for (const std::uint32_t f : facesOf[u]) {
            if (!alive[f]) continue;
            auto& t = faces[f];
            if (t[0] == v || t[1] == v || t[2] == v) {
                alive[f] = 0;
                --triangles;
                continue;
            }
            for (auto& w : t)
                if (w == u) w = v;
            facesOf[v].push_back(f);
        }
        into[u] = v;
        quadric[v] += quadric[u];
        ++stamp[v];
        ++stamp[u];
        for (const std::uint32_t w : neighbours(v)) {
            ++stamp[w];
            push(v, w);
            push(w, v);
            for (const std::uint32_t x : neighbours(w)) push(w, x);
        }
    }
    // Follow chains of collapses to the kept vertex.
    for (std::size_t v = 0; v < n; ++v) {
        std::uint32_t w = std::uint32_t(v);
        while (into[w] != w) w = into[w];
        into[v] = w;
    }
    indices.clear();
    for (std::size_t f = 0; f < faceCount; ++f)
        if (alive[f])
            for (const std::uint32_t w : faces[f]) indices.push_back(into[w]);
    return into;
}

} // namespace bunraku::analysis
