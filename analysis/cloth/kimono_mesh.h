#pragma once
/// The simulated kimono as a surface to draw or export: the cloth's triangles with normals and
/// the puppet's kimono colours, and the modelled puppet without the pieces the cloth replaces (the
/// skirt below the dō-wa and the long sleeves, skinned to the hanging joints), so that a view or a
/// file shows the puppet dressed in the cloth instead of in its skinned kimono.

#include "analysis/body/puppet_model.h"
#include "analysis/cloth/kimono_cloth.h"

#include <Eigen/Core>

#include <cstdint>
#include <vector>

namespace bunraku::analysis {

/// Per-particle unit normals of the cloth's surface at `positions` (area-weighted triangle
/// normals; the side a triangle of KimonoCloth::triangles faces counter-clockwise). A particle of
/// no triangle, or of a degenerate fan, gets +z.
std::vector<Eigen::Vector3f> kimonoNormals(const KimonoCloth& cloth, const std::vector<Eigen::Vector3d>& positions);

/// How each particle of the cloth looks: the colour, sheen and painted region of the puppet's
/// kimono vertex nearest it at rest (in paint coordinates), and its paint position.
struct KimonoLook {
    std::vector<Eigen::Vector3f> colours;
    std::vector<float> sheen;
    std::vector<PuppetRegion> regions;
    std::vector<Eigen::Vector3f> paintPositions;
};
KimonoLook kimonoLook(const KimonoCloth& cloth, const PuppetMesh& puppet);

/// True for a puppet vertex the cloth replaces: its largest skin weight is a hanging joint's (the
/// kimono below the dō-wa or a long sleeve).
bool replacedByCloth(const PuppetMesh& puppet, std::size_t vertex);

/// The puppet's triangles (PuppetMesh::indices order) without those the cloth replaces: a
/// triangle is dropped when every corner is replacedByCloth.
std::vector<std::uint32_t> puppetIndicesUnderCloth(const PuppetMesh& puppet);

} // namespace bunraku::analysis
