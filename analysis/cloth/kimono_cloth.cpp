#include "analysis/cloth/kimono_cloth.h"

#include "analysis/body/body_fit.h"
#include "analysis/body/body_pose.h"
#include "analysis/body/puppet_model.h"
#include "analysis/body/puppet_shapes.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <optional>

namespace bunraku::analysis {
namespace {

constexpr double kGravity = 981.0; // cm/s^2

// The skirt's grid: rings from the dō-wa down to the hem, segments around.
constexpr int kSkirtRings = 13;
constexpr int kSkirtSegments = 28;
// A sleeve's grid: columns along the arm, rows down from above the bone; the top row is sewn to
// the arm (one row: the sleeve turns about it as about a hinge).
constexpr int kSleeveColumns = 7;
constexpr int kSleeveRows = 9;
constexpr int kSleevePinnedRows = 1;

using Capsule = ClothCollider;

const char* const kPointNames[kKimonoPointCount] = {"sleeve_right_tip", "sleeve_left_tip", "hem_front", "hem_back", "hem_left", "hem_right"};

/// The parts of the body that hold the cloth: shoulder, right arm, left arm (body indices).
Result<std::array<int, 3>> holderParts(const BodyDescription& body)
{
    std::array<int, 3> parts{body.partIndex("shoulder"), body.partIndex("right_arm"), body.partIndex("left_arm")};
    for (int k = 0; k < 3; ++k)
        if (parts[std::size_t(k)] < 0)
            return makeError(ErrorCode::InvalidArgument, body.source + ": the kimono needs the body part '" +
                                                              std::string(k == 0 ? "shoulder" : k == 1 ? "right_arm" : "left_arm") + "'");
    return parts;
}

/// The colliders, in the holders' frames of the shipped puppet at rest (then fitted): the
/// torso from the shoulder board to the dō-wa, and each arm along its bone.
std::vector<Capsule> colliders(const BodyDescription& body, const std::array<int, 3>& parts)
{
    const puppet_shapes::RestPose& rest = puppet_shapes::restPose();
    const auto bind = puppetPartBindPoses();
    std::vector<Capsule> out;
    const Eigen::Affine3d& shoulderFit = body.parts[std::size_t(parts[0])].fit;
    const double shoulderScale = std::cbrt(std::abs(shoulderFit.linear().determinant()));
    out.push_back({KimonoCloth::Shoulder, shoulderFit * Eigen::Vector3d(0.0, 0.0, 2.0), shoulderFit * Eigen::Vector3d(0.0, 0.0, rest.dowa.z() + 4.0),
                   6.2 * shoulderScale});
    for (int side = 0; side < 2; ++side) {
        const KimonoCloth::Holder holder = side == 0 ? KimonoCloth::RightArm : KimonoCloth::LeftArm;
        const RigidTransform& model_T_arm = bind[std::size_t(side == 0 ? PuppetJoint::RightArm : PuppetJoint::LeftArm)];
        Eigen::Vector3d shoulderJoint = rest.rightShoulderJoint;
        Eigen::Vector3d wrist = rest.rightShoulderJoint + rest.wristAlong * rest.armDirection;
        if (side == 1) {
            shoulderJoint.y() = -shoulderJoint.y();
            wrist.y() = -wrist.y();
        }
        const Eigen::Affine3d& fit = body.parts[std::size_t(parts[std::size_t(1 + side)])].fit;
        const double scale = std::cbrt(std::abs(fit.linear().determinant()));
        out.push_back({holder, fit * model_T_arm.inverse().apply(shoulderJoint), fit * model_T_arm.inverse().apply(wrist), 2.4 * scale});
    }
    return out;
}

/// A grid of particles (columns x rows, optionally periodic in the columns) with its stretch,
/// shear and bending constraints and its triangles, appended to `cloth`.
void addGrid(KimonoCloth& cloth, const std::vector<Eigen::Vector3d>& model, std::uint32_t first, int columns, int rows, bool periodic)
{
    const auto index = [&](int i, int j) { return first + std::uint32_t(((i % columns + columns) % columns) + j * columns); };
    const auto constrain = [&](std::uint32_t a, std::uint32_t b, bool bending) {
        if (cloth.pinned[a] && cloth.pinned[b]) return;
        cloth.constraints.push_back({a, b, (model[a] - model[b]).norm(), bending});
    };
    const int lastColumn = periodic ? columns : columns - 1;
    for (int j = 0; j < rows; ++j)
        for (int i = 0; i < columns; ++i) {
            if (i < lastColumn) constrain(index(i, j), index(i + 1, j), false);
            if (j + 1 < rows) constrain(index(i, j), index(i, j + 1), false);
            if (i < lastColumn && j + 1 < rows) {
                constrain(index(i, j), index(i + 1, j + 1), false);
                constrain(index(i + 1, j), index(i, j + 1), false);
                // Counter-clockwise seen from outside the skirt (columns go round
                // counter-clockwise seen from above, rows down).
                for (const std::uint32_t v : {index(i, j), index(i + 1, j + 1), index(i + 1, j), index(i, j), index(i, j + 1), index(i + 1, j + 1)})
                    cloth.triangles.push_back(v);
            }
            if ((periodic || i + 2 < columns)) constrain(index(i, j), index(i + 2, j), true);
            if (j + 2 < rows) constrain(index(i, j), index(i, j + 2), true);
        }
}

/// Linear interpolation of a rigid transform (translation lerp, rotation slerp).
RigidTransform blend(const RigidTransform& a, const RigidTransform& b, double f)
{
    return RigidTransform{a.rotation.slerp(f, b.rotation), (1.0 - f) * a.translation + f * b.translation};
}

/// What drives the cloth at one frame: the holders' world poses.
using HolderPoses = std::array<RigidTransform, 3>;

struct Solver {
    const KimonoCloth& cloth;
    const ClothParameters& parameters;
    const std::vector<Capsule>& capsules;
    std::vector<Eigen::Vector3d> x, v, previous;

