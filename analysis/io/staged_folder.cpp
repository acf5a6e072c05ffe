#include "analysis/io/staged_folder.h"

#include "analysis/io/atomic_file.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <map>
#include <optional>
#include <system_error>

#include <fcntl.h>
#include <unistd.h>

namespace bunraku::analysis::io {

namespace {

namespace fs = std::filesystem;
using nlohmann::json;

constexpr const char* kManifestFormat = "bunraku-written-files";
constexpr int kManifestVersion = 1;
constexpr std::size_t kForeignNamesShown = 6;

struct Listed {
    std::uintmax_t size = 0;
    std::uint64_t hash = 0;
};

std::string hexOf(std::uint64_t value)
{
    char text[17];
    std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(value));
    return text;
}

/// The manifest's entries by relative path; nullopt when it is missing or unreadable.
std::optional<std::map<std::string, Listed>> readManifest(const fs::path& folder)
{
    std::map<std::string, Listed> listed;
    auto text = readTextFile(folder / kWrittenFilesManifest, kDocumentLimitBytes);
    if (!text) return std::nullopt;
    const json manifest = json::parse(*text, nullptr, false);
    if (!manifest.is_object()) return std::nullopt;
    const auto format = manifest.find("format");
    if (format == manifest.end() || *format != kManifestFormat) return std::nullopt;
    const auto files = manifest.find("files");
    if (files == manifest.end() || !files->is_array()) return std::nullopt;
    for (const json& entry : *files) {
        if (!entry.is_object()) continue;
        const auto path = entry.find("path"), size = entry.find("size"), hash = entry.find("fnv1a64");
        if (path == entry.end() || !path->is_string() || size == entry.end() || !size->is_number_unsigned() ||
            hash == entry.end() || !hash->is_string())
            continue;
        Listed item;
        item.size = size->get<std::uintmax_t>();
        try {
            item.hash = std::stoull(hash->get<std::string>(), nullptr, 16);
        } catch (const std::exception&) {
            continue;
        }
        listed[path->get<std::string>()] = item;
    }
    return listed;
}

/// FNV-1a of a file read in chunks; nullopt when it cannot be read.
std::optional<std::uint64_t> hashFile(const fs::path& file)
{
    const int fd = ::open(file.c_str(), O_RDONLY | O_CLOEXEC | O_NONBLOCK | O_NOCTTY);
    if (fd < 0) return std::nullopt;
    std::uint64_t hash = 14695981039346656037ull;
    char chunk[65536];
    while (true) {
        const ssize_t got = ::read(fd, chunk, sizeof chunk);
        if (got < 0 && errno == EINTR) continue;
        if (got < 0) {
            ::close(fd);
            return std::nullopt;
        }
        if (got == 0) break;
        for (ssize_t i = 0; i < got; ++i) {
            hash ^= static_cast<unsigned char>(chunk[i]);
            hash *= 1099511628211ull;
        }
    }
    ::close(fd);
    return hash;
}

/// Flushes every folder of the tree (new entries durable before the swap).
Status syncTree(const fs::path& root)
{
    std::error_code ec;
    for (fs::recursive_directory_iterator it(root, ec), end; !ec && it != end; it.increment(ec))
        if (it->is_directory(ec) && !it->is_symlink(ec))
            if (auto synced = syncFolder(it->path()); !synced) return synced;
    if (ec) return makeError(ErrorCode::Io, root.string() + ": cannot list the folder: " + ec.message());
    return syncFolder(root);
}

/// renameat2(2) with flags; false with errno set when the kernel or file system refuses them.
bool renameWithFlags(const fs::path& from, const fs::path& to, unsigned flags)
{
    return ::renameat2(AT_FDCWD, from.c_str(), AT_FDCWD, to.c_str(), flags) == 0;
}

} // namespace

std::uint64_t fnv1a64(std::string_view bytes)
{
    std::uint64_t hash = 14695981039346656037ull;
    for (const char c : bytes) {
        hash ^= static_cast<unsigned char>(c);
        hash *= 1099511628211ull;
    }
    return hash;
}

