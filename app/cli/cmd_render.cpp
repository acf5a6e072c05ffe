// Subcommands: render (thesis 6: images of the puppet, motion axis and orbits, offscreen).
#include "app/cli/commands.h"

#include "analysis/body/body_description.h"
#include "analysis/io/take_reader.h"
#include "analysis/synth/demo_corpus.h"
#include "render/mesh_file.h"
#include "render/offscreen_renderer.h"
#include "render/take_scene.h"

#include <QGuiApplication>
#include <QImage>
#include <QStandardPaths>

#include <cstdlib>
#include <fstream>
#include <iostream>
#include <unistd.h>
#include <filesystem>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
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
    std::string show = "puppet,axis,grid,partner";
    std::string figure = "puppet";
    std::string figureB; // empty: as --figure
    std::string size = "1280x720";
    std::string output;
    std::string mp4;
    std::string body;
    std::vector<std::string> meshes;
    int samples = 4;
    bool json = false;
};

/// "demo:function/emotion/k" from the built-in synthetic corpus, or a take file.
analysis::Take loadTake(const std::string& spec, std::optional<analysis::synth::DemoCorpus>& demo)
{
    const std::string prefix = "demo:";
    if (spec.rfind(prefix, 0) == 0) {
        std::vector<std::string> fields;
        std::stringstream stream(spec.substr(prefix.size()));
        for (std::string field; std::getline(stream, field, '/');) fields.push_back(field);
        int index = 0;
        if (fields.size() != 3 || (index = std::atoi(fields[2].c_str())) <= 0)
            throw CliError("'" + spec + "': expected demo:FUNCTION/EMOTION/K, e.g. demo:greeting/friendly/1");
        if (!demo) demo = analysis::synth::generateDemoCorpus();
        const analysis::Take* take = demo->corpus.find(fields[0], fields[1], index);
        if (take == nullptr) {
            std::string functions, emotions;
            for (const auto& f : demo->corpus.functions()) functions += (functions.empty() ? "" : ", ") + f;
            for (const auto& e : demo->corpus.emotions()) emotions += (emotions.empty() ? "" : ", ") + e;
            throw CliError("'" + spec + "': no such demo take (functions: " + functions + "; emotions: " + emotions +
                           "; K = 1.." + std::to_string(demo->corpus.cell(demo->corpus.functions().front(),
                                                                         demo->corpus.emotions().front())
                                                             .size()) +
                           ")");
        }
        return *take;
    }
    return unwrap(analysis::io::readTakeFile(spec));
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
    visibility.puppet = visibility.axis = visibility.orbits = visibility.grid = visibility.partner = false;
    // Orbits named explicitly are drawn even with the puppet (the thesis shows them instead of it).
    visibility.orbitVisibility = render::OrbitVisibility::Always;
    std::stringstream stream(text);
    for (std::string name; std::getline(stream, name, ',');) {
        if (name == "puppet") visibility.puppet = true;
        else if (name == "axis") visibility.axis = true;
        else if (name == "orbits") visibility.orbits = true;
        else if (name == "grid") visibility.grid = true;
        else if (name == "partner") visibility.partner = true;
        else if (name == "all") visibility.puppet = visibility.axis = visibility.orbits = visibility.grid = visibility.partner = true;
        else if (!name.empty())
            throw CliError("--show: unknown object '" + name + "' (expected puppet, axis, orbits, grid, partner, all)");
    }
    return visibility;
}

