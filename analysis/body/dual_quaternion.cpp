#include "analysis/body/dual_quaternion.h"

namespace bunraku::analysis {
namespace {
Eigen::Vector4d product(const Eigen::Vector4d& a, const Eigen::Vector4d& b)
{
    // Hamilton product of (x, y, z, w) quaternions.
    const Eigen::Vector3d av = a.head<3>(), bv = b.head<3>();
    Eigen::Vector4d r;
    r.head<3>() = a.w() * bv + b.w() * av + av.cross(bv);
    r.w() = a.w() * b.w() - av.dot(bv);
    return r;
}
} // namespace

DualQuaternion DualQuaternion::fromRigid(const RigidTransform& a_T_b)
{
    DualQuaternion q;
    const Eigen::Quaterniond r = a_T_b.rotation.normalized();
    q.real = Eigen::Vector4d(r.x(), r.y(), r.z(), r.w());
    const Eigen::Vector4d t(a_T_b.translation.x(), a_T_b.translation.y(), a_T_b.translation.z(), 0.0);
    q.dual = 0.5 * product(t, q.real);
    return q;
}

RigidTransform DualQuaternion::toRigid() const
{
    const double norm = real.norm();
    const Eigen::Vector4d r = real / norm, d = dual / norm;
    const Eigen::Vector4d conjugate(-r.x(), -r.y(), -r.z(), r.w());
    const Eigen::Vector4d t = 2.0 * product(d, conjugate);
    return RigidTransform{Eigen::Quaterniond(r.w(), r.x(), r.y(), r.z()).normalized(), t.head<3>()};
}

DualQuaternion blendDualQuaternions(const DualQuaternion* q, const double* weights, int count)
{
    DualQuaternion sum;
    sum.real.setZero();
    sum.dual.setZero();
    for (int i = 0; i < count; ++i) {
        const double sign = q[i].real.dot(q[0].real) < 0.0 ? -1.0 : 1.0;
        sum.real += sign * weights[i] * q[i].real;
        sum.dual += sign * weights[i] * q[i].dual;
    }
    const double norm = sum.real.norm();
    if (norm < 1e-12) return q[0];
    sum.real /= norm;
    sum.dual /= norm;
    return sum;
}

} // namespace bunraku::analysis
