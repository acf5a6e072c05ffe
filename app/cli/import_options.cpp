#include "app/cli/import_options.h"

#include "analysis/io/text_format.h"

#include <algorithm>

namespace bunraku::app::cli {

namespace io = analysis::io;

void addImportOptions(CLI::App* command, ImportArguments& arguments, bool withLayout)
{
    command->add_option("--joints", arguments.joints,
                        "BVH part map, e.g. head=Head,shoulder=Chest,arm=LowerArm_R,hand=Hand_R (parts not named are "
                        "mapped automatically, by joint names, then by the skeleton's shape)");
    command->add_option("--joint-map", arguments.jointMapFile,
                        "BVH part map as a JSON file {\"head\": ..., \"shoulder\": ..., \"arm\": ..., \"hand\": ...}");
    command->add_option("--side", arguments.side, "BVH: the limbs the puppet's arm and hand follow: right or left")
        ->check(CLI::IsMember({"right", "left"}))
        ->capture_default_str();
    command->add_option("--up-axis", arguments.upAxis, "BVH up axis: auto, y or z")
        ->check(CLI::IsMember({"auto", "y", "z"}))
        ->capture_default_str();
    command->add_option("--units", arguments.units,
                        "BVH length unit: auto (from the skeleton's height: metres, millimetres or cm), cm, m, mm or in")
        ->check(CLI::IsMember({"auto", "cm", "m", "mm", "in"}))
        ->capture_default_str();
    if (withLayout)
        command->add_flag("--all-joints", arguments.allJoints, "BVH: keep every joint (6 channels each) instead of the 4 puppet parts");
    command->add_option("--rate", arguments.rateHz,
                        "Sample rate in Hz, in (0, 1000000] (CSV without time_s; FASTRAK, default 5; FBX/glTF/Collada without a rate of "
                        "their own and with keys not uniform in time, default 30)");
    command->add_option("--animation", arguments.animation, "FBX/glTF/Collada: the animation to read, by name or 0-based index (default: the first)");
    command->add_option("--fastrak-units", arguments.fastrakUnits, "FASTRAK position unit: cm or in")
        ->check(CLI::IsMember({"cm", "in"}))
        ->capture_default_str();
}

io::ImportOptions importOptions(const ImportArguments& arguments, const std::string& path)
{
    io::ImportOptions options;
    io::JointMap map;
    if (!arguments.jointMapFile.empty()) map = unwrap(io::readJointMapJson(arguments.jointMapFile));
    if (!arguments.joints.empty()) map = unwrap(io::parseJointMap(arguments.joints, map));
    const bool anyJoint = std::any_of(map.joints.begin(), map.joints.end(), [](const std::string& j) { return !j.empty(); });
    if (anyJoint) options.bvh.jointMap = map;
    options.bvh.side = arguments.side == "left" ? analysis::BodySide::Left : analysis::BodySide::Right;
    options.bvh.upAxis = arguments.upAxis == "y" ? io::BvhUpAxis::Y : arguments.upAxis == "z" ? io::BvhUpAxis::Z : io::BvhUpAxis::Auto;
    options.bvh.guessUnits = arguments.units == "auto";
    options.bvh.unitScale = arguments.units == "m" ? 100.0 : arguments.units == "mm" ? 0.1 : arguments.units == "in" ? 2.54 : 1.0;
    options.bvhLayout = arguments.allJoints ? io::BvhTakeLayout::AllJoints : io::BvhTakeLayout::PuppetParts;
    if (arguments.rateHz) {
        if (!analysis::plausibleRate(*arguments.rateHz))
            throw CliError((path.empty() ? std::string() : path + ": ") + "--rate " + io::shortestNumber(*arguments.rateHz) + ": " +
                           analysis::rateExpectation());
        options.csv.rateHz = *arguments.rateHz;
        options.fastrak.rateHz = *arguments.rateHz;
        options.scene.rateHz = *arguments.rateHz;
    }
    options.scene.animation = arguments.animation;
    options.fastrak.units = arguments.fastrakUnits == "in" ? io::FastrakUnits::Inches : io::FastrakUnits::Centimetres;
    return options;
}

} // namespace bunraku::app::cli
