// SPDX-License-Identifier: MIT
// Wrapped text loses nothing: every line of every lesson, wrapped at many widths, gives back all its characters in
// order, each line fits the width, and a pair or list of numbers ("(0.96, 0.28)", "[-0.25, 0.5]") narrower than the
// line stays on one line, and so does a number with its unit ("0.417 s)"). Prose in parentheses that starts with a
// number wraps like any prose.

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

// The numbers with a unit after them in `text` ("0.417 s", "3 m/s"), found by a scan of their own: a run of digits
// and points that starts after a space, a bracket or the start, a space, then one of a few units ended by a space,
// punctuation or the end.
std::vector<std::string> NumbersWithUnits(const std::string& text)
{
    static const char* const kUnits[] = {"m/s", "rad/s", "kg", "rad", "s", "m", "N"};
    std::vector<std::string> found;
    for (size_t i = 0; i < text.size(); ++i)
    {
        if (!(text[i] >= '0' && text[i] <= '9') || (i > 0 && std::strchr(" ([", text[i - 1]) == nullptr))
        {
            continue;
        }
        size_t j = i;
        while (j < text.size() && ((text[j] >= '0' && text[j] <= '9') || text[j] == '.'))
        {
            ++j;
        }
        if (j >= text.size() || text[j] != ' ' || text[j - 1] == '.') // "1. m": a list's number, no measure
        {
            continue;
        }
        for (const char* unit : kUnits)
        {
            const size_t n = std::strlen(unit);
            const size_t after = j + 1 + n;
            if (text.compare(j + 1, n, unit) == 0 &&
                (after == text.size() || std::strchr(" ),.;:", text[after]) != nullptr))
            {
                found.push_back(text.substr(i, after - i));
                break;
            }
        }
        i = j;
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
    // So do a number and its unit.
    for (const std::string& found : NumbersWithUnits(text))
    {
        // Measured with the brackets and punctuation that touch it, as "(0.2 m),", which go on its line too.
        const size_t at = text.find(found);
        const size_t from = text.rfind(' ', at) == std::string::npos ? 0 : text.rfind(' ', at) + 1;
        const size_t to = std::min(text.find(' ', at + found.size()), text.size());
        if (Measure(text.substr(from, to - from)) > width)
        {
            continue;
        }
        INFO("the number and unit " << found);
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
    // The formula in it stays whole; the prose after it wraps.
    CHECK(WrapWords("(0.6 × 0.12 + 0.8 × 0.16 = 0.2, and x = 0.12 lies between)") ==
          std::vector<std::string>{"(0.6 × 0.12 + 0.8 × 0.16 = 0.2,", "and", "x = 0.12", "lies", "between)"});
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

TEST_CASE("A number stays on the line of its unit", "[wrap]")
{
    const std::string header = "After 25 steps of the simulation (time 0.417 s)";
    const std::string speeds = "A at 3 m/s to the right at the start, an impulse of 0.5 N s, spin 1.57 rad/s.";
    REQUIRE(NumbersWithUnits(header) == std::vector<std::string>{"0.417 s"});
    REQUIRE(NumbersWithUnits(speeds) == std::vector<std::string>{"3 m/s", "0.5 N", "1.57 rad/s"});
    for (float width = 35.0f; width <= 400.0f; width += 7.0f)
    {
        CheckWrapped(header, width);
        CheckWrapped(speeds, width);
    }
    // Not every word after a number is a unit: "box 1 moves" wraps between "1" and "moves".
    CHECK(WrapWords("box 1 moves").size() == 3);
    CHECK(WrapWords("0.5 N s").size() == 1);
}

TEST_CASE("A formula stays on one line: its operators join their sides, and a number the pair it scales", "[wrap]")
{
    // disc_cast_cup's header broke "0.30" from "(0.00, 1.00)", the normal it scales, across two lines.
    const std::string sum = "out along it, (2.488, 1.000) + 0.30 \xC3\x97 (0.00, 1.00) = (2.488, 1.300).";
    const std::vector<std::string> words = WrapWords(sum);
    REQUIRE(!words.empty());
    CHECK(words.back() == "(2.488, 1.000) + 0.30 \xC3\x97 (0.00, 1.00) = (2.488, 1.300).");
    CHECK(WrapWords("a + b").size() == 1);
    CHECK(WrapWords("1.632 \xE2\x88\x92 0.514 = 1.118").size() == 1);
    CHECK(WrapWords("0.30 (0.00, 1.00)").size() == 1);
    // A number before prose in brackets, or before a word, still parts from it.
    CHECK(WrapWords("step 2 (the second)").size() == 4);
    CHECK(WrapWords("0.30 metres").size() == 2);
    // Wrapped at any width, nothing is lost, and where the formula fits a line it is not broken.
    const auto measure = [](const std::string& t) { return 7.0f * static_cast<float>(t.size()); };
    for (float width = 35.0f; width <= 700.0f; width += 7.0f)
    {
        CheckWrapped(sum, width);
        const std::vector<std::string> lines = WrapLines(sum, width, measure);
        if (measure(words.back()) <= width)
        {
            CHECK(std::any_of(lines.begin(), lines.end(),
                              [&](const std::string& line) { return line.find(words.back()) != std::string::npos; }));
        }
    }
}

TEST_CASE("A number written in groups of three digits stays whole", "[wrap]")
{
    CHECK(WrapWords("B moves at 100 000 m/s to the left") ==
          std::vector<std::string>{"B", "moves", "at", "100 000 m/s", "to", "the", "left"});
    CHECK(WrapWords("v (-1 250 000, 0.00) now")[1] == "(-1 250 000, 0.00)");
    // Three digits after a word that is not a number, or after a number of four digits, start a word of their own.
    CHECK(WrapWords("box 100 moves").size() == 3);
    CHECK(WrapWords("step 1000 200 times").size() == 4);
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
