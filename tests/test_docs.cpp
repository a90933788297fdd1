// SPDX-License-Identifier: MIT
// The Markdown files of the source tree: every relative link and image names a file or folder that exists, and a
// link to a section ("file.md#section", "#section") names a heading of that file. Text moves between files; a link
// left pointing at its old place fails here.
//
// A heading's anchor is GitHub's: the heading's text in lower case, with backquotes, asterisks and every other
// character that is not a letter, digit, space, '-' or '_' dropped, spaces turned into '-', and "-1", "-2"... added
// to the second and later headings of the same anchor.

#include <catch2/catch.hpp>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace fs = std::filesystem;

namespace
{

const fs::path kSource = fs::path(SATVIZ_SOURCE_DIR);

std::string ReadFile(const fs::path& path)
{
    std::ifstream in(path);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

// Every Markdown file of the source tree, outside build folders and .git.
std::vector<fs::path> MarkdownFiles()
{
    std::vector<fs::path> files;
    for (auto it = fs::recursive_directory_iterator(kSource); it != fs::recursive_directory_iterator(); ++it)
    {
        const std::string name = it->path().filename().string();
        if (it->is_directory() && (name.rfind("build", 0) == 0 || name[0] == '.'))
        {
            it.disable_recursion_pending();
            continue;
        }
        if (it->is_regular_file() && it->path().extension() == ".md")
        {
            files.push_back(it->path());
        }
    }
    std::sort(files.begin(), files.end());
    return files;
}

// The lines of a Markdown text outside fenced code blocks, each with inline code spans blanked out.
std::vector<std::string> ProseLines(const std::string& text)
{
    std::vector<std::string> lines;
    std::istringstream in(text);
    bool fenced = false;
    for (std::string line; std::getline(in, line);)
    {
        const size_t first = line.find_first_not_of(' ');
        if (first != std::string::npos && (line.compare(first, 3, "```") == 0 || line.compare(first, 3, "~~~") == 0))
        {
            fenced = !fenced;
            lines.emplace_back();
            continue;
        }
        if (fenced)
        {
            lines.emplace_back();
            continue;
        }
        bool code = false;
        for (char& c : line)
        {
            if (c == '`')
            {
                code = !code;
            }
            else if (code)
            {
                c = ' ';
            }
        }
        lines.push_back(line);
    }
    return lines;
}

// GitHub's anchor of a heading's text.
std::string Anchor(const std::string& heading)
{
    std::string out;
    for (char c : heading)
    {
        const unsigned char u = static_cast<unsigned char>(c);
        if (std::isalnum(u) || c == '-' || c == '_' || u >= 0x80)
        {
            out += static_cast<char>(std::tolower(u));
        }
        else if (c == ' ')
        {
            out += '-';
        }
    }
    return out;
}

// The anchors of every heading of a Markdown file.
std::set<std::string> Anchors(const fs::path& file)
{
    std::set<std::string> anchors;
    std::map<std::string, int> seen;
    for (const std::string& line : ProseLines(ReadFile(file)))
    {
        const size_t hashes = line.find_first_not_of('#');
        if (hashes == 0 || hashes == std::string::npos || hashes > 6 || line[hashes] != ' ')
        {
            continue;
        }
        std::string anchor = Anchor(line.substr(hashes + 1));
        while (!anchor.empty() && anchor.back() == '-')
        {
            anchor.pop_back();
        }
        const int n = seen[anchor]++;
        anchors.insert(n == 0 ? anchor : anchor + "-" + std::to_string(n));
    }
    return anchors;
}

// Every link and image target of a Markdown text: "[text](target)" and "![alt](target)", an optional title left out.
std::vector<std::string> Targets(const std::string& text)
{
    std::vector<std::string> out;
    for (const std::string& line : ProseLines(text))
    {
        for (size_t at = line.find("]("); at != std::string::npos; at = line.find("](", at + 2))
        {
            const size_t end = line.find(')', at + 2);
            if (end == std::string::npos)
            {
                continue;
            }
            std::string target = line.substr(at + 2, end - at - 2);
            const size_t space = target.find(' ');
            if (space != std::string::npos)
            {
                target.erase(space);
            }
            if (target.size() > 1 && target.front() == '<' && target.back() == '>')
            {
                target = target.substr(1, target.size() - 2);
            }
            out.push_back(target);
        }
    }
    return out;
}

bool External(const std::string& target)
{
    return target.rfind("http://", 0) == 0 || target.rfind("https://", 0) == 0 || target.rfind("mailto:", 0) == 0;
}

} // namespace

TEST_CASE("The anchors of headings are GitHub's", "[docs]")
{
    CHECK(Anchor("What the queries do") == "what-the-queries-do");
    CHECK(Anchor("`satviz-render`") == "satviz-render");
    CHECK(Anchor("The world: collision response and rigid bodies") == "the-world-collision-response-and-rigid-bodies");
    CHECK(Anchor("Two views of one query: the textbook test and the face tests") ==
          "two-views-of-one-query-the-textbook-test-and-the-face-tests");
    CHECK(Anchor("Stress tests, fuzzing (libFuzzer)") == "stress-tests-fuzzing-libfuzzer");
}

TEST_CASE("Every relative link of every Markdown file resolves, to its section too", "[docs]")
{
    const std::vector<fs::path> files = MarkdownFiles();
    REQUIRE(files.size() > 10);
    std::map<fs::path, std::set<std::string>> anchors;
    int links = 0;
    int sections = 0;
    for (const fs::path& file : files)
    {
        for (const std::string& target : Targets(ReadFile(file)))
        {
            if (External(target))
            {
                continue;
            }
            INFO(fs::relative(file, kSource).string() << ": " << target);
            const size_t hash = target.find('#');
            const std::string path = target.substr(0, hash);
            const fs::path linked = path.empty() ? file : (file.parent_path() / path).lexically_normal();
            CHECK(fs::exists(linked));
            ++links;
            if (hash != std::string::npos && fs::exists(linked))
            {
                REQUIRE(linked.extension() == ".md");
                if (anchors.count(linked) == 0)
                {
                    anchors[linked] = Anchors(linked);
                }
                CHECK(anchors[linked].count(target.substr(hash + 1)) == 1);
                ++sections;
            }
        }
    }
    CHECK(links > 100);
    CHECK(sections > 5);
}
