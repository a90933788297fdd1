// SPDX-License-Identifier: MIT
// The response's sentences checked as a student checks them: every product and sum a sentence writes out
// ("a x b = c", "a + b = c", "1 / (a + b + c) = d") is redone by hand from the numbers as printed and must give the
// printed result once rounded to its printed digits. The sentences come from every lesson scene with a world,
// stepped, each pair of bodies in turn; the oracle is the arithmetic on the printed text alone.
#include "support/scene_files.h"

#include <satviz/render/describe.h>
#include <satviz/render/response_steps.h>
#include <satviz/scene.h>
#include <satviz/sim_record.h>

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <string>
#include <vector>

using namespace satviz;

namespace
{

// One number as a sentence prints it: its value and the unit of its last printed digit.
struct Printed
{
    double value = 0.0;
    double unit = 0.0;
};

// The words of a sentence, split at spaces, with the brackets and the punctuation around a number taken off.
std::vector<std::string> Words(const std::string& sentence)
{
    std::vector<std::string> words;
    std::string word;
    for (const char c : sentence + " ")
    {
        if (c == ' ')
        {
            if (!word.empty())
            {
                words.push_back(word);
            }
            word.clear();
        }
        else
        {
            word += c;
        }
    }
    return words;
}

std::string Strip(std::string word)
{
    while (!word.empty() && (word.front() == '(' || word.front() == '['))
    {
        word.erase(0, 1);
    }
    while (!word.empty() && (word.back() == ')' || word.back() == ']' || word.back() == ',' || word.back() == ';' ||
                             word.back() == ':' || word.back() == '.'))
    {
        word.pop_back();
    }
    return word;
}

// A word as a number, with the unit of its last digit (0.00511: 1e-5; 2.5e-5: 1e-6), or false when it is none.
bool ParseNumber(const std::string& word, Printed& out)
{
    const std::string text = Strip(word);
    if (text.empty() || text.find_first_not_of("0123456789.-e") != std::string::npos ||
        text.find_first_of("0123456789") == std::string::npos)
    {
        return false;
    }
    char* end = nullptr;
    out.value = std::strtod(text.c_str(), &end);
    if (end != text.c_str() + text.size())
    {
        return false;
    }
    const size_t e = text.find('e');
    const std::string mantissa = text.substr(0, e);
    const int exponent = e == std::string::npos ? 0 : std::atoi(text.c_str() + e + 1);
    const size_t point = mantissa.find('.');
    const int decimals = point == std::string::npos ? 0 : static_cast<int>(mantissa.size() - point - 1);
    out.unit = std::pow(10.0, exponent - decimals);
    return true;
}

// One written-out computation of a sentence and what redoing it from the printed numbers gave.
struct Check
{
    std::string what;
    double byHand = 0.0;
    Printed printed;
};

// Every "a x b = c", "a + b (+ ...) = c" and "1 / (a + b + ...) = c" of a sentence; a factor may be a name the
// sentence gave a number before ("e = 0.80 ... e x 4.00 = 3.20").
std::vector<Check> Computations(const std::string& sentence)
{
    const std::vector<std::string> w = Words(sentence);
    std::vector<Check> checks;
    std::map<std::string, Printed> names;
    auto number = [&](size_t i, Printed& p) { return i < w.size() && ParseNumber(w[i], p); };
    auto factor = [&](size_t i, Printed& p) {
        if (number(i, p))
        {
            return true;
        }
        const auto named = i < w.size() ? names.find(w[i]) : names.end();
        if (named == names.end())
        {
            return false;
        }
        p = named->second;
        return true;
    };
    for (size_t i = 0; i < w.size(); ++i)
    {
        Printed a, b, c;
        if (i + 2 < w.size() && w[i + 1] == "=" && Strip(w[i]) == w[i] &&
            w[i].find_first_not_of("abcdefghijklmnopqrstuvwxyz_") == std::string::npos && number(i + 2, a))
        {
            names[w[i]] = a;
        }
        // a x b = c
        if (factor(i, a) && i + 4 < w.size() && w[i + 1] == "x" && number(i + 2, b) && w[i + 3] == "=" &&
            number(i + 4, c))
        {
            checks.push_back({w[i] + " x " + w[i + 2] + " = " + w[i + 4], a.value * b.value, c});
        }
        // 1 / (a + b + ...) = c, and a + b + ... = c (not the tail of a longer sum)
        const bool reciprocal =
            w[i] == "1" && i + 2 < w.size() && w[i + 1] == "/" && !w[i + 2].empty() && w[i + 2][0] == '(';
        const size_t first = reciprocal ? i + 2 : i;
        if (!reciprocal && i >= 1 && (w[i - 1] == "+" || w[i - 1] == "/"))
        {
            continue;
        }
        double sum = 0.0;
        size_t k = first;
        int terms = 0;
        std::string what = reciprocal ? "1 / " : "";
        while (number(k, a))
        {
            sum += a.value;
            what += w[k] + " ";
            ++terms;
            if (k + 1 < w.size() && w[k + 1] == "+")
            {
                what += "+ ";
                k += 2;
                continue;
            }
            break;
        }
        if (terms >= 2 && k + 2 < w.size() && w[k + 1] == "=" && number(k + 2, c))
        {
            checks.push_back({what + "= " + w[k + 2], reciprocal ? 1.0 / sum : sum, c});
        }
    }
    return checks;
}

// The lesson scenes that step a world, by file name.
std::vector<std::string> WorldScenes()
{
    std::vector<std::string> files;
    for (const std::string& file : testing::TutorialSceneFiles())
    {
        std::ifstream in(file);
        const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
        if (text.find("\"world\"") != std::string::npos)
        {
            files.push_back(file);
        }
    }
    return files;
}

} // namespace

