// The desktop entry and the shared-mime-info types of packaging/, checked from the source tree
// without building the package (tests_package checks the installed copies): the entry validates,
// update-mime-database accepts the XML, and every take file the readers open (BVH, and the
// extensions of analysis::io::sceneTakeExtensions: FBX, glTF binary and text, Collada) gets a
// type by its name, any case, and by its contents where the format has a signature, which the
// entry's MimeType lists, so a file manager offers the workbench for it. Qt's QMimeDatabase
// reads the database as KDE's file managers do. A missing tool fails under CI=true and is
// reported as skipped otherwise.
#include "tests/support/peer.h"

#include "analysis/io/scene_take.h"

#include <catch2/catch.hpp>

#include <QByteArray>
#include <QMimeDatabase>
#include <QString>

#include <array>
#include <cctype>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <regex>
#include <set>
#include <sstream>
#include <unistd.h>

namespace {

namespace fs = std::filesystem;

const fs::path kPackaging = fs::path(BUNRAKU_SOURCE_DIR) / "packaging";

struct ToolRun {
    int exitCode = -1;
    std::string output; ///< standard output and error
};

ToolRun runTool(const std::string& command)
{
    ToolRun run;
    std::unique_ptr<FILE, int (*)(FILE*)> pipe(::popen((command + " 2>&1").c_str(), "r"), ::pclose);
    if (!pipe) return run;
    std::array<char, 4096> buffer{};
    while (const std::size_t n = std::fread(buffer.data(), 1, buffer.size(), pipe.get())) run.output.append(buffer.data(), n);
    const int status = ::pclose(pipe.release());
    run.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    return run;
}

bool requireTool(const std::string& tool, const std::string& package)
{
    return bunraku::test::requirePeer(runTool("command -v " + tool).exitCode == 0, tool,
                                      "apt-get install " + package + " (scripts/install-deps.sh)");
}

std::string slurp(const fs::path& path)
{
    std::ifstream in(path, std::ios::binary);
    std::stringstream buffer;
    buffer << in.rdbuf();
    return buffer.str();
}

/// The MIME types of the entry's MimeType= line.
std::set<std::string> desktopTypes()
{
    const std::string entry = slurp(kPackaging / "org.bunraku.MotionWorkbench.desktop");
    std::smatch match;
    REQUIRE(std::regex_search(entry, match, std::regex("(^|\n)MimeType=([^\n]*)")));
    std::set<std::string> types;
    std::istringstream list(match[2].str());
    for (std::string type; std::getline(list, type, ';');)
        if (!type.empty()) types.insert(type);
    return types;
}

/// A scratch folder of this process.
fs::path scratch(const std::string& name)
{
    const fs::path dir = fs::temp_directory_path() / ("bunraku_desktop_files_" + std::to_string(::getpid())) / name;
    fs::remove_all(dir);
    fs::create_directories(dir);
    return dir;
}

} // namespace

TEST_CASE("the source desktop entry validates and lists the types of BVH FBX glTF and Collada takes", "[package][desktop]")
{
    if (!requireTool("desktop-file-validate", "desktop-file-utils")) return;
    const ToolRun validate = runTool("desktop-file-validate '" + (kPackaging / "org.bunraku.MotionWorkbench.desktop").string() + "'");
    INFO(validate.output);
    CHECK(validate.exitCode == 0);
    CHECK(validate.output.empty()); // not even a hint

    const auto types = desktopTypes();
    for (const char* type : {"application/x-bunraku-project", "application/x-bunraku-corpus", "application/x-bvh", "model/x-fbx",
                             "model/gltf-binary", "model/gltf+json", "model/vnd.collada+xml"}) {
        INFO(type);
        CHECK(types.count(type) == 1);
    }
}

