// SPDX-License-Identifier: MIT
// The study of a pair in single precision against the same study in double, on random pairs; the numbers of its
// rows and sentences.

#include "render/painter_support.h"
#include "support/random_shapes.h"
#include "support/scene_files.h"

#include <satviz/render/describe.h>
#include <satviz/render/study.h>

#include <catch2/catch.hpp>

#include <cctype>
#include <cmath>
#include <filesystem>
#include <set>
#include <string>
#include <utility>
#include <vector>

using namespace satviz;

namespace
{

// The parsing below is written out: std::regex, compiled with the sanitizers, trips GCC 12's -Wmaybe-uninitialized
// inside <regex>, which the build treats as an error.

/// Reads a number with a decimal point ("0.61", "-2.253") at `at`, moving past it. False, `at` unchanged, if none.
bool ReadDecimal(const std::string& s, size_t& at, std::string& out)
{
    size_t i = at;
    if (i < s.size() && s[i] == '-')
    {
        ++i;
    }
    const size_t digits = i;
    while (i < s.size() && std::isdigit(static_cast<unsigned char>(s[i])))
    {
        ++i;
    }
    if (i == digits || i + 1 >= s.size() || s[i] != '.' || !std::isdigit(static_cast<unsigned char>(s[i + 1])))
    {
        return false;
    }
    ++i;
    while (i < s.size() && std::isdigit(static_cast<unsigned char>(s[i])))
    {
        ++i;
    }
    out = s.substr(at, i - at);
    at = i;
    return true;
}

/// Every number with a decimal point in `s`, left to right.
std::vector<std::string> DecimalNumbers(const std::string& s)
{
    std::vector<std::string> numbers;
    for (size_t at = 0; at < s.size();)
    {
        std::string n;
        const bool starts = at == 0 || !std::isdigit(static_cast<unsigned char>(s[at - 1]));
        if (starts && ReadDecimal(s, at, n))
        {
            numbers.push_back(n);
        }
        else
        {
            ++at;
        }
    }
    return numbers;
}

/// A sentence's "from t = A until t = B" (or "from before the start (t = A) until t = B").
struct TimePair
{
    std::string from, until, text;
};

std::vector<TimePair> TimePairs(const std::string& s)
{
    std::vector<TimePair> pairs;
    const auto skip = [&](size_t& at, const std::string& word) {
        if (s.compare(at, word.size(), word) == 0)
        {
            at += word.size();
            return true;
        }
        return false;
    };
    for (size_t start = s.find("from "); start != std::string::npos; start = s.find("from ", start + 1))
    {
        size_t at = start + 5;
        TimePair pair;
        const bool before = skip(at, "before the start (");
        if (!skip(at, "t = ") || !ReadDecimal(s, at, pair.from))
        {
            continue;
        }
        const bool closed = skip(at, ")");
        if (before && !closed)
        {
            continue;
        }
        if (!skip(at, " until t = ") || !ReadDecimal(s, at, pair.until))
        {
            continue;
        }
        pair.text = s.substr(start, at - start);
        pairs.push_back(pair);
    }
    return pairs;
}

/// The time a time bar's "entry 0.40" or "exit 1.267 (after)" marks.
bool MarkedTime(const std::string& s, std::string& value)
{
    for (const std::string word : {"entry ", "exit "})
    {
        size_t at = word.size();
        if (s.compare(0, word.size(), word) == 0 && ReadDecimal(s, at, value))
        {
            return true;
        }
    }
    return false;
}

} // namespace

TEST_CASE("The single-precision study agrees with double within float rounding, step for step", "[study]")
{
    testing::Rng rng(7);
    int compared = 0;
    for (int i = 0; i < 2000; ++i)
    {
        const Scene scene = painter_test::RandomPolygonPair(rng, 12, 0.4);
        const PairStudy exact = StudyPair(scene, 0, 1, ViewQuery::Collide, false);
        const PairStudy single = StudyPair(scene, 0, 1, ViewQuery::Collide, true);
        if (!single.singlePrecision)
        {
            continue; // a polygon did not survive rounding to float
        }
        // Decisions may differ only where the shapes nearly touch.
        const double margin = exact.manifold.overlap ? exact.manifold.depth : exact.manifold.gap;
        if (margin < 1e-4)
        {
            continue;
        }
        REQUIRE(single.manifold.overlap == exact.manifold.overlap);
        if (exact.manifold.overlap)
        {
            CHECK(std::abs(single.manifold.depth - exact.manifold.depth) < 1e-5);
        }
        REQUIRE(!single.trace.axes.empty());
        for (const AxisTest& t : single.trace.axes)
        {
            CHECK(std::isfinite(t.minA));
            CHECK(std::abs(Length(t.direction) - 1.0) < 1e-6);
        }
        ++compared;
    }
    CHECK(compared > 1500);
}

