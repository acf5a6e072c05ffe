// The Debian package as built by `cmake --build build --target package`, checked with the tools
// a Debian system judges it by: dpkg-deb, lintian, desktop-file-validate, appstreamcli,
// update-mime-database (with Qt's MIME database reading the result), man and dpkg-parsechangelog.
#include "tests/package/installed_run.h"

#include <catch2/catch.hpp>

#include <QFileInfo>
#include <QImage>
#include <QMimeDatabase>

#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <sstream>

using namespace bunraku::test;
namespace fs = std::filesystem;

namespace {

std::string slurp(const fs::path& path)
{
    std::ifstream in(path, std::ios::binary);
    std::stringstream buffer;
    buffer << in.rdbuf();
    return buffer.str();
}

void requireTools(std::initializer_list<const char*> tools)
{
    for (const char* tool : tools)
        if (!hasTool(tool)) failOrSkip(std::string(tool) + " is not installed (scripts/install-deps.sh installs it)");
}

/// The control fields of the package (dpkg-deb -f), continuation lines joined with '\n'.
std::map<std::string, std::string> controlFields()
{
    const ProgramRun run = runTool("dpkg-deb -f " + shellQuoted(packageFile().string()));
    REQUIRE(run.exitCode == 0);
    std::map<std::string, std::string> fields;
    std::string current;
    std::istringstream lines(run.out);
    for (std::string line; std::getline(lines, line);) {
        if (!line.empty() && line[0] == ' ') {
            fields[current] += "\n" + line;
        } else if (const auto colon = line.find(':'); colon != std::string::npos) {
            current = line.substr(0, colon);
            fields[current] = line.substr(colon + 2 <= line.size() ? colon + 2 : line.size());
        }
    }
    return fields;
}

/// The names in a Depends-like field, versions dropped.
std::vector<std::string> packageNames(const std::string& field)
{
    std::vector<std::string> names;
    static const std::regex name(R"((?:^|,)\s*([a-z0-9][a-z0-9.+-]+))");
    for (std::sregex_iterator it(field.begin(), field.end(), name), end; it != end; ++it) names.push_back((*it)[1].str());
    return names;
}

/// The value of `key=` in the desktop entry.
std::string desktopValue(const std::string& entry, const std::string& key)
{
    const std::regex line("(^|\n)" + key + "=([^\n]*)");
    std::smatch match;
    return std::regex_search(entry, match, line) ? match[2].str() : std::string();
}

const fs::path kDesktopFile = "usr/share/applications/org.bunraku.MotionWorkbench.desktop";
const fs::path kMetainfoFile = "usr/share/metainfo/org.bunraku.MotionWorkbench.metainfo.xml";

} // namespace

TEST_CASE("the package's control data describes it, names a maintainer with an address, recommends ffmpeg and invents no homepage",
          "[package]")
{
    requireTools({"dpkg-deb"});
    auto fields = controlFields();
    INFO(fields["Description"]);
    CHECK(fields["Package"] == "bunraku-motion-workbench");
    CHECK(fields["Version"] == BUNRAKU_PROJECT_VERSION);
    CHECK(fields["Section"] == "science");
    CHECK(std::regex_match(fields["Maintainer"], std::regex(R"([^<>]+ <[^<>@ ]+@[^<> ]+\.[^<> ]+>)")));
    // A synopsis and an extended description of several lines.
    const std::string description = fields["Description"];
    CHECK(std::count(description.begin(), description.end(), '\n') >= 10);
    CHECK(description.find("bunraku-workbench") != std::string::npos);
    const auto recommends = packageNames(fields["Recommends"]);
    CHECK(std::find(recommends.begin(), recommends.end(), "ffmpeg") != recommends.end());
    const auto depends = packageNames(fields["Depends"]);
    for (const char* needed : {"qt6-qpa-plugins", "hicolor-icon-theme", "libqcustomplot2.1-qt6", "libfftw3-double3", "libassimp5", "libqt6widgets6"})
        CHECK(std::find(depends.begin(), depends.end(), needed) != depends.end());
    CHECK(fields.count("Homepage") == 0);
}

