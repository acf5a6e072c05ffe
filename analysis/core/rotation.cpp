#include "analysis/core/rotation.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace bunraku::analysis {

Eigen::Vector3d logMap(const Eigen::Quaterniond& q)
{
    Eigen::Quaterniond unit = q.normalized();
    if (unit.w() < 0.0) unit.coeffs() = -unit.coeffs(); // the same rotation, angle in [0, pi]
    const Eigen::Vector3d v = unit.vec();
    const double s = v.norm();
    if (s < 1e-8) {
        // angle = 2 atan2(s, w) ~ 2 s / w (1 - s^2 / (3 w^2)): the axis comes from v itself.
        const double w = unit.w();
        return (2.0 / w) * (1.0 - s * s / (3.0 * w * w)) * v;
    }
    const double angle = 2.0 * std::atan2(s, unit.w());
    return (angle / s) * v;
}

Eigen::Quaterniond expMap(const Eigen::Vector3d& r)
{
    const double angle = r.norm();
    const double half = 0.5 * angle;
    // sin(half) / angle, by its series near zero.
    const double factor = angle < 1e-8 ? 0.5 - angle * angle / 48.0 : std::sin(half) / angle;
    Eigen::Quaterniond q;
    q.w() = std::cos(half);
    q.vec() = factor * r;
    return q.normalized();
}

Eigen::Vector3d nearestRotationVector(const Eigen::Quaterniond& q, const Eigen::Vector3d& previous)
{
    const Eigen::Vector3d principal = logMap(q);
    const double angle = principal.norm();
    constexpr double turn = 2.0 * std::numbers::pi;
    if (angle < 1e-12) {
        // The identity: 2 pi k along any axis; the one along `previous` nearest it.
        const double length = previous.norm();
        if (length < 1e-12) return principal;
        return (turn * std::round(length / turn) / length) * previous;
    }
    const Eigen::Vector3d axis = principal / angle;
    const double k = std::round((previous.dot(axis) - angle) / turn);
    return (angle + k * turn) * axis;
}

Eigen::Quaterniond chordalMeanRotation(std::span<const Eigen::Quaterniond> rotations, std::span<const double> weights)
{
    if (rotations.empty()) return Eigen::Quaterniond::Identity();
    // Quaternions sign-aligned with the first, summed.
    Eigen::Vector4d sum = Eigen::Vector4d::Zero();
    const Eigen::Vector4d first = rotations[0].coeffs();
    for (std::size_t k = 0; k < rotations.size(); ++k) {
        const Eigen::Vector4d c = rotations[k].coeffs();
        sum += (weights.empty() ? 1.0 : weights[k]) * (c.dot(first) < 0.0 ? -c : c);
    }
    const double norm = sum.norm();
    if (!(norm > 1e-12)) return rotations[0].normalized();
    return Eigen::Quaterniond(sum / norm);
}

Eigen::Quaterniond meanRotation(std::span<const Eigen::Quaterniond> rotations, std::span<const double> weights)
{
    if (rotations.empty()) return Eigen::Quaterniond::Identity();
    auto weight = [&](std::size_t k) { return weights.empty() ? 1.0 : weights[k]; };
    double total = 0.0;
    for (std::size_t k = 0; k < rotations.size(); ++k) total += weight(k);
    if (!(total > 0.0)) return rotations[0].normalized();
    Eigen::Quaterniond mean = chordalMeanRotation(rotations, weights);
    // Gauss-Newton on the sum of squared geodesic distances (quadratic convergence from the
    // chordal start; 1e-12 rad is far below any motion capture's resolution).
    for (int iteration = 0; iteration < 20; ++iteration) {
        Eigen::Vector3d step = Eigen::Vector3d::Zero();
        for (std::size_t k = 0; k < rotations.size(); ++k) step += weight(k) * logMap(mean.conjugate() * rotations[k]);
        step /= total;
        mean = (mean * expMap(step)).normalized();
        if (step.norm() < 1e-12) break;
    }
    return mean;
}

Eigen::Quaterniond slerpShortest(const Eigen::Quaterniond& a, const Eigen::Quaterniond& b, double w)
{
    if (w <= 0.0) return a.normalized();
    if (w >= 1.0) return b.normalized();
    return a.slerp(w, b).normalized();
}

double rotationDistance(const Eigen::Quaterniond& a, const Eigen::Quaterniond& b)
{
    return logMap(a.conjugate() * b).norm();
}

} // namespace bunraku::analysis
