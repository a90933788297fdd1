// SPDX-License-Identifier: MIT
// Wrapped text loses nothing: every line of every lesson, wrapped at many widths, gives back all its characters in
// order, each line fits the width, and a pair or list of numbers ("(0.96, 0.28)", "[-0.25, 0.5]") narrower than the
// line stays on one line. Prose in parentheses that starts with a number wraps like any prose.

#include <satviz/render/wrap.h>

#include <catch2/catch.hpp>

#include <algorithm>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

using namespace satviz;

namespace
{

// The brackets of numbers in `text`, left to right: an opening bracket, a sign or none, a digit, then digits, points,
// commas, spaces and signs, and a closing bracket (written out rather than as a std::regex, whose GCC 12 header trips
// -Wmaybe-uninitialized under the sanitizers).
std::vector<std::string> NumberBrackets(const std::string& text)
{
    std::vector<std::string> found;
    const auto digit = [](char c) { return c >= '0' && c <= '9'; };
    size_t i = 0;
    while (i < text.size())
    {
        if (text[i] != '(' && text[i] != '[')
        {
            ++i;
            continue;
        }
        size_t j = i + 1;
        if (j < text.size() && (text[j] == '-' || text[j] == '+'))
        {
            ++j;
        }
        if (j < text.size() && digit(text[j]))
        {
            while (j < text.size() && (digit(text[j]) || std::strchr("., +-", text[j]) != nullptr))
            {
                ++j;
            }
            if (j < text.size() && (text[j] == ')' || text[j] == ']'))
            {
                found.push_back(text.substr(i, j + 1 - i));
                i = j + 1;
                continue;
            }
        }
        ++i;
    }
    return found;
}

// A monospaced measure: 7 px a character (a UTF-8 character counts once).
float Measure(const std::string& text)
{
    return 7.0f * static_cast<float>(std::count_if(text.begin(), text.end(), [](char c) {
               return (static_cast<unsigned char>(c) & 0xC0) != 0x80;
           }));
}

std::string WithoutSpaces(const std::string& text)
{
    std::string kept;
    std::copy_if(text.begin(), text.end(), std::back_inserter(kept), [](char c) { return c != ' '; });
    return kept;
}

// The lines of every lesson, as the Markdown has them.
std::vector<std::string> LessonLines()
{
    std::vector<std::string> lines;
    for (const auto& entry : std::filesystem::directory_iterator(std::string(SATVIZ_SOURCE_DIR) + "/tutorials"))
    {
        if (entry.path().extension() != ".md" || entry.path().filename() == "README.md")
        {
            continue;
        }
        std::ifstream in(entry.path());
        for (std::string line; std::getline(in, line);)
        {
            lines.push_back(line);
        }
    }
    return lines;
}

void CheckWrapped(const std::string& text, float width)
{
    const std::vector<std::string> lines = WrapLines(text, width, Measure);
    std::string joined;
    for (const std::string& line : lines)
    {
        INFO("\"" << text << "\" at " << width << " px, line \"" << line << "\"");
        CHECK(Measure(line) <= width);
        joined += line;
    }
    INFO("\"" << text << "\" at " << width << " px");
    REQUIRE(WithoutSpaces(joined) == WithoutSpaces(text));
    // Pairs and lists of numbers, found by a scan of their own, that fit the width sit on one line.
    for (const std::string& found : NumberBrackets(text))
    {
        if (found.find(' ') == std::string::npos || Measure(found) > width)
        {
            continue;
        }
        INFO("the numbers " << found);
        CHECK(std::any_of(lines.begin(), lines.end(),
                          [&](const std::string& line) { return line.find(found) != std::string::npos; }));
    }
}

} // namespace

TEST_CASE("Wrapped text keeps every character: prose in brackets wraps, an over-wide word breaks", "[wrap]")
{
    // Lesson 11's parenthesis opens with a number but is prose; its code line has no space at all.
    const std::string prose = "(0.1645 in full; the figure prints 0.164, the difference of the deciding axis's "
                              "interval ends as the figures print them) and so on";
    CHECK(WrapWords(prose).size() > 10);
    CHECK(WrapWords("(0.6 × 0.12 + 0.8 × 0.16 = 0.2, and x = 0.12 lies between)").size() > 5);
    CHECK(WrapWords("the axis (0.96, 0.28) and [-0.25, 0.5] here") ==
          std::vector<std::string>{"the", "axis", "(0.96, 0.28)", "and", "[-0.25, 0.5]", "here"});
    const std::string code = R"("interval_a":[-0.2,0.2],"interval_b":[0.19999999999999998,0.4],"overlap":2.7e-17)";
    const std::vector<std::string> pieces = WrapLines(code, 200.0f, Measure);
    REQUIRE(pieces.size() > 1);
    // Broken after punctuation where it can be.
    CHECK(std::strchr(",:]", pieces.front().back()) != nullptr);
    for (float width = 35.0f; width <= 595.0f; width += 40.0f)
    {
        CheckWrapped(prose, width);
        CheckWrapped(code, width);
    }
}

TEST_CASE("Every line of every lesson wraps with nothing lost at any width", "[wrap]")
{
    const std::vector<std::string> lines = LessonLines();
    REQUIRE(lines.size() > 1000);
    for (const std::string& line : lines)
    {
        for (float width = 35.0f; width <= 635.0f; width += 60.0f)
        {
            CheckWrapped(line, width);
        }
    }
}
