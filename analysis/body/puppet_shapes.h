#pragma once
/// The puppet's signed distance field (internal to puppet_model.cpp and its tests): the shapes
/// in model space (the shoulder frame at rest, cm) in the order they are blended, each with the
/// group whose skin weights it takes and its material.

#include "analysis/core/pose.h"

#include <Eigen/Core>

#include <array>
#include <vector>

namespace bunraku::analysis::puppet_shapes {

enum class Kind { RoundBox, Ellipsoid, Capsule, EllipticFrustum, Panel };
/// Which rule weights a vertex nearest to the shape: the body (shoulder, kimono by height), the
/// head (head, shoulder along the neck), an arm in its sleeve (shoulder, arm, hand along the
/// bone), a hand (arm, hand along the hand).
enum class Group { Body, Head, RightArm, LeftArm, RightHand, LeftHand };
enum class Material { Skin, Hair, Kimono, CollarWhite, CollarRed, Obi, ObiCord, ObiKnot, Gold, Coral, Tegara };

struct Shape {
    Kind kind = Kind::Ellipsoid;
    Group group = Group::Body;
    Material material = Material::Kimono;
    float blend = 0.0f;                  ///< smooth-union radius with everything before it (cm)
    bool growsFromBody = false;          ///< an arm's root: body vertices near it take the arm's weights
    Eigen::Matrix3f toLocal = Eigen::Matrix3f::Identity(); ///< local = toLocal * (p - origin); orthogonal
    Eigen::Vector3f origin = Eigen::Vector3f::Zero();
    Eigen::Vector3f a = Eigen::Vector3f::Zero(); ///< box half extents / ellipsoid radii / capsule start
    Eigen::Vector3f b = Eigen::Vector3f::Zero(); ///< capsule end; frustum: (bottom z, top z, 0); panel: see below
    float r0 = 0.0f, r1 = 0.0f;          ///< rounding / capsule radii at a and b; frustum: x radii bottom, top
    float r2 = 0.0f, r3 = 0.0f;          ///< frustum: y radii bottom, top; panel: half thickness, corner radius
    Eigen::Vector3f panelAxis = Eigen::Vector3f::UnitX(); ///< panel: the arm's direction (unit); `a` = (t0, s0), `b` = (t1, s1)
    Eigen::Vector3f centre = Eigen::Vector3f::Zero(); ///< bounding sphere (model space)
    float radius = 0.0f;
};

/// The model's rest pose: model_T_part of head, shoulder, right arm, right hand (the left ones
/// mirror them) and the dō-wa's centre in the shoulder frame.
struct RestPose {
    RigidTransform head, shoulder, rightArm, rightHand;
    Eigen::Vector3d rightShoulderJoint{0.0, -9.0, -1.0}; ///< model space
    Eigen::Vector3d armDirection = Eigen::Vector3d::UnitX(); ///< unit, the right arm's bone
    double wristAlong = 20.0;                          ///< cm from the shoulder joint along the bone
    Eigen::Vector3d neckJoint{1.0, 0.0, 8.0};
    Eigen::Vector3d dowa{0.0, 0.0, -24.0};
    double hemZ = -53.0;
};
const RestPose& restPose();

/// Every shape, left arm included (the right arm's shapes mirrored in y).
const std::vector<Shape>& shapes();

struct Nearest {
    float distance = 0.0f;
    int shape = -1; ///< the shape whose own distance is smallest
};
/// One shape's own distance at p (cm).
float shapeDistance(const Shape& shape, const Eigen::Vector3f& p);
/// The blended distance at p; `nearest` (optional) gets the shape nearest p.
float evaluate(const std::vector<Shape>& shapes, const Eigen::Vector3f& p, Nearest* nearest = nullptr);

} // namespace bunraku::analysis::puppet_shapes
