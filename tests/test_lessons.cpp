// SPDX-License-Identifier: MIT
// The lessons in tutorials/: every figure they show exists and comes from a scene, every scene they name loads,
// and every number of a worked example that is marked for checking matches satviz-query on its scene.
//
// A checked number is written after an HTML comment that names the scene and a JSON pointer into satviz-query's
// answer for it (with --trace, textbook view):
//     the overlap is <!--check overlapping_boxes /pairs/0/depth-->0.18
// The number must equal the value rounded to the decimals it shows.

#include <satviz/query_json.h>
#include <satviz/scene.h>

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <regex>
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
    const std::string stem = fs::path(figure).stem().string();
    static const std::regex step("-step[0-9]+$");
    return std::regex_replace(stem, step, "");
}

// Decimals a printed number shows: "0.18" -> 2, "3" -> 0.
int Decimals(const std::string& number)
{
    const size_t dot = number.find('.');
    return dot == std::string::npos ? 0 : static_cast<int>(number.size() - dot - 1);
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
    static const std::regex image(R"(!\[[^\]]*\]\(([^)\s]+\.png)\))");
    int figures = 0;
    for (const fs::path& lesson : Lessons())
    {
        const std::string text = ReadFile(lesson);
        for (std::sregex_iterator it(text.begin(), text.end(), image), end; it != end; ++it)
        {
            const std::string figure = (*it)[1].str();
            INFO(lesson.filename().string() << ": " << figure);
            CHECK(figure.rfind("figures/", 0) == 0);
            CHECK(fs::exists(kTutorials / figure));
            CHECK(fs::exists(kTutorials / "scenes" / (SceneOfFigure(figure) + ".json")));
            ++figures;
        }
    }
    CHECK(figures > 0);
}

TEST_CASE("Every scene a lesson names loads and can be pictured", "[lessons]")
{
    static const std::regex named(R"(scenes/([A-Za-z0-9_]+)\.json)");
    int scenes = 0;
    for (const fs::path& lesson : Lessons())
    {
        const std::string text = ReadFile(lesson);
        for (std::sregex_iterator it(text.begin(), text.end(), named), end; it != end; ++it)
        {
            const fs::path file = kTutorials / "scenes" / ((*it)[1].str() + ".json");
            const SceneResult loaded = LoadScene(file.string());
            INFO(lesson.filename().string() << ": " << loaded.error);
            CHECK(loaded.Ok());
            ++scenes;
        }
    }
    CHECK(scenes > 0);
}

TEST_CASE("Every checked number of a worked example matches satviz-query on its scene", "[lessons]")
{
    static const std::regex check(R"(<!--check ([A-Za-z0-9_]+) (/[^ ]*)-->(-?[0-9]+(\.[0-9]+)?))");
    int checked = 0;
    for (const fs::path& lesson : Lessons())
    {
        const std::string text = ReadFile(lesson);
        for (std::sregex_iterator it(text.begin(), text.end(), check), end; it != end; ++it)
        {
            const std::string scene = (*it)[1].str();
            const std::string pointer = (*it)[2].str();
            const std::string shown = (*it)[3].str();
            INFO(lesson.filename().string() << ": " << scene << " " << pointer << " shown as " << shown);
            const fs::path file = kTutorials / "scenes" / (scene + ".json");
            const SceneResult loaded = LoadScene(file.string());
            REQUIRE(loaded.Ok());
            const nlohmann::ordered_json answer = QuerySceneJson(loaded.scene, file.string(), true);
            const nlohmann::ordered_json::json_pointer at(pointer);
            REQUIRE(answer.contains(at));
            REQUIRE(answer.at(at).is_number());
            const double value = answer.at(at).get<double>();
            const double unit = std::pow(10.0, -Decimals(shown));
            INFO("satviz-query says " << value);
            CHECK(std::abs(value - std::stod(shown)) <= 0.5 * unit * (1.0 + 1e-9));
            ++checked;
        }
    }
    CHECK(checked > 0);
}