TEST_CASE("the package's programs are stripped and their symbols are in the -dbgsym package under their build ids", "[package]")
{
    requireTools({"file", "readelf", "dpkg-deb"});
    const ProgramRun contents = runTool("dpkg-deb -c " + shellQuoted(dbgsymFile().string()));
    REQUIRE(contents.exitCode == 0);
    for (const char* program : {"bunraku", "bunraku-workbench"}) {
        const fs::path binary = installedRoot() / "usr/bin" / program;
        const ProgramRun file = runTool("file -b " + shellQuoted(binary.string()));
        INFO(program << ": " << file.out);
        CHECK(file.out.find("ELF 64-bit") != std::string::npos);
        CHECK(file.out.find(", stripped") != std::string::npos);
        const ProgramRun notes = runTool("readelf -n " + shellQuoted(binary.string()));
        std::smatch id;
        REQUIRE(std::regex_search(notes.out, id, std::regex("Build ID: ([0-9a-f]{2})([0-9a-f]+)")));
        const std::string debugFile = "./usr/lib/debug/.build-id/" + id[1].str() + "/" + id[2].str() + ".debug";
        INFO(contents.out);
        CHECK(contents.out.find(debugFile) != std::string::npos);
    }
}

TEST_CASE("the licence: GPL-3 at the root, a machine-readable copyright naming every library the package depends on, a changelog",
          "[package]")
{
    requireTools({"dpkg-deb", "dpkg-parsechangelog", "gzip"});
    // The licence text is Debian's copy of the GPL version 3.
    if (fs::exists("/usr/share/common-licenses/GPL-3"))
        CHECK(slurp(fs::path(BUNRAKU_SOURCE_DIR) / "LICENSE") == slurp("/usr/share/common-licenses/GPL-3"));
    else
        failOrSkip("/usr/share/common-licenses/GPL-3 (base-files) is missing");

    const fs::path doc = installedRoot() / "usr/share/doc/bunraku-motion-workbench";
    const std::string copyright = slurp(doc / "copyright");
    CHECK(copyright.rfind("Format: https://www.debian.org/doc/packaging-manuals/copyright-format/1.0/\n", 0) == 0);
    CHECK(copyright.find("\nFiles: *\n") != std::string::npos);
    CHECK(copyright.find("License: GPL-3+\n") != std::string::npos);
    CHECK(copyright.find("/usr/share/common-licenses/GPL-3") != std::string::npos);
    auto fields = controlFields();
    for (const std::string& dependency : packageNames(fields["Depends"])) {
        INFO("the copyright file does not name " << dependency);
        CHECK(copyright.find(dependency) != std::string::npos);
    }

    const fs::path scratch = stageDir("changelog");
    const ProgramRun unzip = runTool("gzip -dc " + shellQuoted((doc / "changelog.gz").string()) + " > " + shellQuoted((scratch / "changelog").string()));
    REQUIRE(unzip.exitCode == 0);
    const ProgramRun parsed = runTool("dpkg-parsechangelog -l " + shellQuoted((scratch / "changelog").string()));
    INFO(parsed.err);
    REQUIRE(parsed.exitCode == 0);
    CHECK(parsed.out.find("\nVersion: " + fields["Version"] + "\n") != std::string::npos);
    CHECK(parsed.out.find("\nMaintainer: " + fields["Maintainer"] + "\n") != std::string::npos);
}

TEST_CASE("lintian reports no error on the package", "[package][lintian]")
{
    requireTools({"lintian"});
    const ProgramRun run = runTool("lintian --tag-display-limit 0 " + shellQuoted(packageFile().string()));
    std::vector<std::string> errors;
    std::vector<std::string> warnings;
    std::istringstream lines(run.out);
    for (std::string line; std::getline(lines, line);) {
        if (line.rfind("E: ", 0) == 0) errors.push_back(line);
        if (line.rfind("W: ", 0) == 0) warnings.push_back(line);
    }
    INFO(run.out << run.err);
    CHECK(errors.empty());
    CHECK(run.err.find("lintian: ") == std::string::npos); // lintian itself did not fail
    for (const std::string& warning : warnings) WARN(warning);
}

