#include "analysis/skeleton/skeleton_resample.h"

#include "analysis/core/rotation.h"

#include <algorithm>
#include <cassert>
#include <cmath>

namespace bunraku::analysis {

namespace {

/// A copy of `motion`'s layout (skeleton, static translations, moving joints) for `frames` frames.
std::shared_ptr<SkeletalMotion> emptyLike(const SkeletalMotion& motion, Eigen::Index frames)
{
    auto out = std::make_shared<SkeletalMotion>();
    out->skeleton = motion.skeleton;
    out->staticTranslations = motion.staticTranslations;
    out->movingJoints = motion.movingJoints;
    out->rotations.resize(std::size_t(frames) * std::size_t(motion.jointSlots()));
    out->movingTranslations.resize(frames, motion.movingTranslations.cols());
    return out;
}

/// Makes `joint` a moving joint of `motion` (its static translation at every frame); returns its
/// index in movingJoints.
std::size_t ensureMoving(SkeletalMotion& motion, int joint)
{
    for (std::size_t k = 0; k < motion.movingJoints.size(); ++k)
        if (motion.movingJoints[k] == joint) return k;
    const Eigen::Index frames = motion.frameCount();
    Eigen::MatrixXd widened(frames, motion.movingTranslations.cols() + 3);
    widened.leftCols(motion.movingTranslations.cols()) = motion.movingTranslations;
    widened.rightCols(3) = motion.staticTranslations[std::size_t(joint)].transpose().replicate(frames, 1);
    motion.movingTranslations = std::move(widened);
    motion.movingJoints.push_back(joint);
    return motion.movingJoints.size() - 1;
}

} // namespace

SkeletalMotionPtr resampleSkeletalMotion(const SkeletalMotion& motion, const Eigen::VectorXd& at)
{
    const Eigen::Index sourceFrames = motion.frameCount();
    if (sourceFrames == 0 || !motion.skeleton) return nullptr;
    const int slots = motion.jointSlots();
    const Eigen::Index frames = at.size();
    auto out = emptyLike(motion, frames);
    const Eigen::Index last = sourceFrames - 1;
    for (Eigen::Index u = 0; u < frames; ++u) {
        const double s = std::clamp(std::isfinite(at[u]) ? at[u] : 0.0, 0.0, double(last));
        const Eigen::Index k = std::min<Eigen::Index>(Eigen::Index(std::floor(s)), last);
        const double w = s - double(k);
        const Eigen::Index k1 = std::min<Eigen::Index>(k + 1, last);
        if (w <= 0.0 || k1 == k) {
            for (int j = 0; j < slots; ++j) out->rotation(u, j) = motion.rotation(k, j);
            out->movingTranslations.row(u) = motion.movingTranslations.row(k);
            continue;
        }
        for (int j = 0; j < slots; ++j) out->rotation(u, j) = slerpShortest(motion.rotation(k, j), motion.rotation(k1, j), w);
        out->movingTranslations.row(u) = (1.0 - w) * motion.movingTranslations.row(k) + w * motion.movingTranslations.row(k1);
    }
    return out;
}

Eigen::VectorXd shiftedFrames(Eigen::Index sourceFrames, Eigen::Index frames, int shift)
{
    Eigen::VectorXd at(frames);
    for (Eigen::Index t = 0; t < frames; ++t)
        at[t] = double(std::clamp<Eigen::Index>(t + shift, 0, std::max<Eigen::Index>(sourceFrames - 1, 0)));
    return at;
}

SkeletalMotionPtr moveSkeletalMotion(const SkeletalMotion& motion, const RigidTransform& world_T_new)
{
    if (!motion.skeleton) return nullptr;
    auto out = std::make_shared<SkeletalMotion>(motion);
    const auto& joints = motion.skeleton->joints;
    for (std::size_t j = 0; j < joints.size(); ++j) {
        if (joints[j].parent >= 0) continue;
        const int root = int(j);
        for (Eigen::Index f = 0; f < out->frameCount(); ++f)
            out->rotation(f, root) = (world_T_new.rotation * out->rotation(f, root)).normalized();
        bool moving = false;
        for (std::size_t k = 0; k < out->movingJoints.size(); ++k) {
            if (out->movingJoints[k] != root) continue;
            moving = true;
            for (Eigen::Index f = 0; f < out->frameCount(); ++f) {
                const Eigen::Vector3d t = out->movingTranslations.block<1, 3>(f, Eigen::Index(3 * k)).transpose();
                out->movingTranslations.block<1, 3>(f, Eigen::Index(3 * k)) = world_T_new.apply(t).transpose();
            }
        }
        if (!moving) out->staticTranslations[j] = world_T_new.apply(out->staticTranslations[j]);
    }
    return out;
}

SkeletalMotionPtr moveSkeletalRoots(const SkeletalMotion& motion, const std::vector<RigidTransform>& corrections,
                                    const std::vector<int>& roots)
{
    if (!motion.skeleton) return nullptr;
    assert(Eigen::Index(corrections.size()) == motion.frameCount());
    auto out = std::make_shared<SkeletalMotion>(motion);
    for (int root : roots) {
        const std::size_t k = ensureMoving(*out, root);
        for (Eigen::Index f = 0; f < out->frameCount(); ++f) {
            const RigidTransform& c = corrections[std::size_t(f)];
            out->rotation(f, root) = (c.rotation * out->rotation(f, root)).normalized();
            const Eigen::Vector3d t = out->movingTranslations.block<1, 3>(f, Eigen::Index(3 * k)).transpose();
            out->movingTranslations.block<1, 3>(f, Eigen::Index(3 * k)) = c.apply(t).transpose();
        }
    }
    return out;
}

std::vector<int> partChainRoots(const Skeleton& skeleton)
{
    std::vector<int> roots;
    auto rootOf = [&](int j) {
        while (j >= 0 && skeleton.joints[std::size_t(j)].parent >= 0) j = skeleton.joints[std::size_t(j)].parent;
        return j;
    };
    for (const PartBinding& binding : skeleton.parts) {
        if (binding.joint < 0 || binding.joint >= int(skeleton.joints.size())) continue;
        const int root = rootOf(binding.joint);
        if (std::find(roots.begin(), roots.end(), root) == roots.end()) roots.push_back(root);
    }
    if (roots.empty())
        for (std::size_t j = 0; j < skeleton.joints.size(); ++j)
            if (skeleton.joints[j].parent < 0) roots.push_back(int(j));
    std::sort(roots.begin(), roots.end());
    return roots;
}

std::vector<int> translatingJoints(const std::vector<const SkeletalMotion*>& motions)
{
    std::vector<int> result;
    if (motions.empty() || !motions.front()->skeleton) return result;
    const auto& joints = motions.front()->skeleton->joints;
    for (std::size_t j = 0; j < joints.size(); ++j) {
        bool translating = joints[j].parent < 0;
        for (const SkeletalMotion* motion : motions)
            translating = translating || std::find(motion->movingJoints.begin(), motion->movingJoints.end(), int(j)) !=
                                             motion->movingJoints.end();
        if (translating) result.push_back(int(j));
    }
    return result;
}

bool compatibleMotions(const SkeletalMotion& a, const SkeletalMotion& b)
{
    if (!a.skeleton || !b.skeleton) return false;
    if (a.skeleton != b.skeleton) {
        const auto& x = a.skeleton->joints;
        const auto& y = b.skeleton->joints;
        if (x.size() != y.size()) return false;
        for (std::size_t j = 0; j < x.size(); ++j)
            if (x[j].name != y[j].name || x[j].parent != y[j].parent || x[j].endSite != y[j].endSite) return false;
    }
    // Bones may differ (two recordings of one performer, End Sites written differently): a motion
    // averaged or weighted from both moves the first one's bones (one body).
    return a.staticTranslations.size() == b.staticTranslations.size();
}

} // namespace bunraku::analysis
