// Takes, skeletons and corpora for Python: read_take (the command line's reader and import
// options), Take (values as a NumPy view of the take's own memory), Skeleton, Corpus.
#include "bindings/python/common.h"

#include "app/cli/cli.h"
#include "app/cli/import_options.h"

#include "analysis/core/skeleton.h"
#include "analysis/io/corpus_builder.h"
#include "analysis/io/corpus_io.h"
#include "analysis/io/take_reader.h"
#include "analysis/io/text_format.h"
#include "analysis/pipeline/stages.h"

#include <filesystem>
#include <sstream>

namespace bunraku::python {
namespace {

namespace an = bunraku::analysis;
namespace io = bunraku::analysis::io;
namespace cli = bunraku::app::cli;
namespace pl = bunraku::analysis::pipeline;

using TakePtr = std::shared_ptr<an::Take>;
using CorpusPtr = std::shared_ptr<an::Corpus>;
using SkeletonPtr = std::shared_ptr<an::SkeletalMotion>;

/// The command line's import options from read_take's keywords (app/cli/import_options.cpp):
/// the same function `bunraku info/convert/corpus` call, so the same part maps and messages.
io::ImportOptions importOptions(const std::string& joints, const std::string& jointMap, const std::string& side,
                                const std::string& upAxis, const std::string& units, bool allJoints,
                                std::optional<double> rateHz, const std::string& fastrakUnits, const std::string& path)
{
    const auto member = [](const char* option, const std::string& value, std::initializer_list<const char*> allowed) {
        std::string list;
        for (const char* name : allowed) {
            if (value == name) return;
            list += (list.empty() ? "" : ", ") + std::string(name);
        }
        throw Failure(std::string(option) + ": " + value + " not in {" + list + "}");
    };
    // The checks CLI11 makes on the command line's options (CLI::IsMember), in its words.
    member("--side", side, {"right", "left"});
    member("--up-axis", upAxis, {"auto", "y", "z"});
    member("--units", units, {"auto", "cm", "m", "mm", "in"});
    member("--fastrak-units", fastrakUnits, {"cm", "in"});
    cli::ImportArguments arguments;
    arguments.joints = joints;
    arguments.jointMapFile = jointMap;
    arguments.side = side;
    arguments.upAxis = upAxis;
    arguments.units = units;
    arguments.allJoints = allJoints;
    arguments.rateHz = rateHz;
    arguments.fastrakUnits = fastrakUnits;
    try {
        return cli::importOptions(arguments, path);
    } catch (const cli::CliError& error) {
        throw Failure(error.what());
    }
}

std::string takeRepr(const an::Take& take)
{
    std::ostringstream text;
    text << "<bunraku.Take " << take.displayName() << ": " << take.frameCount() << " frames x " << take.channelCount()
         << " channels at " << io::shortestNumber(take.rateHz) << " Hz";
    if (take.skeleton && take.skeleton->skeleton)
        text << ", skeleton '" << take.skeleton->skeleton->name << "' (" << take.skeleton->skeleton->joints.size() << " joints)";
    text << ">";
    return text.str();
}

std::vector<std::string> channelNames(const an::Take& take)
{
    std::vector<std::string> names;
    for (const auto& channel : take.channels) names.push_back(channel.name());
    return names;
}

/// A NumPy structured table as a pandas DataFrame: frames as index (seconds), channels as columns.
py::object takeFrame(const py::object& self)
{
    const an::Take& take = self.cast<const an::Take&>();
    py::module_ pandas = py::module_::import("pandas");
    py::module_ numpy = py::module_::import("numpy");
    py::object time = numpy.attr("arange")(take.frameCount()).attr("__truediv__")(take.rateHz);
    py::dict kwargs;
    kwargs["columns"] = channelNames(take);
    kwargs["index"] = pandas.attr("Index")(time, py::arg("name") = "time_s");
    return pandas.attr("DataFrame")(self.attr("values"), **kwargs);
}

} // namespace

py::object corpusObject(const CorpusPtr& corpus) { return py::cast(corpus); }

void bindTakes(py::module_& m)
{
    py::class_<an::SkeletalMotion, SkeletonPtr>(m, "Skeleton", R"doc(
The performer's full skeleton a take carries (from a BVH file, or derived with the take), and
its motion frame for frame with the take's values (analysis/core/skeleton.h). Joints are in
file order, parents before children; End Sites are named "<parent>_End". Workbench axes
(z up, x towards the partner), cm.)doc")
        .def_property_readonly("name", [](const an::SkeletalMotion& s) { return s.skeleton ? s.skeleton->name : std::string(); },
                               "The skeleton's name (usually the source file's stem).")
        .def_property_readonly("joints",
                               [](const an::SkeletalMotion& s) {
                                   std::vector<std::string> names;
                                   if (s.skeleton)
                                       for (const auto& joint : s.skeleton->joints) names.push_back(joint.name);
                                   return names;
                               },
                               "Joint names in file order.")
        .def_property_readonly("parents",
                               [](const an::SkeletalMotion& s) {
                                   std::vector<int> parents;
                                   if (s.skeleton)
                                       for (const auto& joint : s.skeleton->joints) parents.push_back(joint.parent);
                                   return parents;
                               },
                               "Index of each joint's parent in joints, -1 for a root.")
        .def_property_readonly("offsets",
                               [](const an::SkeletalMotion& s) {
                                   const std::size_t n = s.skeleton ? s.skeleton->joints.size() : 0;
                                   py::array_t<double> out({py::ssize_t(n), py::ssize_t(3)});
                                   auto w = out.mutable_unchecked<2>();
                                   for (std::size_t j = 0; j < n; ++j)
                                       for (int k = 0; k < 3; ++k) w(py::ssize_t(j), k) = s.skeleton->joints[j].offset[k];
                                   return out;
                               },
                               "joints x 3: each joint's rest offset from its parent (cm, a copy).")
        .def_property_readonly("parts",
                               [](const an::SkeletalMotion& s) {
                                   py::dict parts;
                                   if (s.skeleton)
                                       for (const auto& binding : s.skeleton->parts)
                                           if (binding.joint >= 0 && std::size_t(binding.joint) < s.skeleton->joints.size())
                                               parts[py::str(binding.part)] = s.skeleton->joints[std::size_t(binding.joint)].name;
                                   return parts;
                               },
                               "The puppet parts bound to joints: {\"head\": \"Head\", ...}.")
        .def_property_readonly("frames", [](const an::SkeletalMotion& s) { return s.frameCount(); }, "Frames of the motion.")
        .def_property_readonly("rotations",
                               [](py::object self) {
                                   const auto& s = self.cast<const an::SkeletalMotion&>();
                                   const py::ssize_t joints = s.jointSlots();
                                   const py::ssize_t q = sizeof(Eigen::Quaterniond);
                                   return view<double>(s.rotations.empty() ? nullptr : s.rotations.front().coeffs().data(),
                                                       {py::ssize_t(s.frameCount()), joints, 4}, {q * joints, q, sizeof(double)}, self);
                               },
                               "frames x joints x 4: each joint's rotation relative to its parent as a unit quaternion "
                               "(x, y, z, w) - a read-only view of the skeleton's own memory.")
        .def("world_poses",
             [](const an::SkeletalMotion& s, Eigen::Index frame) {
                 if (frame < 0 || frame >= s.frameCount())
                     throw py::index_error("frame " + std::to_string(frame) + " outside 0.." + std::to_string(s.frameCount() - 1));
                 const auto poses = s.worldPoses(frame);
                 py::array_t<double> out({py::ssize_t(poses.size()), py::ssize_t(4), py::ssize_t(4)});
                 auto w = out.mutable_unchecked<3>();
                 for (std::size_t j = 0; j < poses.size(); ++j) {
                     const Eigen::Matrix4d matrix = poses[j].isometry().matrix();
                     for (int r = 0; r < 4; ++r)
                         for (int c = 0; c < 4; ++c) w(py::ssize_t(j), r, c) = matrix(r, c);
                 }
                 return out;
             },
             py::arg("frame"), "joints x 4 x 4: world_T_joint of every joint at a frame (homogeneous matrices, cm).")
        .def("__repr__", [](const an::SkeletalMotion& s) {
            return "<bunraku.Skeleton '" + (s.skeleton ? s.skeleton->name : std::string()) + "': " +
                   std::to_string(s.jointSlots()) + " joints, " + std::to_string(s.frameCount()) + " frames>";
        });

    py::class_<an::Take, TakePtr>(m, "Take", R"doc(
One recording: frames x channels (rows = time), the sample rate, a name and unit per channel,
labels (function, emotion, take index, source) and, when it came from a file with one, the
performer's skeleton (analysis/core/take.h). Positions in cm, angles in degrees.

``values`` is a read-only NumPy view of the take's own memory (no copy: ``OWNDATA`` is false
and the array keeps the take alive); ``numpy.array(take.values)`` copies it.)doc")
        .def_property_readonly("values", [](py::object self) { return matrixView(self.cast<const an::Take&>().values, self); },
                               "frames x channels, float64: a read-only view of the take's memory (Fortran order).")
        .def_property_readonly("channels", &channelNames, "Channel names \"part.dof\", one per column.")
        .def_property_readonly("units",
                               [](const an::Take& take) {
                                   std::vector<std::string> units;
                                   for (const auto& channel : take.channels) units.push_back(channel.unit);
                                   return units;
                               },
                               "The unit of each channel (\"cm\", \"deg\").")
        .def_property_readonly("parts", &an::Take::parts, "Part names in the order of their first channel.")
        .def_property_readonly("rate_hz", [](const an::Take& take) { return take.rateHz; }, "Sample rate, Hz.")
        .def_property_readonly("frames", &an::Take::frameCount, "Number of frames.")
        .def_property_readonly("duration", &an::Take::duration, "Seconds from the first to the last frame.")
        .def_property_readonly("function", [](const an::Take& take) { return take.labels.function; }, "Function label.")
        .def_property_readonly("emotion", [](const an::Take& take) { return take.labels.emotion; }, "Emotion label.")
        .def_property_readonly("take_index", [](const an::Take& take) { return take.labels.takeIndex; },
                               "1-based index within its function x emotion cell, 0 when unknown.")
        .def_property_readonly("source", [](const an::Take& take) { return take.labels.source; },
                               "The file it came from, or the recipe that derived it.")
        .def_property_readonly("labels",
                               [](const an::Take& take) {
                                   py::dict labels;
                                   labels["function"] = take.labels.function;
                                   labels["emotion"] = take.labels.emotion;
                                   labels["take_index"] = take.labels.takeIndex;
                                   labels["source"] = take.labels.source;
                                   return labels;
                               },
                               "{\"function\", \"emotion\", \"take_index\", \"source\"}.")
        .def_property_readonly("name", &an::Take::displayName, "\"function/emotion/k\" when labelled, else the source.")
        .def_property_readonly("skeleton",
                               [](const TakePtr& take) -> py::object {
                                   if (!take->skeleton) return py::none();
                                   return py::cast(alias(take, *take->skeleton));
                               },
                               "The performer's Skeleton and its motion, or None.")
        .def("write", [](const an::Take& take, const std::string& path) { unwrap(io::writeTakeFile(take, path)); }, py::arg("path"),
             "Writes the take as .csv or .bvh by the extension (atomic; as `bunraku convert`).")
        .def("to_pandas", &takeFrame, "The values as a pandas DataFrame: channels as columns, time (s) as the index.")
        .def("__repr__", &takeRepr);

