#pragma once
/// A fixture family's BVH (bvh_fixtures.h) read with every joint as a part (the whole body:
/// io::bvhToJointTake, units guessed), and the family's joint at a canonical point.
#include "analysis/core/take.h"
#include "analysis/io/bvh.h"
#include "analysis/io/bvh_import.h"
#include "tests/support/bvh_fixtures.h"

#include <catch2/catch.hpp>

#include <string>

namespace bunraku::test {

inline analysis::Take fixtureJointTake(const BvhFamily& family)
{
    auto file = analysis::io::parseBvh(fixtureBvh(family, 12), family.id + ".bvh");
    INFO(family.id << ": " << (file.ok() ? std::string() : file.error().message));
    REQUIRE(file.ok());
    analysis::io::BvhImportOptions options;
    options.guessUnits = true;
    auto take = analysis::io::bvhToJointTake(*file, options);
    INFO(family.id << ": " << (take.ok() ? std::string() : take.error().message));
    REQUIRE(take.ok());
    REQUIRE(take->skeleton);
    return std::move(take).value();
}

/// The fixture's joint at a canonical point ("kneeL"), empty when the family has none.
inline std::string fixtureJointAt(const BvhFamily& family, const std::string& point)
{
    for (const auto& joint : family.joints)
        if (joint.point == point) return joint.name;
    return {};
}

} // namespace bunraku::test
