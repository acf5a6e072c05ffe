#include "analysis/normalise/average_take.h"

#include "analysis/skeleton/skeleton_blend.h"

#include <algorithm>
#include <string>

namespace bunraku::analysis {

namespace {

// y at x = 0..count-1 from a curve with non-decreasing abscissae, linear between points,
// clamped beyond the ends; of several points on one abscissa the first is used.
Eigen::VectorXd resampleMonotone(const Eigen::VectorXd& abscissa, const Eigen::VectorXd& ordinate, Eigen::Index count)
{
    Eigen::VectorXd out(count);
    const Eigen::Index n = abscissa.size();
    Eigen::Index k = 0;
    for (Eigen::Index t = 0; t < count; ++t) {
        const double x = double(t);
        if (x <= abscissa[0]) {
            out[t] = ordinate[0];
            continue;
        }
        if (x >= abscissa[n - 1]) {
            out[t] = ordinate[n - 1];
            continue;
        }
        while (k + 1 < n && abscissa[k + 1] < x) ++k; // abscissa[k] < x <= abscissa[k + 1]
        const double span = abscissa[k + 1] - abscissa[k];
        const double f = span > 0 ? (x - abscissa[k]) / span : 1.0;
        out[t] = ordinate[k] + f * (ordinate[k + 1] - ordinate[k]);
    }
    return out;
}

} // namespace

namespace {

/// The checked base and the included takes other than the base, in the takes' order.
struct Members {
    const Take* base = nullptr;
    std::vector<int> others; ///< indices into the takes
    std::string names;       ///< "3,1,2,5": the base first
};

Result<Members> membersOf(const std::vector<const Take*>& takes, const AverageOptions& options)
{
    const int count = int(takes.size());
    if (count == 0) return makeError(ErrorCode::InvalidArgument, "average take: no takes given");
    if (options.baseTake < 0 || options.baseTake >= count)
        return makeError(ErrorCode::InvalidArgument, "average take: base take index " + std::to_string(options.baseTake)
                                                         + " is not in 0.." + std::to_string(count - 1));
    std::vector<bool> included(std::size_t(count), true);
    for (int excluded : options.excludedTakes) {
        if (excluded < 0 || excluded >= count)
            return makeError(ErrorCode::InvalidArgument, "average take: excluded take index " + std::to_string(excluded)
                                                             + " is not in 0.." + std::to_string(count - 1));
        if (excluded == options.baseTake)
            return makeError(ErrorCode::InvalidArgument, "average take: the base take cannot be excluded");
        included[std::size_t(excluded)] = false;
    }
    Members members;
    members.base = takes[std::size_t(options.baseTake)];
    members.names = std::to_string(members.base->labels.takeIndex);
    for (int k = 0; k < count; ++k) {
        if (k == options.baseTake || !included[std::size_t(k)]) continue;
        members.others.push_back(k);
        members.names.push_back(',');
        members.names.append(std::to_string(takes[std::size_t(k)]->labels.takeIndex));
    }
    return members;
}

/// Thesis 3.7: t_bar = mean_k t_k, x_bar = mean_k x_k(t_k), the base contributing t_b itself;
/// angles as rotation coordinates about the base's mean part orientations. `normalised` holds
/// the other members normalised to the base, in the members' order.
Take averageOf(const std::vector<const Take*>& takes, const Members& members, const std::vector<const TakeNormalisation*>& normalised)
{
    const Take& base = *members.base;
    const Eigen::Index frames = base.frameCount();
    const double members_count = double(normalised.size() + 1);
    const RotationChart chart = normalised.empty() ? meanPartChart({&base}) : normalised.front()->chart;
    const Eigen::MatrixXd baseCoordinates = rotationCoordinates(base, chart);
    Take average;
    average.channels = base.channels;
    average.rateHz = base.rateHz;
    average.labels = base.labels;
    average.labels.takeIndex = 0;
    average.labels.source = "average of takes " + members.names + " (base " + std::to_string(base.labels.takeIndex) + ")";
    Eigen::MatrixXd coordinates(frames, base.channelCount());
    const Eigen::VectorXd baseTimes = Eigen::VectorXd::LinSpaced(frames, 0.0, double(frames - 1));
    for (Eigen::Index c = 0; c < base.channelCount(); ++c) {
        Eigen::VectorXd time = baseTimes;
        Eigen::VectorXd value = baseCoordinates.col(c);
        for (const TakeNormalisation* one : normalised) {
            time += one->correspondence.col(c).cast<double>();
            value += one->coordinates.col(c);
        }
        time /= members_count;
        value /= members_count;
        coordinates.col(c) = resampleMonotone(time, value, frames);
    }
    average.values = eulerFromRotationCoordinates(base, coordinates, chart, Eigen::RowVectorXd(base.values.row(0)));

    // The skeleton: per base frame every joint's mean rotation of the members at their body
    // times, shown at the mean body time t_bar and resampled onto the base's frames.
    bool skeletons = bool(base.skeleton);
    for (int k : members.others) skeletons = skeletons && takes[std::size_t(k)]->skeleton;
    if (skeletons) {
        std::vector<BlendMember> blend{{base.skeleton.get(), baseTimes, 1.0}};
        Eigen::VectorXd meanTime = baseTimes;
        for (std::size_t k = 0; k < members.others.size(); ++k) {
            blend.push_back({takes[std::size_t(members.others[k])]->skeleton.get(), normalised[k]->bodyTime, 1.0});
            meanTime += normalised[k]->bodyTime;
        }
        meanTime /= members_count;
        auto mean = meanSkeletalMotion(blend);
        // Takes on other skeletons average their channels only.
        if (mean) average.skeleton = resampleSkeletalMotion(**mean, resampleMonotone(meanTime, baseTimes, frames));
    }
    return average;
}

} // namespace

Result<Take> averageTake(const std::vector<const Take*>& takes, const AverageOptions& options, const RunControl& control)
{
    auto members = membersOf(takes, options);
    if (!members) return members.error();
    std::vector<const Take*> others;
    for (int k : members->others) others.push_back(takes[std::size_t(k)]);
    auto normalised = normaliseTakes(*members->base, others, options.normalise, control);
    if (!normalised) return normalised.error();
    std::vector<const TakeNormalisation*> pointers;
    for (const auto& one : *normalised) pointers.push_back(&one);
    Take average = averageOf(takes, *members, pointers);
    control.report(1.0);
    return average;
}

Result<Take> averageTakeFrom(const std::vector<const Take*>& takes, const AverageOptions& options,
                             const std::vector<TakeNormalisation>& toBase)
{
    auto members = membersOf(takes, options);
    if (!members) return members.error();
    if (toBase.size() != takes.size())
        return makeError(ErrorCode::InvalidArgument, "average take: " + std::to_string(toBase.size()) + " normalisations for " +
                                                         std::to_string(takes.size()) + " takes");
    std::vector<const TakeNormalisation*> pointers;
    for (int k : members->others) {
        const TakeNormalisation& one = toBase[std::size_t(k)];
        if (one.normalised.values.rows() != members->base->frameCount() ||
            one.normalised.values.cols() != members->base->channelCount() || one.correspondence.rows() != members->base->frameCount() ||
            one.correspondence.cols() != members->base->channelCount() || one.coordinates.rows() != members->base->frameCount() ||
            one.coordinates.cols() != members->base->channelCount() || one.bodyTime.size() != members->base->frameCount())
            return makeError(ErrorCode::InvalidArgument, "average take: the normalisation of take " + takes[std::size_t(k)]->displayName() +
                                                             " is not on the base take's frames and channels");
        pointers.push_back(&one);
    }
    return averageOf(takes, *members, pointers);
}

} // namespace bunraku::analysis
