// Subcommands: render (thesis 6: images of the puppet, motion axis and orbits, offscreen).
#include "app/cli/commands.h"
#include "app/cli/output_guard.h"

#include "app/multimodal_export.h"
#include "app/video_export.h"

#include "analysis/body/body_description.h"
#include "analysis/io/atomic_file.h"
#include "analysis/io/take_reader.h"
#include "analysis/pipeline/stages.h"
#include "analysis/synth/demo_corpus.h"
#include "render/mesh_file.h"
#include "render/offscreen_renderer.h"
#include "render/take_scene.h"

#include <QBuffer>
#include <QGuiApplication>
#include <QImage>
#include <QSaveFile>
#include <QStandardPaths>

#include <atomic>
#include <cmath>
#include <csignal>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <memory>
#include <unistd.h>
#include <filesystem>
#include <optional>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

namespace bunraku::app::cli {

namespace {

struct RenderArguments {
    std::string take;
    std::string takeB;
    std::optional<long> frame;
    std::optional<double> time;
    std::string frames;
    float cameraDeg = 340.0f;
    float elevationDeg = 15.0f;
    float distanceCm = 0.0f; // 0: chosen from the scene
    std::string preset;
    std::string show = "puppet,axis,grid,shadows,partner";
    std::string figure = "puppet";
    std::string figureB; // empty: as --figure
    std::string size = "1280x720";
    std::string output;
    std::string mp4;
    std::string body;
    std::vector<std::string> meshes;
    int samples = 4;
    bool follow = false;
    bool kimono = false;
    analysis::ClothParameters cloth;
    bool json = false;
    // --multimodal: the thesis's multimodal display (chapter 6), view and graphs in one picture
    bool multimodal = false;
    std::string graphs = "all";
    std::string part;
    std::string dof;
    std::string ticks = "thesis";
    double fps = 0.0;
    bool overwrite = false;
};

/// Set by SIGINT / SIGTERM during a multimodal export: the export stops and removes what it wrote.
std::atomic<bool> g_interrupted{false};

extern "C" void interruptExport(int) { g_interrupted = true; }

/// "demo:FUNCTION/EMOTION/K" from the built-in synthetic corpus, or a take file.
analysis::Take loadTake(const std::string& spec)
{
    return unwrap(analysis::synth::isDemoTakeName(spec) ? analysis::synth::demoTake(spec) : analysis::io::readTakeFile(spec));
}

QSize parseSize(const std::string& text)
{
    int width = 0, height = 0;
    char separator = 0;
    std::istringstream stream(text);
    if (!(stream >> width >> separator >> height) || (separator != 'x' && separator != 'X') || width < 16 ||
        height < 16 || width > 8192 || height > 8192 || !stream.eof())
        throw CliError("--size '" + text + "': expected WIDTHxHEIGHT in pixels, 16..8192, e.g. 1280x720");
    return {width, height};
}

std::pair<long, long> parseFrameRange(const std::string& text)
{
    long first = 0, last = 0;
    char separator = 0;
    std::istringstream stream(text);
    if (!(stream >> first >> separator >> last) || separator != ':' || first < 0 || last < first || !stream.eof())
        throw CliError("--frames '" + text + "': expected FIRST:LAST frame numbers, 0 <= FIRST <= LAST");
    return {first, last};
}

render::SceneVisibility parseShow(const std::string& text)
{
    render::SceneVisibility visibility;
    for (const auto& [name, shown] : render::kSceneObjects) visibility.*shown = false;
    // Orbits named explicitly are drawn even with the puppet (the thesis shows them instead of it).
    visibility.orbitVisibility = render::OrbitVisibility::Always;
    std::stringstream stream(text);
    for (std::string word; std::getline(stream, word, ',');) {
        bool known = word.empty() || word == "all";
        for (const auto& [name, shown] : render::kSceneObjects)
            if (word == name || word == "all") visibility.*shown = known = true;
        if (!known) throw CliError("--show: unknown object '" + word + "' (expected puppet, axis, orbits, grid, shadows, partner, all)");
    }
    return visibility;
}

render::FigureStyle parseFigure(const std::string& text, const std::string& option)
{
    if (const auto style = render::figureStyleFromName(text)) return *style;
    throw CliError(option + " '" + text + "': expected puppet, skeleton, both, body or mesh");
}

bool hasDisplay() { return std::getenv("DISPLAY") != nullptr || std::getenv("WAYLAND_DISPLAY") != nullptr; }

/// Without a display Mesa offers OpenGL to Qt only through an X server: run this same command
/// again under `xvfb-run -a` when it is installed (once: the environment marks the retry).
/// Returns only when that is not possible.
void rerunUnderXvfbWithoutDisplay()
{
    if (hasDisplay() || std::getenv("QT_QPA_PLATFORM") != nullptr || std::getenv("BUNRAKU_RENDER_XVFB") != nullptr)
        return;
    if (QStandardPaths::findExecutable(QStringLiteral("xvfb-run")).isEmpty()) return;
    std::ifstream cmdline("/proc/self/cmdline", std::ios::binary);
    std::vector<std::string> words;
    for (std::string word; std::getline(cmdline, word, '\0');) words.push_back(word);
    std::error_code error;
    const auto self = std::filesystem::read_symlink("/proc/self/exe", error);
    if (words.empty() || error) return;
    words[0] = self.string();
    std::vector<char*> argv{const_cast<char*>("xvfb-run"), const_cast<char*>("-a")};
    for (std::string& word : words) argv.push_back(word.data());
    argv.push_back(nullptr);
    setenv("BUNRAKU_RENDER_XVFB", "1", 1);
    std::cout.flush();
    execvp("xvfb-run", argv.data());
}

/// A QGuiApplication for offscreen OpenGL: xcb when there is a display, else Qt's offscreen
/// platform (which has OpenGL only where the system offers it without X).
std::unique_ptr<QGuiApplication> makeGuiApplication()
{
    if (QCoreApplication::instance() != nullptr) return nullptr;
    if (!hasDisplay() && std::getenv("QT_QPA_PLATFORM") == nullptr) setenv("QT_QPA_PLATFORM", "offscreen", 1);
    static int argc = 1;
    static char name[] = "bunraku";
    static char* argv[] = {name, nullptr};
    return std::make_unique<QGuiApplication>(argc, argv);
}

/// The image as PNG bytes.
QByteArray pngBytes(const QImage& image, const std::filesystem::path& file)
{
    if (image.isNull()) throw CliError(file.string() + ": rendering produced no image");
    QByteArray bytes;
    QBuffer buffer(&bytes);
    if (!buffer.open(QIODevice::WriteOnly) || !image.save(&buffer, "PNG")) throw CliError(file.string() + ": cannot encode the PNG");
    return bytes;
}

std::string_view view(const QByteArray& bytes) { return {bytes.constData(), std::size_t(bytes.size())}; }

/// Runs a video export (app/video_export.h) that Ctrl+C or SIGTERM stop, removing what it wrote;
/// progress on standard error when it is a terminal and --json is not given. Throws CliError
/// naming `output` when the export fails or is stopped.
template <class Export>
VideoExportResult interruptible(const char* what, bool json, const std::string& output, Export&& run)
{
    g_interrupted = false;
    std::signal(SIGINT, interruptExport);
    std::signal(SIGTERM, interruptExport);
    const bool terminal = ::isatty(STDERR_FILENO) == 1 && !json;
    const VideoExportResult result = run([terminal, what](int done, int total) {
        if (terminal) std::fprintf(stderr, "\r%s %d / %d", what, done, total);
        if (terminal && done == total) std::fprintf(stderr, "\n");
        return !g_interrupted.load();
    });
    std::signal(SIGINT, SIG_DFL);
    std::signal(SIGTERM, SIG_DFL);
    if (result.cancelled) throw CliError("interrupted: nothing was written to " + output);
    if (!result.ok()) throw CliError(result.error.toStdString());
    return result;
}

nlohmann::json rectJson(const QRect& rect) { return {rect.x(), rect.y(), rect.width(), rect.height()}; }

/// --multimodal: one frame as a PNG, or a range as MP4 / PNG frames through the workbench's
/// video export (atomic output; Ctrl+C cancels and removes what was written).
/// `summary`: what every render says (its size, camera and takes).
void runMultimodal(const RenderArguments& args, const render::SceneContent& scene, render::OffscreenRenderer& offscreen,
                   const render::Camera& camera, QSize size, nlohmann::json summary)
{
    MultimodalOptions options;
    options.layout = args.graphs == "part"     ? widgets::GraphLayout::OnePart
                     : args.graphs == "dof"    ? widgets::GraphLayout::OneDof
                     : args.graphs == "single" ? widgets::GraphLayout::Single
                                               : widgets::GraphLayout::AllChannels;
    options.part = args.part;
    options.dof = args.dof;
    options.thesisTicks = args.ticks == "thesis";
    options.size = size;
    const auto takeA = std::make_shared<const analysis::Take>(scene.takes.front().take);
    const auto takeB = scene.takes.size() > 1 ? std::make_shared<const analysis::Take>(scene.takes[1].take) : nullptr;
    const MultimodalFrame frame = unwrap(MultimodalFrame::create(takeA, takeB, options));
    const ViewImage view = [&offscreen, &camera](double seconds, QSize viewSize) -> analysis::Result<QImage> {
        if (!offscreen.makeCurrent())
            return analysis::makeError(analysis::ErrorCode::Io, "the offscreen OpenGL context could not be made current");
        offscreen.renderer().setTime(seconds);
        return offscreen.render(camera, viewSize);
    };
    summary["view"] = rectJson(frame.geometry().view);
    summary["graphs"] = nlohmann::json::array();
    for (std::size_t i = 0; i < frame.geometry().cells.size(); ++i) {
        const auto& cell = frame.geometry().cells[i];
        summary["graphs"].push_back({{"part", cell.part},
                                     {"dof", cell.dof},
                                     {"take", cell.takes == widgets::GraphTakes::OnlyB ? "B" : "A"},
                                     {"rect", rectJson(frame.geometry().graphs[i])},
                                     {"plot", rectJson(frame.geometry().plots[i])}});
    }
    summary["duration_s"] = frame.duration();
    summary["thesis_ticks"] = options.thesisTicks;
    if (args.frames.empty() && args.output.ends_with(".png")) {
        // one frame, written atomically
        const double seconds = args.time ? *args.time : double(args.frame.value_or(0)) / takeA->rateHz;
        const QImage image = unwrap(frame.render(view, seconds));
        QSaveFile file(QString::fromStdString(args.output));
        if (!file.open(QIODevice::WriteOnly) || !image.save(&file, "PNG") || !file.commit())
            throw CliError("could not write " + args.output + ": " + file.errorString().toStdString());
        summary["output"] = args.output;
        summary["time_s"] = seconds;
        summary["frame"] = offscreen.renderer().frame(0);
        if (args.json) printJson(summary);
        return;
    }
    VideoExportOptions video;
    const bool mp4 = args.output.ends_with(".mp4");
    video.format = mp4 ? VideoFormat::Mp4 : VideoFormat::PngSequence;
    video.output = QString::fromStdString(args.output);
    video.overwrite = args.overwrite;
    video.fps = args.fps;
    if (!args.frames.empty()) {
        const auto range = parseFrameRange(args.frames);
        video.firstFrame = int(range.first);
        video.lastFrame = int(range.second);
    }
    const VideoExportResult result = interruptible("multimodal frames", args.json, args.output, [&](const ExportProgress& progress) {
        return exportMultimodalVideo(frame, view, video, progress);
    });
    summary["output"] = args.output;
    summary["format"] = mp4 ? "mp4" : "png";
    summary["frames_written"] = result.frames;
    if (args.json) printJson(summary);
    else std::cout << "wrote " << result.frames << " multimodal frames to " << args.output << "\n";
}

void runRender(const RenderArguments& args)
{
    if (args.output.empty()) throw CliError("-o is required: the PNG file (or the folder with --frames)");
    std::vector<std::string> inputs{args.take, args.takeB, args.body};
    for (const std::string& entry : args.meshes) inputs.push_back(entry.substr(entry.find('=') + 1));
    refuseOutputOverInputs(args.output, args.frames.empty() ? OutputKind::File : OutputKind::Folder, inputs);
    refuseOutputOverInputs(args.mp4, OutputKind::File, inputs, "--mp4");
    if (args.frame && args.time) throw CliError("give --frame or --time, not both");
    if (!args.frames.empty() && (args.frame || args.time))
        throw CliError("--frames renders a sequence: drop --frame / --time");
    if (!args.mp4.empty() && args.multimodal)
        throw CliError("--multimodal writes MP4 itself: give -o FILE.mp4 (or a folder for PNG frames), not --mp4");
    if (!args.mp4.empty() && args.frames.empty()) throw CliError("--mp4 needs --frames FIRST:LAST");
    if (args.multimodal && args.output.ends_with(".mp4") &&
        QStandardPaths::findExecutable(QStringLiteral("ffmpeg")).isEmpty())
        throw CliError("an MP4 output needs ffmpeg on PATH, which was not found: install Debian's ffmpeg "
                       "(apt-get install ffmpeg) or give a folder for PNG frames");
    if (!(args.fps >= 0.0) || args.fps > 1000.0) throw CliError("--fps: expected 0 (the take's rate) .. 1000");
    if (!args.mp4.empty() && QStandardPaths::findExecutable(QStringLiteral("ffmpeg")).isEmpty())
        throw CliError("--mp4 needs ffmpeg on PATH, which was not found: install Debian's ffmpeg "
                       "(apt-get install ffmpeg) or drop --mp4 and encode the PNG frames yourself");
    if (args.samples < 0 || args.samples > 16) throw CliError("--samples: expected 0..16");
    const QSize size = parseSize(args.size);
    render::SceneVisibility visibility = parseShow(args.show);
    visibility.figures = {parseFigure(args.figure, "--figure"), parseFigure(args.figureB.empty() ? args.figure : args.figureB, "--figure-b")};
    std::optional<std::pair<long, long>> range;
    if (!args.frames.empty()) range = parseFrameRange(args.frames);

    std::vector<analysis::Take> takes{loadTake(args.take)};
    if (!args.takeB.empty()) takes.push_back(loadTake(args.takeB));
    // "mesh" asks for the skinned mesh a take's file carries: a take without one is an error.
    for (std::size_t t = 0; t < takes.size(); ++t)
        if (visibility.figures[t] == render::FigureStyle::FileMesh && !render::takeHasFileMesh(takes[t]))
            throw CliError(std::string(t == 0 ? "--figure" : "--figure-b") + " mesh: the take " + (t == 0 ? args.take : args.takeB) +
                           " carries no skinned mesh of its file (expected an FBX, glTF or Collada take with a mesh skinned to its skeleton; "
                           "`bunraku info` says why a file's mesh was dropped)");
    const analysis::BodyDescription body =
        args.body.empty() ? analysis::defaultBodyDescription() : unwrap(analysis::loadBodyDescription(args.body));

    render::TakeSceneOptions sceneOptions;
    sceneOptions.computeAxes = visibility.axis;
    sceneOptions.fitToSkeleton = args.body.empty() && args.meshes.empty(); // a body or meshes given are drawn as given
    render::SceneContent scene = unwrap(render::makeTakeScene(body, std::move(takes), sceneOptions));
    for (const std::string& entry : args.meshes) {
        const auto equals = entry.find('=');
        if (equals == std::string::npos || equals == 0)
            throw CliError("--mesh '" + entry + "': expected PART=FILE, e.g. head=scans/head.glb");
        scene.partMeshes[entry.substr(0, equals)] = unwrap(render::loadMeshFile(entry.substr(equals + 1)));
    }
    // The kimono as cloth: each take's simulated on the body it is drawn with (the workbench's
    // Cloth box runs the same stage).
    if (args.kimono) {
        if (!scene.partMeshes.empty() || !analysis::bodyHasPuppetParts(scene.body))
            throw CliError("--kimono dresses the modelled puppet: it needs the shipped body's six parts and no --mesh");
        for (auto& slot : scene.takes)
            slot.kimono = std::make_shared<const analysis::KimonoSimulation>(
                unwrap(analysis::pipeline::runKimono(slot.take, slot.body ? *slot.body : scene.body, args.cloth)));
    }

    const long frameCount = long(scene.takes.front().take.frameCount());
    long lastFrame = frameCount - 1;
    for (const auto& slot : scene.takes) lastFrame = std::max(lastFrame, long(slot.take.frameCount()) - 1);
    if (args.frame && (*args.frame < 0 || *args.frame > lastFrame))
        throw CliError("--frame " + std::to_string(*args.frame) + ": the take has frames 0.." + std::to_string(lastFrame));
    if (range && range->second > lastFrame)
        throw CliError("--frames " + args.frames + ": the take has frames 0.." + std::to_string(lastFrame));

    rerunUnderXvfbWithoutDisplay();
    auto application = makeGuiApplication();
    auto created = render::OffscreenRenderer::create(render::OffscreenOptions{args.samples});
    if (!created.ok() && !hasDisplay())
        throw CliError(created.error().message + ": there is no display; install xvfb and run `xvfb-run -a bunraku render ...`");
    auto offscreen = unwrap(std::move(created));
    unwrap(offscreen->setScene(scene));
    offscreen->renderer().setVisibility(visibility);

    render::Camera camera = offscreen->renderer().framingCamera();
    camera.angleDeg = args.cameraDeg;
    camera.elevationDeg = args.elevationDeg;
    if (args.distanceCm > 0.0f) camera.distance = args.distanceCm;
    if (args.preset == "top") camera = camera.withPreset(render::CameraPreset::Top);
    else if (args.preset == "bottom") camera = camera.withPreset(render::CameraPreset::Bottom);
    else if (!args.preset.empty()) throw CliError("--preset: expected top or bottom");

    nlohmann::json summary;
    summary["size"] = {size.width(), size.height()};
    summary["camera"] = {{"angle_deg", camera.angleDeg}, {"elevation_deg", camera.elevationDeg}, {"distance_cm", camera.distance}};
    for (const auto& slot : scene.takes) summary["takes"].push_back(slot.take.displayName());
    if (args.multimodal) return runMultimodal(args, scene, *offscreen, camera, size, summary);
    for (int s = 0; s < int(scene.takes.size()); ++s)
        summary["figures"].push_back({{"puppet", offscreen->renderer().puppetDrawn(s)},
                                      {"skeleton", offscreen->renderer().skeletonDrawn(s)},
                                      {"mesh", offscreen->renderer().skeletonDrawn(s) && visibility.figures[std::size_t(s)] == render::FigureStyle::FileMesh}});

    // --follow: the camera carried along the floor with the figures (as the 3D view's Follow).
    const auto follow = [&] {
        if (!args.follow) return;
        render::BoundsQuery now;
        now.span = render::FramingSpan::CurrentFrame;
        now.figuresOnly = true;
        camera = render::followingCamera(camera, offscreen->renderer().displayedBounds(camera, now));
    };
    if (!range) {
        offscreen->makeCurrent();
        if (args.time) offscreen->renderer().setTime(*args.time);
        else offscreen->renderer().setFrame(args.frame.value_or(0));
        follow();
        unwrap(analysis::io::writeFileAtomically(args.output, view(pngBytes(offscreen->render(camera, size), args.output))));
        summary["output"] = args.output;
        summary["frame"] = offscreen->renderer().frame(0);
    } else {
        // The 3D view's video export (app/video_export.h), as File > Export 3D View Video: the frames
        // appear in the folder only once all are written, and the MP4 is encoded from them.
        const std::string folder = args.output;
        const double rate = scene.takes.front().take.rateHz;
        const FramePlan plan = planFrames(rate, int(range->first), int(range->second), 0.0);
        const FrameRenderer renderFrame = [&](double seconds) -> analysis::Result<QImage> {
            if (!offscreen->makeCurrent())
                return analysis::makeError(analysis::ErrorCode::Io, "the offscreen OpenGL context could not be made current");
            offscreen->renderer().setFrame(std::lround(seconds * rate));
            follow();
            return offscreen->render(camera, size);
        };
        VideoExportOptions video;
        video.format = VideoFormat::PngSequence;
        video.output = QString::fromStdString(folder);
        video.overwrite = true; // as before: the folder holds the new sequence alone
        video.size = size;
        interruptible("frames", args.json, folder, [&](const ExportProgress& progress) { return exportFrames(video, plan, renderFrame, progress); });
        summary["output"] = folder;
        summary["frames"] = {range->first, range->second};
        if (!args.mp4.empty()) {
            const FrameRenderer writtenFrame = [&](double seconds) -> analysis::Result<QImage> {
                char name[32];
                std::snprintf(name, sizeof name, "frame_%05ld.png", std::lround((seconds - plan.times.front()) * rate));
                const std::string file = (std::filesystem::path(folder) / name).string();
                QImage image(QString::fromStdString(file));
                if (image.isNull()) return analysis::makeError(analysis::ErrorCode::Io, file + ": the frame could not be read back");
                return image;
            };
            video.format = VideoFormat::Mp4;
            video.output = QString::fromStdString(args.mp4);
            interruptible("MP4 frames", args.json, args.mp4, [&](const ExportProgress& progress) {
                return exportFrames(video, plan, writtenFrame, progress);
            });
            summary["mp4"] = args.mp4;
        }
    }
    if (args.json) printJson(summary);
}

} // namespace

void addRenderCommands(CommandSet& commands)
{
    auto [render, args] = addCommand(commands.root, "render", runRender);
    render->add_option("take", args.take, "Take file (.csv, .bvh, FASTRAK .txt) or demo:FUNCTION/EMOTION/K")
        ->required();
    render->add_option("--take-b", args.takeB, "A second take, shown to the right of the first");
    render->add_option("--frame", args.frame, "Frame to render (default 0)");
    render->add_option("--time", args.time, "Time to render, seconds (nearest frame)");
    render->add_option("--frames", args.frames, "FIRST:LAST: render a PNG sequence into the -o folder");
    render->add_option("--camera", args.cameraDeg, "Camera angle around the origin, deg (0 = on +y)")
        ->capture_default_str();
    render->add_option("--elevation", args.elevationDeg, "Camera elevation, deg")->capture_default_str();
    render->add_option("--distance", args.distanceCm, "Camera distance, cm (default: fits the scene)");
    render->add_option("--preset", args.preset, "Camera preset: top or bottom");
    render->add_option("--show", args.show, "Objects to draw: puppet,axis,orbits,grid (the floor),shadows (the figures' on the floor),partner or all")
        ->capture_default_str();
    render->add_option("--figure", args.figure,
                       "Figure of the take(s): puppet, skeleton (the performer's, for takes read from BVH), both, body "
                       "(the performer's body, a smooth mannequin skinned to that skeleton) or mesh (the skinned mesh an "
                       "FBX, glTF or Collada take's file carries, moved by the take)")
        ->capture_default_str();
    render->add_option("--figure-b", args.figureB, "Figure of the second take (default: as --figure)");
    render->add_option("--size", args.size, "Image size WIDTHxHEIGHT")->capture_default_str();
    render->add_option("-o,--output", args.output, "PNG file, or the folder of a --frames sequence");
    render->add_option("--mp4", args.mp4, "Also encode the --frames sequence to this MP4 file (needs ffmpeg), from the frames once they are in the -o folder");
    render->add_option("--body", args.body, "Body description JSON (default: the shipped puppet)");
    render->add_option("--mesh", args.meshes, "PART=FILE: a mesh file (glTF, OBJ...) replacing a body part");
    render->add_option("--samples", args.samples, "Multisampling, 0..16")->capture_default_str();
    render->add_flag("--follow", args.follow,
                     "Carry the camera along the floor with the figures at every frame (a walking take stays in frame)");
    render->add_flag("--multimodal", args.multimodal,
                     "The thesis's multimodal display: the 3D view and the graphs with a moving time cursor in one picture "
                     "(-o FILE.png: one frame; -o FILE.mp4 or -o FOLDER: the whole take or --frames as MP4 or PNG frames)");
    render->add_option("--graphs", args.graphs,
                       "--multimodal graphs: all (24, two takes 48), part (6/12), dof (4/8) or single (1/2)")
        ->check(CLI::IsMember({"all", "part", "dof", "single"}))
        ->capture_default_str();
    render->add_option("--part", args.part, "--multimodal: the part of the part and single layouts (default: the first)");
    render->add_option("--dof", args.dof, "--multimodal: the DOF of the dof and single layouts (default: the first)");
    render->add_option("--ticks", args.ticks, "--multimodal graph ticks: thesis (values every 10, time every 2 s) or auto")
        ->check(CLI::IsMember({"thesis", "auto"}))
        ->capture_default_str();
    render->add_option("--fps", args.fps, "--multimodal video: frames per second (default: the take's rate)");
    render->add_flag("--overwrite", args.overwrite, "--multimodal PNG frames: replace the frame_*.png of an earlier export");
    render->add_flag("--kimono", args.kimono,
                     "Dress the puppet in its kimono simulated as cloth (the skirt and long sleeves swing with the motion; "
                     "the orbits then include the sleeve tips and the hem); the --cloth-* options set the cloth");
    addClothOptions(render, args.cloth);
}

} // namespace bunraku::app::cli