TEST_CASE("the desktop entry and the AppStream metainfo validate, with the licence, a content rating and release notes", "[package]")
{
    requireTools({"desktop-file-validate", "appstreamcli"});
    const fs::path desktop = installedRoot() / kDesktopFile;
    const ProgramRun entry = runTool("desktop-file-validate " + shellQuoted(desktop.string()));
    INFO(entry.out << entry.err);
    CHECK(entry.exitCode == 0);
    CHECK(entry.out.empty()); // not even a hint (one main category)

    const fs::path metainfo = installedRoot() / kMetainfoFile;
    for (const fs::path& file : {metainfo, fs::path(BUNRAKU_METAINFO_WITH_SCREENSHOTS)}) {
        const ProgramRun valid = runTool("appstreamcli validate --no-net " + shellQuoted(file.string()));
        INFO(file << "\n" << valid.out << valid.err);
        CHECK(valid.exitCode == 0);
    }
    const std::string xml = slurp(metainfo);
    CHECK(xml.find("<project_license>GPL-3.0-or-later</project_license>") != std::string::npos);
    CHECK(xml.find("<content_rating type=\"oars-1.1\"") != std::string::npos);
    CHECK(xml.find("<release version=\"" BUNRAKU_PROJECT_VERSION "\"") != std::string::npos);
    CHECK(slurp(BUNRAKU_METAINFO_WITH_SCREENSHOTS).find("<image>https://example.org/bunraku/docs/screenshot.png</image>")
          != std::string::npos);
}

TEST_CASE("the application icon is in the hicolor theme at every size under the desktop entry's Icon name", "[package]")
{
    const std::string entry = slurp(installedRoot() / kDesktopFile);
    const std::string icon = desktopValue(entry, "Icon");
    REQUIRE(icon == "org.bunraku.MotionWorkbench");
    const fs::path hicolor = installedRoot() / "usr/share/icons/hicolor";
    for (int size : {16, 24, 32, 48, 64, 128, 256, 512}) {
        const fs::path png = hicolor / (std::to_string(size) + "x" + std::to_string(size)) / "apps" / (icon + ".png");
        const QImage image(QString::fromStdString(png.string()));
        INFO(png);
        CHECK(image.size() == QSize(size, size));
        CHECK(image.hasAlphaChannel());
    }
    const std::string svg = slurp(hicolor / "scalable/apps" / (icon + ".svg"));
    CHECK(svg.find("<svg") != std::string::npos);
    CHECK(svg.find("viewBox=\"0 0 256 256\"") != std::string::npos);
}