    void start(const HolderPoses& poses)
    {
        x.resize(cloth.size());
        v.assign(cloth.size(), Eigen::Vector3d::Zero());
        previous.resize(cloth.size());
        for (std::size_t i = 0; i < cloth.size(); ++i) x[i] = poses[cloth.holder[i]].apply(cloth.restLocal[i]);
    }

    /// One substep of length h from the holders at `before` to `after`.
    void step(const HolderPoses& before, const HolderPoses& after, double h)
    {
        const Eigen::Vector3d gravity(0.0, 0.0, -kGravity);
        const double damping = std::exp(-parameters.damping * h);
        const double drag = std::exp(-parameters.drag * h);
        for (std::size_t i = 0; i < cloth.size(); ++i) {
            previous[i] = x[i];
            const Eigen::Vector3d attachedBefore = before[cloth.holder[i]].apply(cloth.restLocal[i]);
            const Eigen::Vector3d attachedAfter = after[cloth.holder[i]].apply(cloth.restLocal[i]);
            if (cloth.pinned[i]) {
                x[i] = attachedAfter;
                continue;
            }
            // Damping: towards the velocity the holder would give the particle (internal
            // friction); drag: towards rest in the air.
            const Eigen::Vector3d carried = (attachedAfter - attachedBefore) / h;
            v[i] = carried + damping * (v[i] - carried);
            v[i] = drag * v[i] + h * gravity;
            x[i] += h * v[i];
        }
        const double stretch = parameters.stretchCompliance / (h * h);
        const double bend = parameters.bendCompliance / (h * h);
        for (const KimonoCloth::Constraint& c : cloth.constraints) {
            const double wa = cloth.inverseMass[c.a], wb = cloth.inverseMass[c.b];
            const Eigen::Vector3d d = x[c.a] - x[c.b];
            const double length = d.norm();
            if (length < 1e-12) continue;
            const double alpha = c.bending ? bend : stretch;
            const double lambda = -(length - c.rest) / (wa + wb + alpha);
            const Eigen::Vector3d n = d / length;
            x[c.a] += wa * lambda * n;
            x[c.b] -= wb * lambda * n;
        }
        for (std::size_t i = 0; i < cloth.size(); ++i) {
            if (cloth.pinned[i]) continue;
            for (const Capsule& capsule : capsules) {
                const RigidTransform& pose = after[capsule.holder];
                const Eigen::Vector3d a = pose.apply(capsule.a), b = pose.apply(capsule.b);
                const Eigen::Vector3d ab = b - a;
                const double t = std::clamp((x[i] - a).dot(ab) / std::max(ab.squaredNorm(), 1e-12), 0.0, 1.0);
                const Eigen::Vector3d closest = a + t * ab;
                const Eigen::Vector3d away = x[i] - closest;
                const double distance = away.norm();
                const double reach = capsule.radius + parameters.collisionMargin;
                if (distance < reach && distance > 1e-9) x[i] = closest + away * (reach / distance);
            }
        }
        keepSleevesOutOfSkirt();
        for (std::size_t i = 0; i < cloth.size(); ++i)
            v[i] = (x[i] - previous[i]) / h;
    }

