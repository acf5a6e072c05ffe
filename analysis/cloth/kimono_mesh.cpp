#include "analysis/cloth/kimono_mesh.h"

#include <Eigen/Geometry>

#include <limits>

namespace bunraku::analysis {

std::vector<Eigen::Vector3f> kimonoNormals(const KimonoCloth& cloth, const std::vector<Eigen::Vector3d>& positions)
{
    std::vector<Eigen::Vector3d> sum(positions.size(), Eigen::Vector3d::Zero());
    for (std::size_t t = 0; t + 2 < cloth.triangles.size(); t += 3) {
        const std::uint32_t a = cloth.triangles[t], b = cloth.triangles[t + 1], c = cloth.triangles[t + 2];
        if (a >= positions.size() || b >= positions.size() || c >= positions.size()) continue;
        // The cross product's length is twice the area: an area-weighted sum.
        const Eigen::Vector3d n = (positions[b] - positions[a]).cross(positions[c] - positions[a]);
        sum[a] += n;
        sum[b] += n;
        sum[c] += n;
    }
    std::vector<Eigen::Vector3f> normals(positions.size());
    for (std::size_t i = 0; i < sum.size(); ++i) {
        const double length = sum[i].norm();
        normals[i] = length > 1e-12 ? Eigen::Vector3f((sum[i] / length).cast<float>()) : Eigen::Vector3f::UnitZ();
    }
    return normals;
}

bool replacedByCloth(const PuppetMesh& puppet, std::size_t vertex)
{
    const int joint = puppet.dominantJoint(vertex);
    return joint == int(PuppetJoint::Kimono) || joint == int(PuppetJoint::RightSleeve) || joint == int(PuppetJoint::LeftSleeve);
}

KimonoLook kimonoLook(const KimonoCloth& cloth, const PuppetMesh& puppet)
{
    // The candidates: the vertices the cloth replaces (the skinned kimono's surface); every
    // vertex when there are none.
    std::vector<std::size_t> candidates;
    for (std::size_t v = 0; v < puppet.vertexCount(); ++v)
        if (replacedByCloth(puppet, v)) candidates.push_back(v);
    if (candidates.empty())
        for (std::size_t v = 0; v < puppet.vertexCount(); ++v) candidates.push_back(v);
    KimonoLook look;
    look.paintPositions = cloth.paintPositions;
    look.colours.resize(cloth.size(), Eigen::Vector3f(0.6f, 0.1f, 0.15f));
    look.sheen.resize(cloth.size(), 0.3f);
    look.regions.resize(cloth.size(), PuppetRegion::Kimono);
    for (std::size_t i = 0; i < cloth.size() && i < cloth.paintPositions.size(); ++i) {
        float best = std::numeric_limits<float>::infinity();
        std::size_t nearest = puppet.vertexCount();
        for (const std::size_t v : candidates) {
            const float d = (puppet.paintPositions[v] - cloth.paintPositions[i]).squaredNorm();
            if (d < best) {
                best = d;
                nearest = v;
            }
        }
        if (nearest == puppet.vertexCount()) continue;
        look.colours[i] = puppet.colours[nearest];
        look.sheen[i] = puppet.sheen[nearest];
        look.regions[i] = puppet.regions[nearest];
    }
    return look;
}

std::vector<std::uint32_t> puppetIndicesUnderCloth(const PuppetMesh& puppet)
{
    std::vector<std::uint32_t> kept;
    kept.reserve(puppet.indices.size());
    for (std::size_t t = 0; t + 2 < puppet.indices.size(); t += 3) {
        const std::uint32_t a = puppet.indices[t], b = puppet.indices[t + 1], c = puppet.indices[t + 2];
        if (replacedByCloth(puppet, a) && replacedByCloth(puppet, b) && replacedByCloth(puppet, c)) continue;
        kept.insert(kept.end(), {a, b, c});
    }
    return kept;
}

} // namespace bunraku::analysis
