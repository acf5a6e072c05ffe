#include "analysis/io/atomic_file.h"

#include <atomic>
#include <chrono>
#include <fstream>
#include <sstream>
#include <system_error>

namespace bunraku::analysis::io {

std::string temporarySiblingName(std::string_view leaf, std::string_view marker)
{
    static std::atomic<unsigned> counter{0};
    const auto now = std::chrono::steady_clock::now().time_since_epoch().count();
    // Built stepwise: GCC 12 warns falsely (-Wrestrict) on one concatenation expression.
    std::string name = ".";
    name += leaf;
    name += marker;
    name += std::to_string(now);
    name += '-';
    name += std::to_string(counter.fetch_add(1));
    return name;
}

Status writeFileAtomically(const std::filesystem::path& file, std::string_view content)
{
    namespace fs = std::filesystem;
    const fs::path folder = file.has_parent_path() ? file.parent_path() : fs::path(".");
    std::error_code ec;
    if (!fs::is_directory(folder, ec))
        return makeError(ErrorCode::Io, file.string() + ": cannot write, folder " + folder.string() + " does not exist");
    if (fs::is_directory(file, ec))
        return makeError(ErrorCode::Io, file.string() + ": cannot write, a folder of that name exists");
    const fs::path temp = folder / temporarySiblingName(file.filename().string(), ".tmp-");
    {
        std::ofstream out(temp, std::ios::binary | std::ios::trunc);
        if (!out) return makeError(ErrorCode::Io, file.string() + ": cannot create a temporary file in " + folder.string());
        out.write(content.data(), std::streamsize(content.size()));
        out.flush();
        if (!out) {
            out.close();
            fs::remove(temp, ec);
            return makeError(ErrorCode::Io, file.string() + ": writing failed (disk full?)");
        }
    }
    fs::rename(temp, file, ec);
    if (ec) {
        std::error_code ignored;
        fs::remove(temp, ignored);
        return makeError(ErrorCode::Io, file.string() + ": cannot replace the file: " + ec.message());
    }
    return okStatus();
}

Result<std::string> readTextFile(const std::filesystem::path& file)
{
    std::error_code ec;
    if (!std::filesystem::exists(file, ec)) return makeError(ErrorCode::NotFound, file.string() + ": no such file");
    if (std::filesystem::is_directory(file, ec))
        return makeError(ErrorCode::Io, file.string() + ": is a folder, expected a file");
    std::ifstream in(file, std::ios::binary);
    if (!in) return makeError(ErrorCode::Io, file.string() + ": cannot open for reading");
    std::ostringstream buffer;
    buffer << in.rdbuf();
    if (in.bad()) return makeError(ErrorCode::Io, file.string() + ": read error");
    return buffer.str();
}

} // namespace bunraku::analysis::io
