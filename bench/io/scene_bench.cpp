// Opening an FBX take (issue 26): a 2-minute 60 Hz take of a Mixamo-size skeleton (65 joints:
// spine, head, arms with five fingers of four joints, legs) made at benchmark time, read as the
// workbench reads a take: readTakeFile (assimp, the conversion, the BVH import with the part
// map, calibration and skeleton). Two files of it: FBX binary exported by Blender 3.4 from the
// same take written as BVH (skipped without Blender), and FBX 7.4 ASCII written here with
// pre-rotations on the arms as Mixamo's rigs have (the slower encoding for assimp to parse).
// docs/PERFORMANCE.md.
#include "analysis/io/bvh.h"
#include "analysis/io/scene_take.h"
#include "analysis/io/take_reader.h"

#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;

struct SyntheticJoint {
    std::string name;
    int parent;
    double x, y, z; ///< local translation, cm
    bool preRotation;
};

std::vector<SyntheticJoint> mixamoSizeSkeleton()
{
    std::vector<SyntheticJoint> joints;
    auto add = [&](const std::string& name, int parent, double x, double y, double z, bool pre = false) {
        joints.push_back({"mixamorig:" + name, parent, x, y, z, pre});
        return int(joints.size()) - 1;
    };
    const int hips = add("Hips", -1, 0, 100, 0);
    int spine = add("Spine", hips, 0, 10, 0);
    spine = add("Spine1", spine, 0, 12, 0);
    spine = add("Spine2", spine, 0, 12, 0);
    const int neck = add("Neck", spine, 0, 14, 0);
    const int head = add("Head", neck, 0, 10, 0);
    add("HeadTop_End", head, 0, 18, 0);
    for (const std::string side : {"Left", "Right"}) {
        const double s = side == "Left" ? 1.0 : -1.0;
        int j = add(side + "Shoulder", spine, s * 6, 10, 0, true);
        j = add(side + "Arm", j, s * 12, 0, 0, true);
        j = add(side + "ForeArm", j, s * 26, 0, 0, true);
        const int hand = add(side + "Hand", j, s * 24, 0, 0, true);
        for (const std::string finger : {"Thumb", "Index", "Middle", "Ring", "Pinky"}) {
            int f = hand;
            for (int k = 1; k <= 4; ++k) f = add(side + "Hand" + finger + std::to_string(k), f, s * (k == 1 ? 4 : 3), 0, 0);
        }
        int leg = add(side + "UpLeg", hips, s * 9, -5, 0);
        leg = add(side + "Leg", leg, 0, -42, 0);
        leg = add(side + "Foot", leg, 0, -40, 0);
        leg = add(side + "ToeBase", leg, 0, -6, 12);
        add(side + "Toe_End", leg, 0, 0, 8);
    }
    return joints;
}

