#pragma once
/// Keys of pipeline stages: a 64-bit hash of everything a stage's result depends on - the key of
/// its input stage (or the content of the corpus) and its own parameters. Equal keys mean equal
/// results, so a result may be taken from a cache instead of recomputed; a stage whose key did
/// not change keeps running when something else changes.

#include "analysis/core/corpus.h"
#include "analysis/core/take.h"

#include <Eigen/Core>

#include <cstdint>
#include <string>
#include <string_view>

namespace bunraku::analysis::pipeline {

struct StageKey {
    std::uint64_t value = 0;
    bool operator==(const StageKey&) const = default;
    bool empty() const { return value == 0; }
    /// 16 lower-case hex digits.
    std::string hex() const;
};

/// Builds a key by mixing 64-bit words (FNV-1a over words, then a final avalanche): every value
/// added changes the key; the order matters.
class KeyBuilder {
public:
    /// Seeded with the stage's name, so two stages with equal inputs get different keys.
    explicit KeyBuilder(std::string_view stage);

    KeyBuilder& add(std::uint64_t word);
    KeyBuilder& add(std::int64_t value) { return add(std::uint64_t(value)); }
    KeyBuilder& add(int value) { return add(std::uint64_t(std::int64_t(value))); }
    KeyBuilder& add(bool value) { return add(std::uint64_t(value ? 1 : 2)); }
    /// The bits of the double (so -0.0 and 0.0 differ; a NaN never equals another key's NaN).
    KeyBuilder& add(double value);
    KeyBuilder& add(std::string_view text);
    KeyBuilder& add(const char* text) { return add(std::string_view(text)); }
    KeyBuilder& add(const std::string& text) { return add(std::string_view(text)); }
    KeyBuilder& add(StageKey key) { return add(key.value); }
    /// Shape and every coefficient.
    KeyBuilder& add(const Eigen::MatrixXd& values);

    StageKey key() const;

private:
    std::uint64_t m_state;
};

/// Values, rate, channels and labels of a take.
StageKey takeKey(const Take& take);
/// Every take, the rate, the neutral emotion and the name: the key of the import stage.
StageKey corpusKey(const Corpus& corpus);

} // namespace bunraku::analysis::pipeline
