#pragma once
/// BVH (Biovision hierarchy) files: parsing of HIERARCHY and MOTION and forward kinematics to
/// the world pose of every joint. Units and axes are the file's own here; bvh_import.h converts
/// to the workbench convention. Format notes: docs/FORMATS.md.

#include "analysis/core/pose.h"
#include "analysis/core/result.h"
#include "analysis/core/run_control.h"
#include "analysis/core/skeleton_mesh.h"

#include <Eigen/Core>

#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace bunraku::analysis::io {

enum class BvhChannel { Xposition, Yposition, Zposition, Xrotation, Yrotation, Zrotation };

/// "Xposition" ... "Zrotation".
const char* bvhChannelName(BvhChannel channel);
/// True for the three position channels.
bool isPositionChannel(BvhChannel channel);
/// 0, 1, 2 for the channel's axis X, Y, Z.
int channelAxis(BvhChannel channel);

/// One ROOT/JOINT or End Site of the hierarchy.
struct BvhJoint {
    std::string name;          ///< End Sites are named "<parent>_End"
    int parent = -1;           ///< index into BvhSkeleton::joints, -1 for a root
    Eigen::Vector3d offset = Eigen::Vector3d::Zero(); ///< file units, in the parent's frame
    std::vector<BvhChannel> channels; ///< in file order, 0 to 6 of them (usually 3 or 6)
    int firstChannel = 0;      ///< column of its first channel in BvhMotion::values
    bool endSite = false;
    long offsetLine = 0;       ///< the file line of its OFFSET, for messages (0: none, or not read from text)
};

struct BvhSkeleton {
    std::vector<BvhJoint> joints; ///< parents precede children (file order)
    int channelCount = 0;

    /// Index of the joint (or End Site) with this name, -1 when absent.
    int find(const std::string& name) const;
    /// Number of joints that are not End Sites.
    int jointCount() const;
    int endSiteCount() const;
};

struct BvhMotion {
    /// frames x channels, rows = time, file units and degrees.
    Eigen::MatrixXd values;
    double frameTime = 0.0; ///< seconds
    /// Where the rows are in the file, for messages: row r is on line `second + (r - first)` of
    /// the last entry with `first <= r` (an entry starts the text and follows each blank line).
    /// Empty for a motion not read from text.
    std::vector<std::pair<Eigen::Index, long>> rowLines;
    /// The file line of a row (0 when unknown).
    long lineOfRow(Eigen::Index row) const;
};

struct BvhFile {
    BvhSkeleton skeleton;
    BvhMotion motion;
    std::string source;
    /// A skinned mesh for this skeleton in the file's axes and units (a scene file's, converted
    /// by scene_take.h; never in a .bvh): the import puts it on the Skeleton (Skeleton::mesh).
    std::shared_ptr<const SkeletonMesh> mesh;
};

/// The longest frame time accepted (s): one frame an hour. Larger values (a corrupt
/// `Frame Time: 1e308`) would give frame times that overflow.
inline constexpr double kMaxBvhFrameTime = 3600.0;
/// The largest BVH file read (bytes), checked before reading.
inline constexpr std::uintmax_t kMaxBvhFileBytes = std::uintmax_t(2) << 30;

/// Parses BVH text: ROOT/JOINT/End Site at any depth, OFFSET, CHANNELS with 0 to 6 channels
/// in any order, MOTION with Frames and Frame Time. Tolerates CRLF, tabs, trailing spaces and
/// scientific notation. Errors: "source:line: what was expected"; NaN/Inf are rejected.
/// Linear in the size of the text, whatever the hierarchy's shape (40,000 sibling joints or a
/// 10,000-deep chain), and the motion matrix is only allocated once the bytes left in the
/// text can hold the rows `Frames` claims. The control is told the fraction of motion rows read
/// and stops the parse (a Cancelled error) every few thousand rows when asked.
Result<BvhFile> parseBvh(const std::string& text, const std::string& sourceName, const RunControl& control = {});
/// Rotation channel values beyond valueLimit("deg") (+-1e9 deg) are refused with the line.
/// Joint names must be UTF-8 text (they are written to JSON skeleton files).
/// Reads a regular file of at most kMaxBvhFileBytes (a pipe or device is refused) and parses it.
Result<BvhFile> readBvh(const std::filesystem::path& file, const RunControl& control = {});
/// The hierarchy and only the first `frames` motion rows (fewer when the file has fewer; what
/// follows them is not read): enough to map the parts or preview the first pose of a big file.
Result<BvhFile> readBvhStart(const std::filesystem::path& file, Eigen::Index frames = 1);

/// Refuses OFFSETs and position channel values whose length in cm (file units times
/// `cmPerUnit`) is beyond valueLimit("cm") (+-1e7 cm), naming the file, line and joint: the
/// length check parseBvh cannot make before the units are known.
Status checkBvhLengths(const BvhFile& file, double cmPerUnit);

/// How position channels of a joint combine with its OFFSET.
enum class BvhPositionMode {
    /// Position channels, when a joint has them, are its whole local translation (OFFSET is the
    /// rest value). Exporters that write 6 channels on every joint (Bandai, many others) mean this.
    ReplaceOffset,
    /// local translation = OFFSET + position channels.
    AddToOffset,
};

struct BvhKinematicsOptions {
    BvhPositionMode positionMode = BvhPositionMode::ReplaceOffset;
};

/// parent_T_joint of every joint at one frame: translation = OFFSET and/or position channels,
/// rotation = the rotation channels applied in the order listed (intrinsic: R = R1 * R2 * R3).
std::vector<RigidTransform> bvhLocalPoses(const BvhFile& file, Eigen::Index frame,
                                          const BvhKinematicsOptions& options = {});
/// file_T_joint (world poses in the file's axes and units) of every joint at one frame.
std::vector<RigidTransform> bvhWorldPoses(const BvhFile& file, Eigen::Index frame,
                                          const BvhKinematicsOptions& options = {});

/// BVH text for a file structure (inverse of parseBvh; values written with full precision).
std::string formatBvh(const BvhFile& file);

} // namespace bunraku::analysis::io