TEST_CASE("The oracle reads the computations a sentence writes out", "[world][response]")
{
    const std::vector<Check> checks = Computations("e = 0.80: leave at e x 4.00 = 3.20 m/s; in all j = 1.5 + 0.25 = "
                                                   "1.75 N s; m_eff = 1 / (0.637 + 1.273 + 0.00) = 0.524 kg.");
    REQUIRE(checks.size() == 3);
    CHECK(checks[0].what == "e x 4.00 = 3.20");
    CHECK(checks[0].byHand == Approx(3.2));
    CHECK(checks[0].printed.unit == Approx(0.01));
    CHECK(checks[1].byHand == Approx(1.75));
    CHECK(checks[2].byHand == Approx(1.0 / 1.91));
    CHECK(checks[2].printed.unit == Approx(0.001));
    Printed p;
    REQUIRE(ParseNumber("2.5e-5", p));
    CHECK(p.unit == Approx(1e-6));
}

TEST_CASE("Every computation in the response's sentences checks by hand at the printed precision", "[world][response]")
{
    // A student redoes "0.50 x 0.0102 = 0.00511" with the numbers printed: the result must come out as printed,
    // rounded to its last digit. "jn = 0.01" beside "mu_s jn = 0.00511" could not (0.5 x 0.01 = 0.005).
    const std::vector<std::string> files = WorldScenes();
    REQUIRE(files.size() >= 20);
    int checked = 0;
    int frictions = 0;
    for (const std::string& file : files)
    {
        SceneResult loaded = LoadScene(file);
        INFO(file << ": " << loaded.error);
        REQUIRE(loaded.Ok());
        const int count = static_cast<int>(loaded.scene.bodies.size());
        for (int a = 0; a < count; ++a)
        {
            for (int b = a + 1; b < count; ++b)
            {
                SimRecord record = StartRecord(loaded.scene, a, b);
                for (int step = 1; step <= 60; ++step)
                {
                    StepRecord(record);
                    if (!record.contact.found)
                    {
                        continue;
                    }
                    // The pair's static friction, as the world mixes the two bodies' (lesson 14).
                    const double muS = std::sqrt(loaded.scene.bodies[static_cast<size_t>(a)].material.staticFriction *
                                                 loaded.scene.bodies[static_cast<size_t>(b)].material.staticFriction);
                    Printed jn;
                    bool haveJn = false;
                    for (const ResponseStep& s : DescribeResponse(loaded.scene, record))
                    {
                        const std::vector<std::string> w = Words(s.sentence);
                        for (size_t i = 0; i + 2 < w.size(); ++i)
                        {
                            // "after 10 passes jn = 0.01 N s"
                            if (s.title == "Normal impulse" && w[i] == "jn" && w[i + 1] == "=")
                            {
                                haveJn = ParseNumber(w[i + 2], jn);
                            }
                            // "the static limit mu_s jn is 0.00511": mu_s times the jn printed before
                            if (haveJn && i + 3 < w.size() && w[i] == "mu_s" && w[i + 1] == "jn" && w[i + 2] == "is")
                            {
                                Printed limit;
                                if (ParseNumber(w[i + 3], limit))
                                {
                                    ++frictions;
                                    INFO(file << " step " << step << ": " << s.sentence);
                                    INFO("mu_s " << muS << " x jn " << jn.value << " = " << muS * jn.value);
                                    CHECK(std::fabs(muS * jn.value - limit.value) <= limit.unit * 1.000001);
                                }
                            }
                            if (w[i] == "mu_s" && w[i + 1] == "jn" && w[i + 2] == "=")
                            {
                                ++frictions;
                            }
                        }
                        for (const Check& c : Computations(s.sentence))
                        {
                            ++checked;
                            // Rounded to the printed digits, the computation redone by hand gives the printed
                            // result: "2.60 x 1.047 = 2.723" does not (2.7222 is 2.722).
                            const double off = std::fabs(c.byHand - c.printed.value);
                            if (off > c.printed.unit * 0.500001)
                            {
                                INFO(file << " step " << step << ", " << s.title << ": " << s.sentence);
                                INFO(c.what << " gives " << c.byHand << " by hand");
                                CHECK(off <= c.printed.unit * 0.500001);
                            }
                        }
                    }
                }
            }
        }
    }
    CHECK(frictions > 100);
    CHECK(checked > 1000);
}