    m.def(
        "read_take",
        [](const std::string& path, const std::string& joints, const std::string& jointMap, const std::string& side,
           const std::string& upAxis, const std::string& units, bool allJoints, std::optional<double> rate,
           const std::string& fastrakUnits) {
            const io::ImportOptions options =
                importOptions(joints, jointMap, side, upAxis, units, allJoints, rate, fastrakUnits, path);
            return std::make_shared<an::Take>(
                unwrap(runReleased([&](const an::RunControl& control) { return io::readTakeFile(path, options, control); })));
        },
        py::arg("path"), py::kw_only(), py::arg("joints") = "", py::arg("joint_map") = "", py::arg("side") = "right",
        py::arg("up_axis") = "auto", py::arg("units") = "auto", py::arg("all_joints") = false, py::arg("rate") = py::none(),
        py::arg("fastrak_units") = "cm",
        R"doc(Reads a take from a .csv, .bvh or FASTRAK (.txt, .fastrak, .fst) file, chosen by extension:
the reader `bunraku info` and `bunraku convert` use (analysis/io/take_reader.h), with their
import options as keywords:

- joints: the BVH part map, "head=Head,shoulder=Chest,arm=LowerArm_R,hand=Hand_R" (--joints);
  parts not named are mapped automatically
- joint_map: a JSON file {"head": ..., "shoulder": ..., "arm": ..., "hand": ...} (--joint-map)
- side: "right" or "left", the limbs the puppet's arm and hand follow (--side)
- up_axis: "auto", "y" or "z" (--up-axis); units: "auto", "cm", "m", "mm" or "in" (--units)
- all_joints: keep every BVH joint (6 channels each) instead of the 4 puppet parts (--all-joints)
- rate: Hz for a CSV without time_s and FASTRAK files (--rate); fastrak_units: "cm" or "in"

Raises bunraku.Error with the command line's message on a bad file or option.)doc");

    py::class_<an::Corpus, CorpusPtr>(m, "Corpus", R"doc(
Takes labelled function x emotion x take index (analysis/core/corpus.h): a corpus folder
(corpus.json and a CSV per take), or one built from take files whose names carry the labels.)doc")
        .def_static(
            "open",
            [](const std::string& folder) {
                pl::CorpusInput input = unwrap(runReleased([&](const an::RunControl&) { return pl::importCorpus(folder); }));
                return std::const_pointer_cast<an::Corpus>(input.corpus);
            },
            py::arg("folder"),
            "Reads a corpus folder (corpus.json), or \"demo\" for the embedded synthetic corpus - as `bunraku analyse` "
            "reads its CORPUS.")
        .def_static(
            "from_files",
            [](const std::vector<std::string>& paths, const std::string& pattern, const std::string& name, const std::string& neutral,
               double resample, const std::string& joints, const std::string& jointMap, const std::string& side,
               const std::string& upAxis, const std::string& units, bool allJoints, std::optional<double> rate,
               const std::string& fastrakUnits) {
                if (resample < 0.0) throw Failure("--resample must be a positive number of Hz");
                io::CorpusBuildOptions options;
                options.import = importOptions(joints, jointMap, side, upAxis, units, allJoints, rate, fastrakUnits, {});
                options.neutralEmotion = neutral;
                options.rateHz = resample;
                options.name = name;
                std::vector<std::filesystem::path> inputs(paths.begin(), paths.end());
                io::CorpusBuild build = unwrap(runReleased([&](const an::RunControl& control) -> an::Result<io::CorpusBuild> {
                    auto files = io::collectTakeFiles(inputs);
                    if (!files) return files.error();
                    auto sources = io::labelTakeFiles(*files, pattern);
                    if (!sources) return sources.error();
                    return io::buildCorpus(*sources, options, control);
                }));
                return std::make_shared<an::Corpus>(std::move(build.corpus));
            },
            py::arg("paths"), py::kw_only(), py::arg("pattern") = std::string(io::kDefaultLabelPattern), py::arg("name") = "",
            py::arg("neutral") = "", py::arg("resample") = 0.0, py::arg("joints") = "", py::arg("joint_map") = "",
            py::arg("side") = "right", py::arg("up_axis") = "auto", py::arg("units") = "auto", py::arg("all_joints") = false,
            py::arg("rate") = py::none(), py::arg("fastrak_units") = "cm",
            R"doc(A corpus from take files and folders of them, as `bunraku corpus` makes one
(analysis/io/corpus_builder.h): labels from each file's name by `pattern` ("{function}_{emotion}_{take}";
{any} matches anything), every file read with the same import options (read_take's keywords),
takes resampled to one rate when the files' rates differ (`resample` Hz: that rate), the
neutral emotion "neutral", "normal" or "none" when present unless `neutral` names it.)doc")
        .def("write", [](const an::Corpus& corpus, const std::string& folder) { unwrap(io::writeCorpus(corpus, folder)); },
             py::arg("folder"), "Writes the corpus folder (corpus.json and a CSV per take; atomic, as `bunraku corpus`).")
        .def_property_readonly("name", [](const an::Corpus& c) { return c.name; }, "The corpus's name.")
        .def_property_readonly("rate_hz", [](const an::Corpus& c) { return c.rateHz; }, "Sample rate of every take, Hz.")
        .def_property_readonly("neutral_emotion", [](const an::Corpus& c) { return c.neutralEmotion; },
                               "The emotion meaning no emotion (thesis hypothesis 4: z^{i1} = 0).")
        .def_property_readonly("functions", &an::Corpus::functions, "Function labels in order of first appearance.")
        .def_property_readonly("emotions", &an::Corpus::emotions, "Emotion labels, the neutral one first.")
        .def_property_readonly("takes",
                               [](const CorpusPtr& corpus) {
                                   std::vector<TakePtr> takes;
                                   for (const auto& take : corpus->takes) takes.push_back(alias(corpus, take));
                                   return takes;
                               },
                               "Every Take, in corpus order (views: no copy).")
        .def(
            "cell",
            [](const CorpusPtr& corpus, const std::string& function, const std::string& emotion) {
                std::vector<TakePtr> takes;
                for (const an::Take* take : corpus->cell(function, emotion)) takes.push_back(alias(corpus, *take));
                return takes;
            },
            py::arg("function"), py::arg("emotion"), "The takes of one function x emotion cell, by take index.")
        .def("__len__", [](const an::Corpus& c) { return c.takes.size(); })
        .def("__getitem__",
             [](const CorpusPtr& corpus, py::ssize_t k) {
                 const py::ssize_t n = py::ssize_t(corpus->takes.size());
                 if (k < 0) k += n;
                 if (k < 0 || k >= n) throw py::index_error("take " + std::to_string(k) + " of " + std::to_string(n));
                 return alias(corpus, corpus->takes[std::size_t(k)]);
             })
        .def("__repr__", [](const an::Corpus& c) {
            std::ostringstream text;
            text << "<bunraku.Corpus '" << c.name << "': " << c.takes.size() << " takes, " << c.functions().size() << " function(s) x "
                 << c.emotions().size() << " emotion(s) at " << io::shortestNumber(c.rateHz) << " Hz>";
            return text.str();
        });
}

} // namespace bunraku::python
