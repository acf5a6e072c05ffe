#include "app/cli/output_guard.h"

#include "app/cli/cli.h"

#include "analysis/io/atomic_file.h"
#include "analysis/io/corpus_io.h"
#include "analysis/synth/demo_corpus.h"

#include <filesystem>
#include <system_error>

namespace bunraku::app::cli {
namespace {

namespace fs = std::filesystem;

/// The path with links in its existing part resolved, "." and ".." removed.
fs::path resolved(const fs::path& path)
{
    std::error_code ec;
    fs::path out = fs::weakly_canonical(fs::absolute(path, ec), ec);
    if (ec) out = fs::absolute(path, ec).lexically_normal();
    if (out.filename().empty() && out.has_parent_path() && out != out.root_path()) out = out.parent_path();
    return out;
}

/// True when `inner` is `outer` or lies inside it.
bool within(const fs::path& inner, const fs::path& outer)
{
    auto a = outer.begin(), b = inner.begin();
    for (; a != outer.end(); ++a, ++b)
        if (b == inner.end() || *a != *b) return false;
    return true;
}

bool sameFile(const fs::path& a, const fs::path& b)
{
    std::error_code ec;
    if (fs::exists(a, ec) && fs::exists(b, ec) && fs::equivalent(a, b, ec)) return true; // hard links too
    return resolved(a) == resolved(b);
}

/// The files a command reading the corpus folder `folder` reads: corpus.json and the take,
/// skeleton and motion files it names. A manifest that does not parse gives corpus.json alone
/// (reading the corpus then fails before anything is written).
std::vector<std::string> corpusMemberFiles(const std::string& folder)
{
    const fs::path manifestPath = fs::path(folder) / "corpus.json";
    std::vector<std::string> files{manifestPath.string()};
    auto text = analysis::io::readTextFile(manifestPath, analysis::io::kDocumentLimitBytes);
    if (!text) return files;
    auto manifest = analysis::io::parseCorpusManifest(*text, manifestPath.string());
    if (!manifest) return files;
    for (const auto& entry : manifest->takes)
        for (const std::string* name : {&entry.file, &entry.skeleton, &entry.motion})
            if (!name->empty()) files.push_back((fs::path(folder) / *name).string());
    return files;
}

} // namespace

void refuseOutputOverInputs(const std::string& output, OutputKind kind, const std::vector<std::string>& inputs,
                            const std::string& option)
{
    if (output.empty()) return;
    const fs::path out = resolved(output);
    for (const std::string& input : inputs) {
        if (input.empty() || analysis::synth::isDemoTakeName(input)) continue;
        const fs::path in = resolved(input);
        if (sameFile(output, input))
            throw CliError(output + ": " + option + " is the input " + input +
                           ", which writing would destroy: choose another output");
        // A corpus's member files are inputs too: `normalise C -o C/<take>.csv` would overwrite a take.
        if (analysis::io::isCorpusFolder(input))
            for (const std::string& member : corpusMemberFiles(input))
                if (sameFile(output, member))
                    throw CliError(output + ": " + option + " is the file " + member + " of the input corpus " + input +
                                   ", which writing would destroy: choose another output");
        if (kind == OutputKind::Folder && within(in, out))
            throw CliError(output + ": " + option + " is a folder holding the input " + input +
                           ", which replacing it would destroy: choose another output folder");
    }
}

} // namespace bunraku::app::cli