TEST_CASE("Numbers with three significant digits at least: four decimals from 0.01 to 0.1 only", "[response]")
{
    CHECK(FormatNumber(0.0102, 3) == "0.0102");
    CHECK(FormatNumber(-0.0327, 3) == "-0.0327");
    CHECK(FormatNumber(0.0999999, 3) == FormatNumber(0.0999999));
    CHECK(FormatNumber(0.45, 3) == FormatNumber(0.45));
    CHECK(FormatNumber(0.00511, 3) == FormatNumber(0.00511));
    CHECK(FormatNumber(2.5, 3) == FormatNumber(2.5));
    CHECK(FormatNumber(0.0, 3) == FormatNumber(0.0));
    for (const double x : {0.0123456, 0.05, 0.0999, 0.01})
    {
        // Three significant digits: the value to within half of the fourth decimal.
        CHECK(std::fabs(std::strtod(FormatNumber(x, 3).c_str(), nullptr) - x) <= 0.5e-4);
    }
}

TEST_CASE("A pair resting asleep on a held contact is not headed \"No contact\"", "[world][response]")
{
    // l15_slope_sticks: the box falls asleep on the slope; the world keeps their contact (drawn, and counted by the
    // panel as held) without solving it, and the response headed that "No contact".
    SceneResult loaded = LoadScene(std::string(SATVIZ_SOURCE_DIR) + "/tutorials/scenes/l15_slope_sticks.json");
    REQUIRE(loaded.Ok());
    REQUIRE(loaded.scene.bodies.size() >= 2); // the slope and the box, then a mark
    SimRecord record = StartRecord(loaded.scene, 0, 1);
    bool asleep = false;
    for (int step = 1; step <= 240 && !asleep; ++step)
    {
        StepRecord(record);
        const auto& bodies = record.world.bodies;
        asleep = std::none_of(bodies.begin(), bodies.end(),
                              [](const RigidBody& b) { return b.type == BodyType::Dynamic && b.awake; });
    }
    REQUIRE(asleep); // the event the case is about
    bool held = false;
    for (const WorldContact& c : record.world.contacts)
    {
        held = held || (std::min(c.a, c.b) == 0 && std::max(c.a, c.b) == 1);
    }
    REQUIRE(held);
    StepRecord(record);
    const std::vector<ResponseStep> steps = DescribeResponse(loaded.scene, record);
    REQUIRE_FALSE(steps.empty());
    for (const ResponseStep& s : steps)
    {
        INFO(s.title << ": " << s.sentence);
        CHECK(s.title != "No contact");
    }
}
