#include "analysis/pipeline/stages.h"

// The kimono of one take, simulated on demand for the 3D view (one scheduler job per shown take).
namespace bunraku::analysis::pipeline {

StageKey kimonoKey(StageKey take, const BodyDescription& body, const ClothParameters& p)
{
    KeyBuilder builder("kimono");
    builder.add(take).add(std::int64_t(body.parts.size()));
    for (const BodyPart& part : body.parts) builder.add(part.name).add(Eigen::MatrixXd(part.fit.matrix()));
    // Every parameter of the one table of cloth limits, by name: a parameter added to the table
    // joins the key (stage_key_fields_test).
    for (const ClothParameterLimit& limit : clothParameterLimits()) builder.add(limit.name).add(p.*limit.member);
    return builder.key();
}

Result<KimonoSimulation> runKimono(const Take& take, const BodyDescription& body, const ClothParameters& parameters,
                                   const RunControl& control)
{
    auto simulation = simulateKimono(take, body, parameters, control);
    if (!simulation && simulation.error().code != ErrorCode::Cancelled)
        return makeError(simulation.error().code, "kimono of " + take.displayName() + ": " + simulation.error().message);
    return simulation;
}

} // namespace bunraku::analysis::pipeline
