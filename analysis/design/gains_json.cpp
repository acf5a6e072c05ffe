// The gains file (gains.json): every field checked when read.
#include "analysis/design/phrase_gains.h"

#include "analysis/io/atomic_file.h"
#include "analysis/io/json_text.h"

#include <nlohmann/json.hpp>

#include <cmath>
#include <set>
#include <sstream>

namespace bunraku::analysis {

namespace {

using nlohmann::json;

/// Reads fields of one JSON document, every error naming the file and the field.
struct GainsReader {
    std::string file;

    Error error(const std::string& where, const std::string& what) const
    {
        return makeError(ErrorCode::Parse, file + ": " + where + ": " + what);
    }

    /// A whole number in [low, high]: an integer, or a number without a fractional part.
    Result<long long> wholeNumber(const json& value, const std::string& where, long long low, long long high) const
    {
        const auto inRange = [&](long double v) { return v >= low && v <= high; };
        if (value.is_number_unsigned() && inRange(value.get<unsigned long long>())) return value.get<long long>();
        if (value.is_number_integer() && !value.is_number_unsigned() && inRange(value.get<long long>())) return value.get<long long>();
        if (value.is_number_float()) {
            const double v = value.get<double>();
            if (std::isfinite(v) && v == std::floor(v) && inRange(v)) return static_cast<long long>(v);
        }
        return error(where, "expected a whole number in [" + std::to_string(low) + ", " + std::to_string(high) + "], found " +
                                value.dump().substr(0, 40));
    }

    /// An optional finite number within +-limit; `fallback` when the key is missing.
    Result<double> number(const json& object, const char* key, const std::string& where, double fallback, double limit) const
    {
        const auto it = object.find(key);
        if (it == object.end()) return fallback;
        if (!it->is_number() || !std::isfinite(it->get<double>()) || std::fabs(it->get<double>()) > limit)
            return error(where + "." + key, "expected a finite number within +-" + json(limit).dump());
        return it->get<double>();
    }

