#pragma once
/// The runnable parts of docs/TUTORIAL.md: its fenced blocks marked ```sh tutorial (one
/// `bunraku` command per line, `\` continuing a line, `#` comments) and ```json
/// tutorial-file=NAME (a file the commands read, written before them). The tutorial test runs
/// them as they are written, so the page and the test cannot drift apart.
#include <filesystem>
#include <string>
#include <vector>

namespace bunraku::test {

/// One step of the tutorial: a command's words (quotes removed, `$BANDAI` and `*` left for
/// expandTutorialWords) or a file to write.
struct TutorialStep {
    int line = 0;                    ///< line of the command (or of the file block) in the page
    std::vector<std::string> words;  ///< "bunraku", the subcommand, its arguments
    std::vector<bool> globbed;       ///< per word: it has an unquoted `*` to expand
    std::string fileName;            ///< a tutorial-file block: the file's name
    std::string fileText;            ///< ... and its contents
};

/// The steps of a Markdown page in order. Throws std::runtime_error naming the line when a
/// marked block holds a line that is not a `bunraku` command or a quote is not closed.
/// `marker` names the blocks read: ```sh MARKER and ```json MARKER-file=NAME ("tutorial": the
/// tutorial's main thread, which the clean-root package check also runs; "tutorial-mixamo": its
/// FBX section, whose files Blender makes at test time).
std::vector<TutorialStep> parseTutorial(const std::string& markdown, const std::string& marker = "tutorial");

/// A step's arguments (without "bunraku") with `$BANDAI` replaced by `bandai` and every
/// unquoted `*` pattern of a word's last path component expanded to the matching files, sorted
/// (relative to `cwd` when the word is relative). Throws when a pattern matches nothing.
std::vector<std::string> expandTutorialWords(const TutorialStep& step, const std::filesystem::path& bandai,
                                             const std::filesystem::path& cwd);

} // namespace bunraku::test
