// The simulated kimono as a surface (analysis/cloth/kimono_mesh.h): the puppet without the pieces
// the cloth replaces keeps its head, torso, arms and hands, the cloth takes the kimono's colours,
// and its normals face out of the skirt.
#include "analysis/cloth/kimono_mesh.h"

#include "analysis/body/body_description.h"

#include <catch2/catch.hpp>

#include <set>

using namespace bunraku::analysis;

TEST_CASE("the puppet under the cloth drops only the skinned skirt and sleeves")
{
    const PuppetMesh& puppet = shippedPuppetMesh();
    const std::vector<std::uint32_t> kept = puppetIndicesUnderCloth(puppet);
    REQUIRE(kept.size() % 3 == 0);
    CHECK(kept.size() < puppet.indices.size());
    // The dropped surface is the hanging joints' alone: every joint of the six parts keeps
    // every triangle whose corners it dominates.
    std::set<int> keptJoints;
    std::size_t droppedHanging = 0, hangingTotal = 0;
    for (std::size_t t = 0; t < kept.size(); ++t) keptJoints.insert(puppet.dominantJoint(kept[t]));
    for (std::size_t v = 0; v < puppet.vertexCount(); ++v) hangingTotal += replacedByCloth(puppet, v) ? 1 : 0;
    for (int joint = 0; joint < 6; ++joint) CHECK(keptJoints.count(joint) == 1);
    std::set<std::uint32_t> keptVertices(kept.begin(), kept.end());
    for (std::size_t v = 0; v < puppet.vertexCount(); ++v)
        if (replacedByCloth(puppet, v) && !keptVertices.count(std::uint32_t(v))) ++droppedHanging;
    INFO(droppedHanging << " of " << hangingTotal << " hanging vertices dropped");
    CHECK(droppedHanging > hangingTotal / 2);
}

TEST_CASE("the cloth wears the kimono's colours and its skirt's normals face out")
{
    const auto cloth = makeKimonoCloth(defaultBodyDescription());
    REQUIRE(cloth.ok());
    const PuppetMesh& puppet = shippedPuppetMesh();
    const KimonoLook look = kimonoLook(*cloth, puppet);
    REQUIRE(look.colours.size() == cloth->size());
    REQUIRE(look.paintPositions.size() == cloth->size());
    // The colours are colours of the puppet's kimono vertices.
    std::size_t fromKimono = 0;
    for (std::size_t i = 0; i < cloth->size(); ++i)
        for (std::size_t v = 0; v < puppet.vertexCount(); ++v)
            if (replacedByCloth(puppet, v) && puppet.colours[v] == look.colours[i]) {
                ++fromKimono;
                break;
            }
    CHECK(fromKimono == cloth->size());
    // At rest (model space, unfitted body: the paint positions) the skirt's normals point away
    // from its axis.
    std::vector<Eigen::Vector3d> rest;
    for (const Eigen::Vector3f& p : cloth->paintPositions) rest.push_back(p.cast<double>());
    const auto normals = kimonoNormals(*cloth, rest);
    int outward = 0, skirt = 0;
    for (std::uint32_t i = 0; i < cloth->skirtEnd; ++i) {
        const Eigen::Vector2f radial = rest[i].head<2>().cast<float>().normalized();
        CHECK(std::abs(normals[i].norm() - 1.0f) < 1e-5f);
        ++skirt;
        if (normals[i].head<2>().dot(radial) > 0.5f) ++outward;
    }
    CHECK(outward == skirt);
}
