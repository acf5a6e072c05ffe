#include "analysis/pipeline/stage_digest.h"

namespace bunraku::analysis::pipeline {
namespace {

/// A KeyBuilder that also takes the structs stage results are made of.
class Digest {
public:
    explicit Digest(std::string_view stage) : m_builder(stage) {}

    template <class T> Digest& operator<<(const T& value)
    {
        add(value);
        return *this;
    }
    StageKey key() const { return m_builder.key(); }

private:
    void add(double value) { m_builder.add(value); }
    void add(int value) { m_builder.add(value); }
    void add(bool value) { m_builder.add(value); }
    void add(Eigen::Index value) { m_builder.add(std::int64_t(value)); }
    void add(std::size_t value) { m_builder.add(std::uint64_t(value)); }
    void add(const std::string& text) { m_builder.add(text); }
    void add(StageKey key) { m_builder.add(key); }
    void add(const Eigen::MatrixXd& values) { m_builder.add(values); }
    void add(const Eigen::VectorXd& values) { m_builder.add(Eigen::MatrixXd(values)); }
    void add(const Eigen::MatrixX3d& values) { m_builder.add(Eigen::MatrixXd(values)); }
    void add(const Eigen::Vector3d& values) { m_builder.add(Eigen::MatrixXd(values)); }
    void add(const Eigen::VectorXi& values)
    {
        add(values.size());
        for (Eigen::Index i = 0; i < values.size(); ++i) add(values[i]);
    }
    void add(const Eigen::MatrixXi& values)
    {
        add(values.rows());
        add(values.cols());
        for (Eigen::Index i = 0; i < values.size(); ++i) add(values.data()[i]);
    }
    template <class T> void add(const std::vector<T>& values)
    {
        add(values.size());
        for (const auto& value : values) add(value);
    }
    void add(const std::vector<bool>& values)
    {
        add(values.size());
        for (bool value : values) add(value);
    }
    void add(const Take& take) { add(takeKey(take)); }
    void add(const Corpus& corpus) { add(corpusKey(corpus)); }
    void add(const RigidTransform& pose)
    {
        *this << pose.rotation.w() << pose.rotation.x() << pose.rotation.y() << pose.rotation.z();
        add(Eigen::Vector3d(pose.translation));
    }
    void add(const MatchResult& match) { *this << match.correspondence << match.smoothWarp << match.cost; }
    void add(const TakeNormalisation& one)
    {
        *this << one.normalised << one.coupling.sets << one.coupling.names << one.matches << one.correspondence << one.cost;
    }
    void add(const ReferenceSuggestion& s) { *this << s.takeIndex << s.outlier << s.activeFrames << s.startFrame << s.reason; }
    void add(const VarianceTable& v)
    {
        *this << v.takeNames << v.channelNames << v.before << v.after << v.totalBefore << v.totalAfter;
    }
    void add(const CellNormalisation& c)
    {
        *this << c.function << c.emotion << c.takeIndices << c.suggestion << int(c.reference.kind) << c.reference.takeIndex
              << c.referenceName << c.referenceTake << c.normalisations << c.variance << c.average << c.averageMembers
              << c.averageName;
    }
    void add(const preprocess::TakeReport& t)
    {
        *this << t.take << t.framesPadded << t.anglesUnwrapped << t.shiftFrames << t.isTimeReference << t.onsetFrame
              << t.isPositionReference << t.positionOffsets << t.branchTurns << t.headingOffsetDeg << t.isHeadingReference;
    }
    void add(const preprocess::CellTimeReference& r) { *this << r.function << r.emotion << r.takeIndex << r.automatic << r.onsetFrame; }
    void add(const Channel& channel) { *this << channel.part << channel.dof << channel.unit; }
    void add(const TakeLabels& labels) { *this << labels.function << labels.emotion << labels.takeIndex << labels.source; }
    void add(const Decomposition& d)
    {
        *this << d.rateHz << d.channels << d.neutralEmotion;
        for (const auto& f : d.functions) *this << f.function << f.values;
        for (const auto& e : d.emotions) *this << e.function << e.emotion << e.values;
        for (const auto& eta : d.fluctuations) *this << eta.labels << eta.values;
        *this << d.cellMeans;
    }
    void add(const ArmaModel& m) { *this << m.p << m.q << m.a << m.c << m.b << m.innovationVariance << m.fpe << m.iterations; }
    void add(const ArmaCellRow& row) { *this << row.function << row.emotion << row.takes << row.mean; }
    void add(const CellSpectra& s) { *this << s.function << s.emotion << s.frequencyHz << s.power; }
    void add(const WarpCurve& curve)
    {
        add(curve.points.size());
        for (const auto& point : curve.points) *this << point.output << point.source;
        add(curve.outputFrames);
    }
    void add(const DofGain& g)
    {
        *this << g.g0 << g.g1 << int(g.dcMode) << g.offset << int(g.acMode) << g.harmonicCos << g.harmonicSin << g.reason
              << g.a0Functional << g.a0Emotional << g.a1Functional << g.a1Emotional;
    }
    void add(const PhraseGains& p) { *this << p.begin << p.end << p.dofs; }
    void add(const GainSet& set) { *this << set.dofNames << set.phrases << set.blendFrames; }
    void add(const MotionAxis& axis)
    {
        *this << axis.world_T_axis << axis.moments << axis.totalMass << axis.rateHz << axis.labels;
        for (const auto& frame : axis.degenerateFrames)
            *this << frame.frame << int(frame.degeneracy) << frame.relativeGap << frame.affectsAxis;
    }
    void add(const FunctionAxis& f)
    {
        *this << f.function << f.boundaries;
        if (f.basis) {
            *this << f.basis->functional << f.basis->axis << f.basis->coordinates << f.basis->relative.parts;
            for (const auto& frame : f.basis->relative.axis_T_part) add(frame);
        }
    }
    void add(const CellAxis& c)
    {
        const PhaseResult& phase = c.extracted.phase;
        *this << c.function << c.emotion << c.coordinates << c.world_T_axis << phase.correspondence << phase.functionalToEmotional
              << phase.emotionalToFunctional << phase.curve << phase.cost << c.extracted.emotionalOnFunctionalTime
              << c.extracted.gains << c.designRelativeError << c.undesignedRelativeError;
    }

