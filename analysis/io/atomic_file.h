#pragma once
/// Every file the program writes goes through writeFileAtomically: the content is written into
/// a hidden temporary file in the target's folder, flushed to the disk (fsync), renamed over
/// the target, and the folder is flushed too, so after a crash or power cut the target holds
/// either its old content or the new one, never a mix or nothing. Temporary files left by a
/// killed run are removed by the next write to the same place. Every file read whole goes
/// through readTextFile: regular files only (a FIFO or device is refused, never waited on) and
/// a size bound checked before anything is read. docs/RELIABILITY.md.

#include "analysis/core/result.h"

#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>

namespace bunraku::analysis::io {

/// Size bounds of the readers (bytes): take files (CSV, BVH, FASTRAK) and small documents
/// (corpus.json, projects, gains, warp curves, joint maps, body descriptions).
inline constexpr std::uintmax_t kTakeFileLimitBytes = std::uintmax_t(1) << 30;
inline constexpr std::uintmax_t kDocumentLimitBytes = std::uintmax_t(64) << 20;

/// The kinds of hidden siblings a write creates next to its target.
enum class TemporaryKind {
    Temporary, ///< the new content being written
    Old,       ///< a replaced folder on its way out
};

/// ".<leaf>.bunraku-tmp-<pid>-<n>" (or "-old-"): a hidden sibling of `leaf` named after this
/// process, unique within it. removeStaleTemporaries recognises these names.
std::string temporarySiblingName(std::string_view leaf, TemporaryKind kind = TemporaryKind::Temporary);

/// Removes the hidden siblings of `target` (files or folders named by temporarySiblingName) whose
/// process no longer runs: what a killed write left behind. Returns how many were removed.
int removeStaleTemporaries(const std::filesystem::path& target);

/// Writes `content` to `file` atomically and durably (temp file in the same folder, write,
/// fsync, rename, fsync of the folder). A symbolic link is followed; an existing file keeps its
/// permissions. Io errors name the file and the cause (disk full, permission, ...).
Status writeFileAtomically(const std::filesystem::path& file, std::string_view content);

/// Writes `content` into `file` inside a staging folder that nothing reads yet: created or
/// truncated, written and flushed to the disk (fsync), without a temporary of its own. Errors
/// name `shownName` (the file's final place).
Status writeStagedFile(const std::filesystem::path& file, std::string_view content, const std::string& shownName);

/// A fresh hidden folder beside `target` (named by temporarySiblingName, mode 0700) for a file
/// another program writes (ffmpeg); stale ones of killed runs are removed first. Remove it with
/// std::filesystem::remove_all when done.
Result<std::filesystem::path> makeTemporaryFolderBeside(const std::filesystem::path& target);

/// Flushes the complete file `complete` to the disk and renames it over `target` (in the same
/// file system), then flushes the target's folder: the move that publishes a file written
/// elsewhere.
Status moveIntoPlace(const std::filesystem::path& complete, const std::filesystem::path& target);

/// fsync of a folder (makes renames and new entries in it durable).
Status syncFolder(const std::filesystem::path& folder);

/// Ok when `file` is a regular file of at most `maxBytes` bytes; else NotFound or Io naming the
/// file and what it is (a folder, a FIFO, a device, too large).
Status checkReadableFile(const std::filesystem::path& file, std::uintmax_t maxBytes = kTakeFileLimitBytes);

/// The whole file as text. Refuses anything but a regular file and files larger than
/// `maxBytes` before reading; errors name the file.
Result<std::string> readTextFile(const std::filesystem::path& file, std::uintmax_t maxBytes = kTakeFileLimitBytes);

} // namespace bunraku::analysis::io