/// Writes (once) the FBX ASCII take: every joint's rotation keyed on X, Y and Z at every frame,
/// the hips' translation too.
fs::path mixamoSizeFbx(long frames)
{
    const fs::path file = fs::temp_directory_path() / ("bunraku_bench_mixamo_" + std::to_string(frames) + ".fbx");
    if (fs::exists(file)) return file;
    const auto joints = mixamoSizeSkeleton();
    const long long ticksPerFrame = 46186158000LL / 60;
    std::ostringstream out;
    out << "; FBX 7.4.0 project file\nFBXHeaderExtension:  {\n\tFBXHeaderVersion: 1003\n\tFBXVersion: 7400\n}\n"
           "GlobalSettings:  {\n\tVersion: 1000\n\tProperties70:  {\n"
           "\t\tP: \"UpAxis\", \"int\", \"Integer\", \"\",1\n\t\tP: \"UpAxisSign\", \"int\", \"Integer\", \"\",1\n"
           "\t\tP: \"FrontAxis\", \"int\", \"Integer\", \"\",2\n\t\tP: \"FrontAxisSign\", \"int\", \"Integer\", \"\",1\n"
           "\t\tP: \"CoordAxis\", \"int\", \"Integer\", \"\",0\n\t\tP: \"CoordAxisSign\", \"int\", \"Integer\", \"\",1\n"
           "\t\tP: \"UnitScaleFactor\", \"double\", \"Number\", \"\",1\n\t\tP: \"TimeMode\", \"enum\", \"\", \"\",3\n\t}\n}\n";
    out << "Objects:  {\n";
    std::ostringstream connections;
    long long id = 100000;
    std::vector<long long> modelIds;
    for (const auto& joint : joints) {
        modelIds.push_back(++id);
        out << "\tModel: " << id << ", \"Model::" << joint.name << "\", \"LimbNode\" {\n\t\tVersion: 232\n\t\tProperties70:  {\n";
        if (joint.preRotation) out << "\t\t\tP: \"PreRotation\", \"Vector3D\", \"Vector\", \"\",0,0,5\n";
        out << "\t\t\tP: \"Lcl Translation\", \"Lcl Translation\", \"\", \"A\"," << joint.x << "," << joint.y << "," << joint.z << "\n\t\t}\n\t}\n";
        connections << "\tC: \"OO\"," << id << "," << (joint.parent < 0 ? 0 : modelIds[std::size_t(joint.parent)]) << "\n";
    }
    const long long stack = ++id, layer = ++id;
    out << "\tAnimationStack: " << stack << ", \"AnimStack::mixamo.com\", \"\" {\n\t\tProperties70:  {\n\t\t\tP: \"LocalStop\", \"KTime\", \"Time\", \"\","
        << ticksPerFrame * (frames - 1) << "\n\t\t}\n\t}\n";
    out << "\tAnimationLayer: " << layer << ", \"AnimLayer::BaseLayer\", \"\" {\n\t}\n";
    connections << "\tC: \"OO\"," << layer << "," << stack << "\n";
    std::string times;
    for (long f = 0; f < frames; ++f) {
        if (f > 0) times += ',';
        times += std::to_string(ticksPerFrame * f); // appended piecewise: GCC 12's false -Wrestrict
    }
    auto curve = [&](long long node, const char* axis, double amplitude, double phase, double offset) {
        const long long curveId = ++id;
        out << "\tAnimationCurve: " << curveId << ", \"AnimCurve::\", \"\" {\n\t\tDefault: 0\n\t\tKeyVer: 4008\n\t\tKeyTime: *" << frames
            << " {\n\t\t\ta: " << times << "\n\t\t}\n\t\tKeyValueFloat: *" << frames << " {\n\t\t\ta: ";
        for (long f = 0; f < frames; ++f) out << (f ? "," : "") << float(offset + amplitude * std::sin(0.05 * double(f) + phase));
        out << "\n\t\t}\n\t\tKeyAttrFlags: *1 {\n\t\t\ta: 24836\n\t\t}\n\t\tKeyAttrDataFloat: *4 {\n\t\t\ta: 0,0,255790911,0\n\t\t}\n"
               "\t\tKeyAttrRefCount: *1 {\n\t\t\ta: "
            << frames << "\n\t\t}\n\t}\n";
        connections << "\tC: \"OP\"," << curveId << "," << node << ", \"d|" << axis << "\"\n";
    };
    for (std::size_t j = 0; j < joints.size(); ++j) {
        const long long node = ++id;
        out << "\tAnimationCurveNode: " << node << ", \"AnimCurveNode::R\", \"\" {\n\t\tProperties70:  {\n"
               "\t\t\tP: \"d|X\", \"Number\", \"\", \"A\",0\n\t\t\tP: \"d|Y\", \"Number\", \"\", \"A\",0\n\t\t\tP: \"d|Z\", \"Number\", \"\", \"A\",0\n\t\t}\n\t}\n";
        connections << "\tC: \"OO\"," << node << "," << layer << "\n\tC: \"OP\"," << node << "," << modelIds[j] << ", \"Lcl Rotation\"\n";
        for (int a = 0; a < 3; ++a) curve(node, a == 0 ? "X" : a == 1 ? "Y" : "Z", 10.0 + double(a), double(j) * 0.3 + a, 0.0);
        if (j == 0) {
            const long long translation = ++id;
            out << "\tAnimationCurveNode: " << translation << ", \"AnimCurveNode::T\", \"\" {\n\t\tProperties70:  {\n"
                   "\t\t\tP: \"d|X\", \"Number\", \"\", \"A\",0\n\t\t\tP: \"d|Y\", \"Number\", \"\", \"A\",100\n\t\t\tP: \"d|Z\", \"Number\", \"\", \"A\",0\n\t\t}\n\t}\n";
            connections << "\tC: \"OO\"," << translation << "," << layer << "\n\tC: \"OP\"," << translation << "," << modelIds[0] << ", \"Lcl Translation\"\n";
            curve(translation, "X", 20.0, 0.0, 0.0);
            curve(translation, "Y", 3.0, 1.0, 100.0);
            curve(translation, "Z", 40.0, 2.0, 0.0);
        }
    }
    out << "}\nConnections:  {\n" << connections.str() << "}\n";
    std::ofstream(file, std::ios::binary) << out.str();
    return file;
}