    KeyBuilder m_builder;
};

} // namespace

StageKey resultDigest(const PreprocessOutput& p)
{
    return (Digest("preprocess-result") << p.corpus << p.report.takes << p.report.timeReferences << p.report.paddedFrames).key();
}

StageKey resultDigest(const NormaliseOutput& n) { return (Digest("normalise-result") << n.cells << n.normalised).key(); }

StageKey resultDigest(const DecomposeOutput& d)
{
    Digest digest("decompose-result");
    digest << int(d.parameters.input) << int(d.parameters.method) << d.parameters.correlationLength << d.components << d.km2o.has_value();
    if (d.km2o)
        digest << d.km2o->components << d.km2o->correlationLength << d.km2o->candidateLengths << d.km2o->meanErrorPercent
               << d.km2o->cellErrorPercent << d.km2o->meanCellErrorPercent;
    return digest.key();
}

StageKey resultDigest(const FluctuationOutput& f)
{
    return (Digest("fluctuation-result") << f.channelNames << f.spectra << f.armaP << f.armaQ << f.armaTables << f.armaErrors).key();
}

StageKey resultDigest(const AxisOutput& a)
{
    Digest digest("axes-result");
    digest << a.functions << a.cells;
    if (!a.unavailable.empty()) digest << a.unavailable;
    return digest.key();
}

std::string ChainDigest::text() const
{
    std::string text;
    auto item = [&](const char* name, StageKey key) {
        if (key.empty()) return;
        if (!text.empty()) text += ' ';
        text += std::string(name) + "=" + key.hex();
    };
    item("preprocess", preprocess);
    item("normalise", normalise);
    item("decompose", decompose);
    item("fluctuations", fluctuations);
    item("axes", axes);
    return text;
}

ChainDigest chainDigest(const ChainResult& chain)
{
    ChainDigest digest;
    if (chain.preprocessed) digest.preprocess = resultDigest(*chain.preprocessed);
    if (chain.normalised) digest.normalise = resultDigest(*chain.normalised);
    if (chain.decomposed) digest.decompose = resultDigest(*chain.decomposed);
    if (chain.fluctuations) digest.fluctuations = resultDigest(*chain.fluctuations);
    if (chain.axes) digest.axes = resultDigest(*chain.axes);
    return digest;
}

} // namespace bunraku::analysis::pipeline