    Result<std::string> text(const json& object, const char* key, const std::string& where, const std::string& fallback) const
    {
        const auto it = object.find(key);
        if (it == object.end()) return fallback;
        if (!it->is_string()) return error(where + "." + key, "expected a string");
        return it->get<std::string>();
    }
};

} // namespace

Status writeGainsJson(const GainSet& gains, const std::filesystem::path& file)
{
    json document;
    document["dofs"] = gains.dofNames;
    document["blend_frames"] = gains.blendFrames;
    document["convention"] = "thesis eqs. 5.22/5.23: g0 = a0_no/a0_em, g1 = A1_no/A1_em; design: mean_no/g0 (or mean_no + offset) + (x_no - mean_no)/g1";
    json phrases = json::array();
    for (const PhraseGains& phrase : gains.phrases) {
        json entries = json::array();
        for (std::size_t d = 0; d < phrase.dofs.size(); ++d) {
            const DofGain& g = phrase.dofs[d];
            entries.push_back({{"dof", d < gains.dofNames.size() ? gains.dofNames[d] : std::to_string(d)},
                               {"g0", g.g0},
                               {"g1", g.g1},
                               {"mode", g.dcMode == DcMode::Offset ? "offset" : "scale"},
                               {"offset", g.offset},
                               {"ac_mode", g.acMode == AcMode::Additive ? "additive" : "scale"},
                               {"harmonic_cos", g.harmonicCos},
                               {"harmonic_sin", g.harmonicSin},
                               {"reason", g.reason},
                               {"ill_conditioned", g.illConditioned},
                               {"ill_conditioned_reason", g.illConditionedReason},
                               {"a0_functional", g.a0Functional},
                               {"a0_emotional", g.a0Emotional},
                               {"A1_functional", g.a1Functional},
                               {"A1_emotional", g.a1Emotional}});
        }
        phrases.push_back({{"begin", phrase.begin}, {"end", phrase.end}, {"gains", entries}});
    }
    document["phrases"] = phrases;
    return io::writeFileAtomically(file, document.dump(2, ' ', false, json::error_handler_t::replace) + "\n");
}

Result<GainSet> parseGainsJson(const std::string& text, const std::string& sourceName)
{
    const GainsReader reader{sourceName};
    auto parsed = io::parseJsonText(text, sourceName, "expected a JSON gains document");
    if (!parsed) return parsed.error();
    const json document = std::move(parsed).value();
    if (!document.is_object()) return reader.error("top level", "expected a JSON object with dofs and phrases");
    GainSet gains;

    const auto dofs = document.find("dofs");
    if (dofs == document.end() || !dofs->is_array() || dofs->empty() || dofs->size() > 64)
        return reader.error("dofs", "expected a list of 1 to 64 DOF names");
    std::set<std::string> names;
    for (std::size_t d = 0; d < dofs->size(); ++d) {
        if (!(*dofs)[d].is_string()) return reader.error("dofs[" + std::to_string(d) + "]", "expected a string");
        gains.dofNames.push_back((*dofs)[d].get<std::string>());
        if (!names.insert(gains.dofNames.back()).second)
            return reader.error("dofs[" + std::to_string(d) + "]", "\"" + gains.dofNames.back() + "\" is named twice");
    }
    if (const auto blend = document.find("blend_frames"); blend != document.end()) {
        auto frames = reader.wholeNumber(*blend, "blend_frames", 0, kMaxBlendFrames);
        if (!frames) return frames.error();
        gains.blendFrames = int(*frames);
    }

    const auto phrases = document.find("phrases");
    if (phrases == document.end() || !phrases->is_array() || phrases->empty())
        return reader.error("phrases", "expected a non-empty list of phrases");
    for (std::size_t p = 0; p < phrases->size(); ++p) {
        const json& entry = (*phrases)[p];
        const std::string where = "phrases[" + std::to_string(p) + "]";
        if (!entry.is_object()) return reader.error(where, "expected an object {begin, end, gains}");
        PhraseGains phrase;
        const auto begin = entry.find("begin"), end = entry.find("end");
        if (begin == entry.end() || end == entry.end()) return reader.error(where, "expected \"begin\" and \"end\" frames");
        auto first = reader.wholeNumber(*begin, where + ".begin", 0, kMaxGainsFrame);
        if (!first) return first.error();
        auto last = reader.wholeNumber(*end, where + ".end", 0, kMaxGainsFrame);
        if (!last) return last.error();
        phrase.begin = Eigen::Index(*first);
        phrase.end = Eigen::Index(*last);
        if (phrase.begin >= phrase.end)
            return reader.error(where, "begin " + std::to_string(phrase.begin) + " must come before end " + std::to_string(phrase.end));
        const Eigen::Index expectedBegin = p == 0 ? 0 : gains.phrases.back().end;
        if (phrase.begin != expectedBegin)
            return reader.error(where, "begins at frame " + std::to_string(phrase.begin) + ", expected " +
                                           std::to_string(expectedBegin) +
                                           (p == 0 ? " (the first phrase starts the take)"
                                                   : " (where the previous phrase ends: phrases in order, without gaps or overlaps)"));
        const auto entries = entry.find("gains");
        if (entries == entry.end() || !entries->is_array() || entries->size() != gains.dofNames.size())
            return reader.error(where + ".gains", "expected one entry per DOF (" + std::to_string(gains.dofNames.size()) + ")");
        for (std::size_t d = 0; d < entries->size(); ++d) {
            const json& item = (*entries)[d];
            const std::string at = where + ".gains[" + std::to_string(d) + "]";
            if (!item.is_object()) return reader.error(at, "expected an object {dof, g0, g1, ...}");
            DofGain g;
            auto g0 = reader.number(item, "g0", at, 1.0, kMaxGainMagnitude);
            if (!g0) return g0.error();
            auto g1 = reader.number(item, "g1", at, 1.0, kMaxGainMagnitude);
            if (!g1) return g1.error();
            if (*g0 == 0.0 || *g1 == 0.0) return reader.error(at, "g0 and g1 must be non-zero");
            g.g0 = *g0;
            g.g1 = *g1;
            auto mode = reader.text(item, "mode", at, "scale");
            if (!mode) return mode.error();
            if (*mode != "scale" && *mode != "offset") return reader.error(at + ".mode", "expected \"scale\" or \"offset\"");
            g.dcMode = *mode == "offset" ? DcMode::Offset : DcMode::Scale;
            auto acMode = reader.text(item, "ac_mode", at, "scale");
            if (!acMode) return acMode.error();
            if (*acMode != "scale" && *acMode != "additive") return reader.error(at + ".ac_mode", "expected \"scale\" or \"additive\"");
            g.acMode = *acMode == "additive" ? AcMode::Additive : AcMode::Scale;
            double* fields[] = {&g.offset, &g.harmonicCos, &g.harmonicSin, &g.a0Functional, &g.a0Emotional, &g.a1Functional, &g.a1Emotional};
            static constexpr const char* keys[] = {"offset", "harmonic_cos", "harmonic_sin", "a0_functional", "a0_emotional",
                                                   "A1_functional", "A1_emotional"};
            for (std::size_t k = 0; k < std::size(keys); ++k) {
                auto value = reader.number(item, keys[k], at, 0.0, kMaxGainOffset);
                if (!value) return value.error();
                *fields[k] = *value;
            }
            auto reason = reader.text(item, "reason", at, "");
            if (!reason) return reason.error();
            g.reason = *reason;
            if (const auto ill = item.find("ill_conditioned"); ill != item.end()) {
                if (!ill->is_boolean()) return reader.error(at + ".ill_conditioned", "expected true or false");
                g.illConditioned = ill->get<bool>();
            }
            auto illReason = reader.text(item, "ill_conditioned_reason", at, "");
            if (!illReason) return illReason.error();
            g.illConditionedReason = *illReason;
            phrase.dofs.push_back(g);
        }
        gains.phrases.push_back(std::move(phrase));
    }
    return gains;
}

Result<GainSet> readGainsJson(const std::filesystem::path& file)
{
    auto text = io::readTextFile(file, io::kDocumentLimitBytes);
    if (!text) return text.error();
    return parseGainsJson(*text, file.string());
}

nlohmann::json illConditionedGainsJson(const std::vector<IllConditionedGain>& gains)
{
    nlohmann::json list = nlohmann::json::array();
    for (const IllConditionedGain& gain : gains)
        list.push_back({{"phrase", gain.phrase + 1},
                        {"begin", gain.begin},
                        {"end", gain.end},
                        {"dof", gain.dofName},
                        {"A1_functional", gain.a1Functional},
                        {"A1_emotional", gain.a1Emotional},
                        {"g1", gain.g1},
                        {"reason", gain.reason}});
    return list;
}

std::string illConditionedGainsText(const std::vector<IllConditionedGain>& gains)
{
    if (gains.empty()) return {};
    const double fraction = GainOptions{}.illConditionedFraction;
    std::ostringstream out;
    out << gains.size() << " ill-conditioned g1 (A1_em below " << fraction << " x A1_no; regularised to " << 1.0 / fraction << "):\n";
    for (const IllConditionedGain& gain : gains)
        out << "  phrase " << gain.phrase + 1 << " (frames " << gain.begin << "-" << gain.end << "), " << gain.dofName << ": "
            << gain.reason << "\n";
    return out.str();
}

} // namespace bunraku::analysis
