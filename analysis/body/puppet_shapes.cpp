#include "analysis/body/puppet_shapes.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>

namespace bunraku::analysis::puppet_shapes {
namespace {

using V = Eigen::Vector3f;

float smoothMin(float a, float b, float k)
{
    if (k <= 0.0f) return std::min(a, b);
    const float h = std::max(k - std::abs(a - b), 0.0f) / k;
    return std::min(a, b) - h * h * k * 0.25f;
}

Eigen::Matrix3f rotation(double yaw, double pitch, double roll)
{
    return rotationFromYawPitchRoll(YawPitchRoll{yaw, pitch, roll}).toRotationMatrix().cast<float>();
}

struct Builder {
    std::vector<Shape> list;
    Group group = Group::Body;

    Shape& add(Shape s, Material m, float blend)
    {
        s.group = group;
        s.material = m;
        s.blend = blend;
        list.push_back(s);
        return list.back();
    }
    /// An ellipsoid with radii `r` at `c`, its axes turned by `R` (model_R_local).
    Shape& ellipsoid(const V& c, const V& r, Material m, float blend, const Eigen::Matrix3f& R = Eigen::Matrix3f::Identity())
    {
        Shape s;
        s.kind = Kind::Ellipsoid;
        s.origin = c;
        s.toLocal = R.transpose();
        s.a = r;
        s.centre = c;
        s.radius = r.maxCoeff();
        return add(s, m, blend);
    }
    Shape& roundBox(const V& c, const V& half, float rounding, Material m, float blend,
                    const Eigen::Matrix3f& R = Eigen::Matrix3f::Identity())
    {
        Shape s;
        s.kind = Kind::RoundBox;
        s.origin = c;
        s.toLocal = R.transpose();
        s.a = (half - V::Constant(rounding)).cwiseMax(0.0f);
        s.r0 = rounding;
        s.centre = c;
        s.radius = half.norm();
        return add(s, m, blend);
    }
    Shape& capsule(const V& a, const V& b, float ra, float rb, Material m, float blend)
    {
        Shape s;
        s.kind = Kind::Capsule;
        s.a = a;
        s.b = b;
        s.r0 = ra;
        s.r1 = rb;
        s.centre = 0.5f * (a + b);
        s.radius = 0.5f * (b - a).norm() + std::max(ra, rb);
        return add(s, m, blend);
    }
};

float lengthOf(float x, float y) { return std::sqrt(x * x + y * y); }

float distanceOf(const Shape& s, const V& p)
{
    switch (s.kind) {
    case Kind::Ellipsoid: {
        const V q = s.toLocal * (p - s.origin);
        const float k0 = q.cwiseQuotient(s.a).norm();
        const float k1 = q.cwiseQuotient(s.a.cwiseProduct(s.a)).norm();
        if (k1 < 1e-6f) return -s.a.minCoeff();
        return k0 * (k0 - 1.0f) / k1;
    }
    case Kind::RoundBox: {
        const V q = (s.toLocal * (p - s.origin)).cwiseAbs() - s.a;
        return q.cwiseMax(0.0f).norm() + std::min(q.maxCoeff(), 0.0f) - s.r0;
    }
    case Kind::Capsule: {
        const V pa = p - s.a, ba = s.b - s.a;
        const float h = std::clamp(pa.dot(ba) / ba.dot(ba), 0.0f, 1.0f);
        return (pa - ba * h).norm() - (s.r0 + (s.r1 - s.r0) * h);
    }
    case Kind::EllipticFrustum: {
        const V q = s.toLocal * (p - s.origin);
        const float z0 = s.b.x(), z1 = s.b.y();
        const float t = std::clamp((q.z() - z0) / (z1 - z0), 0.0f, 1.0f);
        const float ax = s.r0 + (s.r1 - s.r0) * t, ay = s.r2 + (s.r3 - s.r2) * t;
        const float side = (lengthOf(q.x() / ax, q.y() / ay) - 1.0f) * std::min(ax, ay);
        const float cap = std::max(z0 - q.z(), q.z() - z1);
        const float rounding = s.a.x();
        return lengthOf(std::max(side + rounding, 0.0f), std::max(cap + rounding, 0.0f)) +
               std::min(std::max(side + rounding, cap + rounding), 0.0f) - rounding;
    }
    case Kind::Panel: {
        // A vertical panel hanging from a sloping line: p - origin = t axis + s down + w n.
        const V down(0.0f, 0.0f, -1.0f);
        const V n = s.panelAxis.cross(down).normalized();
        V q = p - s.origin;
        const float w = q.dot(n);
        q -= w * n;
        const float c = s.panelAxis.dot(down);
        const float qd = q.dot(s.panelAxis), qg = q.dot(down);
        const float det = 1.0f - c * c;
        const float t = (qd - c * qg) / det, sd = (qg - c * qd) / det;
        // Rounded rectangle in (t, s), then extruded to the half thickness with rounded edges.
        const float corner = s.r3;
        const float ct = 0.5f * (s.a.x() + s.b.x()), cs = 0.5f * (s.a.y() + s.b.y());
        const float ht = 0.5f * (s.b.x() - s.a.x()) - corner, hs = 0.5f * (s.b.y() - s.a.y()) - corner;
        const float dx = std::abs(t - ct) - ht, dy = std::abs(sd - cs) - hs;
        const float flat = lengthOf(std::max(dx, 0.0f), std::max(dy, 0.0f)) + std::min(std::max(dx, dy), 0.0f) - corner;
        const float edge = 0.5f;
        const float across = std::abs(w) - (s.r2 - edge);
        const float inPlane = flat + edge;
        return lengthOf(std::max(inPlane, 0.0f), std::max(across, 0.0f)) + std::min(std::max(inPlane, across), 0.0f) - edge;
    }
    }
    return 1e9f;
}

} // namespace

float evaluate(const std::vector<Shape>& list, const V& p, Nearest* nearest);

namespace {

RestPose makeRestPose()
{
    RestPose r;
    r.shoulder = RigidTransform{};
    // The rig's rest (analysis/synth/puppet_rig.cpp): neck 8 cm above the shoulder sensor and
    // 1 cm forward, the head sensor 7 cm above and 3 cm in front of it (head upright here).
    r.head = RigidTransform{Eigen::Quaterniond::Identity(), r.neckJoint + Eigen::Vector3d(3.0, 0.0, 7.0)};
    const RigidTransform upperArm{rotationFromYawPitchRoll(YawPitchRoll{-20.0, 35.0, 0.0}), r.rightShoulderJoint};
    r.rightArm = upperArm * RigidTransform{Eigen::Quaterniond::Identity(), Eigen::Vector3d(10.0, 0.0, 0.0)};
    r.rightHand = upperArm *
                  RigidTransform{rotationFromYawPitchRoll(YawPitchRoll{10.0, -25.0, -30.0}), Eigen::Vector3d(r.wristAlong, 0.0, 0.0)} *
                  RigidTransform{Eigen::Quaterniond::Identity(), Eigen::Vector3d(4.0, 0.0, 0.0)};
    r.armDirection = upperArm.rotation * Eigen::Vector3d::UnitX();
    return r;
}

std::vector<Shape> makeShapes()
{
    const RestPose& rest = restPose();
    Builder b;
    const Material K = Material::Kimono;

    // ---- Body: kata-ita under the kimono's shoulders, the chest, collars, obi and its knot,
    // the dō-wa and the skirt down to the padded hem.
    b.group = Group::Body;
    // kata-ita: the board's ends carry the sleeves, the kimono slopes from the neck to them.
    b.roundBox(V(0.0f, 0.0f, 4.2f), V(4.4f, 10.6f, 1.4f), 1.3f, K, 0.0f);
    b.capsule(V(0.0f, -3.0f, 6.0f), V(0.0f, 3.0f, 6.0f), 2.6f, 2.6f, K, 2.5f);
    b.roundBox(V(0.2f, 0.0f, -5.0f), V(5.4f, 6.8f, 9.5f), 3.6f, K, 3.5f);                  // chest
    b.ellipsoid(V(2.2f, 0.0f, -4.0f), V(3.8f, 5.6f, 4.5f), K, 2.5f);                       // bosom of the kimono
    // Collars: the white under-collar and the kimono's red one, laid on the chest (each
    // control point moved onto the surface built so far) and crossing in a V at the front.
    const auto lay = [&](const std::vector<V>& points, float radius, Material m) {
        for (const float side : {1.0f, -1.0f}) {
            std::vector<V> laid;
            for (V p : points) {
                p.y() *= side;
                for (int step = 0; step < 6; ++step) {
                    const float d = evaluate(b.list, p);
                    V g;
                    for (int axis = 0; axis < 3; ++axis) {
                        V e = V::Zero();
                        e[axis] = 0.02f;
                        g[axis] = (evaluate(b.list, p + e) - evaluate(b.list, p - e)) / 0.04f;
                    }
                    p -= (d - 0.45f * radius) * g.normalized();
                }
                laid.push_back(p);
            }
            for (std::size_t i = 0; i + 1 < laid.size(); ++i) b.capsule(laid[i], laid[i + 1], radius, radius, m, 0.25f);
        }
    };
    const std::vector<V> white{V(-1.6f, -1.6f, 9.0f), V(0.8f, -2.3f, 8.6f), V(3.0f, -1.9f, 6.5f), V(4.8f, -1.0f, 3.5f),
                               V(5.8f, 0.3f, 0.5f), V(6.0f, 1.2f, -1.2f)};
    const std::vector<V> red{V(-1.4f, -2.5f, 8.6f), V(1.0f, -3.2f, 8.0f), V(3.2f, -2.9f, 5.6f), V(5.0f, -2.0f, 2.4f),
                             V(5.9f, -0.7f, -0.8f), V(6.1f, 0.5f, -2.8f)};
    lay(white, 0.45f, Material::CollarWhite);
    lay(red, 0.5f, Material::CollarRed);
    b.roundBox(V(0.0f, 0.0f, -18.0f), V(6.3f, 7.9f, 4.3f), 2.6f, Material::Obi, 1.0f);     // obi
    b.roundBox(V(0.0f, 0.0f, -18.2f), V(6.75f, 8.3f, 0.4f), 0.4f, Material::ObiCord, 0.2f); // obi-jime cord
    // The knot at the back: the drum (taiko) with a bow of two wings over it and hanging ends.
    b.roundBox(V(-7.4f, 0.0f, -16.4f), V(1.5f, 6.4f, 4.6f), 1.3f, Material::ObiKnot, 0.8f);
    const Eigen::Matrix3f wingTurn = rotation(0.0, 0.0, 12.0);
    b.ellipsoid(V(-9.2f, -4.2f, -13.4f), V(1.3f, 4.0f, 2.2f), Material::Obi, 0.6f, wingTurn);
    b.ellipsoid(V(-9.2f, 4.2f, -13.4f), V(1.3f, 4.0f, 2.2f), Material::Obi, 0.6f, wingTurn.transpose());
    b.ellipsoid(V(-9.7f, 0.0f, -13.5f), V(1.6f, 1.7f, 2.1f), Material::ObiKnot, 0.5f);
    b.roundBox(V(-8.3f, 0.0f, -22.5f), V(0.8f, 3.4f, 3.6f), 0.7f, Material::Obi, 0.5f);
    // dō-wa: the hoop the skirt hangs from, a little wider than the obi's lower edge.
    b.ellipsoid(V(0.0f, 0.0f, float(rest.dowa.z())), V(7.2f, 8.8f, 2.0f), K, 2.0f);
    Shape skirt;
    skirt.kind = Kind::EllipticFrustum;
    skirt.origin = V(0.0f, 0.0f, 0.0f);
    skirt.b = V(float(rest.hemZ), float(rest.dowa.z()) + 1.0f, 0.0f);
    skirt.r0 = 10.8f; // x radius at the hem
    skirt.r1 = 6.9f;  // at the dō-wa
    skirt.r2 = 13.6f; // y radius at the hem
    skirt.r3 = 8.4f;
    skirt.a = V(1.2f, 0.0f, 0.0f); // edge rounding
    skirt.centre = V(0.0f, 0.0f, 0.5f * float(rest.hemZ + rest.dowa.z()));
    skirt.radius = 22.0f;
    b.add(skirt, K, 2.0f);
    // The padded hem (fuki) rolls out a little at the bottom.
    b.ellipsoid(V(0.0f, 0.0f, float(rest.hemZ) + 1.3f), V(11.3f, 14.1f, 1.1f), K, 1.0f);

    // ---- Head: neck, face with brow, nose, lips and chin, the shimada hairstyle, ornaments.
    b.group = Group::Head;
    b.capsule(V(1.0f, 0.0f, 6.5f), V(1.7f, 0.0f, 11.8f), 1.75f, 1.55f, Material::Skin, 1.2f); // neck
    b.ellipsoid(V(2.3f, 0.0f, 14.6f), V(4.5f, 3.9f, 5.4f), Material::Skin, 1.0f);               // skull and face
    b.ellipsoid(V(3.9f, 0.0f, 11.9f), V(2.7f, 2.6f, 2.3f), Material::Skin, 1.6f);               // jaw and chin
    b.ellipsoid(V(4.9f, -1.9f, 13.3f), V(1.7f, 1.5f, 1.5f), Material::Skin, 1.2f);              // cheeks
    b.ellipsoid(V(4.9f, 1.9f, 13.3f), V(1.7f, 1.5f, 1.5f), Material::Skin, 1.2f);
    b.capsule(V(6.05f, -1.9f, 15.75f), V(6.25f, 0.0f, 15.95f), 0.55f, 0.55f, Material::Skin, 0.9f); // brow
    b.capsule(V(6.25f, 0.0f, 15.95f), V(6.05f, 1.9f, 15.75f), 0.55f, 0.55f, Material::Skin, 0.9f);
    b.capsule(V(6.55f, 0.0f, 15.3f), V(7.25f, 0.0f, 13.55f), 0.38f, 0.55f, Material::Skin, 0.6f);  // nose
    b.ellipsoid(V(6.45f, 0.0f, 12.45f), V(0.45f, 0.95f, 0.3f), Material::Skin, 0.3f);              // upper lip
    b.ellipsoid(V(6.3f, 0.0f, 11.95f), V(0.5f, 0.8f, 0.33f), Material::Skin, 0.3f);                // lower lip
    b.ellipsoid(V(5.4f, 0.0f, 10.35f), V(1.1f, 1.3f, 0.9f), Material::Skin, 0.8f);                 // chin
    // Hair: the cap over the skull (leaving the face), the side wings (bin), the front
    // (maegami), the topknot (mage) and the bun at the nape (tabo).
    const Material H = Material::Hair;
    b.ellipsoid(V(1.2f, 0.0f, 15.9f), V(4.75f, 4.35f, 5.45f), H, 0.4f);
    b.ellipsoid(V(1.0f, -3.9f, 14.6f), V(2.7f, 1.7f, 3.0f), H, 1.0f);
    b.ellipsoid(V(1.0f, 3.9f, 14.6f), V(2.7f, 1.7f, 3.0f), H, 1.0f);
    b.ellipsoid(V(4.1f, 0.0f, 19.7f), V(2.3f, 2.9f, 1.9f), H, 1.2f);
    b.ellipsoid(V(0.2f, 0.0f, 21.6f), V(3.4f, 1.7f, 1.8f), H, 1.0f);
    b.ellipsoid(V(-3.6f, 0.0f, 13.2f), V(2.2f, 3.7f, 2.4f), H, 1.2f);
    b.capsule(V(0.6f, -1.85f, 21.7f), V(0.6f, 1.85f, 21.7f), 0.6f, 0.6f, Material::Tegara, 0.2f);   // tegara band
    b.roundBox(V(2.9f, 0.0f, 21.1f), V(0.4f, 2.9f, 1.0f), 0.35f, Material::Gold, 0.1f, rotation(0.0, -30.0, 0.0)); // comb
    b.capsule(V(-0.6f, -5.0f, 20.7f), V(-0.6f, 5.0f, 20.7f), 0.34f, 0.34f, Material::Gold, 0.1f);  // kanzashi
    b.ellipsoid(V(-0.6f, -5.3f, 20.7f), V(0.8f, 0.8f, 0.8f), Material::Coral, 0.1f);
    b.ellipsoid(V(-0.6f, 5.3f, 20.7f), V(0.8f, 0.8f, 0.8f), Material::Coral, 0.1f);
    b.capsule(V(-1.5f, 2.0f, 19.6f), V(-2.6f, 5.6f, 22.6f), 0.34f, 0.34f, Material::Gold, 0.1f);   // a pin with a flower
    b.ellipsoid(V(-2.6f, 5.6f, 22.6f), V(1.2f, 0.5f, 1.2f), Material::Coral, 0.2f, rotation(70.0, 0.0, 0.0));

    // ---- Right arm in its sleeve, the wrist and the carved hand (the left mirrors them).
    b.group = Group::RightArm;
    const V S = rest.rightShoulderJoint.cast<float>();
    const V d = rest.armDirection.cast<float>();
    // The arm in the kimono: grown out of the shoulder (a wide blend there only), then clear
    // of the chest so that nothing joins the arm to the body below the shoulder.
    b.capsule(S - 1.5f * d + V(0.0f, 1.5f, 1.2f), S + 2.5f * d, 2.8f, 2.6f, K, 2.6f).growsFromBody = true;
    b.capsule(S + 1.0f * d, S + 17.0f * d, 2.55f, 2.05f, K, 0.5f);
    Shape sleeve;
    sleeve.kind = Kind::Panel;
    sleeve.origin = S;
    sleeve.panelAxis = d;
    sleeve.a = V(7.5f, -2.6f, 0.0f);
    sleeve.b = V(18.4f, 14.5f, 0.0f);
    sleeve.r2 = 1.5f;  // half thickness
    sleeve.r3 = 3.2f;  // rounded corners
    sleeve.centre = S + 12.0f * d + V(0.0f, 0.0f, -6.5f);
    sleeve.radius = 16.0f;
    b.add(sleeve, K, 1.2f);
    const V wrist = S + float(rest.wristAlong) * d;
    b.capsule(S + 15.5f * d, wrist, 1.15f, 1.0f, Material::Skin, 0.8f);
    // The hand in its own frame (x to the finger tips, palm across y, z its normal).
    const Eigen::Matrix3f R = rest.rightHand.rotation.toRotationMatrix().cast<float>();
    const V H0 = rest.rightHand.translation.cast<float>();
    const auto inHand = [&](float x, float y, float z) { return V(H0 + R * V(x, y, z)); };
    b.group = Group::RightHand;
    b.capsule(inHand(-4.6f, 0.0f, 0.0f), inHand(-2.6f, 0.0f, 0.0f), 1.0f, 1.05f, Material::Skin, 0.6f);
    b.roundBox(inHand(-0.7f, 0.0f, 0.0f), V(2.3f, 2.0f, 0.75f), 0.6f, Material::Skin, 0.9f, R); // palm
    const std::array<std::array<float, 3>, 4> fingers{{{-1.35f, 5.9f, 0.42f}, {-0.45f, 6.9f, 0.46f}, {0.45f, 6.6f, 0.45f}, {1.35f, 5.6f, 0.4f}}};
    for (const auto& f : fingers)
        b.capsule(inHand(1.2f, f[0], 0.0f), inHand(f[1], f[0] * 1.05f, -0.45f), f[2] + 0.06f, f[2], Material::Skin, 0.2f);
    b.capsule(inHand(-1.6f, -1.9f, -0.3f), inHand(1.5f, -2.9f, -0.9f), 0.62f, 0.5f, Material::Skin, 0.5f); // thumb

    // The left arm: the right's shapes mirrored in the sagittal plane (y -> -y).
    const std::size_t rightEnd = b.list.size();
    const Eigen::Matrix3f F = Eigen::Vector3f(1.0f, -1.0f, 1.0f).asDiagonal();
    for (std::size_t i = 0; i < rightEnd; ++i) {
        if (b.list[i].group != Group::RightArm && b.list[i].group != Group::RightHand) continue;
        Shape m = b.list[i];
        m.group = b.list[i].group == Group::RightArm ? Group::LeftArm : Group::LeftHand;
        m.toLocal = m.toLocal * F; // local = toLocal F (p - F origin): the mirror image
        m.origin = F * m.origin;
        if (m.kind == Kind::Capsule) {
            m.a = F * m.a;
            m.b = F * m.b;
        }
        if (m.kind == Kind::Panel) m.panelAxis = F * m.panelAxis;
        m.centre = F * m.centre;
        b.list.push_back(m);
    }
    return b.list;
}

} // namespace

float shapeDistance(const Shape& shape, const V& p) { return distanceOf(shape, p); }

const RestPose& restPose()
{
    static const RestPose pose = makeRestPose();
    return pose;
}

const std::vector<Shape>& shapes()
{
    static const std::vector<Shape> list = makeShapes();
    return list;
}

float evaluate(const std::vector<Shape>& list, const V& p, Nearest* nearest)
{
    float d = 1e9f;
    float best = 1e9f;
    int bestShape = -1;
    for (std::size_t i = 0; i < list.size(); ++i) {
        const Shape& s = list[i];
        const float lower = (p - s.centre).norm() - s.radius;
        if (lower >= d + s.blend && (nearest == nullptr || lower >= best)) continue;
        const float di = distanceOf(s, p);
        d = smoothMin(d, di, s.blend);
        if (di < best) {
            best = di;
            bestShape = int(i);
        }
    }
    if (nearest) *nearest = Nearest{d, bestShape};
    return d;
}

} // namespace bunraku::analysis::puppet_shapes