std::vector<std::string> foreignFiles(const fs::path& folder)
{
    std::vector<std::string> foreign;
    std::error_code ec;
    if (!fs::is_directory(folder, ec)) return foreign;
    const auto manifest = readManifest(folder);
    const bool manifestValid = manifest.has_value();
    const std::map<std::string, Listed> listed = manifest.value_or(std::map<std::string, Listed>{});
    for (fs::recursive_directory_iterator it(folder, ec), end; !ec && it != end; it.increment(ec)) {
        const fs::path relative = it->path().lexically_relative(folder);
        const std::string name = relative.generic_string();
        if (it->is_symlink(ec)) {
            foreign.push_back(name);
            continue;
        }
        if (it->is_directory(ec)) continue;
        if (name == kWrittenFilesManifest && manifestValid) continue;
        const auto found = listed.find(name);
        const bool regular = it->is_regular_file(ec);
        if (!regular || found == listed.end() || it->file_size(ec) != found->second.size || hashFile(it->path()) != found->second.hash)
            foreign.push_back(name);
    }
    if (ec) foreign.push_back("(a part of the folder that could not be listed: " + ec.message() + ")");
    std::sort(foreign.begin(), foreign.end());
    return foreign;
}

Status checkReplaceableFolder(const fs::path& target)
{
    std::error_code ec;
    if (!fs::exists(fs::symlink_status(target, ec))) return okStatus();
    if (fs::is_symlink(target, ec))
        return makeError(ErrorCode::Io, target.string() + ": is a symbolic link: refusing to replace it with a folder");
    if (!fs::is_directory(target, ec)) return makeError(ErrorCode::Io, target.string() + ": exists and is not a folder");
    const auto foreign = foreignFiles(target);
    if (foreign.empty()) return okStatus();
    std::string names;
    for (std::size_t i = 0; i < foreign.size() && i < kForeignNamesShown; ++i) names += (i ? ", " : "") + foreign[i];
    if (foreign.size() > kForeignNamesShown) names += " and " + std::to_string(foreign.size() - kForeignNamesShown) + " more";
    return makeError(ErrorCode::Io, target.string() + ": refusing to replace this folder: it holds " +
                                        std::to_string(foreign.size()) + (foreign.size() == 1 ? " file" : " files") +
                                        " this program did not write there (" + names +
                                        "); move them away or choose another output folder");
}

Result<StagedFolder> StagedFolder::begin(const fs::path& requested)
{
    std::error_code ec;
    fs::path target = fs::absolute(requested, ec).lexically_normal();
    if (ec) return makeError(ErrorCode::Io, requested.string() + ": cannot resolve the folder: " + ec.message());
    if (target.filename().empty()) target = target.parent_path(); // "out/" names "out"
    if (target.filename().empty() || target == target.root_path())
        return makeError(ErrorCode::InvalidArgument, requested.string() + ": not a folder that can be written");
    if (auto replaceable = checkReplaceableFolder(target); !replaceable) return replaceable.error();
    const fs::path parent = target.parent_path();
    fs::create_directories(parent, ec);
    if (ec) return makeError(ErrorCode::Io, parent.string() + ": cannot create the folder: " + ec.message());
    removeStaleTemporaries(target);
    const fs::path stage = parent / temporarySiblingName(target.filename().string());
    fs::create_directory(stage, ec);
    if (ec) return makeError(ErrorCode::Io, target.string() + ": cannot create a temporary folder beside it: " + ec.message());
    return StagedFolder(target, stage);
}

StagedFolder::StagedFolder(fs::path target, fs::path stage) : m_target(std::move(target)), m_stage(std::move(stage)) {}

StagedFolder::StagedFolder(StagedFolder&& other) noexcept
    : m_target(std::move(other.m_target)),
      m_stage(std::move(other.m_stage)),
      m_entries(std::move(other.m_entries)),
      m_committed(other.m_committed)
{
    other.m_stage.clear();
    other.m_committed = true;
}

StagedFolder::~StagedFolder()
{
    if (m_committed || m_stage.empty()) return;
    std::error_code ignored;
    fs::remove_all(m_stage, ignored);
}

Result<fs::path> StagedFolder::stagedName(const fs::path& relative) const
{
    const fs::path clean = relative.lexically_normal();
    const std::string name = clean.generic_string();
    const bool climbs = std::any_of(clean.begin(), clean.end(), [](const fs::path& part) { return part == ".."; });
    if (clean.empty() || clean.is_absolute() || climbs || name == kWrittenFilesManifest)
        return makeError(ErrorCode::InvalidArgument, (m_target / relative).string() + ": not a file name inside the folder");
    if (m_committed) return makeError(ErrorCode::InvalidArgument, (m_target / clean).string() + ": the folder is already written");
    return clean;
}

