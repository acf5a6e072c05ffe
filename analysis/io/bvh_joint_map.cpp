#include "analysis/io/bvh_joint_map.h"

#include "analysis/core/puppet_layout.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <cstdlib>

namespace bunraku::analysis::io {
namespace {

/// Body words that may follow a one-letter side mark ("rhand", "lhumerus", "rShldr").
constexpr std::array<std::string_view, 40> kBodyTerms{
    "head", "neck", "collar", "clavicle", "shoulder", "shldr", "uparm", "upperarm", "arm", "humerus",
    "forearm", "lowerarm", "lowarm", "elbow", "radius", "wrist", "hand", "palm", "finger", "thumb",
    "index", "mid", "ring", "pinky", "hip", "thigh", "upleg", "femur", "knee", "shin",
    "lowleg", "leg", "tibia", "ankle", "foot", "toe", "heel", "eye", "ear", "buttock"};

constexpr std::array<std::string_view, 5> kForearmTerms{"forearm", "lowerarm", "lowarm", "elbow", "radius"};

bool startsWithTerm(std::string_view text)
{
    return std::any_of(kBodyTerms.begin(), kBodyTerms.end(), [&](std::string_view t) { return text.substr(0, t.size()) == t; });
}

bool isForearm(std::string_view term)
{
    return std::find(kForearmTerms.begin(), kForearmTerms.end(), term) != kForearmTerms.end();
}

std::optional<BodySide> sideWord(std::string_view token)
{
    if (token == "r" || token == "right" || token == "rt") return BodySide::Right;
    if (token == "l" || token == "left" || token == "lt") return BodySide::Left;
    return std::nullopt;
}

/// The skeleton's joints as trees: children that are joints (End Sites left out) and subtree sizes.
struct Tree {
    std::vector<std::vector<int>> children;
    std::vector<int> size;
    explicit Tree(const BvhSkeleton& skeleton) : children(skeleton.joints.size()), size(skeleton.joints.size(), 0)
    {
        for (std::size_t j = 0; j < skeleton.joints.size(); ++j)
            if (skeleton.joints[j].parent >= 0 && !skeleton.joints[j].endSite)
                children[std::size_t(skeleton.joints[j].parent)].push_back(int(j));
        for (std::size_t j = skeleton.joints.size(); j-- > 0;) {
            size[j] += skeleton.joints[j].endSite ? 0 : 1;
            if (skeleton.joints[j].parent >= 0) size[std::size_t(skeleton.joints[j].parent)] += size[j];
        }
    }
    int largestChild(int joint) const
    {
        int best = -1;
        for (int c : children[std::size_t(joint)])
            if (best < 0 || size[std::size_t(c)] > size[std::size_t(best)]) best = c;
        return best;
    }
};

/// True when an End Site of `joint` lies away from it.
bool hasLengthyEnd(const BvhSkeleton& skeleton, int joint)
{
    for (const auto& j : skeleton.joints)
        if (j.endSite && j.parent == joint && j.offset.norm() > 1e-9) return true;
    return false;
}

int lowestCommonAncestor(const BvhSkeleton& skeleton, int a, int b)
{
    std::vector<char> onPath(skeleton.joints.size(), 0);
    for (int j = a; j >= 0; j = skeleton.joints[std::size_t(j)].parent) onPath[std::size_t(j)] = 1;
    for (int j = b; j >= 0; j = skeleton.joints[std::size_t(j)].parent)
        if (onPath[std::size_t(j)]) return j;
    return -1;
}

/// What the topology says (docs/FORMATS.md): the pelvis is the first branching joint, the
/// spine its largest child subtree, the chest the first joint up the spine with three or more
/// children (two of them a matching pair of arms, the rest the neck), the head the top of the
/// neck's chain, the elbow the arm chain's joint between its two longest bones, the hand the
/// joint after it. Left and right: the toes point forward (else the BVH custom, +x).
struct Topology {
    int chest = -1;
    int head = -1;
    std::array<int, 2> armRoot{-1, -1}; ///< right, left
};

Topology readTopology(const BvhSkeleton& skeleton, const Tree& tree, const std::vector<Eigen::Vector3d>& positions)
{
    Topology t;
    int root = -1;
    for (std::size_t j = 0; j < skeleton.joints.size(); ++j)
        if (skeleton.joints[j].parent < 0 && (root < 0 || tree.size[j] > tree.size[std::size_t(root)])) root = int(j);
    if (root < 0) return t;
    int hips = root;
    while (tree.children[std::size_t(hips)].size() == 1) hips = tree.children[std::size_t(hips)].front();
    if (tree.children[std::size_t(hips)].size() < 2) return t;
    // The chest: the hips themselves when the arms branch there (an upper body), else up the spine.
    const auto armsBranch = [&](int j) {
        const auto& c = tree.children[std::size_t(j)];
        if (c.size() < 3) return false;
        const int largest = tree.largestChild(j);
        int rest = 0;
        for (int k : c) rest += k == largest ? 0 : tree.size[std::size_t(k)];
        return tree.size[std::size_t(largest)] <= rest; // the hips' spine outweighs its legs
    };
    int chest = hips;
    if (!armsBranch(chest)) {
        chest = tree.largestChild(hips);
        while (chest >= 0 && !armsBranch(chest)) chest = tree.largestChild(chest);
    }
    if (chest < 0) return t;
    t.chest = chest;
    // Arms: the pair of children with the most similar subtrees (ties: the larger pair, then
    // the earlier). The most similar pair is adjacent once sorted by size: n log n, not n^2.
    const auto& c = tree.children[std::size_t(chest)];
    std::vector<int> bySize(c.begin(), c.end());
    std::stable_sort(bySize.begin(), bySize.end(), [&](int x, int y) { return tree.size[std::size_t(x)] < tree.size[std::size_t(y)]; });
    int a = -1, b = -1;
    for (std::size_t i = 0; i + 1 < bySize.size(); ++i) {
        const int si = tree.size[std::size_t(bySize[i])], sk = tree.size[std::size_t(bySize[i + 1])];
        const int best = a < 0 ? 0 : tree.size[std::size_t(b)] - tree.size[std::size_t(a)];
        if (a < 0 || sk - si < best || (sk - si == best && si + sk > tree.size[std::size_t(a)] + tree.size[std::size_t(b)])) {
            a = std::min(bySize[i], bySize[i + 1]);
            b = std::max(bySize[i], bySize[i + 1]);
        }
    }
    int neck = -1;
    for (int k : c)
        if (k != a && k != b && (neck < 0 || tree.size[std::size_t(k)] > tree.size[std::size_t(neck)])) neck = k;
    if (neck >= 0) {
        int head = neck;
        int chain = 1;
        while (tree.children[std::size_t(head)].size() == 1) {
            head = tree.children[std::size_t(head)].front();
            ++chain;
        }
        // A head-top marker (Mixamo's HeadTop_End): a leaf ending in nothing, above a neck and a head.
        if (chain >= 3 && tree.children[std::size_t(head)].empty() && !hasLengthyEnd(skeleton, head))
            head = skeleton.joints[std::size_t(head)].parent;
        t.head = head;
    }
    // Right and left from the facing direction.
    Eigen::Vector3d forward = Eigen::Vector3d::Zero();
    for (int leg : tree.children[std::size_t(hips)]) {
        if (hips != chest && leg == tree.largestChild(hips)) continue;
        if (hips == chest && (leg == a || leg == b || leg == neck)) continue;
        int toe = leg;
        while (!tree.children[std::size_t(toe)].empty()) toe = tree.largestChild(toe);
        const int foot = skeleton.joints[std::size_t(toe)].parent;
        if (foot < 0 || toe == leg) continue;
        Eigen::Vector3d d = positions[std::size_t(toe)] - positions[std::size_t(foot)];
        d.z() = 0.0;
        forward += d;
    }
    if (forward.norm() < 1e-9) forward = Eigen::Vector3d::UnitX();
    const Eigen::Vector3d left = Eigen::Vector3d::UnitZ().cross(forward.normalized());
    const Eigen::Vector3d chestAt = positions[std::size_t(chest)];
    const auto lateral = [&](int arm) {
        // The deepest joint of the arm's chain tells its side more clearly than its root.
        int j = arm;
        for (int step = 0; step < 2 && !tree.children[std::size_t(j)].empty(); ++step) j = tree.largestChild(j);
        return (positions[std::size_t(j)] - chestAt).dot(left);
    };
    if (a >= 0 && b >= 0) {
        const bool aRight = lateral(a) < lateral(b);
        t.armRoot = aRight ? std::array<int, 2>{a, b} : std::array<int, 2>{b, a};
    }
    return t;
}

/// The elbow and the hand on an arm chain from `root`: the chain joint between the two longest
/// consecutive bones, and the joint after it.
std::pair<int, int> elbowAndHand(const BvhSkeleton& skeleton, const Tree& tree, int root)
{
    std::vector<int> chain{root};
    while (tree.children[std::size_t(chain.back())].size() == 1) chain.push_back(tree.children[std::size_t(chain.back())].front());
    if (chain.size() < 2) return {-1, -1};
    if (chain.size() == 2) return {chain[0], chain[1]};
    const auto bone = [&](int j) { return skeleton.joints[std::size_t(j)].offset.norm(); };
    std::size_t best = 1;
    for (std::size_t i = 1; i + 1 < chain.size(); ++i)
        if (std::min(bone(chain[i]), bone(chain[i + 1])) > std::min(bone(chain[best]), bone(chain[best + 1]))) best = i;
    return {chain[best], chain[best + 1]};
}

std::string jointList(const BvhSkeleton& skeleton)
{
    std::string out;
    std::size_t shown = 0;
    for (const auto& joint : skeleton.joints) {
        if (joint.endSite) continue;
        if (shown == 60) {
            out += ", ...";
            break;
        }
        if (!out.empty()) out += ", ";
        out += joint.name;
        ++shown;
    }
    return out;
}

/// Rest-pose positions from the offsets in the BVH custom's axes (Y up, facing +Z) turned into
/// workbench axes (x forward, y left, z up).
std::vector<Eigen::Vector3d> restPositions(const BvhSkeleton& skeleton)
{
    std::vector<Eigen::Vector3d> world(skeleton.joints.size());
    for (std::size_t j = 0; j < world.size(); ++j) {
        const Eigen::Vector3d o = skeleton.joints[j].offset;
        const Eigen::Vector3d w(o.z(), o.x(), o.y());
        const int parent = skeleton.joints[j].parent;
        world[j] = w + (parent >= 0 ? world[std::size_t(parent)] : Eigen::Vector3d::Zero());
    }
    return world;
}

} // namespace

const char* mapMethodName(MapMethod method)
{
    switch (method) {
    case MapMethod::Given: return "given";
    case MapMethod::Name: return "name";
    case MapMethod::Topology: return "topology";
    }
    return "";
}

JointNameInfo jointNameInfo(std::string_view name)
{
    std::string lower;
    lower.reserve(name.size());
    for (char ch : name) lower.push_back(char(std::tolower(static_cast<unsigned char>(ch))));
    std::string_view s = lower;
    if (const auto colon = s.find_last_of(":|"); colon != std::string_view::npos) s.remove_prefix(colon + 1);
    // 3ds Max Biped: "bip01 r forearm", "bip001_l_hand".
    if (s.substr(0, 4) == "bip0") {
        std::size_t i = 4;
        while (i < s.size() && std::isdigit(static_cast<unsigned char>(s[i]))) ++i;
        if (i < s.size() && (s[i] == ' ' || s[i] == '_')) s.remove_prefix(i + 1);
    }
    std::vector<std::string_view> tokens;
    std::size_t start = 0;
    for (std::size_t i = 0; i <= s.size(); ++i)
        if (i == s.size() || s[i] == ' ' || s[i] == '_' || s[i] == '.' || s[i] == '-') {
            if (i > start) tokens.push_back(s.substr(start, i - start));
            start = i + 1;
        }
    JointNameInfo info;
    if (tokens.size() > 1) {
        if (auto side = sideWord(tokens.front())) {
            info.side = side;
            tokens.erase(tokens.begin());
        } else if (auto sideAtEnd = sideWord(tokens.back())) {
            info.side = sideAtEnd;
            tokens.pop_back();
        }
    }
    std::string term;
    for (auto t : tokens) term += t;
    if (!info.side) {
        for (const auto& [word, side] : {std::pair{std::string_view("right"), BodySide::Right}, std::pair{std::string_view("left"), BodySide::Left}}) {
            if (term.size() > word.size() && term.compare(0, word.size(), word) == 0) {
                info.side = side;
                term.erase(0, word.size());
                break;
            }
            if (term.size() > word.size() && term.compare(term.size() - word.size(), word.size(), word) == 0) {
                info.side = side;
                term.erase(term.size() - word.size());
                break;
            }
        }
    }
    if (!info.side && term.size() > 1 && (term[0] == 'r' || term[0] == 'l') && !startsWithTerm(term) &&
        startsWithTerm(std::string_view(term).substr(1))) {
        info.side = term[0] == 'r' ? BodySide::Right : BodySide::Left;
        term.erase(0, 1);
    }
    info.term = std::move(term);
    return info;
}

std::string PartMap::text() const
{
    std::string out;
    for (std::size_t p = 0; p < 4; ++p) {
        if (p > 0) out += ',';
        out.append(kPuppetParts[p]);
        out += '=';
        out += names.joints[p];
    }
    return out;
}

std::string PartMap::describe() const
{
    std::string out;
    for (std::size_t p = 0; p < 4; ++p) {
        if (p > 0) out += ", ";
        out.append(kPuppetParts[p]);
        out += '=';
        out += names.joints[p];
        out += " (";
        out += mapMethodName(methods[p]);
        out += ')';
    }
    out += ", ";
    out += bodySideName(side);
    out += " side";
    return out;
}

Result<PartMap> mapPuppetParts(const BvhSkeleton& skeleton, const std::optional<JointMap>& given, const PartMapOptions& options,
                               const std::vector<Eigen::Vector3d>* positions)
{
    PartMap map;
    map.side = options.side;
    const std::vector<Eigen::Vector3d> rest = positions ? std::vector<Eigen::Vector3d>{} : restPositions(skeleton);
    const auto& where = positions ? *positions : rest;
    const Tree tree(skeleton);

    // Explicit joints first.
    for (std::size_t p = 0; p < 4; ++p) {
        const std::string name = given ? given->joints[p] : std::string();
        if (name.empty()) continue;
        const int index = skeleton.find(name);
        if (index < 0)
            return makeError(ErrorCode::NotFound, "joint '" + name + "' (for part '" + std::string(kPuppetParts[p]) +
                                                      "') is not in the skeleton (joints: " + jointList(skeleton) + ")");
        map.joints[p] = index;
        map.methods[p] = MapMethod::Given;
    }
    // Names.
    int head = -1, forearm = -1, hand = -1, wrist = -1;
    for (std::size_t j = 0; j < skeleton.joints.size(); ++j) {
        if (skeleton.joints[j].endSite) continue;
        const JointNameInfo info = jointNameInfo(skeleton.joints[j].name);
        const bool onSide = info.side == options.side;
        if (!info.side && info.term == "head" && head < 0) head = int(j);
        if (onSide && isForearm(info.term) && forearm < 0) forearm = int(j);
        if (onSide && info.term == "hand" && hand < 0) hand = int(j);
        if (onSide && info.term == "wrist" && wrist < 0) wrist = int(j);
    }
    if (hand < 0) hand = wrist;
    const auto setPart = [&](int part, int joint, MapMethod method) {
        if (map.joints[std::size_t(part)] >= 0 || joint < 0) return;
        map.joints[std::size_t(part)] = joint;
        map.methods[std::size_t(part)] = method;
    };
    setPart(0, head, MapMethod::Name);
    setPart(2, forearm, MapMethod::Name);
    setPart(3, hand, MapMethod::Name);
    // A named hand without a named forearm: the joint before the hand, and the reverse.
    if (map.joints[2] < 0 && map.joints[3] >= 0) setPart(2, skeleton.joints[std::size_t(map.joints[3])].parent, MapMethod::Topology);
    if (map.joints[3] < 0 && map.joints[2] >= 0) setPart(3, tree.largestChild(map.joints[2]), MapMethod::Topology);

    // Topology for what names did not find.
    if (map.joints[0] < 0 || map.joints[2] < 0 || map.joints[3] < 0 || map.joints[1] < 0) {
        const Topology topology = readTopology(skeleton, tree, where);
        setPart(0, topology.head, MapMethod::Topology);
        const int armRoot = topology.armRoot[options.side == BodySide::Right ? 0 : 1];
        if (armRoot >= 0 && map.joints[2] < 0 && map.joints[3] < 0) {
            const auto [elbow, wristJoint] = elbowAndHand(skeleton, tree, armRoot);
            setPart(2, elbow, MapMethod::Topology);
            setPart(3, wristJoint, MapMethod::Topology);
        }
        // The shoulder: where the arm chain branches from the head's chain.
        if (map.joints[1] < 0 && map.joints[0] >= 0 && map.joints[2] >= 0) {
            const int branch = lowestCommonAncestor(skeleton, map.joints[0], map.joints[2]);
            if (branch != map.joints[0] && branch != map.joints[2]) setPart(1, branch, MapMethod::Topology);
        }
        setPart(1, topology.chest, MapMethod::Topology);
    }
    for (std::size_t p = 0; p < 4; ++p) {
        if (map.joints[p] < 0)
            return makeError(ErrorCode::NotFound,
                             "no joint for the puppet part '" + std::string(kPuppetParts[p]) + "': neither the names nor the " +
                                 "skeleton's shape tell which joint it is; give --joints head=...,shoulder=...,arm=...,hand=... " +
                                 "(joints: " + jointList(skeleton) + ")");
        map.names.joints[p] = skeleton.joints[std::size_t(map.joints[p])].name;
    }
    for (std::size_t p = 0; p < 4; ++p)
        for (std::size_t q = p + 1; q < 4; ++q)
            if (map.joints[p] == map.joints[q])
                return makeError(ErrorCode::InvalidArgument, "joint '" + map.names.joints[p] + "' is mapped to two parts (" +
                                                                 std::string(kPuppetParts[p]) + " and " + std::string(kPuppetParts[q]) +
                                                                 "): each part needs its own joint");
    return map;
}

Result<PartMap> mapPuppetParts(const BvhFile& file, const std::optional<JointMap>& given, const PartMapOptions& options,
                               const BvhImportOptions& axes)
{
    std::vector<Eigen::Vector3d> positions;
    if (file.motion.values.rows() > 0) {
        for (const auto& pose : bvhWorkbenchPoses(file, 0, axes.upAxis, 1.0, axes.kinematics)) positions.push_back(pose.translation);
    }
    auto map = mapPuppetParts(file.skeleton, given, options, positions.empty() ? nullptr : &positions);
    if (!map) return makeError(map.error().code, file.source + ": " + map.error().message);
    return map;
}

} // namespace bunraku::analysis::io
