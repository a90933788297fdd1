// SPDX-License-Identifier: MIT
// The lessons in tutorials/: every figure they show exists and comes from a scene, every scene they name loads,
// and every number of a worked example that is marked for checking matches satviz-query or satviz-sim on its scene.
//
// A checked number is written after an HTML comment that names the scene and a JSON pointer into satviz-query's
// answer for it (with --trace, textbook view):
//     the overlap is <!--check overlapping_boxes /pairs/0/depth-->0.18
// or, with @N after the scene, into the last line satviz-sim prints for it after N steps (with --counts --energy):
//     it stops at <!--check l14_slide@60 /bodies/1/position/0-->-1.107
// or, with :faces after the scene, into satviz-query's answer with the face view's trace (--trace --view faces):
//     the face tests run <!--check many_sides:faces /pairs/0/trace/faces_tested-->67 times
// The number must equal the value rounded to the decimals it shows; its minus may be a hyphen or the minus sign.

#include <satviz/query_json.h>
#include <satviz/scene.h>

#include "support/run_tool.h"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

using namespace satviz;
namespace fs = std::filesystem;

namespace
{

const fs::path kTutorials = fs::path(SATVIZ_SOURCE_DIR) / "tutorials";

std::string ReadFile(const fs::path& path)
{
    std::ifstream in(path);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

std::vector<fs::path> Lessons()
{
    std::vector<fs::path> lessons;
    for (const auto& entry : fs::directory_iterator(kTutorials))
    {
        const std::string name = entry.path().filename().string();
        if (entry.path().extension() == ".md" && name.size() > 3 && std::isdigit(static_cast<unsigned char>(name[0])))
        {
            lessons.push_back(entry.path());
        }
    }
    std::sort(lessons.begin(), lessons.end());
    return lessons;
}

// The scene a figure was rendered from: "figures/faces/overlapping_boxes-step6.png" -> "overlapping_boxes".
std::string SceneOfFigure(const std::string& figure)
{
    std::string stem = fs::path(figure).stem().string();
    size_t digits = stem.size();
    while (digits > 0 && std::isdigit(static_cast<unsigned char>(stem[digits - 1])))
    {
        --digits;
    }
    if (digits < stem.size() && digits >= 5 && stem.compare(digits - 5, 5, "-step") == 0)
    {
        stem.erase(digits - 5);
    }
    return stem;
}

// The run of characters from `at` that `keep` accepts.
template <typename Keep>
std::string Run(const std::string& text, size_t at, Keep keep)
{
    size_t end = at;
    while (end < text.size() && keep(text[end]))
    {
        ++end;
    }
    return text.substr(at, end - at);
}

bool NameCharacter(char c)
{
    return std::isalnum(static_cast<unsigned char>(c)) || c == '_';
}

// A scene's name as the lessons write it: a file of tutorials/scenes, or of one of its folders ("concave/l18_seam").
bool SceneNameCharacter(char c)
{
    return NameCharacter(c) || c == '/';
}

// Every "![alt](target)" image target.
std::vector<std::string> Images(const std::string& text)
{
    std::vector<std::string> out;
    for (size_t at = text.find("!["); at != std::string::npos; at = text.find("![", at + 2))
    {
        const size_t close = text.find("](", at);
        const size_t end = close == std::string::npos ? std::string::npos : text.find(')', close);
        if (end != std::string::npos)
        {
            out.push_back(text.substr(close + 2, end - close - 2));
        }
    }
    return out;
}

// Every "scenes/NAME.json" a text names, as NAME.
std::vector<std::string> Scenes(const std::string& text)
{
    std::vector<std::string> out;
    for (size_t at = text.find("scenes/"); at != std::string::npos; at = text.find("scenes/", at + 1))
    {
        const std::string name = Run(text, at + 7, SceneNameCharacter);
        if (!name.empty() && text.compare(at + 7 + name.size(), 5, ".json") == 0)
        {
            out.push_back(name);
        }
    }
    return out;
}

// A checked number: "<!--check SCENE /pointer-->NUMBER", "<!--check SCENE@STEPS /pointer-->NUMBER" for
// satviz-sim's state after STEPS steps, or "<!--check SCENE:faces /pointer-->NUMBER" for satviz-query's face view.
struct CheckMark
{
    std::string scene;
    int steps = 0; // 0: satviz-query
    bool faces = false; // satviz-query's trace in the face view, not the textbook view
    std::string pointer;
    std::string shown;
};

// The number written from `at`: digits and '.', after a minus that typeset prose may write as the minus sign U+2212
// rather than the hyphen-minus; either is read as '-', the form std::stod reads.
std::string ShownNumber(const std::string& text, size_t at)
{
    static const std::string kMinusSign = "\u2212";
    std::string sign;
    if (text.compare(at, kMinusSign.size(), kMinusSign) == 0)
    {
        sign = "-";
        at += kMinusSign.size();
    }
    else if (at < text.size() && text[at] == '-')
    {
        sign = "-";
        ++at;
    }
    const std::string digits =
        Run(text, at, [](char c) { return std::isdigit(static_cast<unsigned char>(c)) || c == '.'; });
    return digits.empty() ? std::string() : sign + digits;
}

std::vector<CheckMark> CheckMarks(const std::string& text)
{
    std::vector<CheckMark> out;
    const std::string open = "<!--check ";
    for (size_t at = text.find(open); at != std::string::npos; at = text.find(open, at + 1))
    {
        CheckMark mark;
        size_t p = at + open.size();
        mark.scene = Run(text, p, SceneNameCharacter);
        p += mark.scene.size();
        if (p < text.size() && text[p] == '@')
        {
            const std::string digits =
                Run(text, p + 1, [](char c) { return std::isdigit(static_cast<unsigned char>(c)) != 0; });
            if (digits.empty() || digits.size() > 7)
            {
                continue;
            }
            mark.steps = std::stoi(digits);
            p += 1 + digits.size();
        }
        else if (text.compare(p, 6, ":faces") == 0)
        {
            mark.faces = true;
            p += 6;
        }
        if (p >= text.size() || text[p] != ' ')
        {
            continue;
        }
        const size_t close = text.find("-->", p);
        if (close == std::string::npos)
        {
            continue;
        }
        mark.pointer = text.substr(p + 1, close - p - 1);
        mark.shown = ShownNumber(text, close + 3);
        // A sentence's full stop after the number is not one of its decimals.
        while (!mark.shown.empty() && mark.shown.back() == '.')
        {
            mark.shown.pop_back();
        }
        out.push_back(mark);
    }
    return out;
}

// Decimals a printed number shows: "0.18" -> 2, "3" -> 0.
int Decimals(const std::string& number)
{
    const size_t dot = number.find('.');
    return dot == std::string::npos ? 0 : static_cast<int>(number.size() - dot - 1);
}

// The last line satviz-sim prints for a scene of tutorials/scenes after `steps` steps, with --counts --energy: the
// program itself, run once per scene and count.
nlohmann::json SimulatedState(const std::string& scene, int steps)
{
    static std::map<std::pair<std::string, int>, nlohmann::json> done;
    const auto key = std::make_pair(scene, steps);
    if (const auto found = done.find(key); found != done.end())
    {
        return found->second;
    }
    const testing::ToolRun run =
        testing::RunTool(std::string(SATVIZ_SIM_EXE) + " " + (kTutorials / "scenes" / (scene + ".json")).string() +
                         " --steps " + std::to_string(steps) + " --every " + std::to_string(steps) +
                         " --counts --energy");
    const std::vector<std::string> lines = testing::SplitLines(run.out);
    nlohmann::json state;
    if (run.exitCode == 0 && !lines.empty() && !lines.back().empty())
    {
        state = nlohmann::json::parse(lines.back());
    }
    done.emplace(key, state);
    return state;
}

} // namespace

TEST_CASE("The lessons exist, in order, with the index that lists them", "[lessons]")
{
    const std::vector<fs::path> lessons = Lessons();
    REQUIRE(!lessons.empty());
    const std::string index = ReadFile(kTutorials / "README.md");
    for (size_t i = 0; i < lessons.size(); ++i)
    {
        const std::string name = lessons[i].filename().string();
        INFO(name);
        // Numbered from 01 without gaps.
        const std::string expected = (i + 1 < 10 ? "0" : "") + std::to_string(i + 1) + "-";
        CHECK(name.rfind(expected, 0) == 0);
        CHECK(index.find("(" + name + ")") != std::string::npos);
    }
}

TEST_CASE("Every figure a lesson shows exists and is rendered from a scene of tutorials/scenes", "[lessons]")
{
    int figures = 0;
    for (const fs::path& lesson : Lessons())
    {
        const std::string text = ReadFile(lesson);
        for (const std::string& figure : Images(text))
        {
            INFO(lesson.filename().string() << ": " << figure);
            CHECK(figure.rfind("figures/", 0) == 0);
            CHECK(fs::exists(kTutorials / figure));
            // Figures are written flat into figures/; their scenes may sit in a folder of scenes/ (concave/ holds
            // those whose figures frame themselves).
            const std::string scene = SceneOfFigure(figure) + ".json";
            CHECK((fs::exists(kTutorials / "scenes" / scene) ||
                   fs::exists(kTutorials / "scenes" / "concave" / scene)));
            ++figures;
        }
    }
    CHECK(figures > 0);
}

TEST_CASE("Every scene a lesson names loads and can be pictured", "[lessons]")
{
    int scenes = 0;
    for (const fs::path& lesson : Lessons())
    {
        const std::string text = ReadFile(lesson);
        for (const std::string& name : Scenes(text))
        {
            const fs::path file = kTutorials / "scenes" / (name + ".json");
            const SceneResult loaded = LoadScene(file.string(), SceneOptions{true}); // concave too
            INFO(lesson.filename().string() << ": " << loaded.error);
            CHECK(loaded.Ok());
            ++scenes;
        }
    }
    CHECK(scenes > 0);
}

TEST_CASE("A checked number may be written with the minus sign of typeset text", "[lessons]")
{
    const std::vector<CheckMark> marks = CheckMarks("a gap of <!--check pair /pairs/0/gap-->\u2212""1.40, a depth of "
                                                    "<!--check pair /pairs/0/depth-->-0.50. and <!--check pair /x-->2.5.");
    REQUIRE(marks.size() == 3);
    CHECK(marks[0].shown == "-1.40");
    CHECK(std::stod(marks[0].shown) == -1.40);
    CHECK(marks[1].shown == "-0.50");
    CHECK(marks[2].shown == "2.5");
    // The face view is named after the scene; a view that is not one is no mark.
    const std::vector<CheckMark> views =
        CheckMarks("<!--check pair:faces /pairs/0/trace/faces_tested-->11 <!--check pair:edges /x-->2");
    REQUIRE(views.size() == 1);
    CHECK(views[0].scene == "pair");
    CHECK(views[0].faces);
    CHECK(views[0].steps == 0);
    CHECK(views[0].shown == "11");
    CHECK(!marks[0].faces);
    // A minus sign alone is no number.
    CHECK(CheckMarks("<!--check pair /x-->\u2212 then")[0].shown.empty());
}

TEST_CASE("Every checked number of a worked example matches satviz-query or satviz-sim on its scene", "[lessons]")
{
    int checked = 0;
    int simulated = 0;
    for (const fs::path& lesson : Lessons())
    {
        const std::string text = ReadFile(lesson);
        for (const CheckMark& mark : CheckMarks(text))
        {
            const std::string& scene = mark.scene;
            const std::string& pointer = mark.pointer;
            const std::string& shown = mark.shown;
            REQUIRE(!shown.empty());
            REQUIRE(pointer.rfind("/", 0) == 0);
            INFO(lesson.filename().string() << ": " << scene << " " << pointer << " shown as " << shown);
            const fs::path file = kTutorials / "scenes" / (scene + ".json");
            const SceneResult loaded = LoadScene(file.string(), SceneOptions{true}); // concave too
            REQUIRE(loaded.Ok());
            double value = 0.0;
            if (mark.steps > 0)
            {
                INFO("after " << mark.steps << " steps");
                const nlohmann::json state = SimulatedState(scene, mark.steps);
                REQUIRE(state.is_object());
                const nlohmann::json::json_pointer at(pointer);
                REQUIRE(state.contains(at));
                REQUIRE(state.at(at).is_number());
                value = state.at(at).get<double>();
                ++simulated;
            }
            else
            {
                const StepView view = mark.faces ? StepView::Faces : StepView::Textbook;
                const nlohmann::ordered_json answer = QuerySceneJson(loaded.scene, file.string(), true, view);
                const nlohmann::ordered_json::json_pointer at(pointer);
                REQUIRE(answer.contains(at));
                REQUIRE(answer.at(at).is_number());
                value = answer.at(at).get<double>();
            }
            const double unit = std::pow(10.0, -Decimals(shown));
            const char* tool = mark.steps > 0 ? "satviz-sim" : mark.faces ? "satviz-query --view faces" : "satviz-query";
            INFO(tool << " says " << value);
            CHECK(std::abs(value - std::stod(shown)) <= 0.5 * unit * (1.0 + 1e-9));
            ++checked;
        }
    }
    CHECK(checked > 0);
    CHECK(simulated > 0);
}