void StagedFolder::record(const std::string& name, std::string_view content)
{
    m_entries.erase(std::remove_if(m_entries.begin(), m_entries.end(), [&](const Entry& e) { return e.path == name; }),
                    m_entries.end());
    m_entries.push_back(Entry{name, content.size(), fnv1a64(content)});
}

Status StagedFolder::writeFile(const fs::path& relative, std::string_view content)
{
    auto clean = stagedName(relative);
    if (!clean) return clean.error();
    const fs::path file = m_stage / *clean;
    std::error_code ec;
    fs::create_directories(file.parent_path(), ec);
    if (ec) return makeError(ErrorCode::Io, (m_target / *clean).parent_path().string() + ": cannot create the folder: " + ec.message());
    if (auto written = writeStagedFile(file, content, (m_target / *clean).string()); !written) return written;
    record(clean->generic_string(), content);
    return okStatus();
}

Status StagedFolder::recordFile(const fs::path& relative)
{
    auto clean = stagedName(relative);
    if (!clean) return clean.error();
    auto content = readTextFile(m_stage / *clean, kTakeFileLimitBytes);
    if (!content) return content.error();
    record(clean->generic_string(), *content);
    return okStatus();
}

Status StagedFolder::copyFolder(const fs::path& source, const fs::path& relative)
{
    std::error_code ec;
    for (fs::recursive_directory_iterator it(source, ec), end; !ec && it != end; it.increment(ec)) {
        if (it->is_directory(ec) && !it->is_symlink(ec)) continue;
        auto content = readTextFile(it->path(), kTakeFileLimitBytes);
        if (!content) return content.error();
        if (auto written = writeFile(relative / it->path().lexically_relative(source), *content); !written) return written;
    }
    if (ec) return makeError(ErrorCode::Io, source.string() + ": cannot list the folder: " + ec.message());
    return okStatus();
}

Status StagedFolder::commit()
{
    if (m_committed) return okStatus();
    json files = json::array();
    for (const Entry& entry : m_entries) files.push_back({{"path", entry.path}, {"size", entry.size}, {"fnv1a64", hexOf(entry.hash)}});
    const json manifest{{"format", kManifestFormat}, {"version", kManifestVersion}, {"files", files}};
    if (auto written = writeStagedFile(m_stage / kWrittenFilesManifest, manifest.dump(1, ' ', false, json::error_handler_t::replace) + "\n",
                                       (m_target / kWrittenFilesManifest).string());
        !written)
        return written;
    if (auto synced = syncTree(m_stage); !synced) return synced;
    // Checked again: files may have appeared in the target while the new content was built.
    if (auto replaceable = checkReplaceableFolder(m_target); !replaceable) return replaceable.error();

    const fs::path parent = m_target.parent_path();
    std::error_code ec;
    const bool exists = fs::exists(fs::symlink_status(m_target, ec));
    fs::path old; // where the previous folder is after the swap
    if (exists) {
        if (renameWithFlags(m_stage, m_target, RENAME_EXCHANGE)) {
            old = m_stage; // the names swapped in one step: the stage's name now holds the old folder
        } else if (errno == EINVAL || errno == ENOSYS) {
            // No atomic exchange on this file system: move the old folder aside, then the new in.
            old = parent / temporarySiblingName(m_target.filename().string(), TemporaryKind::Old);
            if (::rename(m_target.c_str(), old.c_str()) != 0)
                return makeError(ErrorCode::Io, m_target.string() + ": cannot move the old folder aside: " + std::strerror(errno));
            if (::rename(m_stage.c_str(), m_target.c_str()) != 0) {
                const int code = errno;
                ::rename(old.c_str(), m_target.c_str());
                return makeError(ErrorCode::Io, m_target.string() + ": cannot move the new folder in place: " + std::strerror(code));
            }
        } else {
            return makeError(ErrorCode::Io, m_target.string() + ": cannot replace the folder: " + std::strerror(errno));
        }
    } else if (!renameWithFlags(m_stage, m_target, RENAME_NOREPLACE)) {
        if (errno != EINVAL && errno != ENOSYS)
            return makeError(ErrorCode::Io, m_target.string() + ": cannot move the new folder in place: " + std::strerror(errno));
        if (::rename(m_stage.c_str(), m_target.c_str()) != 0)
            return makeError(ErrorCode::Io, m_target.string() + ": cannot move the new folder in place: " + std::strerror(errno));
    }
    m_committed = true;
    const Status synced = syncFolder(parent);
    if (!old.empty()) fs::remove_all(old, ec); // a failure leaves a hidden folder the next write removes
    return synced;
}

} // namespace bunraku::analysis::io
