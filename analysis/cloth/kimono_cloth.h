#pragma once
/// The kimono as cloth: the skirt hanging from the dō-wa and the two long sleeves hanging from
/// the arms, simulated by extended position-based dynamics (XPBD, in the "small steps" form: one
/// constraint pass per substep) and driven by a take's part poses (the thesis's future work:
/// "dress the puppet object in its kimono and simulate it").
///
/// The cloth: the skirt is a tube of rings from the dō-wa (pinned to the shoulder part, where it
/// hangs) down to the hem, in the modelled puppet's rest shape (puppet_shapes: an elliptic frustum
/// widening from the dō-wa to the hem); each sleeve is a panel in the vertical plane under its
/// arm, its top edge pinned along the arm's bone, its front (wrist side) and bottom edges free.
/// Constraints: stretch along the grid's edges and diagonals, bending across every second
/// particle (a distance constraint, so a flared skirt keeps its flare), gravity, damping, air
/// drag, and collisions with the body (capsules round the torso and the arms, in their parts'
/// frames). Lengths in cm, masses in g, time in s.
///
/// Determinism: one fixed order of every operation, so the same take, body and parameters give
/// the same cloth bit for bit; the state is kept every `checkpointInterval` frames, and any
/// frame is rebuilt by simulating on from the checkpoint before it (the same bits as playing).

#include "analysis/body/body_description.h"
#include "analysis/core/pose.h"
#include "analysis/core/result.h"
#include "analysis/core/run_control.h"
#include "analysis/core/take.h"

#include <Eigen/Core>

#include <array>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace bunraku::analysis {

/// Cloth parameters; the defaults look like silk crepe (chirimen, about 150 g/m^2).
struct ClothParameters {
    double massPerArea = 0.015;       ///< g/cm^2
    double stretchCompliance = 0.0;   ///< cm/dyn (inverse stiffness) of the grid's edges; 0: inextensible
    double bendCompliance = 2e-4;     ///< cm/dyn of the bending constraints
    double damping = 1.5;             ///< 1/s: the velocity lost per second (internal friction)
    double drag = 0.6;                ///< 1/s: air drag on the velocity
    double substepRate = 240.0;       ///< Hz: the substeps per second of take (at least one per frame)
    double collisionMargin = 0.3;     ///< cm the cloth keeps off the body
    double settleSeconds = 0.5;       ///< s of the first pose held before frame 0, so frame 0 hangs at rest
};

/// One parameter's name (as `cloth.<name>` in errors and `--cloth-<name>` spelt in dashes on the
/// command line), the member it sets and the closed range validate accepts.
struct ClothParameterLimit {
    const char* name;
    double ClothParameters::*member;
    double low, high;
};
/// Every parameter with its range, in ClothParameters order: the one table of limits that
/// validate, the command line and the 3D view's cloth settings use.
const std::vector<ClothParameterLimit>& clothParameterLimits();

/// Range checks of the parameters (the error names the parameter and its range).
Status validate(const ClothParameters& parameters);

/// The points measured on the kimono (channels `<name>.x/.y/.z`, cm, world).
enum class KimonoPoint { SleeveRightTip, SleeveLeftTip, HemFront, HemBack, HemLeft, HemRight };
inline constexpr int kKimonoPointCount = 6;
/// "sleeve_right_tip", "sleeve_left_tip", "hem_front", "hem_back", "hem_left", "hem_right".
const char* kimonoPointName(KimonoPoint point);
/// The 18 channels of the measured points, in KimonoPoint order, x y z each.
std::vector<Channel> kimonoChannels();

/// The most a simulation keeps of every frame's particles (KimonoSimulation::particleFrames).
inline constexpr std::size_t kKimonoStoredFramesBytes = 16u << 20;

/// The cloth at rest: particles in the frames of the parts that hold them.
struct KimonoCloth {
    enum Holder : std::uint8_t { Shoulder = 0, RightArm = 1, LeftArm = 2 };
    std::vector<Eigen::Vector3d> restLocal; ///< cm, in the holder part's frame at rest
    /// cm, where the particle lies on the shipped (unfitted) puppet in model space: the
    /// coordinates the kimono's paint is evaluated at, as PuppetMesh::paintPositions.
    std::vector<Eigen::Vector3f> paintPositions;
    std::vector<Holder> holder;
    std::vector<bool> pinned;               ///< moves with its holder, not simulated
    std::vector<double> inverseMass;        ///< 1/g; 0 when pinned
    struct Constraint {
        std::uint32_t a = 0, b = 0;
        double rest = 0.0;       ///< cm
        bool bending = false;
    };
    std::vector<Constraint> constraints;
    std::vector<std::uint32_t> triangles;   ///< the cloth's surface (for drawing and exporting)
    std::array<std::uint32_t, kKimonoPointCount> measured{}; ///< particle of each KimonoPoint
    /// Where the pieces lie in `restLocal`: the skirt, then the right and the left sleeve.
    std::uint32_t skirtEnd = 0, rightSleeveEnd = 0;
    std::size_t size() const { return restLocal.size(); }
};

/// The kimono of `body` (the shipped puppet or the puppet fitted to a performer: each piece is
/// placed by its holder part's `fit`, as the drawn puppet is). Errors when the body lacks the
/// shoulder or the arms.
Result<KimonoCloth> makeKimonoCloth(const BodyDescription& body, const ClothParameters& parameters = {});