    /// Where the sleeves meet the skirt (an arm hanging at the side): a sleeve particle inside
    /// the skirt is moved out, horizontally, to the skirt's surface there plus the margin. The
    /// skirt's surface at a height is its two rings around that height (centres and, in the
    /// particle's direction from the centre, where that ray leaves the ring's polygon seen from
    /// above), interpolated. The skirt is not moved (it is the heavier, inner layer).
    void keepSleevesOutOfSkirt()
    {
        if (cloth.skirtEnd != std::uint32_t(kSkirtRings * kSkirtSegments)) return;
        std::array<Eigen::Vector3d, kSkirtRings> centre;
        for (int j = 0; j < kSkirtRings; ++j) {
            Eigen::Vector3d sum = Eigen::Vector3d::Zero();
            for (int i = 0; i < kSkirtSegments; ++i) sum += x[std::size_t(j * kSkirtSegments + i)];
            centre[std::size_t(j)] = sum / double(kSkirtSegments);
        }
        // The skirt's axis (from the hem's centre to the top ring's) and a plane across it: a
        // ring's polygon and a particle's distance from the axis are taken in that plane.
        const Eigen::Vector3d base = centre.back();
        const Eigen::Vector3d along = centre.front() - base;
        const double length = along.norm();
        if (length < 1e-6) return;
        const Eigen::Vector3d u = along / length;
        const Eigen::Vector3d e1 = u.unitOrthogonal(), e2 = u.cross(e1);
        const auto across = [&](const Eigen::Vector3d& v) { return Eigen::Vector2d(v.dot(e1), v.dot(e2)); };
        std::array<double, kSkirtRings> height;
        std::array<double, kSkirtRings> widest{}; // each ring's farthest particle from its centre, in the plane
        for (int j = 0; j < kSkirtRings; ++j) {
            height[std::size_t(j)] = (centre[std::size_t(j)] - base).dot(u);
            for (int i = 0; i < kSkirtSegments; ++i)
                widest[std::size_t(j)] = std::max(widest[std::size_t(j)], across(x[std::size_t(j * kSkirtSegments + i)] - centre[std::size_t(j)]).norm());
        }
        // How far from the ring's centre the ray in direction `d` (unit, in the plane) leaves
        // the ring's polygon: the farthest crossing of an edge.
        const auto radius = [&](int ring, const Eigen::Vector2d& d) {
            const auto cross = [](const Eigen::Vector2d& p, const Eigen::Vector2d& q) { return p.x() * q.y() - p.y() * q.x(); };
            double r = 0.0;
            for (int i = 0; i < kSkirtSegments; ++i) {
                const Eigen::Vector2d a = across(x[std::size_t(ring * kSkirtSegments + i)] - centre[std::size_t(ring)]);
                const Eigen::Vector2d b = across(x[std::size_t(ring * kSkirtSegments + (i + 1) % kSkirtSegments)] - centre[std::size_t(ring)]);
                const Eigen::Vector2d edge = b - a;
                const double denominator = cross(d, edge);
                if (std::abs(denominator) < 1e-12) continue;
                // t d = a + s edge: t = (a x edge) / (d x edge), s = (a x d) / (d x edge).
                const double s = cross(a, d) / denominator;
                const double t = cross(a, edge) / denominator;
                if (s >= 0.0 && s <= 1.0 && t > r) r = t;
            }
            return r;
        };
        for (std::size_t i = cloth.skirtEnd; i < cloth.size(); ++i) {
            if (cloth.pinned[i]) continue;
            const double h = (x[i] - base).dot(u);
            if (h > height.front() || h < height.back()) continue; // above the dō-wa or below the hem
            int ring = 0;
            while (ring + 2 < kSkirtRings && height[std::size_t(ring + 1)] > h) ++ring;
            const double span = height[std::size_t(ring)] - height[std::size_t(ring + 1)];
            const double f = span > 1e-9 ? std::clamp((height[std::size_t(ring)] - h) / span, 0.0, 1.0) : 0.0;
            const Eigen::Vector3d c = (1.0 - f) * centre[std::size_t(ring)] + f * centre[std::size_t(ring + 1)];
            const Eigen::Vector2d away = across(x[i] - c);
            const double distance = away.norm();
            if (distance < 1e-9) continue;
            // Beyond both rings' farthest particles: outside (the common case, no polygon walked).
            if (distance >= std::max(widest[std::size_t(ring)], widest[std::size_t(ring + 1)]) + parameters.collisionMargin) continue;
            const Eigen::Vector2d d = away / distance;
            const double reach = (1.0 - f) * radius(ring, d) + f * radius(ring + 1, d) + parameters.collisionMargin;
            if (distance < reach) x[i] += (reach - distance) * (d.x() * e1 + d.y() * e2);
        }
    }