/// The same skeleton and motion as BVH (60 Hz, ZXY rotations, the hips' translation), exported by
/// Blender 3.4 as binary FBX with its defaults (once); empty when Blender fails or is missing.
fs::path blenderFbx(long frames)
{
    const fs::path file = fs::temp_directory_path() / ("bunraku_bench_mixamo_" + std::to_string(frames) + "_blender.fbx");
    if (fs::exists(file)) return file;
    const auto joints = mixamoSizeSkeleton();
    bunraku::analysis::io::BvhFile bvh;
    using Channel = bunraku::analysis::io::BvhChannel;
    int column = 0;
    for (std::size_t j = 0; j < joints.size(); ++j) {
        bunraku::analysis::io::BvhJoint joint;
        joint.name = joints[j].name;
        joint.parent = joints[j].parent;
        joint.offset = Eigen::Vector3d(joints[j].x, joints[j].y, joints[j].z);
        joint.endSite = joint.name.find("_End") != std::string::npos;
        if (!joint.endSite) {
            if (j == 0) joint.channels = {Channel::Xposition, Channel::Yposition, Channel::Zposition};
            joint.channels.insert(joint.channels.end(), {Channel::Zrotation, Channel::Xrotation, Channel::Yrotation});
            joint.firstChannel = column;
            column += int(joint.channels.size());
        }
        bvh.skeleton.joints.push_back(joint);
    }
    bvh.skeleton.channelCount = column;
    bvh.motion.frameTime = 1.0 / 60.0;
    bvh.motion.values.resize(frames, column);
    for (long f = 0; f < frames; ++f)
        for (int c = 0; c < column; ++c) bvh.motion.values(f, c) = (c == 1 ? 100.0 : 0.0) + (10.0 + c % 3) * std::sin(0.05 * double(f) + 0.3 * c);
    const fs::path folder = fs::temp_directory_path();
    const fs::path source = folder / ("bunraku_bench_mixamo_" + std::to_string(frames) + ".bvh");
    std::ofstream(source) << bunraku::analysis::io::formatBvh(bvh);
    const fs::path script = folder / "bunraku_bench_bvh_to_fbx.py";
    std::ofstream(script) << "import builtins, sys, bpy\n"
                             "_open = builtins.open\n"
                             "builtins.open = lambda f, m='r', *a, **k: _open(f, m.replace('U', '') if isinstance(m, str) else m, *a, **k)\n"
                             "source, target = sys.argv[sys.argv.index('--') + 1:][:2]\n"
                             "bpy.ops.wm.read_factory_settings(use_empty=True)\n"
                             "bpy.ops.import_anim.bvh(filepath=source, global_scale=0.01, update_scene_fps=True, update_scene_duration=True)\n"
                             "bpy.ops.export_scene.fbx(filepath=target)\n";
    const std::string command = "blender -b --factory-startup --python-exit-code 1 -P '" + script.string() + "' -- '" + source.string() +
                                "' '" + file.string() + "' >/dev/null 2>&1 </dev/null";
    if (std::system(command.c_str()) != 0 || !fs::exists(file)) return {};
    return file;
}

/// The workbench's File > Import Take of the Blender FBX take, without the window: readTakeFile.
void BM_OpenMixamoSizeBlenderFbxTake(benchmark::State& state)
{
    const long frames = long(state.range(0));
    const fs::path file = blenderFbx(frames);
    if (file.empty()) {
        state.SkipWithError("Blender 3.4 could not make the FBX file");
        return;
    }
    bunraku::analysis::io::ImportOptions options;
    options.bvh.jointMap = bunraku::analysis::io::JointMap{{"mixamorig:Head", "mixamorig:Spine2", "mixamorig:RightForeArm", "mixamorig:RightHand"}};
    for (auto _ : state) {
        auto take = bunraku::analysis::io::readTakeFile(file, options);
        if (!take) {
            state.SkipWithError(take.error().message.c_str());
            break;
        }
        benchmark::DoNotOptimize(take->values.data());
    }
    state.counters["frames"] = double(frames);
    state.counters["file_MB"] = double(fs::file_size(file)) / 1e6;
}
BENCHMARK(BM_OpenMixamoSizeBlenderFbxTake)->Arg(120 * 60)->Unit(benchmark::kMillisecond)->UseRealTime();

/// The workbench's File > Import Take of the ASCII FBX take, without the window: readTakeFile.
void BM_OpenMixamoSizeFbxTake(benchmark::State& state)
{
    const long frames = long(state.range(0));
    const fs::path file = mixamoSizeFbx(frames);
    bunraku::analysis::io::ImportOptions options;
    options.bvh.jointMap = bunraku::analysis::io::JointMap{{"mixamorig:Head", "mixamorig:Spine2", "mixamorig:RightForeArm", "mixamorig:RightHand"}};
    for (auto _ : state) {
        auto take = bunraku::analysis::io::readTakeFile(file, options);
        if (!take) {
            state.SkipWithError(take.error().message.c_str());
            break;
        }
        benchmark::DoNotOptimize(take->values.data());
    }
    state.counters["frames"] = double(frames);
    state.counters["file_MB"] = double(fs::file_size(file)) / 1e6;
}
BENCHMARK(BM_OpenMixamoSizeFbxTake)->Arg(120 * 60)->Unit(benchmark::kMillisecond)->UseRealTime();

/// assimp's parse and the conversion alone (readSceneTake), for the share of each.
void BM_ReadMixamoSizeFbxScene(benchmark::State& state)
{
    const fs::path file = mixamoSizeFbx(long(state.range(0)));
    for (auto _ : state) {
        auto scene = bunraku::analysis::io::readSceneTake(file);
        if (!scene) {
            state.SkipWithError(scene.error().message.c_str());
            break;
        }
        benchmark::DoNotOptimize(scene->bvh.motion.values.data());
    }
}
BENCHMARK(BM_ReadMixamoSizeFbxScene)->Arg(120 * 60)->Unit(benchmark::kMillisecond)->UseRealTime();

} // namespace

BENCHMARK_MAIN();
