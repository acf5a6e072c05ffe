#include "analysis/io/atomic_file.h"

#include <atomic>
#include <cerrno>
#include <charconv>
#include <cstring>
#include <system_error>

#include <fcntl.h>
#include <signal.h>
#include <sys/stat.h>
#include <unistd.h>

namespace bunraku::analysis::io {

namespace {

namespace fs = std::filesystem;

constexpr std::string_view kTemporaryMarker = ".bunraku-tmp-";
constexpr std::string_view kOldMarker = ".bunraku-old-";

std::string errnoText(int code) { return std::generic_category().message(code); }

/// Why a write failed, for a person: the common causes named plainly.
std::string writeFailure(int code)
{
    switch (code) {
    case ENOSPC: return "the disk is full (" + errnoText(code) + ")";
    case EDQUOT: return "the disk quota is exceeded (" + errnoText(code) + ")";
    case EFBIG: return "the file is larger than this file system or the process's file size limit allows (" + errnoText(code) + ")";
    case EACCES:
    case EPERM: return "permission denied";
    case EROFS: return "the file system is read-only";
    default: return errnoText(code);
    }
}

/// The pid in a temporary sibling's name ("...-<pid>-<n>" after the marker), 0 when none.
long pidOfTemporary(std::string_view name, std::string_view leaf)
{
    // "." + leaf + marker + pid + "-" + counter
    if (name.size() < leaf.size() + 2 || name[0] != '.' || name.substr(1, leaf.size()) != leaf) return 0;
    std::string_view rest = name.substr(1 + leaf.size());
    if (rest.substr(0, kTemporaryMarker.size()) == kTemporaryMarker) rest.remove_prefix(kTemporaryMarker.size());
    else if (rest.substr(0, kOldMarker.size()) == kOldMarker) rest.remove_prefix(kOldMarker.size());
    else return 0;
    long pid = 0;
    const auto [end, ec] = std::from_chars(rest.data(), rest.data() + rest.size(), pid);
    if (ec != std::errc() || end == rest.data() || end == rest.data() + rest.size() || *end != '-' || pid <= 0) return 0;
    const std::string_view counter(end + 1, std::size_t(rest.data() + rest.size() - (end + 1)));
    if (counter.empty() || counter.find_first_not_of("0123456789") != std::string_view::npos) return 0;
    return pid;
}

bool processRuns(long pid) { return ::kill(pid_t(pid), 0) == 0 || errno == EPERM; }

/// Writes all of `content` to `fd`, retrying short writes and interruptions; 0 or an errno.
int writeAll(int fd, std::string_view content)
{
    const char* data = content.data();
    std::size_t left = content.size();
    while (left > 0) {
        const ssize_t written = ::write(fd, data, left);
        if (written < 0) {
            if (errno == EINTR) continue;
            return errno;
        }
        if (written == 0) return EIO;
        data += written;
        left -= std::size_t(written);
    }
    return 0;
}

} // namespace

std::string temporarySiblingName(std::string_view leaf, TemporaryKind kind)
{
    static std::atomic<unsigned> counter{0};
    // Built stepwise: GCC 12 warns falsely (-Wrestrict) on one concatenation expression.
    std::string name = ".";
    name += leaf;
    name += kind == TemporaryKind::Old ? kOldMarker : kTemporaryMarker;
    name += std::to_string(long(::getpid()));
    name += '-';
    name += std::to_string(counter.fetch_add(1));
    return name;
}

int removeStaleTemporaries(const fs::path& target)
{
    const fs::path folder = target.has_parent_path() ? target.parent_path() : fs::path(".");
    const std::string leaf = target.filename().string();
    if (leaf.empty()) return 0;
    std::error_code ec;
    fs::directory_iterator it(folder, ec);
    if (ec) return 0;
    int removed = 0;
    const long self = long(::getpid());
    for (; it != fs::directory_iterator(); it.increment(ec)) {
        if (ec) break;
        const std::string name = it->path().filename().string();
        const long pid = pidOfTemporary(name, leaf);
        if (pid == 0 || pid == self || processRuns(pid)) continue;
        std::error_code ignored;
        if (fs::remove_all(it->path(), ignored) > 0) ++removed;
    }
    return removed;
}

Status syncFolder(const fs::path& folder)
{
    const int fd = ::open(folder.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (fd < 0) return makeError(ErrorCode::Io, folder.string() + ": cannot open the folder to flush it: " + errnoText(errno));
    const int status = ::fsync(fd);
    const int code = errno;
    ::close(fd);
    // Some file systems cannot fsync a folder (EINVAL): their renames are as durable as they get.
    if (status != 0 && code != EINVAL)
        return makeError(ErrorCode::Io, folder.string() + ": cannot flush the folder: " + errnoText(code));
    return okStatus();
}

Status writeFileAtomically(const fs::path& requested, std::string_view content)
{
    std::error_code ec;
    fs::path file = requested;
    if (fs::is_symlink(file, ec)) {
        const fs::path resolved = fs::read_symlink(file, ec);
        if (!ec) file = resolved.is_absolute() ? resolved : file.parent_path() / resolved;
    }
    const fs::path folder = file.has_parent_path() ? file.parent_path() : fs::path(".");
    if (!fs::is_directory(folder, ec))
        return makeError(ErrorCode::Io, requested.string() + ": cannot write, folder " + folder.string() + " does not exist");
    struct stat existing {};
    const bool exists = ::stat(file.c_str(), &existing) == 0;
    if (exists && S_ISDIR(existing.st_mode))
        return makeError(ErrorCode::Io, requested.string() + ": cannot write, a folder of that name exists");
    if (exists && !S_ISREG(existing.st_mode))
        return makeError(ErrorCode::Io, requested.string() + ": cannot write, it is not a regular file (a FIFO or device)");
    removeStaleTemporaries(file);

    const fs::path temp = folder / temporarySiblingName(file.filename().string());
    const int fd = ::open(temp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
    if (fd < 0)
        return makeError(ErrorCode::Io, requested.string() + ": cannot create a temporary file in " + folder.string() + ": " +
                                            writeFailure(errno));
    const auto fail = [&](const std::string& what, int code) -> Status {
        ::close(fd);
        ::unlink(temp.c_str());
        return makeError(ErrorCode::Io, requested.string() + ": " + what + ": " + writeFailure(code));
    };
    if (exists && ::fchmod(fd, existing.st_mode & 07777) != 0) return fail("cannot keep the file's permissions", errno);
    if (const int code = writeAll(fd, content); code != 0) return fail("writing failed", code);
    if (::fsync(fd) != 0) return fail("flushing to the disk failed", errno);
    if (::close(fd) != 0) {
        const int code = errno;
        ::unlink(temp.c_str());
        return makeError(ErrorCode::Io, requested.string() + ": writing failed: " + writeFailure(code));
    }
    if (::rename(temp.c_str(), file.c_str()) != 0) {
        const int code = errno;
        ::unlink(temp.c_str());
        return makeError(ErrorCode::Io, requested.string() + ": cannot replace the file: " + writeFailure(code));
    }
    return syncFolder(folder);
}

Status writeStagedFile(const fs::path& file, std::string_view content, const std::string& shownName)
{
    const int fd = ::open(file.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0666);
    if (fd < 0) return makeError(ErrorCode::Io, shownName + ": cannot create: " + writeFailure(errno));
    int code = writeAll(fd, content);
    if (code == 0 && ::fsync(fd) != 0) code = errno;
    if (::close(fd) != 0 && code == 0) code = errno;
    if (code != 0) {
        ::unlink(file.c_str());
        return makeError(ErrorCode::Io, shownName + ": writing failed: " + writeFailure(code));
    }
    return okStatus();
}

Result<fs::path> makeTemporaryFolderBeside(const fs::path& target)
{
    const fs::path folder = target.has_parent_path() ? target.parent_path() : fs::path(".");
    std::error_code ec;
    if (!fs::is_directory(folder, ec))
        return makeError(ErrorCode::Io, target.string() + ": cannot write, folder " + folder.string() + " does not exist");
    removeStaleTemporaries(target);
    const fs::path temporary = folder / temporarySiblingName(target.filename().string());
    if (::mkdir(temporary.c_str(), 0700) != 0)
        return makeError(ErrorCode::Io, target.string() + ": cannot create a temporary folder beside it: " + writeFailure(errno));
    return temporary;
}

Status moveIntoPlace(const fs::path& complete, const fs::path& target)
{
    const int fd = ::open(complete.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd < 0) return makeError(ErrorCode::Io, target.string() + ": the finished file is missing: " + errnoText(errno));
    const int synced = ::fsync(fd);
    const int code = errno;
    ::close(fd);
    if (synced != 0) return makeError(ErrorCode::Io, target.string() + ": flushing to the disk failed: " + writeFailure(code));
    struct stat existing {};
    if (::stat(target.c_str(), &existing) == 0 && S_ISDIR(existing.st_mode))
        return makeError(ErrorCode::Io, target.string() + ": cannot write, a folder of that name exists");
    if (::rename(complete.c_str(), target.c_str()) != 0)
        return makeError(ErrorCode::Io, target.string() + ": cannot replace the file: " + writeFailure(errno));
    return syncFolder(target.has_parent_path() ? target.parent_path() : fs::path("."));
}

Status checkReadableFile(const fs::path& file, std::uintmax_t maxBytes)
{
    struct stat info {};
    if (::stat(file.c_str(), &info) != 0) {
        const int code = errno;
        if (code == ENOENT || code == ENOTDIR) return makeError(ErrorCode::NotFound, file.string() + ": no such file");
        return makeError(ErrorCode::Io, file.string() + ": cannot read: " + errnoText(code));
    }
    if (S_ISDIR(info.st_mode)) return makeError(ErrorCode::Io, file.string() + ": is a folder, expected a file");
    if (!S_ISREG(info.st_mode)) {
        const char* what = S_ISFIFO(info.st_mode) ? "a FIFO" : S_ISCHR(info.st_mode) || S_ISBLK(info.st_mode) ? "a device" : "a socket";
        return makeError(ErrorCode::Io, file.string() + ": is " + std::string(what) + ", not a regular file: refusing to read it");
    }
    if (std::uintmax_t(info.st_size) > maxBytes)
        return makeError(ErrorCode::Io, file.string() + ": is " + std::to_string(info.st_size) + " bytes, more than the " +
                                            std::to_string(maxBytes) + " bytes accepted for this kind of file");
    return okStatus();
}

Result<std::string> readTextFile(const fs::path& file, std::uintmax_t maxBytes)
{
    if (auto readable = checkReadableFile(file, maxBytes); !readable) return readable.error();
    // O_NONBLOCK: should the file be swapped for a FIFO after the check, open() does not wait.
    const int fd = ::open(file.c_str(), O_RDONLY | O_CLOEXEC | O_NONBLOCK | O_NOCTTY);
    if (fd < 0) return makeError(ErrorCode::Io, file.string() + ": cannot open for reading: " + errnoText(errno));
    struct stat info {};
    if (::fstat(fd, &info) != 0 || !S_ISREG(info.st_mode)) {
        ::close(fd);
        return makeError(ErrorCode::Io, file.string() + ": is not a regular file: refusing to read it");
    }
    // The size stat() gave, then whatever the file grew by meanwhile, in chunks, up to the bound.
    std::string text(std::size_t(info.st_size), '\0');
    std::size_t used = 0;
    char chunk[65536];
    while (true) {
        char* into = used < text.size() ? text.data() + used : chunk;
        const std::size_t room = used < text.size() ? text.size() - used : sizeof chunk;
        const ssize_t got = ::read(fd, into, room);
        if (got < 0) {
            if (errno == EINTR) continue;
            const int code = errno;
            ::close(fd);
            return makeError(ErrorCode::Io, file.string() + ": read error: " + errnoText(code));
        }
        if (got == 0) break;
        if (into == chunk) {
            if (used + std::size_t(got) > maxBytes) {
                ::close(fd);
                return makeError(ErrorCode::Io, file.string() + ": grew past " + std::to_string(maxBytes) +
                                                    " bytes while being read");
            }
            text.append(chunk, std::size_t(got));
        }
        used += std::size_t(got);
    }
    ::close(fd);
    text.resize(used);
    return text;
}

} // namespace bunraku::analysis::io
