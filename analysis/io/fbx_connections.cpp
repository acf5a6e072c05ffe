#include "analysis/io/fbx_connections.h"

#include <array>
#include <cstdint>
#include <cstring>
#include <map>
#include <string_view>
#include <utility>
#include <vector>

namespace bunraku::analysis::io {

namespace {

using Edge = std::pair<std::int64_t, std::int64_t>; ///< child (source) -> parent (destination)

constexpr std::string_view kBinaryMagic{"Kaydara FBX Binary  \0", 21};

template <typename T>
bool readLittle(std::string_view bytes, std::size_t at, T& value)
{
    if (at > bytes.size() || bytes.size() - at < sizeof(T)) return false;
    std::memcpy(&value, bytes.data() + at, sizeof(T));
    return true;
}

/// One binary FBX node record: its end offset, property count and bytes, name, and where its
/// properties and children start.
struct FbxRecord {
    std::uint64_t end = 0, properties = 0, propertyBytes = 0;
    std::string_view name;
    std::size_t propertiesAt = 0, childrenAt = 0;
};

/// Reads the record at `at` (`wide`: version 7500 and later, 64-bit offsets); false when it does
/// not fit the bytes or ends past `limit`.
bool readFbxRecord(std::string_view bytes, bool wide, std::size_t at, std::size_t limit, FbxRecord& record)
{
    const std::size_t headerSize = wide ? 25 : 13;
    if (wide) {
        if (!readLittle(bytes, at, record.end) || !readLittle(bytes, at + 8, record.properties) || !readLittle(bytes, at + 16, record.propertyBytes))
            return false;
    } else {
        std::uint32_t end = 0, properties = 0, propertyBytes = 0;
        if (!readLittle(bytes, at, end) || !readLittle(bytes, at + 4, properties) || !readLittle(bytes, at + 8, propertyBytes)) return false;
        record.end = end;
        record.properties = properties;
        record.propertyBytes = propertyBytes;
    }
    std::uint8_t nameLength = 0;
    if (!readLittle(bytes, at + headerSize - 1, nameLength)) return false;
    if (bytes.size() - (at + headerSize) < nameLength) return false;
    record.name = bytes.substr(at + headerSize, nameLength);
    record.propertiesAt = at + headerSize + nameLength;
    if (record.propertyBytes > bytes.size() - record.propertiesAt) return false;
    record.childrenAt = record.propertiesAt + std::size_t(record.propertyBytes);
    return record.end == 0 || (record.end > at && record.end <= limit && record.end >= record.childrenAt);
}

/// Binary FBX: the top-level "Connections" record's "C" children, each with a type string and
/// two integer ids. Returns false when the records cannot be walked (assimp then reports it).
bool binaryConnections(std::string_view bytes, std::vector<Edge>& edges)
{
    std::uint32_t version = 0;
    if (!readLittle(bytes, 23, version)) return false;
    const bool wide = version >= 7500; // 64-bit record offsets and counts
    using Record = FbxRecord;
    const auto readRecord = [&](std::size_t at, Record& record) { return readFbxRecord(bytes, wide, at, bytes.size(), record); };
    // The top-level records, from after the 27-byte header, until the null record.
    std::size_t at = 27;
    Record record;
    while (true) {
        if (!readRecord(at, record)) return false;
        if (record.end == 0) return true; // no Connections record: nothing to check
        if (record.name == "Connections") break;
        at = std::size_t(record.end);
    }
    const std::size_t connectionsEnd = std::size_t(record.end);
    for (std::size_t child = record.childrenAt; child < connectionsEnd;) {
        Record c;
        if (!readRecord(child, c)) return false;
        if (c.end == 0) break;
        if (std::size_t(c.end) > connectionsEnd) return false;
        if (c.name == "C" && c.properties >= 3) {
            // Properties: 'S' type, then two ids ('L' 64-bit, or 'I' 32-bit in old files).
            std::size_t p = c.propertiesAt;
            const std::size_t propertiesEnd = c.childrenAt;
            char type = 0;
            std::uint32_t length = 0;
            if (!readLittle(bytes, p, type) || type != 'S' || !readLittle(bytes, p + 1, length)) return false;
            if (length > propertiesEnd - std::min(propertiesEnd, p + 5)) return false;
            p += 5 + length;
            std::int64_t ids[2] = {0, 0};
            bool read = true;
            for (std::int64_t& id : ids) {
                if (!readLittle(bytes, p, type) || p >= propertiesEnd) return false;
                if (type == 'L') {
                    read = read && readLittle(bytes, p + 1, id);
                    p += 9;
                } else if (type == 'I') {
                    std::int32_t small = 0;
                    read = read && readLittle(bytes, p + 1, small);
                    id = small;
                    p += 5;
                } else {
                    read = false;
                }
                if (!read || p > propertiesEnd) return false;
            }
            edges.emplace_back(ids[0], ids[1]);
        }
        child = std::size_t(c.end);
    }
    return true;
}

/// FBX ASCII: the values after every `C:` key, tokenised as assimp's ASCII tokenizer does
/// (`;` comments, quoted strings, `,` `{` `}` and blanks between tokens, `:` ending a key).
void asciiConnections(std::string_view text, std::vector<Edge>& edges)
{
    static const std::array<bool, 256> delimiters = [] {
        std::array<bool, 256> table{};
        for (const char c : std::string_view(",;\" \t\r\n{}:")) table[std::uint8_t(c)] = true;
        return table;
    }();
    std::vector<std::string_view> values; // after the last key "C"
    bool inConnection = false;
    const auto finish = [&] {
        if (inConnection && values.size() >= 3) {
            std::int64_t ids[2] = {0, 0};
            for (int k = 0; k < 2; ++k) {
                const std::string_view token = values[std::size_t(k) + 1];
                std::size_t i = 0;
                bool negative = false;
                if (i < token.size() && (token[i] == '-' || token[i] == '+')) negative = token[i++] == '-';
                if (i == token.size()) return;
                std::uint64_t value = 0;
                for (; i < token.size(); ++i) {
                    if (token[i] < '0' || token[i] > '9' || value > (std::uint64_t(1) << 62)) return;
                    value = value * 10 + std::uint64_t(token[i] - '0');
                }
                ids[k] = negative ? -std::int64_t(value) : std::int64_t(value);
            }
            edges.emplace_back(ids[0], ids[1]);
        }
        values.clear();
    };
    std::size_t i = 0;
    while (i < text.size()) {
        const char c = text[i];
        if (c == ';') {
            while (i < text.size() && text[i] != '\n') ++i;
        } else if (c == '"') {
            const std::size_t start = ++i;
            while (i < text.size() && text[i] != '"') ++i;
            if (inConnection) values.push_back(text.substr(start, i - start));
            ++i;
        } else if (c == ',' || c == ' ' || c == '\t' || c == '\r' || c == '\n') {
            ++i;
        } else if (c == '{' || c == '}' || c == ':') { // ':' alone: a key without a name
            finish();
            inConnection = false;
            ++i;
        } else {
            // Every other byte (NUL too: found by fuzz_scene_take when it ended a word without
            // being consumed) belongs to a word, so each turn of the loop moves on.
            const std::size_t start = i++;
            while (i < text.size() && !delimiters[std::uint8_t(text[i])]) ++i;
            const std::string_view word = text.substr(start, i - start);
            if (i < text.size() && text[i] == ':') { // a key: the previous element ends
                finish();
                inConnection = word == "C";
                ++i;
            } else if (inConnection) {
                values.push_back(word);
            }
        }
    }
    finish();
}

std::string idText(std::int64_t id) { return std::to_string(id); }

/// Binary FBX: the offsets of "KTime" type strings of Objects > Model > Properties70 > P records.
void binaryModelTimeProperties(std::string_view bytes, std::vector<std::size_t>& offsets)
{
    std::uint32_t version = 0;
    if (!readLittle(bytes, 23, version)) return;
    const bool wide = version >= 7500;
    using Record = FbxRecord;
    const auto readRecord = [&](std::size_t at, std::size_t limit, Record& record) { return readFbxRecord(bytes, wide, at, limit, record); };
    // Calls `visit` for each child record of [from, to) until the null record; false when unreadable.
    const auto children = [&](std::size_t from, std::size_t to, const auto& visit) {
        for (std::size_t at = from; at < to;) {
            Record r;
            if (!readRecord(at, to, r)) return false;
            if (r.end == 0) return true;
            if (!visit(r)) return false;
            at = std::size_t(r.end);
        }
        return true;
    };
    children(27, bytes.size(), [&](const Record& top) {
        if (top.name != "Objects") return true;
        return children(top.childrenAt, std::size_t(top.end), [&](const Record& model) {
            if (model.name != "Model") return true;
            return children(model.childrenAt, std::size_t(model.end), [&](const Record& table) {
                if (table.name != "Properties70") return true;
                return children(table.childrenAt, std::size_t(table.end), [&](const Record& p) {
                    // 'S' name, then 'S' type.
                    std::size_t at = p.propertiesAt;
                    for (int k = 0; k < 2; ++k) {
                        char type = 0;
                        std::uint32_t length = 0;
                        if (!readLittle(bytes, at, type) || type != 'S' || !readLittle(bytes, at + 1, length)) return true;
                        if (at + 5 > p.childrenAt || length > p.childrenAt - (at + 5)) return true;
                        if (k == 1 && p.name == "P" && bytes.substr(at + 5, length) == "KTime") offsets.push_back(at + 5);
                        at += 5 + length;
                    }
                    return true;
                });
            });
        });
    });
}

/// FBX ASCII: the same, with the tokens of asciiConnections and the scopes their braces open.
void asciiModelTimeProperties(std::string_view text, std::vector<std::size_t>& offsets)
{
    static const std::array<bool, 256> delimiters = [] {
        std::array<bool, 256> table{};
        for (const char c : std::string_view(",;\" \t\r\n{}:")) table[std::uint8_t(c)] = true;
        return table;
    }();
    std::vector<std::string_view> scopes; // the keys whose braces are open
    std::string_view key;                  // the current element's key
    int values = 0;                        // values read after it
    const auto inModelProperties = [&] {
        return scopes.size() == 3 && scopes[0] == "Objects" && scopes[1] == "Model" && scopes[2] == "Properties70" && key == "P";
    };
    std::size_t i = 0;
    while (i < text.size()) {
        const char c = text[i];
        if (c == ';') {
            while (i < text.size() && text[i] != '\n') ++i;
        } else if (c == '"') {
            const std::size_t start = ++i;
            while (i < text.size() && text[i] != '"') ++i;
            if (values++ == 1 && inModelProperties() && text.substr(start, i - start) == "KTime") offsets.push_back(start);
            ++i;
        } else if (c == ',' || c == ' ' || c == '\t' || c == '\r' || c == '\n') {
            ++i;
        } else if (c == '{') {
            scopes.push_back(key);
            key = {};
            ++i;
        } else if (c == '}') {
            if (!scopes.empty()) scopes.pop_back();
            key = {};
            ++i;
        } else if (c == ':') {
            key = {};
            values = 0;
            ++i;
        } else {
            const std::size_t start = i++;
            while (i < text.size() && !delimiters[std::uint8_t(text[i])]) ++i;
            const std::string_view word = text.substr(start, i - start);
            if (i < text.size() && text[i] == ':') {
                key = word;
                values = 0;
                ++i;
            } else {
                ++values;
            }
        }
    }
}

} // namespace

std::optional<Error> checkFbxConnections(const std::string& bytes, const std::string& source)
{
    std::vector<Edge> edges;
    const std::string_view view(bytes);
    if (view.substr(0, kBinaryMagic.size()) == kBinaryMagic) {
        if (!binaryConnections(view, edges)) return std::nullopt;
    } else {
        asciiConnections(view, edges);
    }
    // Each object's parents (destinations); 0 is the scene's root.
    std::map<std::int64_t, std::vector<std::int64_t>> parents;
    for (const auto& [child, parent] : edges) {
        if (child == parent)
            return makeError(ErrorCode::Parse, source + ": FBX object " + idText(child) +
                                                   " is connected to itself (expected the objects' connections to form a tree)");
        if (parent != 0) parents[child].push_back(parent);
    }
    // Depth-first over every object's ancestors, without recursion: a cycle is an ancestor met
    // again on the current path; depth is the longest chain of ancestors.
    enum class State : std::uint8_t { New, OnPath, Done };
    std::map<std::int64_t, State> state;
    std::map<std::int64_t, int> depth; // longest ancestor chain above the object, when Done
    for (const auto& [start, unused] : parents) {
        (void)unused;
        if (state[start] == State::Done) continue;
        std::vector<std::pair<std::int64_t, std::size_t>> path{{start, 0}};
        state[start] = State::OnPath;
        while (!path.empty()) {
            auto& [object, next] = path.back();
            const auto found = parents.find(object);
            const std::vector<std::int64_t>* above = found == parents.end() ? nullptr : &found->second;
            if (above && next < above->size()) {
                const std::int64_t parent = (*above)[next++];
                State& parentState = state[parent];
                if (parentState == State::OnPath)
                    return makeError(ErrorCode::Parse, source + ": FBX object " + idText(parent) +
                                                           " is connected below itself (expected the objects' connections to form a tree)");
                if (parentState == State::New) {
                    parentState = State::OnPath;
                    path.emplace_back(parent, 0);
                }
                continue;
            }
            int longest = 0;
            if (above)
                for (const std::int64_t parent : *above) longest = std::max(longest, depth[parent] + 1);
            if (longest > kMaxFbxConnectionDepth)
                return makeError(ErrorCode::Parse, source + ": FBX object " + idText(object) + " is connected more than " +
                                                       std::to_string(kMaxFbxConnectionDepth) + " levels deep (expected at most that)");
            depth[object] = longest;
            state[object] = State::Done;
            path.pop_back();
        }
    }
    return std::nullopt;
}

} // namespace bunraku::analysis::io

namespace bunraku::analysis::io {

std::vector<std::size_t> fbxModelTimeProperties(const std::string& bytes)
{
    std::vector<std::size_t> offsets;
    const std::string_view view(bytes);
    if (view.substr(0, kBinaryMagic.size()) == kBinaryMagic)
        binaryModelTimeProperties(view, offsets);
    else
        asciiModelTimeProperties(view, offsets);
    return offsets;
}

} // namespace bunraku::analysis::io
