#include "tests/cli/tutorial_script.h"

#include <algorithm>
#include <fnmatch.h>
#include <sstream>
#include <stdexcept>

namespace bunraku::test {
namespace {

std::runtime_error errorAt(int line, const std::string& what)
{
    return std::runtime_error("docs/TUTORIAL.md:" + std::to_string(line) + ": " + what);
}

/// Shell-like words of one command line: blanks separate, '...' and "..." quote, $BANDAI is
/// kept as text (expanded later), an unquoted '*' marks the word for globbing.
TutorialStep splitCommand(const std::string& text, int line)
{
    TutorialStep step;
    step.line = line;
    std::string word;
    bool inWord = false, star = false;
    char quote = 0;
    for (char c : text) {
        if (quote) {
            if (c == quote) quote = 0;
            else word += c;
            continue;
        }
        if (c == '\'' || c == '"') {
            quote = c;
            inWord = true;
        } else if (c == ' ' || c == '\t') {
            if (inWord) {
                step.words.push_back(word);
                step.globbed.push_back(star);
            }
            word.clear();
            inWord = star = false;
        } else {
            if (c == '*') star = true;
            word += c;
            inWord = true;
        }
    }
    if (quote) throw errorAt(line, "unclosed quote");
    if (inWord) {
        step.words.push_back(word);
        step.globbed.push_back(star);
    }
    return step;
}

std::string replaceAll(std::string text, const std::string& from, const std::string& to)
{
    for (std::size_t at = text.find(from); at != std::string::npos; at = text.find(from, at + to.size()))
        text.replace(at, from.size(), to);
    return text;
}

} // namespace

std::vector<TutorialStep> parseTutorial(const std::string& markdown, const std::string& marker)
{
    const std::string fileMarker = "json " + marker + "-file=";
    std::vector<TutorialStep> steps;
    std::istringstream in(markdown);
    std::string line;
    int number = 0;
    enum class Block { None, Other, Commands, File } block = Block::None;
    TutorialStep file;
    std::string pending; // a command continued with '\'
    int pendingLine = 0;
    while (std::getline(in, line)) {
        ++number;
        if (!line.empty() && line.back() == '\r') line.pop_back();
        if (line.rfind("```", 0) == 0) {
            if (block != Block::None) {
                if (!pending.empty()) throw errorAt(pendingLine, "command continued past the end of its block");
                if (block == Block::File) steps.push_back(file);
                block = Block::None;
                continue;
            }
            const std::string info = line.substr(3);
            block = Block::Other;
            if (info == "sh " + marker) block = Block::Commands;
            if (info.rfind(fileMarker, 0) == 0) {
                block = Block::File;
                file = {};
                file.line = number;
                file.fileName = info.substr(fileMarker.size());
                if (file.fileName.empty() || file.fileName.find('/') != std::string::npos)
                    throw errorAt(number, "expected a plain file name after " + marker + "-file=");
            }
            continue;
        }
        if (block == Block::File) file.fileText += line + "\n";
        if (block != Block::Commands) continue;
        if (pending.empty()) pendingLine = number;
        if (!line.empty() && line.back() == '\\') {
            pending += line.substr(0, line.size() - 1) + " ";
            continue;
        }
        const std::string text = pending + line;
        pending.clear();
        const std::size_t first = text.find_first_not_of(" \t");
        if (first == std::string::npos || text[first] == '#') continue;
        TutorialStep step = splitCommand(text, pendingLine);
        if (step.words.empty() || step.words.front() != "bunraku" || step.words.size() < 2)
            throw errorAt(pendingLine, "a ```sh " + marker + " block holds only bunraku commands, got: " + text);
        steps.push_back(std::move(step));
    }
    if (block != Block::None) throw errorAt(number, "unclosed code block");
    return steps;
}

std::vector<std::string> expandTutorialWords(const TutorialStep& step, const std::filesystem::path& bandai,
                                             const std::filesystem::path& cwd)
{
    std::vector<std::string> words;
    for (std::size_t i = 1; i < step.words.size(); ++i) {
        const std::string word = replaceAll(step.words[i], "$BANDAI", bandai.string());
        if (!step.globbed[i]) {
            words.push_back(word);
            continue;
        }
        const std::filesystem::path pattern(word);
        const std::filesystem::path parent = pattern.has_parent_path() ? pattern.parent_path() : std::filesystem::path(".");
        const std::filesystem::path folder = parent.is_absolute() ? parent : cwd / parent;
        std::vector<std::string> matches;
        if (std::filesystem::is_directory(folder))
            for (const auto& entry : std::filesystem::directory_iterator(folder))
                if (::fnmatch(pattern.filename().c_str(), entry.path().filename().c_str(), FNM_PERIOD) == 0)
                    matches.push_back((parent / entry.path().filename()).string());
        if (matches.empty()) throw errorAt(step.line, word + " matches no file");
        std::sort(matches.begin(), matches.end());
        words.insert(words.end(), matches.begin(), matches.end());
    }
    return words;
}

} // namespace bunraku::test
