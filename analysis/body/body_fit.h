#pragma once
/// The puppet's body fitted to a performer: the body description's primitives scaled and
/// placed so that the puppet's proportions follow the skeleton a take came with (a 170 cm
/// performer's head sits on their shoulders, the arm lies along the forearm, the hand covers
/// the hand). The 3D view draws a take with its fitted body and the motion axis of such a take
/// integrates over it. Rule (docs/FORMATS.md, "Calibration"): each driving part's primitives
/// are mapped by p -> A_s + R S (p - A_p), taking two puppet landmarks A_p, B_p (in the part
/// frame) onto the skeleton's A_s, B_s: S scales by |B_s - A_s| / |B_p - A_p| (the torso's
/// width and depth by 0.8 x the shoulder-joint distance / its width), R is the smallest rotation taking B_p - A_p
/// onto B_s - A_s. Mirrored parts reflect their fitted source.

#include "analysis/body/body_description.h"
#include "analysis/core/result.h"
#include "analysis/core/skeleton.h"
#include "analysis/core/take.h"

#include <Eigen/Core>

namespace bunraku::analysis {

/// Landmarks of the shipped puppet in its part frames (cm; resources/puppet/bunraku_puppet.json,
/// its comment and analysis/synth/puppet_rig.cpp): the part pairs mapped onto the skeleton.
struct PuppetLandmarks {
    Eigen::Vector3d headNeck{-3.0, 0.0, -7.0};     ///< head frame: the neck joint
    Eigen::Vector3d headTop{-3.0, 0.0, 6.5};       ///< head frame: the top of the hair
    Eigen::Vector3d shoulderNeck{1.0, 0.0, 8.0};   ///< shoulder frame: the neck joint
    Eigen::Vector3d shoulderWaist{0.0, 0.0, -20.0}; ///< shoulder frame: the waist the puppeteer holds
    double torsoWidth = 22.0;                      ///< the torso box's width (y)
    /// The fitted torso is this fraction of the performer's shoulder-joint distance wide (a
    /// person's chest is narrower than their shoulders; the arms hang outside it).
    double torsoPerShoulders = 0.8;
    Eigen::Vector3d armStart{-10.0, 0.0, 0.0};     ///< arm frame: the shoulder end of the arm
    Eigen::Vector3d armEnd{10.0, 0.0, 0.0};        ///< arm frame: the wrist
    Eigen::Vector3d handWrist{-4.0, 0.0, 0.0};     ///< hand frame: the wrist
    Eigen::Vector3d handTip{7.5, 0.0, 0.0};        ///< hand frame: the finger tips
};

struct BodyFitOptions {
    Eigen::Index referenceFrame = 0; ///< the frame whose pose is measured
    PuppetLandmarks puppet;
};

/// `puppet` fitted to the skeleton of `motion`, whose head, shoulder, arm and hand must be
/// bound (PartBinding). The skeleton's landmarks are analysis/core/skeleton_anatomy.h's.
Result<BodyDescription> fitBodyToSkeleton(const BodyDescription& puppet, const SkeletalMotion& motion,
                                          const BodyFitOptions& options = {});

/// `puppet` fitted to the take's skeleton when the take has one with the four parts bound,
/// else `puppet` itself.
BodyDescription bodyForTake(const BodyDescription& puppet, const Take& take);

} // namespace bunraku::analysis