render::FigureStyle parseFigure(const std::string& text, const std::string& option)
{
    if (text == "puppet") return render::FigureStyle::Puppet;
    if (text == "skeleton") return render::FigureStyle::Skeleton;
    if (text == "both") return render::FigureStyle::PuppetAndSkeleton;
    throw CliError(option + " '" + text + "': expected puppet, skeleton or both");
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

void saveImage(const QImage& image, const std::filesystem::path& file)
{
    if (image.isNull()) throw CliError("rendering produced no image");
    if (!image.save(QString::fromStdString(file.string()), "PNG"))
        throw CliError("could not write " + file.string());
}

void runRender(const RenderArguments& args)
{
    if (args.output.empty()) throw CliError("-o is required: the PNG file (or the folder with --frames)");
    if (args.frame && args.time) throw CliError("give --frame or --time, not both");
    if (!args.frames.empty() && (args.frame || args.time))
        throw CliError("--frames renders a sequence: drop --frame / --time");
    if (!args.mp4.empty() && args.frames.empty()) throw CliError("--mp4 needs --frames FIRST:LAST");
    if (!args.mp4.empty() && QStandardPaths::findExecutable(QStringLiteral("ffmpeg")).isEmpty())
        throw CliError("--mp4 needs ffmpeg on PATH, which was not found: install Debian's ffmpeg "
                       "(apt-get install ffmpeg) or drop --mp4 and encode the PNG frames yourself");
    if (args.samples < 0 || args.samples > 16) throw CliError("--samples: expected 0..16");
    const QSize size = parseSize(args.size);
    render::SceneVisibility visibility = parseShow(args.show);
    visibility.figures = {parseFigure(args.figure, "--figure"), parseFigure(args.figureB.empty() ? args.figure : args.figureB, "--figure-b")};
    std::optional<std::pair<long, long>> range;
    if (!args.frames.empty()) range = parseFrameRange(args.frames);

    std::optional<analysis::synth::DemoCorpus> demo;
    std::vector<analysis::Take> takes{loadTake(args.take, demo)};
    if (!args.takeB.empty()) takes.push_back(loadTake(args.takeB, demo));
    const analysis::BodyDescription body =
        args.body.empty() ? analysis::defaultBodyDescription() : unwrap(analysis::loadBodyDescription(args.body));

    render::TakeSceneOptions sceneOptions;
    sceneOptions.computeAxes = visibility.axis;
    render::SceneContent scene = unwrap(render::makeTakeScene(body, std::move(takes), sceneOptions));
    for (const std::string& entry : args.meshes) {
        const auto equals = entry.find('=');
        if (equals == std::string::npos || equals == 0)
            throw CliError("--mesh '" + entry + "': expected PART=FILE, e.g. head=scans/head.glb");
        scene.partMeshes[entry.substr(0, equals)] = unwrap(render::loadMeshFile(entry.substr(equals + 1)));
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
    summary["camera"] = {{"angle_deg", camera.angleDeg}, {"elevation_deg", camera.elevationDeg},
                         {"distance_cm", camera.distance}};
    for (const auto& slot : scene.takes) summary["takes"].push_back(slot.take.displayName());
    for (int s = 0; s < int(scene.takes.size()); ++s)
        summary["figures"].push_back({{"puppet", offscreen->renderer().puppetDrawn(s)}, {"skeleton", offscreen->renderer().skeletonDrawn(s)}});

    if (!range) {
        offscreen->makeCurrent();
        if (args.time) offscreen->renderer().setTime(*args.time);
        else offscreen->renderer().setFrame(args.frame.value_or(0));
        saveImage(offscreen->render(camera, size), args.output);
        summary["output"] = args.output;
        summary["frame"] = offscreen->renderer().frame(0);
    } else {
        const std::filesystem::path folder = args.output;
        std::error_code error;
        std::filesystem::create_directories(folder, error);
        if (error) throw CliError("could not create " + folder.string() + ": " + error.message());
        for (long f = range->first; f <= range->second; ++f) {
            offscreen->makeCurrent();
            offscreen->renderer().setFrame(f);
            char name[32];
            std::snprintf(name, sizeof name, "frame_%05ld.png", f - range->first);
            saveImage(offscreen->render(camera, size), folder / name);
        }
        summary["output"] = folder.string();
        summary["frames"] = {range->first, range->second};
        if (!args.mp4.empty()) {
            const double rate = scene.takes.front().take.rateHz;
            const std::string command = "ffmpeg -y -loglevel error -framerate " + std::to_string(rate) + " -i '" +
                                        (folder / "frame_%05d.png").string() +
                                        "' -c:v libx264 -pix_fmt yuv420p -vf 'pad=ceil(iw/2)*2:ceil(ih/2)*2' '" +
                                        args.mp4 + "'";
            if (std::system(command.c_str()) != 0) throw CliError("ffmpeg failed to write " + args.mp4);
            summary["mp4"] = args.mp4;
        }
    }
    if (args.json) printJson(summary);
}

} // namespace

void addRenderCommands(CommandSet& commands)
{
    auto args = std::make_shared<RenderArguments>();
    CLI::App* render = commands.root.add_subcommand(
        "render", "Render the puppet, motion axis and orbits of a take (or two side by side) to PNG offscreen");
    render->add_option("take", args->take, "Take file (.csv, .bvh, FASTRAK .txt) or demo:FUNCTION/EMOTION/K")
        ->required();
    render->add_option("--take-b", args->takeB, "A second take, shown to the right of the first");
    render->add_option("--frame", args->frame, "Frame to render (default 0)");
    render->add_option("--time", args->time, "Time to render, seconds (nearest frame)");
    render->add_option("--frames", args->frames, "FIRST:LAST: render a PNG sequence into the -o folder");
    render->add_option("--camera", args->cameraDeg, "Camera angle around the origin, deg (0 = on +y)")
        ->capture_default_str();
    render->add_option("--elevation", args->elevationDeg, "Camera elevation, deg")->capture_default_str();
    render->add_option("--distance", args->distanceCm, "Camera distance, cm (default: fits the scene)");
    render->add_option("--preset", args->preset, "Camera preset: top or bottom");
    render->add_option("--show", args->show, "Objects to draw: puppet,axis,orbits,grid,partner or all")
        ->capture_default_str();
    render->add_option("--figure", args->figure,
                       "Figure of the take(s): puppet, skeleton (the performer's, for takes read from BVH) or both")
        ->capture_default_str();
    render->add_option("--figure-b", args->figureB, "Figure of the second take (default: as --figure)");
    render->add_option("--size", args->size, "Image size WIDTHxHEIGHT")->capture_default_str();
    render->add_option("-o,--output", args->output, "PNG file, or the folder of a --frames sequence");
    render->add_option("--mp4", args->mp4, "Also encode the --frames sequence to this MP4 file (needs ffmpeg)");
    render->add_option("--body", args->body, "Body description JSON (default: the shipped puppet)");
    render->add_option("--mesh", args->meshes, "PART=FILE: a mesh file (glTF, OBJ...) replacing a body part");
    render->add_option("--samples", args->samples, "Multisampling, 0..16")->capture_default_str();
    render->add_flag("--json", args->json, "Print a JSON summary");
    render->callback([args] { runRender(*args); });
}

} // namespace bunraku::app::cli
