#include "analysis/core/corpus.h"

#include <algorithm>
#include <cmath>
#include <set>
#include <tuple>

namespace bunraku::analysis {
namespace {

void addUnique(std::vector<std::string>& list, const std::string& value)
{
    if (std::find(list.begin(), list.end(), value) == list.end()) list.push_back(value);
}

} // namespace

std::vector<std::string> Corpus::functions() const
{
    std::vector<std::string> result;
    for (const auto& t : takes) addUnique(result, t.labels.function);
    return result;
}

std::vector<std::string> Corpus::emotions() const
{
    std::vector<std::string> result;
    for (const auto& t : takes) addUnique(result, t.labels.emotion);
    auto neutral = std::find(result.begin(), result.end(), neutralEmotion);
    if (neutral != result.end()) std::rotate(result.begin(), neutral, neutral + 1);
    return result;
}

std::vector<const Take*> Corpus::cell(const std::string& function, const std::string& emotion) const
{
    std::vector<const Take*> result;
    for (const auto& t : takes)
        if (t.labels.function == function && t.labels.emotion == emotion) result.push_back(&t);
    std::stable_sort(result.begin(), result.end(),
                     [](const Take* a, const Take* b) { return a->labels.takeIndex < b->labels.takeIndex; });
    return result;
}

const Take* Corpus::find(const std::string& function, const std::string& emotion, int takeIndex) const
{
    for (const auto& t : takes)
        if (t.labels.function == function && t.labels.emotion == emotion && t.labels.takeIndex == takeIndex) return &t;
    return nullptr;
}

Status validateCorpus(const Corpus& corpus)
{
    std::set<std::tuple<std::string, std::string, int>> seen;
    for (const auto& take : corpus.takes) {
        if (auto s = validateTake(take); !s) return s;
        if (std::abs(take.rateHz - corpus.rateHz) > 1e-9 * corpus.rateHz)
            return makeError(ErrorCode::InvalidArgument, take.displayName() + ": rate " + std::to_string(take.rateHz) +
                                                             " Hz differs from the corpus rate " +
                                                             std::to_string(corpus.rateHz) + " Hz");
        if (take.channels != corpus.takes.front().channels)
            return makeError(ErrorCode::InvalidArgument,
                             take.displayName() + ": channels differ from the first take's");
        if (!seen.insert({take.labels.function, take.labels.emotion, take.labels.takeIndex}).second)
            return makeError(ErrorCode::InvalidArgument, take.displayName() + ": label used by two takes");
    }
    return okStatus();
}

} // namespace bunraku::analysis
