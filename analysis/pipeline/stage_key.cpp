#include "analysis/pipeline/stage_key.h"

#include <bit>
#include <cstring>

namespace bunraku::analysis::pipeline {
namespace {

constexpr std::uint64_t kOffset = 0xcbf29ce484222325ull;
constexpr std::uint64_t kPrime = 0x100000001b3ull;

/// splitmix64's finaliser: every input bit reaches every output bit.
std::uint64_t avalanche(std::uint64_t x)
{
    x ^= x >> 30;
    x *= 0xbf58476d1ce4e5b9ull;
    x ^= x >> 27;
    x *= 0x94d049bb133111ebull;
    x ^= x >> 31;
    return x;
}

} // namespace

std::string StageKey::hex() const
{
    static const char digits[] = "0123456789abcdef";
    std::string text(16, '0');
    for (int i = 0; i < 16; ++i) text[std::size_t(15 - i)] = digits[(value >> (4 * i)) & 0xf];
    return text;
}

KeyBuilder::KeyBuilder(std::string_view stage) : m_state(kOffset) { add(stage); }

KeyBuilder& KeyBuilder::add(std::uint64_t word)
{
    m_state = (m_state ^ word) * kPrime;
    m_state ^= m_state >> 29;
    return *this;
}

KeyBuilder& KeyBuilder::add(double value) { return add(std::bit_cast<std::uint64_t>(value)); }

KeyBuilder& KeyBuilder::add(std::string_view text)
{
    add(std::uint64_t(text.size()));
    std::size_t i = 0;
    for (; i + 8 <= text.size(); i += 8) {
        std::uint64_t word = 0;
        std::memcpy(&word, text.data() + i, 8);
        add(word);
    }
    std::uint64_t tail = 0;
    std::memcpy(&tail, text.data() + i, text.size() - i);
    return add(tail);
}

KeyBuilder& KeyBuilder::add(const Eigen::MatrixXd& values)
{
    add(std::int64_t(values.rows()));
    add(std::int64_t(values.cols()));
    const double* data = values.data();
    for (Eigen::Index i = 0; i < values.size(); ++i) add(std::bit_cast<std::uint64_t>(data[i]));
    return *this;
}

StageKey KeyBuilder::key() const
{
    const std::uint64_t key = avalanche(m_state);
    return StageKey{key == 0 ? 1 : key}; // 0 means "no key"
}

StageKey takeKey(const Take& take)
{
    KeyBuilder builder("take");
    builder.add(take.values).add(take.rateHz);
    for (const auto& channel : take.channels) builder.add(channel.part).add(channel.dof).add(channel.unit);
    builder.add(take.labels.function).add(take.labels.emotion).add(take.labels.takeIndex).add(take.labels.source);
    return builder.key();
}

StageKey corpusKey(const Corpus& corpus)
{
    KeyBuilder builder("import");
    builder.add(corpus.name).add(corpus.rateHz).add(corpus.neutralEmotion).add(std::uint64_t(corpus.takes.size()));
    for (const auto& take : corpus.takes) builder.add(takeKey(take));
    return builder.key();
}

} // namespace bunraku::analysis::pipeline