    void record(Eigen::MatrixXd& points, Eigen::Index frame) const
    {
        for (int p = 0; p < kKimonoPointCount; ++p)
            points.block<1, 3>(frame, 3 * p) = x[cloth.measured[std::size_t(p)]].transpose();
    }
};

/// The holders' world poses at frames [from, to] of the take (element k - from for frame k).
std::vector<HolderPoses> holderPoses(const BodyDescription& body, const BodyBinding& binding, const Take& take, const std::array<int, 3>& parts,
                                     Eigen::Index from, Eigen::Index to)
{
    std::vector<HolderPoses> poses(std::size_t(std::max<Eigen::Index>(0, to - from + 1)));
    for (Eigen::Index k = from; k <= to; ++k) {
        const auto world = worldPartPoses(body, binding, take, k);
        for (int h = 0; h < 3; ++h) poses[std::size_t(k - from)][std::size_t(h)] = world[std::size_t(parts[std::size_t(h)])];
    }
    return poses;
}

/// The holders' world poses of every frame (the take bound to the body once).
Result<std::vector<HolderPoses>> allHolderPoses(const BodyDescription& body, const Take& take, const std::array<int, 3>& parts)
{
    auto binding = bindBody(body, take);
    if (!binding) return binding.error();
    return holderPoses(body, *binding, take, parts, 0, take.frameCount() - 1);
}

int substepsPerFrame(const ClothParameters& parameters, double rateHz)
{
    return std::max(1, int(std::ceil(parameters.substepRate / rateHz - 1e-9)));
}

/// Simulates frames (from, to] from the solver's state at `from`, recording each; `poses` holds
/// the holders from frame `first` on (element k - first for frame k).
void simulateFrames(Solver& solver, const std::vector<HolderPoses>& poses, Eigen::Index first, double rateHz, Eigen::Index from,
                    Eigen::Index to, Eigen::MatrixXd* points)
{
    const int substeps = substepsPerFrame(solver.parameters, rateHz);
    const double h = 1.0 / (rateHz * substeps);
    for (Eigen::Index k = from; k < to; ++k) {
        const HolderPoses& a = poses[std::size_t(k - first)];
        const HolderPoses& b = poses[std::size_t(k + 1 - first)];
        HolderPoses before = a;
        for (int s = 0; s < substeps; ++s) {
            const double f = double(s + 1) / double(substeps);
            HolderPoses after;
            for (int p = 0; p < 3; ++p) after[std::size_t(p)] = blend(a[std::size_t(p)], b[std::size_t(p)], f);
            solver.step(before, after, h);
            before = after;
        }
        if (points) solver.record(*points, k + 1);
    }
}

} // namespace

std::vector<ClothCollider> kimonoColliders(const BodyDescription& body)
{
    auto parts = holderParts(body);
    return parts ? colliders(body, *parts) : std::vector<ClothCollider>{};
}

Result<std::array<RigidTransform, 3>> kimonoHolderPoses(const BodyDescription& body, const Take& take, Eigen::Index frame)
{
    auto parts = holderParts(body);
    if (!parts) return parts.error();
    auto binding = bindBody(body, take);
    if (!binding) return binding.error();
    if (frame < 0 || frame >= take.frameCount()) return makeError(ErrorCode::InvalidArgument, "kimono: no such frame");
    const auto world = worldPartPoses(body, *binding, take, frame);
    return std::array<RigidTransform, 3>{world[std::size_t((*parts)[0])], world[std::size_t((*parts)[1])], world[std::size_t((*parts)[2])]};
}

Status validate(const ClothParameters& p)
{
    const auto check = [](const char* name, double value, double low, double high) -> Status {
        if (!(std::isfinite(value) && value >= low && value <= high))
            return makeError(ErrorCode::InvalidArgument, std::string("cloth.") + name + ": expected a number in " + std::to_string(low) + ".." +
                                                              std::to_string(high) + ", got " + std::to_string(value));
        return okStatus();
    };
    for (const ClothParameterLimit& limit : clothParameterLimits())
        if (auto status = check(limit.name, p.*(limit.member), limit.low, limit.high); !status) return status;
    return okStatus();
}

const std::vector<ClothParameterLimit>& clothParameterLimits()
{
    static const std::vector<ClothParameterLimit> limits{
        {"massPerArea", &ClothParameters::massPerArea, 1e-4, 1.0},       {"stretchCompliance", &ClothParameters::stretchCompliance, 0.0, 1.0},
        {"bendCompliance", &ClothParameters::bendCompliance, 0.0, 1.0},  {"damping", &ClothParameters::damping, 0.0, 100.0},
        {"drag", &ClothParameters::drag, 0.0, 100.0},                    {"substepRate", &ClothParameters::substepRate, 30.0, 10000.0},
        {"collisionMargin", &ClothParameters::collisionMargin, 0.0, 5.0}, {"settleSeconds", &ClothParameters::settleSeconds, 0.0, 10.0}};
    return limits;
}

const char* kimonoPointName(KimonoPoint point) { return kPointNames[int(point)]; }

std::vector<Channel> kimonoChannels()
{
    std::vector<Channel> channels;
    for (const char* name : kPointNames)
        for (const char* axis : {"x", "y", "z"}) channels.push_back({name, axis, "cm"});
    return channels;
}

Result<KimonoCloth> makeKimonoCloth(const BodyDescription& body, const ClothParameters& parameters)
{
    if (auto status = validate(parameters); !status) return status.error();
    auto parts = holderParts(body);
    if (!parts) return parts.error();
    const puppet_shapes::RestPose& rest = puppet_shapes::restPose();
    const auto bind = puppetPartBindPoses();
    KimonoCloth cloth;
    // Model-space rest positions (the fitted puppet's), for rest lengths and areas.
    std::vector<Eigen::Vector3d> model;
    const auto add = [&](const Eigen::Vector3d& modelPoint, KimonoCloth::Holder holder, PuppetJoint joint, bool pinned) {
        const Eigen::Affine3d& fit = body.parts[std::size_t((*parts)[holder])].fit;
        const RigidTransform& model_T_part = bind[std::size_t(joint)];
        const Eigen::Vector3d local = fit * model_T_part.inverse().apply(modelPoint);
        cloth.restLocal.push_back(local);
        cloth.paintPositions.push_back(modelPoint.cast<float>());
        cloth.holder.push_back(holder);
        cloth.pinned.push_back(pinned);
        model.push_back(model_T_part.apply(local));
    };

    // The skirt: an elliptic frustum from just below the dō-wa to the hem (puppet_shapes' skirt).
    const double top = rest.dowa.z() + 1.0, hem = rest.hemZ;
    for (int j = 0; j < kSkirtRings; ++j) {
        const double t = double(j) / double(kSkirtRings - 1);
        const double z = top + (hem - top) * t;
        const double rx = 6.9 + (10.8 - 6.9) * t, ry = 8.4 + (13.6 - 8.4) * t;
        for (int i = 0; i < kSkirtSegments; ++i) {
            const double angle = 2.0 * M_PI * double(i) / double(kSkirtSegments);
            add(Eigen::Vector3d(rx * std::cos(angle), ry * std::sin(angle), z), KimonoCloth::Shoulder, PuppetJoint::Shoulder, j == 0);
        }
    }
    cloth.skirtEnd = std::uint32_t(cloth.size());
    // The sleeves: a vertical panel under each arm's bone (the right one; the left mirrors it).
    for (int side = 0; side < 2; ++side) {
        for (int j = 0; j < kSleeveRows; ++j)
            for (int i = 0; i < kSleeveColumns; ++i) {
                const double along = 7.5 + (18.4 - 7.5) * double(i) / double(kSleeveColumns - 1);
                const double down = -2.6 + (14.5 + 2.6) * double(j) / double(kSleeveRows - 1);
                Eigen::Vector3d p = rest.rightShoulderJoint + along * rest.armDirection + Eigen::Vector3d(0.0, 0.0, -down);
                if (side == 1) p.y() = -p.y();
                add(p, side == 0 ? KimonoCloth::RightArm : KimonoCloth::LeftArm, side == 0 ? PuppetJoint::RightArm : PuppetJoint::LeftArm,
                    j < kSleevePinnedRows);
            }
        if (side == 0) cloth.rightSleeveEnd = std::uint32_t(cloth.size());
    }
    addGrid(cloth, model, 0, kSkirtSegments, kSkirtRings, true);
    addGrid(cloth, model, cloth.skirtEnd, kSleeveColumns, kSleeveRows, false);
    addGrid(cloth, model, cloth.rightSleeveEnd, kSleeveColumns, kSleeveRows, false);

    // Masses: a third of each triangle's area to each of its corners.
    std::vector<double> area(cloth.size(), 0.0);
    for (std::size_t t = 0; t + 2 < cloth.triangles.size(); t += 3) {
        const auto a = cloth.triangles[t], b = cloth.triangles[t + 1], c = cloth.triangles[t + 2];
        const double third = (model[b] - model[a]).cross(model[c] - model[a]).norm() / 6.0;
        area[a] += third;
        area[b] += third;
        area[c] += third;
    }
    cloth.inverseMass.resize(cloth.size());
    for (std::size_t i = 0; i < cloth.size(); ++i) {
        const double mass = parameters.massPerArea * std::max(area[i], 1e-6);
        cloth.inverseMass[i] = cloth.pinned[i] ? 0.0 : 1.0 / mass;
    }
    // The measured points: each sleeve's lower wrist-side corner, the hem at front, back, left, right.
    const auto sleeveTip = [&](std::uint32_t first) { return first + std::uint32_t((kSleeveRows - 1) * kSleeveColumns + kSleeveColumns - 1); };
    const std::uint32_t hemRing = std::uint32_t((kSkirtRings - 1) * kSkirtSegments);
    cloth.measured = {sleeveTip(cloth.skirtEnd), sleeveTip(cloth.rightSleeveEnd), hemRing, hemRing + kSkirtSegments / 2,
                      hemRing + kSkirtSegments / 4, hemRing + 3 * kSkirtSegments / 4};
    return cloth;
}

Result<KimonoSimulation> simulateKimono(const Take& take, const ClothParameters& parameters, const RunControl& control)
{
    return simulateKimono(take, take.skeleton ? bodyForTake(defaultBodyDescription(), take) : defaultBodyDescription(), parameters, control);
}

Result<KimonoSimulation> simulateKimono(const Take& take, const BodyDescription& body, const ClothParameters& parameters,
                                        const RunControl& control)
{
    if (auto status = validate(parameters); !status) return status.error();
    if (take.frameCount() < 1 || !(take.rateHz > 0.0)) return makeError(ErrorCode::InvalidArgument, take.displayName() + ": the kimono needs frames and a rate");
    KimonoSimulation simulation;
    simulation.body = body;
    auto parts = holderParts(simulation.body);
    if (!parts) return parts.error();
    auto cloth = makeKimonoCloth(simulation.body, parameters);
    if (!cloth) return cloth.error();
    simulation.cloth = std::make_shared<const KimonoCloth>(std::move(*cloth));
    simulation.parameters = parameters;
    simulation.rateHz = take.rateHz;
    auto poses = allHolderPoses(simulation.body, take, *parts);
    if (!poses) return makeError(poses.error().code, take.displayName() + ": " + poses.error().message);
    const Eigen::Index frames = take.frameCount();
    // At most about 2,000 kept states whatever the take's length (an hour at 120 Hz keeps one
    // every 216 frames, 47 MB).
    simulation.checkpointInterval = int(std::max<Eigen::Index>(30, (frames + 1999) / 2000));
    simulation.points.resize(frames, 3 * kKimonoPointCount);

    const std::vector<Capsule> capsules = colliders(simulation.body, *parts);
    Solver solver{*simulation.cloth, parameters, capsules, {}, {}, {}};
    solver.start((*poses)[0]);
    const int settle = int(std::ceil(parameters.settleSeconds * parameters.substepRate));
    for (int s = 0; s < settle; ++s) solver.step((*poses)[0], (*poses)[0], 1.0 / parameters.substepRate);
    solver.record(simulation.points, 0);
    const auto keep = [&] {
        simulation.checkpointPositions.push_back(solver.x);
        simulation.checkpointVelocities.push_back(solver.v);
    };
    // Every frame's particles too when they fit the budget (a view plays them back without
    // simulating).
    const std::size_t particles = simulation.cloth->size();
    const bool store = double(frames) * double(particles) * 3.0 * sizeof(float) <= double(kKimonoStoredFramesBytes);
    const auto storeFrame = [&] {
        if (!store) return;
        for (const Eigen::Vector3d& p : solver.x) simulation.particleFrames.insert(simulation.particleFrames.end(), {float(p.x()), float(p.y()), float(p.z())});
    };
    if (store) simulation.particleFrames.reserve(std::size_t(frames) * particles * 3);
    keep();
    storeFrame();
    for (Eigen::Index k = 0; k + 1 < frames; ++k) {
        if (control.cancelled()) return makeError(ErrorCode::Cancelled, take.displayName() + ": the kimono's simulation was cancelled");
        simulateFrames(solver, *poses, 0, take.rateHz, k, k + 1, &simulation.points);
        storeFrame();
        if ((k + 1) % simulation.checkpointInterval == 0) keep();
        if (k % 64 == 0) control.report(double(k + 1) / double(frames));
    }
    control.report(1.0);
    return simulation;
}

Result<std::vector<Eigen::Vector3d>> kimonoFrame(const KimonoSimulation& simulation, const Take& take, Eigen::Index frame)
{
    // A player of its own, whose first frame is simulated from the checkpoint before it.
    KimonoPlayer player(std::shared_ptr<const KimonoSimulation>(&simulation, [](const KimonoSimulation*) {}),
                        std::shared_ptr<const Take>(&take, [](const Take*) {}));
    auto particles = player.frame(frame);
    if (!particles) return particles.error();
    return *particles.value();
}

struct KimonoPlayer::State {
    std::optional<BodyBinding> binding;
    std::array<int, 3> parts{};
    std::vector<Capsule> capsules;
    std::unique_ptr<Solver> solver;
};

KimonoPlayer::KimonoPlayer(std::shared_ptr<const KimonoSimulation> simulation, std::shared_ptr<const Take> take)
    : simulation_(std::move(simulation)), take_(std::move(take)), state_(std::make_unique<State>())
{
}

KimonoPlayer::~KimonoPlayer() = default;
KimonoPlayer::KimonoPlayer(KimonoPlayer&&) noexcept = default;
KimonoPlayer& KimonoPlayer::operator=(KimonoPlayer&&) noexcept = default;

Result<const std::vector<Eigen::Vector3d>*> KimonoPlayer::frame(Eigen::Index frame)
{
    const KimonoSimulation& simulation = *simulation_;
    const Take& take = *take_;
    if (frame < 0 || frame >= simulation.frameCount() || take.frameCount() != simulation.frameCount())
        return makeError(ErrorCode::InvalidArgument, take.displayName() + ": frame " + std::to_string(frame) + " is not a frame of the simulated take");
    State& state = *state_;
    if (!state.binding) {
        auto parts = holderParts(simulation.body);
        if (!parts) return parts.error();
        auto binding = bindBody(simulation.body, take);
        if (!binding) return binding.error();
        state.parts = *parts;
        state.binding = std::move(*binding);
        state.capsules = colliders(simulation.body, state.parts);
    }
    const Eigen::Index interval = simulation.checkpointInterval;
    const Eigen::Index checkpointFrame = (frame / interval) * interval;
    // Step on from the frame shown last when it is behind `frame` and no farther than the
    // checkpoint; else start again from the checkpoint (the same bits either way: the state is
    // the particles' positions and velocities).
    const bool stepOn = state.solver && current_ <= frame && current_ >= checkpointFrame;
    if (!stepOn) {
        const std::size_t checkpoint = std::size_t(frame / interval);
        if (checkpoint >= simulation.checkpointPositions.size()) return makeError(ErrorCode::InvalidArgument, "kimono: no state kept before that frame");
        state.solver = std::make_unique<Solver>(Solver{*simulation.cloth, simulation.parameters, state.capsules, simulation.checkpointPositions[checkpoint],
                                                       simulation.checkpointVelocities[checkpoint],
                                                       std::vector<Eigen::Vector3d>(simulation.cloth->size())});
        current_ = checkpointFrame;
    }
    if (current_ < frame) {
        const auto poses = holderPoses(simulation.body, *state.binding, take, state.parts, current_, frame);
        simulateFrames(*state.solver, poses, current_, simulation.rateHz, current_, frame, nullptr);
        current_ = frame;
    }
    return &state.solver->x;
}

Result<KimonoMeasures> measureKimono(const Take& take, const KimonoSimulation& simulation)
{
    const Eigen::Index frames = take.frameCount();
    if (frames < 3 || simulation.frameCount() != frames) return makeError(ErrorCode::InvalidArgument, take.displayName() + ": the kimono's measures need 3 frames or more");
    const auto hand = take.channelIndex("hand", "x");
    if (!hand) return makeError(ErrorCode::InvalidArgument, take.displayName() + ": the kimono's measures need the hand part");
    const KimonoCloth& cloth = *simulation.cloth;
    KimonoMeasures measures;
    // Displacement from rigid carrying, per frame: right tip, left tip, the hem's four points.
    // Its slow part is where the cloth hangs as the pose changes (a raised arm's sleeve hangs
    // along it); what swings is the rest: the RMS about a centred moving mean of 0.5 s.
    const int half = std::max(1, int(std::lround(0.25 * take.rateHz)));
    const auto spread = [&](const std::vector<Eigen::Vector3d>& values) {
        const long n = long(values.size());
        double sum = 0.0;
        for (long k = 0; k < n; ++k) {
            Eigen::Vector3d mean = Eigen::Vector3d::Zero();
            const long from = std::max(0L, k - half), to = std::min(n - 1, k + half);
            for (long j = from; j <= to; ++j) mean += values[std::size_t(j)];
            mean /= double(to - from + 1);
            sum += (values[std::size_t(k)] - mean).squaredNorm();
        }
        return std::sqrt(sum / double(n));
    };
    auto parts = holderParts(simulation.body);
    if (!parts) return parts.error();
    // The holders' poses of every frame, bound once (as the simulation does).
    auto poses = allHolderPoses(simulation.body, take, *parts);
    if (!poses) return poses.error();
    std::array<std::vector<Eigen::Vector3d>, kKimonoPointCount> displacement;
    for (Eigen::Index k = 0; k < frames; ++k) {
        const HolderPoses& holders = (*poses)[std::size_t(k)];
        for (int p = 0; p < kKimonoPointCount; ++p) {
            const std::uint32_t i = cloth.measured[std::size_t(p)];
            const Eigen::Vector3d carried = holders[cloth.holder[i]].apply(cloth.restLocal[i]);
            displacement[std::size_t(p)].push_back(simulation.points.block<1, 3>(k, 3 * p).transpose() - carried);
        }
    }
    measures.sleeveSwingCm[0] = spread(displacement[0]);
    measures.sleeveSwingCm[1] = spread(displacement[1]);
    double hem = 0.0;
    for (int p = 2; p < kKimonoPointCount; ++p) hem += spread(displacement[std::size_t(p)]) / 4.0;
    measures.hemSwingCm = hem;
    std::vector<Eigen::Vector3d> handPositions;
    for (Eigen::Index k = 0; k < frames; ++k) handPositions.push_back(take.values.block<1, 3>(k, *hand).transpose());
    measures.handSwingCm = spread(handPositions);
    // The lag: velocities of the hand's sensor and the right sleeve tip.
    std::vector<Eigen::Vector3d> handVelocity, tipVelocity;
    for (Eigen::Index k = 1; k < frames; ++k) {
        handVelocity.push_back((take.values.block<1, 3>(k, *hand) - take.values.block<1, 3>(k - 1, *hand)).transpose());
        tipVelocity.push_back((simulation.points.block<1, 3>(k, 0) - simulation.points.block<1, 3>(k - 1, 0)).transpose());
    }
    const int window = std::max(1, int(std::lround(0.5 * take.rateHz)));
    const auto correlation = [&](int lag) {
        double sum = 0.0;
        for (std::size_t t = 0; t < handVelocity.size(); ++t) {
            const long u = long(t) + lag;
            if (u >= 0 && std::size_t(u) < tipVelocity.size()) sum += handVelocity[t].dot(tipVelocity[std::size_t(u)]);
        }
        return sum;
    };
    int best = 0;
    for (int lag = -window; lag <= window; ++lag)
        if (correlation(lag) > correlation(best)) best = lag;
    double lag = best;
    if (best > -window && best < window) {
        const double before = correlation(best - 1), at = correlation(best), after = correlation(best + 1);
        const double curvature = before - 2.0 * at + after;
        if (curvature < 0.0) lag += 0.5 * (before - after) / curvature;
    }
    measures.sleeveLagSeconds = lag / take.rateHz;
    return measures;
}

Take withKimonoChannels(const Take& take, const KimonoSimulation& simulation)
{
    Take out = take;
    const auto channels = kimonoChannels();
    out.channels.insert(out.channels.end(), channels.begin(), channels.end());
    out.values.conservativeResize(take.frameCount(), take.channelCount() + Eigen::Index(channels.size()));
    out.values.rightCols(Eigen::Index(channels.size())) = simulation.points;
    return out;
}

Take kimonoTake(const Take& take, const KimonoSimulation& simulation)
{
    Take out;
    out.channels = kimonoChannels();
    out.values = simulation.points;
    out.rateHz = take.rateHz;
    out.labels.function = take.labels.function;
    out.labels.emotion = take.labels.emotion;
    out.labels.takeIndex = take.labels.takeIndex;
    out.labels.source = "kimono of " + take.displayName();
    return out;
}

} // namespace bunraku::analysis