TEST_CASE("every take file the readers open gets a MIME type from the package's XML that the desktop entry opens", "[package][mime]")
{
    if (!requireTool("update-mime-database", "shared-mime-info")) return;
    const fs::path system = "/usr/share/mime/packages/freedesktop.org.xml";
    if (!bunraku::test::requirePeer(fs::exists(system), "shared-mime-info's database (" + system.string() + ")",
                                    "apt-get install shared-mime-info (scripts/install-deps.sh)"))
        return;
    // What dpkg's trigger does on installation: update-mime-database over the package's XML and
    // shared-mime-info's own (which has the glTF types), merged into one database as in
    // /usr/share/mime. (Qt reading two databases lets the later one's magic win whatever the
    // priorities: application/xml over Collada.)
    const fs::path share = scratch("share");
    fs::create_directories(share / "mime/packages");
    fs::copy_file(kPackaging / "org.bunraku.MotionWorkbench.mime.xml", share / "mime/packages/org.bunraku.MotionWorkbench.xml");
    fs::copy_file(system, share / "mime/packages/freedesktop.org.xml");
    const ToolRun update = runTool("XDG_DATA_DIRS='" + share.string() + "' update-mime-database '" + (share / "mime").string() + "' 2>&1 >/dev/null");
    INFO(update.output);
    REQUIRE(update.exitCode == 0);
    REQUIRE(update.output.empty());

    // The first use of Qt's database in this process reads this folder only (and the user's
    // ~/.local/share/mime, if any).
    REQUIRE(::setenv("XDG_DATA_DIRS", share.string().c_str(), 1) == 0);
    const QMimeDatabase database;
    const auto byName = [&](const std::string& name) {
        return database.mimeTypeForFile(QString::fromStdString(name), QMimeDatabase::MatchExtension).name().toStdString();
    };
    const auto byContent = [&](const std::string& bytes) {
        return database.mimeTypeForData(QByteArray::fromStdString(bytes)).name().toStdString();
    };

    // Every extension a take is read from, in both cases, has a type the entry lists.
    const auto listed = desktopTypes();
    std::vector<std::string> extensions = bunraku::analysis::io::sceneTakeExtensions();
    extensions.push_back(".bvh");
    REQUIRE(extensions.size() == 5);
    const std::map<std::string, std::string> expected{{".bvh", "application/x-bvh"},
                                                      {".fbx", "model/x-fbx"},
                                                      {".glb", "model/gltf-binary"},
                                                      {".gltf", "model/gltf+json"},
                                                      {".dae", "model/vnd.collada+xml"}};
    for (const auto& extension : extensions) {
        INFO(extension);
        REQUIRE(expected.count(extension) == 1);
        const std::string type = byName("walk" + extension);
        CHECK(type == expected.at(extension));
        CHECK(listed.count(type) == 1);
        std::string upper = extension;
        for (char& c : upper) c = char(std::toupper(static_cast<unsigned char>(c)));
        CHECK(byName("WALK" + upper) == type);
    }

    // Files without an extension, by their first bytes as a file manager sniffs them.
    CHECK(byContent(std::string("Kaydara FBX Binary  \0\x1a\0\x4c\x1d\0\0", 27)) == "model/x-fbx");
    CHECK(byContent("; FBX 7.4.0 project file\n; ----------------------------------------------------\n\nFBXHeaderExtension:  {\n")
          == "model/x-fbx");
    CHECK(byContent(std::string("HIERARCHY\nROOT Hips\n{\n")) == "application/x-bvh");
    CHECK(byContent(std::string("glTF\x02\0\0\0\x40\0\0\0", 12)) == "model/gltf-binary");
    CHECK(byContent("<?xml version=\"1.0\" encoding=\"utf-8\"?>\n<COLLADA xmlns=\"http://www.collada.org/2005/11/COLLADASchema\" "
                    "version=\"1.4.1\">\n  <asset/>\n</COLLADA>\n")
          == "model/vnd.collada+xml");
    // Other XML files are left alone.
    CHECK(byContent("<?xml version=\"1.0\"?>\n<svg xmlns=\"http://www.w3.org/2000/svg\"/>\n") != "model/vnd.collada+xml");
    CHECK(database.mimeTypeForName(QStringLiteral("model/vnd.collada+xml")).inherits(QStringLiteral("application/xml")));
    fs::remove_all(share.parent_path());
}
