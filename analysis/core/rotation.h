#pragma once
/// Rotations as points of a curved space: the log and exp maps between unit quaternions and
/// rotation vectors (angle * unit axis, radians), the rotation vector continuous with a previous
/// one, and the mean rotation. Means, differences and weighted sums of rotations are taken on
/// rotation vectors about a base rotation (q = base * exp(r)), never on Euler numbers, so they
/// do not depend on which of the equivalent angle triples a take happens to store.

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <optional>
#include <span>

namespace bunraku::analysis {

/// The rotation vector of q (radians), angle in [0, pi]: q = exp(logMap(q)). Accurate near the
/// identity (no division by a vanishing sine).
Eigen::Vector3d logMap(const Eigen::Quaterniond& q);
/// The unit quaternion of a rotation vector (radians), w >= 0 for angles up to pi.
Eigen::Quaterniond expMap(const Eigen::Vector3d& rotationVector);

/// Of the rotation vectors of q ((angle + 2 pi k) * axis for every integer k) the one nearest
/// `previous`: a track of rotations becomes a continuous curve of vectors that may grow past pi
/// (a part turned about its reference by more than half a turn keeps going instead of jumping).
Eigen::Vector3d nearestRotationVector(const Eigen::Quaterniond& q, const Eigen::Vector3d& previous);

/// The rotation m minimising sum_k w_k |log(m^-1 q_k)|^2 (the Karcher mean, by Gauss-Newton from
/// the sign-aligned chordal mean; it converges in a few steps for rotations within a half turn
/// of each other). Equal weights when `weights` is empty. Identity for no rotations.
Eigen::Quaterniond meanRotation(std::span<const Eigen::Quaterniond> rotations, std::span<const double> weights = {});

/// The chordal mean: the normalised weighted sum of the quaternions sign-aligned with the
/// first - the Karcher mean's starting point, within a small fraction of the spread of it for
/// rotations within a quarter turn of each other, at a fraction of its cost. Charts use it:
/// any base near the data serves for rotation coordinates. Identity for no rotations.
Eigen::Quaterniond chordalMeanRotation(std::span<const Eigen::Quaterniond> rotations, std::span<const double> weights = {});

/// Spherical interpolation a -> b at w in [0, 1] along the shorter arc, normalised.
Eigen::Quaterniond slerpShortest(const Eigen::Quaterniond& a, const Eigen::Quaterniond& b, double w);

/// The angle of the rotation a^-1 b, radians in [0, pi].
double rotationDistance(const Eigen::Quaterniond& a, const Eigen::Quaterniond& b);

} // namespace bunraku::analysis
