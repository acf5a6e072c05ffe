// Subcommands: axis, phase, gains, design, experiment design (thesis chapter 5).
#include "app/cli/commands.h"
#include "app/cli/chain_parameters.h"
#include "app/cli/take_output.h"
#include "app/cli/output_guard.h"

#include "analysis/axis/axis_channels.h"
#include "analysis/axis/inertia_axis.h"
#include "analysis/body/body_description.h"
#include "analysis/body/body_fit.h"
#include "analysis/core/puppet_layout.h"
#include "analysis/design/design_corpus.h"
#include "analysis/design/design_experiment.h"
#include "analysis/design/motion_design.h"
#include "analysis/io/corpus_io.h"
#include "analysis/io/take_csv.h"
#include "analysis/io/take_reader.h"
#include "analysis/pipeline/stage_parameters.h"
#include "analysis/pipeline/stages.h"
#include "analysis/report/experiment_tables.h"
#include "analysis/synth/demo_corpus.h"
#include "analysis/synth/demo_corpus_io.h"

#include <cmath>
#include <filesystem>
#include <iomanip>
#include <iostream>

namespace bunraku::app::cli {
namespace {

/// Options every chapter-5 command shares: which body and how its axis x is chosen.
struct AxisArguments {
    std::string body;
    an::AxisOptions options;
    bool allJoints = false;
};

void addAxisOptions(CLI::App* command, AxisArguments& arguments, bool readsTakes = true)
{
    if (readsTakes)
        addNamedParameter(command, "--segments", arguments.options.segments,
                          "The whole body's segment table (with --all-joints): de Leva's (1996) 'male' (default) or 'female'");
    if (readsTakes)
        command->add_flag("--all-joints", arguments.allJoints,
                      "Read a BVH, FBX, glTF or Collada take with every joint of its skeleton (6 channels each) instead of the "
                      "puppet's four parts: the axis is the performer's whole body, its segments from de Leva (1996)");
    command->add_option("--body", arguments.body, "Body description JSON (default: the shipped Bunraku puppet)")
        ->check(CLI::ExistingFile);
    addNamedParameter(command, "--front-back", arguments.options.frontBack,
                      "Axis x: 'shoulder' (the shoulder's facing, default) or 'principal' (thesis-literal principal axis)");
    command->add_option("--spacing", arguments.options.massPoints.spacing, "Mass point lattice step, cm (default 1)")
        ->transform(parameterCheck("axis.massSpacing"));
    addNamedParameter(command, "--masses", arguments.options.massPoints.source,
                      "Where the masses come from: 'model' (the modelled puppet's solid, default) or 'primitives' (the body "
                      "description's primitives); a --body with other parts than the puppet's uses its primitives");
}

/// A take file as the chapter-5 commands read it: every joint with --all-joints.
an::Take readAxisTake(const std::string& path, const AxisArguments& arguments)
{
    an::io::ImportOptions options;
    if (arguments.allJoints) options.bvhLayout = an::io::BvhTakeLayout::AllJoints;
    return unwrap(an::io::readTakeFile(path, options));
}

/// The body given with --body, else the pipeline's for `take` (pipeline::axisModelFor): the
/// performer's segments for a take of a skeleton's joints, else the shipped puppet, fitted to the
/// take's skeleton when it has one and `fitToSkeleton` (analysis/body/body_fit.h: the axis of a
/// BVH take is its performer's).
an::AxisModel axisModel(const AxisArguments& arguments, const an::Take* take = nullptr, bool fitToSkeleton = true)
{
    if (!arguments.body.empty()) return an::makeAxisModel(unwrap(an::loadBodyDescription(arguments.body)), arguments.options);
    if (take) return *unwrap(an::pipeline::axisModelFor(*take, arguments.options, fitToSkeleton));
    return an::makeAxisModel(an::defaultBodyDescription(), arguments.options);
}

an::MotionAxis motionAxis(const an::AxisModel& model, const an::Take& take, const AxisArguments& arguments)
{
    an::MotionAxis axis = unwrap(an::computeMotionAxis(model, take, arguments.options));
    if (const std::string report = axis.degeneracyReport(); !report.empty())
        std::cerr << "bunraku: warning: " << take.displayName() << ": " << report << "\n";
    return axis;
}

/// The emotional -> functional warp sampled per emotional frame, and its inverse per functional frame.
Eigen::VectorXd functionalToEmotional(const an::WarpCurve& curve, Eigen::Index functionalFrames)
{
    return an::invertMonotone(an::sampleWarp(curve), functionalFrames);
}

/// The two takes `phase` and `gains` compare: --reference (functional) and --sample (emotional).
struct TakePair {
    std::string reference;
    std::string sample;
};

/// The pair's takes as read.
struct AxisPair {
    an::Take reference, sample;
};

AxisPair readAxisPair(const TakePair& takes, const AxisArguments& arguments)
{
    return {readAxisTake(takes.reference, arguments), readAxisTake(takes.sample, arguments)};
}

/// A take's axis coordinates on its own body (not fitted to its skeleton), as phase and gains compare them.
Eigen::MatrixXd axisCoordinatesOf(const an::Take& take, const AxisArguments& arguments)
{
    return an::axisCoordinates(motionAxis(axisModel(arguments, &take, false), take, arguments).world_T_axis);
}

void addTakePairOptions(CLI::App* command, TakePair& takes)
{
    command->add_option("--reference", takes.reference, "Functional take")->required()->check(CLI::ExistingFile);
    command->add_option("--sample", takes.sample, "Emotional take")->required()->check(CLI::ExistingFile);
}

// ---- axis ---------------------------------------------------------------------------------

struct AxisCommandArguments {
    std::string take;
    std::string output;
    bool coordinates = false;
    bool json = false;
    AxisArguments axis;
};

void runAxis(const AxisCommandArguments& arguments)
{
    refuseOutputOverInputs(arguments.output, OutputKind::File, {arguments.take, arguments.axis.body});
    const an::Take take = readAxisTake(arguments.take, arguments.axis);
    const an::AxisModel model = axisModel(arguments.axis, &take);
    const an::MotionAxis axis = motionAxis(model, take, arguments.axis);
    an::Take out = an::axisTake(axis);
    if (arguments.coordinates) {
        out.channels = an::axisCoordinateChannels();
        out.values = an::axisCoordinates(axis.world_T_axis);
    }
    unwrap(an::io::writeTakeCsv(out, arguments.output));
    nlohmann::json degenerate = nlohmann::json::array();
    for (const an::DegenerateFrame& frame : axis.degenerateFrames)
        if (frame.affectsAxis) degenerate.push_back(frame.frame);
    nlohmann::json masses = nlohmann::json::object(), centres = nlohmann::json::object(), channels = nlohmann::json::array();
    for (std::size_t p = 0; p < model.parts.size() && p < model.body.parts.size(); ++p) {
        masses[model.body.parts[p].name] = model.parts[p].mass;
        centres[model.body.parts[p].name] = {model.parts[p].centre.x(), model.parts[p].centre.y(), model.parts[p].centre.z()};
    }
    for (const an::Channel& c : out.channels) channels.push_back(c.name());
    const nlohmann::json summary{{"take", take.displayName()},
                                 {"frames", axis.frameCount()},
                                 {"mass_g", axis.totalMass},
                                 {"mass_source", an::massSourceName(model.massSource)},
                                 {"part_masses_g", masses},
                                 {"part_centres_cm", centres},
                                 {"channels", channels},
                                 {"degenerate_frames", degenerate},
                                 {"output", arguments.output}};
    report(arguments.json, summary, [&] {
        std::cout << "axis of " << take.displayName() << ": " << axis.frameCount() << " frames, body mass " << std::fixed
                  << std::setprecision(0) << axis.totalMass << " g (masses from the "
                  << (model.massSource == an::MassSource::Model        ? "modelled puppet"
                      : model.massSource == an::MassSource::Segments ? "performer's segments, de Leva 1996"
                                                                     : "body's primitives")
                  << ") -> " << arguments.output << "\n";
    });
}

// ---- phase --------------------------------------------------------------------------------

/// The defaults: the axis stage's (stage_parameters.h), as `bunraku analyse` runs it.
struct PhaseArguments {
    MatchingArguments matching = matchingDefaults(pl::AxisParameters{});
    int maxScale = pl::AxisParameters{}.maxScale;
    int spacing = pl::AxisParameters{}.controlSpacing;
};

void addPhaseOptions(CLI::App* command, PhaseArguments& arguments)
{
    addMatchingOptions(command, arguments.matching, true);
    command->add_option("--max-scale", arguments.maxScale, "Scales 1..N")->transform(parameterCheck("axis.maxScale"))->capture_default_str();
    // --weight, the old name of --approximation-weight here, is kept out of the help (`emotion
    // --weight` is the emotion weight).
    command->add_option("--weight", arguments.matching.options.approximationWeight, "Old name of --approximation-weight")
        ->transform(parameterCheck("axis.approximationWeight"))
        ->group("");
    command->add_option("--control-spacing", arguments.spacing, "Frames between warp control points")
        ->transform(parameterCheck("axis.controlSpacing"))
        ->capture_default_str();
}

an::PhaseOptions phaseOptions(const PhaseArguments& arguments)
{
    an::PhaseOptions options;
    options.match = arguments.matching.options;
    options.match.scales = an::integerScales(arguments.maxScale);
    options.controlPointSpacing = arguments.spacing;
    return options;
}

struct PhaseCommandArguments {
    TakePair takes;
    std::string output;
    bool json = false;
    AxisArguments axis;
    PhaseArguments phase;
};

void runPhase(const PhaseCommandArguments& arguments)
{
    const TakePair& takes = arguments.takes;
    refuseOutputOverInputs(arguments.output, OutputKind::File, {takes.reference, takes.sample, arguments.axis.body});
    const auto [reference, sample] = readAxisPair(takes, arguments.axis);
    const Eigen::MatrixXd functional = axisCoordinatesOf(reference, arguments.axis);
    auto extracted = an::extractPhase(functional, axisCoordinatesOf(sample, arguments.axis), phaseOptions(arguments.phase));
    if (!extracted) throw CliError(takes.sample + " against " + takes.reference + ": " + extracted.error().message);
    const an::PhaseResult phase = std::move(extracted).value();
    unwrap(an::writeWarpCsv(phase.curve, arguments.output));
    const Eigen::VectorXd identity = Eigen::VectorXd::LinSpaced(phase.emotionalToFunctional.size(), 0.0,
                                                                 double(phase.emotionalToFunctional.size() - 1));
    const double meanShift = (phase.emotionalToFunctional - identity).cwiseAbs().mean();
    nlohmann::json points = nlohmann::json::array();
    for (const an::WarpPoint& p : phase.curve.points) points.push_back({p.output, p.source});
    const nlohmann::json summary{
        {"reference", reference.displayName()},
        {"sample", sample.displayName()},
        {"control_points", points},
        {"correspondence", std::vector<int>(phase.correspondence.data(), phase.correspondence.data() + phase.correspondence.size())},
        {"mean_abs_shift_frames", meanShift},
        {"cost", phase.cost},
        {"output", arguments.output}};
    report(arguments.json, summary, [&] {
        std::cout << "phase of " << sample.displayName() << " against " << reference.displayName() << ": "
                  << phase.curve.points.size() << " control points, mean |shift| " << std::fixed << std::setprecision(2)
                  << meanShift << " frames -> " << arguments.output << "\n";
    });
}

// ---- gains --------------------------------------------------------------------------------

struct GainsCommandArguments {
    TakePair takes;
    std::string warp;
    std::string phrases;
    std::string output;
    bool json = false;
    AxisArguments axis;
};

void runGains(const GainsCommandArguments& arguments)
{
    refuseOutputOverInputs(arguments.output, OutputKind::File,
                           {arguments.takes.reference, arguments.takes.sample, arguments.warp, arguments.axis.body});
    const auto [reference, sample] = readAxisPair(arguments.takes, arguments.axis);
    const an::WarpCurve warp = unwrap(an::readWarpCsv(arguments.warp));
    const Eigen::MatrixXd functional = axisCoordinatesOf(reference, arguments.axis);
    const Eigen::MatrixXd emotional = axisCoordinatesOf(sample, arguments.axis);
    const std::vector<Eigen::Index> boundaries = arguments.phrases.empty()
                                                     ? an::suggestPhraseBoundaries(functional)
                                                     : unwrap(an::parsePhraseBoundaries(arguments.phrases, functional.rows()));
    an::WarpCurve curve = warp;
    curve.outputFrames = emotional.rows();
    const an::GainSet gains =
        unwrap(an::extractGainsWithWarp(functional, emotional, functionalToEmotional(curve, functional.rows()), boundaries));
    unwrap(an::writeGainsJson(gains, arguments.output));
    std::vector<std::string> reasons;
    for (const an::PhraseGains& phrase : gains.phrases)
        for (const an::DofGain& gain : phrase.dofs)
            if (!gain.reason.empty()) reasons.push_back(gain.reason);
    const std::vector<an::IllConditionedGain> illConditioned = an::illConditionedGains(gains);
    const nlohmann::json summary{{"phrases", boundaries},
                                 {"notes", reasons},
                                 {"output", arguments.output},
                                 {"ill_conditioned", an::illConditionedGainsJson(illConditioned)}};
    report(arguments.json, summary, [&] {
        std::cout << gains.phrases.size() << " phrases (boundaries";
        for (Eigen::Index b : boundaries) std::cout << " " << b;
        std::cout << (arguments.phrases.empty() ? ", suggested at minima of the axis speed" : "") << ") -> " << arguments.output
                  << "\n";
        for (const std::string& reason : reasons) std::cout << "  note: " << reason << "\n";
        std::cout << an::illConditionedGainsText(illConditioned);
    });
}

// ---- design -------------------------------------------------------------------------------

struct DesignCommandArguments {
    std::string take;
    std::string warp;
    std::string gains;
    std::string output;
    std::string axisOutput;
    bool json = false;
    AxisArguments axis;
    KimonoOutputArguments kimono;
};

void runDesign(const DesignCommandArguments& arguments)
{
    requireTakeOutput(arguments.output);
    requireKimonoOutput(arguments.kimono, arguments.output);
    for (const std::string& output : {arguments.output, arguments.axisOutput})
        refuseOutputOverInputs(output, OutputKind::File, {arguments.take, arguments.warp, arguments.gains, arguments.axis.body},
                               output == arguments.output ? "-o" : "--axis-output");
    if (arguments.output == arguments.axisOutput) throw CliError(arguments.output + ": -o and --axis-output name the same file");
    const an::Take take = readAxisTake(arguments.take, arguments.axis);
    const an::AxisModel model = axisModel(arguments.axis, &take);
    const an::DesignBasis basis = unwrap(an::prepareDesign(model, take, arguments.axis.options));
    const an::WarpCurve warp = arguments.warp.empty() ? an::identityWarp(take.frameCount()) : unwrap(an::readWarpCsv(arguments.warp));
    if (!warp.points.empty() && warp.points.back().source > double(take.frameCount() - 1) + 1e-9)
        throw CliError(arguments.warp + ": the warp reaches source frame " + std::to_string(warp.points.back().source) +
                       " but " + arguments.take + " has " + std::to_string(take.frameCount()) + " frames");
    an::GainSet gains;
    if (!arguments.gains.empty()) {
        gains = unwrap(an::readGainsJson(arguments.gains));
        if (gains.dofNames.size() != an::kAxisDofCount) throw CliError(arguments.gains + ": expected gains for the 6 axis DOF");
        if (!gains.phrases.empty() && gains.phrases.back().end != take.frameCount() - 1)
            throw CliError(arguments.gains + ": the phrases end at frame " + std::to_string(gains.phrases.back().end) + " but " +
                           arguments.take + " ends at " + std::to_string(take.frameCount() - 1));
    }
    const an::DesignedMotion designed = an::designMotion(basis, warp, gains);
    writeTakeOutput(designed.take, arguments.output, arguments.kimono.parameters());
    if (!arguments.axisOutput.empty()) {
        an::MotionAxis axis;
        axis.world_T_axis = designed.world_T_axis;
        axis.rateHz = designed.take.rateHz;
        axis.labels = designed.take.labels;
        unwrap(an::io::writeTakeCsv(an::axisTake(axis), arguments.axisOutput));
    }
    const nlohmann::json summary{{"frames", designed.take.frameCount()}, {"phrases", gains.phrases.size()}, {"output", arguments.output}};
    report(arguments.json, summary, [&] {
        std::cout << "designed " << designed.take.frameCount() << " frames from " << take.displayName() << " -> " << arguments.output
                  << "\n";
    });
}

// ---- experiment design --------------------------------------------------------------------

struct ExperimentArguments {
    std::string corpus;
    std::string means = "measured";
    an::preprocess::PositionAlignment position = an::preprocess::PositionAlignment::Rigid;
    bool json = false;
    AxisArguments axis;
    PhaseArguments phase;
};

void runExperiment(const ExperimentArguments& arguments)
{
    const an::synth::DemoGroundTruth truth = groundTruthOf(arguments.corpus);
    an::DesignCorpusOptions corpusOptions;
    corpusOptions.preprocess.positionAlignment = arguments.position;
    an::Corpus corpus;
    if (arguments.means == "measured") {
        corpus = unwrap(an::io::readCorpus(arguments.corpus));
    } else {
        corpusOptions.means = an::DesignMeans::Truth;
    }
    const std::vector<an::SyntheticDesignCell> designCells = unwrap(an::syntheticDesignCells(corpus, truth, corpusOptions));

    const an::AxisModel model = axisModel(arguments.axis);
    an::ExtractionOptions options;
    options.phase = phaseOptions(arguments.phase);
    nlohmann::json cells = nlohmann::json::array();
    if (!arguments.json) std::cout << rp::designExperimentHeader();
    for (const an::SyntheticDesignCell& designCell : designCells) {
        const rp::DesignExperimentCell cell =
            unwrap(rp::runDesignExperimentCell(model, designCell, options, arguments.axis.options));
        cells.push_back(rp::designExperimentCellJson(cell));
        if (!arguments.json) std::cout << rp::designExperimentCellText(cell); // line by line, as the cells are done
    }
    if (arguments.json) printJson({{"means", arguments.means}, {"cells", cells}});
}

} // namespace

void addMotionAxisCommands(CommandSet& commands)
{
    {
        auto [command, arguments] = addCommand(commands.root, "axis", runAxis);
        command->add_option("TAKE", arguments.take, "Take file (.csv, .bvh, FASTRAK text)")->required()->check(CLI::ExistingFile);
        command->add_option("-o,--output", arguments.output, "Axis take CSV")->required()->type_name("FILE");
        command->add_flag("--coordinates", arguments.coordinates,
                          "Write the axis coordinates (centre + continuous rotation vector) instead of the thesis channels");
        addAxisOptions(command, arguments.axis);
    }
    {
        auto [command, arguments] = addCommand(commands.root, "phase", runPhase);
        addTakePairOptions(command, arguments.takes);
        command->add_option("-o,--output", arguments.output, "Warp curve CSV")->required()->type_name("FILE");
        addAxisOptions(command, arguments.axis);
        addPhaseOptions(command, arguments.phase);
    }
    {
        auto [command, arguments] = addCommand(commands.root, "gains", runGains);
        addTakePairOptions(command, arguments.takes);
        command->add_option("--warp", arguments.warp, "Warp curve CSV from `bunraku phase`")->required()->check(CLI::ExistingFile);
        command->add_option("--phrases", arguments.phrases,
                            "Phrase boundaries in functional frames, e.g. 0,40,105 (default: minima of the axis speed)");
        command->add_option("-o,--output", arguments.output, "Gains JSON")->required()->type_name("FILE");
        addAxisOptions(command, arguments.axis);
    }
    {
        auto [command, arguments] = addCommand(commands.root, "design", runDesign);
        command->add_option("TAKE", arguments.take, "Functional take")->required()->check(CLI::ExistingFile);
        command->add_option("--warp", arguments.warp, "Warp curve CSV (default: identity)")->check(CLI::ExistingFile);
        command->add_option("--gains", arguments.gains, "Gains JSON (default: no scaling)")->check(CLI::ExistingFile);
        command->add_option("-o,--output", arguments.output, "Designed take (.bvh, .glb or .csv)")->required()->type_name("FILE");
        command->add_option("--axis-output", arguments.axisOutput, "Also write the designed axis take (CSV)");
        addAxisOptions(command, arguments.axis);
        addKimonoOutputOptions(command, arguments.kimono);
    }
    {
        auto [command, arguments] = addCommand(commands.experiment, "design", runExperiment);
        command->add_option("CORPUS", arguments.corpus, "Demo corpus folder (with truth/ from `bunraku demo`)")
            ->required()
            ->check(CLI::ExistingDirectory);
        command->add_option("--means", arguments.means,
                            "'measured' (default): the preprocessed takes of each cell averaged by the thesis 3.7 average take; "
                            "'truth': the ground truth's noiseless cell motions")
            ->check(CLI::IsMember({"truth", "measured"}));
        addNamedParameter(command, "--position", arguments.position,
                          "Start-position step of the preprocessing (thesis 2.2-4): rigid (one translation per take, "
                          "default) or per-part");
        addAxisOptions(command, arguments.axis, false);
        addPhaseOptions(command, arguments.phase);
    }
}

} // namespace bunraku::app::cli