TEST_CASE("projects, corpus manifests and BVH FBX glTF and Collada takes get MIME types which the desktop entry opens", "[package][mime]")
{
    requireTools({"update-mime-database"});
    // What dpkg's trigger does on installation: update-mime-database over the installed XML.
    const fs::path share = stageDir("mime") / "share";
    fs::create_directories(share / "mime/packages");
    fs::copy_file(installedRoot() / "usr/share/mime/packages/org.bunraku.MotionWorkbench.xml",
                  share / "mime/packages/org.bunraku.MotionWorkbench.xml");
    const ProgramRun update = runTool("XDG_DATA_DIRS=" + shellQuoted(share.string()) + " update-mime-database " +
                                      shellQuoted((share / "mime").string()));
    INFO(update.out << update.err);
    REQUIRE(update.exitCode == 0);
    REQUIRE(update.err.empty());

    // Qt reads the database like a desktop's file manager does (first use in this process).
    qputenv("XDG_DATA_DIRS", QByteArray::fromStdString(share.string() + ":/usr/share"));
    const QMimeDatabase database;
    const fs::path files = stageDir("mime-files");
    std::ofstream(files / "session.bunraku.json") << "{\"format\": \"bunraku-project\", \"version\": 1}\n";
    fs::create_directories(files / "demo");
    std::ofstream(files / "demo" / "corpus.json") << "{\"format\": \"bunraku-corpus\", \"version\": 1}\n";
    std::ofstream(files / "take.bvh") << "HIERARCHY\nROOT Hips\n{\n}\n";
    std::ofstream(files / "other.json") << "{}\n";
    std::ofstream(files / "walk.fbx", std::ios::binary) << std::string("Kaydara FBX Binary  \0\x1a\0", 23);
    std::ofstream(files / "walk.glb", std::ios::binary) << std::string("glTF\x02\0\0\0", 8);
    std::ofstream(files / "walk.gltf") << "{\"asset\": {\"version\": \"2.0\"}}\n";
    std::ofstream(files / "walk.dae") << "<?xml version=\"1.0\"?>\n<COLLADA xmlns=\"http://www.collada.org/2005/11/COLLADASchema\"/>\n";
    const auto typeOf = [&](const fs::path& file) {
        return database.mimeTypeForFile(QString::fromStdString(file.string())).name().toStdString();
    };
    CHECK(typeOf(files / "session.bunraku.json") == "application/x-bunraku-project");
    CHECK(typeOf(files / "demo" / "corpus.json") == "application/x-bunraku-corpus");
    CHECK(typeOf(files / "take.bvh") == "application/x-bvh");
    CHECK(typeOf(files / "other.json") == "application/json"); // other JSON files are left alone
    CHECK(typeOf(files / "walk.fbx") == "model/x-fbx");
    CHECK(typeOf(files / "walk.glb") == "model/gltf-binary"); // shared-mime-info's own glTF types
    CHECK(typeOf(files / "walk.gltf") == "model/gltf+json");
    CHECK(typeOf(files / "walk.dae") == "model/vnd.collada+xml");
    CHECK(database.mimeTypeForName(QStringLiteral("application/x-bunraku-project")).inherits(QStringLiteral("application/json")));

    const std::string types = desktopValue(slurp(installedRoot() / kDesktopFile), "MimeType");
    for (const char* type : {"application/x-bunraku-project;", "application/x-bunraku-corpus;", "application/x-bvh;", "model/x-fbx;",
                             "model/gltf-binary;", "model/gltf+json;", "model/vnd.collada+xml;"})
        CHECK(types.find(type) != std::string::npos);
    CHECK(desktopValue(slurp(installedRoot() / kDesktopFile), "Exec") == "bunraku-workbench %F");
}

TEST_CASE("the man pages of both programs render without warnings and document every subcommand", "[package][man]")
{
    requireTools({"man"});
    const fs::path home = stageDir("man");
    const ProgramRun help = runInstalled("bunraku", {"--help"}, home);
    REQUIRE(help.exitCode == 0);
    std::set<std::string> subcommands;
    static const std::regex listed(R"(\n  ([a-z][a-z0-9-]*) )");
    const std::string after = help.out.substr(help.out.find("Subcommands:"));
    for (std::sregex_iterator it(after.begin(), after.end(), listed), end; it != end; ++it) subcommands.insert((*it)[1].str());
    REQUIRE(subcommands.size() >= 10);

    for (const char* program : {"bunraku", "bunraku-workbench"}) {
        const fs::path page = installedRoot() / "usr/share/man/man1" / (std::string(program) + ".1.gz");
        REQUIRE(fs::exists(page));
        const ProgramRun man = runTool("LC_ALL=C.UTF-8 MANROFFSEQ='' MANWIDTH=100 man --warnings -E UTF-8 -l " + shellQuoted(page.string()));
        INFO(program << "\n" << man.err);
        CHECK(man.exitCode == 0);
        CHECK(man.err.empty());
        CHECK(man.out.find("NAME") != std::string::npos);
        CHECK(man.out.find("COPYRIGHT") != std::string::npos);
        CHECK(man.out.find("GPL-3.0-or-later") != std::string::npos);
        if (std::string(program) == "bunraku") {
            CHECK(man.out.find("SUBCOMMANDS") != std::string::npos);
            for (const std::string& name : subcommands) {
                if (name == "help" || name == "experiment") continue;
                INFO("the man page of bunraku has no section for " << name);
                CHECK(man.out.find("bunraku " + name + " [OPTIONS]") != std::string::npos);
            }
            CHECK(man.out.find("bunraku experiment km2o [OPTIONS]") != std::string::npos);
        } else {
            CHECK(man.out.find("--screenshot") != std::string::npos);
        }
    }
}
