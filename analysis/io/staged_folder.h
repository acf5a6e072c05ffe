#pragma once
/// Folder outputs (corpora, analysis outputs, PNG sequences) are built in a hidden folder beside
/// the target and swapped in with one atomic rename (Linux RENAME_EXCHANGE), so the target holds
/// the old folder or the new one, never a mix. Each folder written this way carries a manifest
/// (kWrittenFilesManifest: every file's path, size and FNV-1a hash); an existing folder is only
/// replaced when it holds nothing but those files, unchanged. Anything else in it (a user's
/// notes, a file edited since) makes the write fail with a message naming those files, before
/// anything is written. docs/RELIABILITY.md.

#include "analysis/core/result.h"

#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace bunraku::analysis::io {

/// The manifest of a folder this program wrote (hidden, JSON).
inline constexpr const char* kWrittenFilesManifest = ".bunraku-files.json";

/// 64-bit FNV-1a of `bytes` (the manifest's content check).
std::uint64_t fnv1a64(std::string_view bytes);

/// The files in `folder` (relative paths, sorted) that its manifest does not list with their
/// size and hash: what replacing the folder would destroy. Empty for a missing or empty folder;
/// every file of a folder without a manifest.
std::vector<std::string> foreignFiles(const std::filesystem::path& folder);

/// Ok when `target` may be replaced by a folder output (see foreignFiles); else an Io error
/// naming the target and its foreign files.
Status checkReplaceableFolder(const std::filesystem::path& target);

class StagedFolder {
public:
    /// Checks that `target` may be replaced (checkReplaceableFolder; a file of that name is
    /// refused), removes what killed runs left beside it and creates the hidden staging folder.
    static Result<StagedFolder> begin(const std::filesystem::path& target);

    StagedFolder(StagedFolder&& other) noexcept;
    StagedFolder& operator=(StagedFolder&&) = delete;
    StagedFolder(const StagedFolder&) = delete;
    StagedFolder& operator=(const StagedFolder&) = delete;
    /// Removes the staging folder and everything in it unless committed.
    ~StagedFolder();

    /// The folder being replaced (absolute, normalised).
    const std::filesystem::path& target() const { return m_target; }
    /// The hidden staging folder the new content is built in.
    const std::filesystem::path& path() const { return m_stage; }

    /// Writes `relative` (a path inside the folder, subfolders created) into the stage, flushed
    /// to the disk, and records it in the manifest. Errors name the target's file.
    Status writeFile(const std::filesystem::path& relative, std::string_view content);

    /// Records in the manifest a file another writer (an atomic, durable one) already wrote at
    /// `relative` inside the stage (path()), read once for its size and hash.
    Status recordFile(const std::filesystem::path& relative);

    /// Copies every regular file under `source` into `relative` inside the stage (recorded in the
    /// manifest); anything else in `source` (a link, a FIFO) is refused with its name.
    Status copyFolder(const std::filesystem::path& source, const std::filesystem::path& relative);

    /// Writes the manifest, flushes the stage and swaps it in place of the target; the old folder
    /// is removed after the swap. Checks again that the target holds no foreign files.
    Status commit();

private:
    StagedFolder(std::filesystem::path target, std::filesystem::path stage);
    /// `relative` normalised when it names a file inside the folder and the folder is not yet
    /// committed; else the error naming the target's file.
    Result<std::filesystem::path> stagedName(const std::filesystem::path& relative) const;
    /// Lists `name` in the manifest (once) with the content's size and hash.
    void record(const std::string& name, std::string_view content);

    struct Entry {
        std::string path;
        std::uintmax_t size = 0;
        std::uint64_t hash = 0;
    };

    std::filesystem::path m_target;
    std::filesystem::path m_stage;
    std::vector<Entry> m_entries;
    bool m_committed = false;
};

} // namespace bunraku::analysis::io