TEST_CASE("A sweep where nothing moves says what the static test at t = 0 decided, with its gap", "[study]")
{
    // Two unit boxes moving together: no relative motion, so the static test decides. Apart, B's left face is
    // 1.50 - 0.50 - 0.50 = 0.50 beyond A's right one; at 1.00 they touch.
    auto verdict = [](double x, StepView view) {
        const std::string text = R"({"bodies": [
            {"name": "A", "box": [1, 1], "position": [0, 0], "velocity": [1, 0.5]},
            {"name": "B", "box": [1, 1], "position": [)" + std::to_string(x) + R"(, 0], "velocity": [1, 0.5]}]})";
        SceneResult loaded = ParseScene(text, "moving_together.json");
        REQUIRE(loaded.Ok());
        const PairStudy study = StudyPair(loaded.scene, 0, 1, ViewQuery::Sweep, false, view);
        REQUIRE(study.sweep);
        return DescribeStep(loaded.scene, study, study.VerdictStep());
    };
    for (const StepView view : {StepView::Textbook, StepView::Faces})
    {
        const std::string apart = verdict(1.5, view);
        INFO(apart);
        CHECK(apart.find("nothing moves") != std::string::npos);
        CHECK(apart.find("static test at t = 0 decides: it finds them apart, with a gap of 0.50") != std::string::npos);
        const std::string touching = verdict(1.0, view);
        INFO(touching);
        CHECK(touching.find("static test at t = 0 decides: it finds them touching without overlapping") != std::string::npos);
    }
}

TEST_CASE("The numbers of an axis row, and a sentence's times from and until, are written with as many decimals each",
          "[study]")
{
    // A student reads a row's two times together: circle_and_polygon's sweep row read "overlap from 0.61 to 2.253",
    // as if the first were rounded further than the second. Every row of the axes list (StepTitle) of every course
    // scene, static and swept, in both step views; the times a step's sentence gives as "from t = .. until t = ..";
    // and the entry and exit its time bar marks at an axis step. A number of more than three decimals is a small
    // one's significant digits, not a width for the others.
    const auto decimals = [](const std::string& t) {
        const size_t dot = t.find('.');
        return dot == std::string::npos ? 0 : static_cast<int>(t.size() - dot - 1);
    };
    std::vector<std::string> mixed;
    int rows = 0;
    int pairs = 0;
    int bars = 0;
    const auto check = [&](const std::vector<std::string>& numbers, const std::string& where) {
        std::set<int> counts;
        for (const std::string& n : numbers)
        {
            if (decimals(n) <= 3)
            {
                counts.insert(decimals(n));
            }
        }
        if (counts.size() > 1)
        {
            mixed.push_back(where);
        }
    };
    for (const std::string& file : testing::TutorialSceneFiles(true))
    {
        SceneResult loaded = LoadScene(file, SceneOptions{true});
        REQUIRE(loaded.Ok());
        const Scene& scene = loaded.scene;
        if (scene.bodies.size() < 2 || scene.bodies[0].IsConcave() || scene.bodies[1].IsConcave())
        {
            continue;
        }
        const std::string name = std::filesystem::path(file).filename().string();
        for (const ViewQuery query : {ViewQuery::Collide, ViewQuery::Sweep})
        {
            for (const StepView view : {StepView::Textbook, StepView::Faces})
            {
                const PairStudy study = StudyPair(scene, 0, 1, query, false, view);
                for (int step = 0; step < study.StepCount() && step < 80; ++step)
                {
                    const std::string row = StepTitle(scene, study, step);
                    ++rows;
                    check(DecimalNumbers(row), name + ": " + row);
                    const std::string sentence = DescribeStep(scene, study, step);
                    for (const TimePair& t : TimePairs(sentence))
                    {
                        ++pairs;
                        check({t.from, t.until}, name + " step " + std::to_string(step + 1) + ": " + t.text);
                    }
                }
                if (!study.sweep)
                {
                    continue;
                }
                Scene asked = scene;
                asked.view.query = query;
                asked.view.steps = view;
                FigureSetup setup = SetUpFigure(asked, {});
                if (!setup.Ok() || setup.figure.kind != FigureKind::Pair)
                {
                    continue;
                }
                for (int step = 0; step < setup.study.VerdictStep() && step < 80; ++step)
                {
                    const RecordingCanvas canvas = painter_test::Paint(asked, setup, step, setup.figure.layers);
                    std::vector<std::string> times;
                    std::string bar;
                    for (const DrawCommand* c : canvas.InGroup("timebar"))
                    {
                        std::string value;
                        if (c->kind == DrawCommand::Kind::Text && MarkedTime(c->text, value))
                        {
                            times.push_back(value);
                            bar += " | " + c->text;
                        }
                    }
                    if (times.size() == 2)
                    {
                        ++bars;
                        check(times, name + " time bar of step " + std::to_string(step + 1) + bar);
                    }
                }
            }
        }
    }
    CHECK(rows > 1000);
    CHECK(pairs > 50);
    CHECK(bars > 50);
    for (const std::string& m : mixed)
    {
        UNSCOPED_INFO(m);
    }
    CHECK(mixed.empty());
}