/// A simulated take's cloth: the measured channels of every frame and checkpoints of the state.
struct KimonoSimulation {
    std::shared_ptr<const KimonoCloth> cloth;
    ClothParameters parameters;
    BodyDescription body;
    Eigen::MatrixXd points;        ///< frames x 18: the measured points, cm, world
    double rateHz = 0.0;
    int checkpointInterval = 30;   ///< frames between kept states
    /// The state (positions and velocities, world, cm and cm/s) at frames 0, k, 2k, ...
    std::vector<std::vector<Eigen::Vector3d>> checkpointPositions, checkpointVelocities;
    /// Every frame's particles (world, cm, x y z per particle, frame after frame) as floats, when
    /// they take at most kKimonoStoredFramesBytes (about 2,700 frames: 90 s at 30 Hz); else empty
    /// and a view steps the cloth on from the checkpoints (KimonoPlayer).
    std::vector<float> particleFrames;
    Eigen::Index frameCount() const { return points.rows(); }
    /// Frame `frame`'s particles in particleFrames (3 floats each), or null when not stored.
    const float* storedFrame(Eigen::Index frame) const
    {
        const std::size_t stride = cloth ? 3 * cloth->size() : 0;
        if (stride == 0 || frame < 0 || particleFrames.size() < std::size_t(frame + 1) * stride) return nullptr;
        return particleFrames.data() + std::size_t(frame) * stride;
    }
};

/// A capsule of the body the cloth keeps off (the torso from the shoulder board to the dō-wa, each
/// arm along its bone), in its holder part's frame, cm.
struct ClothCollider {
    KimonoCloth::Holder holder = KimonoCloth::Shoulder;
    Eigen::Vector3d a = Eigen::Vector3d::Zero(), b = Eigen::Vector3d::Zero();
    double radius = 0.0;
};
/// The colliders of `body` (fitted like the cloth); empty when the body lacks the holders.
std::vector<ClothCollider> kimonoColliders(const BodyDescription& body);
/// The holders' world poses (shoulder, right arm, left arm) at `frame` of a take with the
/// puppet's parts, for `body` (as the simulation places them).
Result<std::array<RigidTransform, 3>> kimonoHolderPoses(const BodyDescription& body, const Take& take, Eigen::Index frame);

/// Simulates the kimono over every frame of `take` (a take with the puppet's parts; a skeleton
/// take's puppet is fitted to it: bodyForTake). Reports progress and stops when cancelled.
Result<KimonoSimulation> simulateKimono(const Take& take, const ClothParameters& parameters = {}, const RunControl& control = {});
/// The same on a given body (the one the view draws the take with: the default puppet, or the
/// puppet fitted to the take's skeleton, bodyForTake; it needs the shoulder and the arms).
Result<KimonoSimulation> simulateKimono(const Take& take, const BodyDescription& body, const ClothParameters& parameters = {},
                                        const RunControl& control = {});

/// The cloth's particles (world, cm) at `frame`, rebuilt from the checkpoint before it: the same
/// values as simulating from frame 0.
Result<std::vector<Eigen::Vector3d>> kimonoFrame(const KimonoSimulation& simulation, const Take& take, Eigen::Index frame);

/// Plays a simulation: the cloth's particles at any frame, the same bits as kimonoFrame, cheaply
/// frame after frame (it steps on from the frame asked last when that lies between the checkpoint
/// before the new frame and the new frame; else it starts again from that checkpoint, at most
/// `checkpointInterval` - 1 frames of simulation). Not thread-safe: one player per thread.
class KimonoPlayer {
public:
    KimonoPlayer(std::shared_ptr<const KimonoSimulation> simulation, std::shared_ptr<const Take> take);
    ~KimonoPlayer();
    KimonoPlayer(KimonoPlayer&&) noexcept;
    KimonoPlayer& operator=(KimonoPlayer&&) noexcept;
    /// The particles (world, cm) at `frame`; valid until the next call.
    Result<const std::vector<Eigen::Vector3d>*> frame(Eigen::Index frame);
    const KimonoSimulation& simulation() const { return *simulation_; }
    const Take& take() const { return *take_; }

private:
    struct State;
    std::shared_ptr<const KimonoSimulation> simulation_;
    std::shared_ptr<const Take> take_;
    std::unique_ptr<State> state_;
    Eigen::Index current_ = -1;
};

/// How the kimono moves beyond what the parts' motion predicts (issue "The kimono", item 4).
struct KimonoMeasures {
    /// RMS (cm) of a sleeve tip's displacement from where its arm would carry it rigidly (its rest
    /// point in the arm's frame), about the displacement's centred moving mean over 0.5 s (the
    /// slow part is how the sleeve hangs in the pose; the rest is its own swing). Right, left.
    double sleeveSwingCm[2] = {0.0, 0.0};
    /// s by which the right sleeve tip's velocity follows the right hand's (the lag of the best
    /// cross-correlation of the two velocities within +-0.5 s, refined between frames).
    double sleeveLagSeconds = 0.0;
    /// RMS (cm) of the hem's four points' displacement from where the shoulder would carry them
    /// rigidly, about its 0.5 s moving mean (as for the sleeves): the skirt's own swing.
    double hemSwingCm = 0.0;
    /// The hand sensor's own swing by the same measure (its position about its 0.5 s moving
    /// mean): what the arm does, to set the sleeves' swing against.
    double handSwingCm = 0.0;
};
/// The measures of a simulated take (the take the simulation was made of). Errors when the take
/// has no hand part or fewer than 3 frames.
Result<KimonoMeasures> measureKimono(const Take& take, const KimonoSimulation& simulation);

/// The take with the kimono's 18 channels appended (measured points), e.g. for
/// `bunraku convert TAKE --kimono -o FILE.csv` and the analysis chain.
Take withKimonoChannels(const Take& take, const KimonoSimulation& simulation);
/// The kimono's 18 channels alone, at the take's rate, labelled "kimono of <the take's name>"
/// (what the workbench graphs as the "kimono" take beside the motion it was simulated for).
Take kimonoTake(const Take& take, const KimonoSimulation& simulation);

} // namespace bunraku::analysis
