// SPDX-License-Identifier: MIT
// The world in words (DescribeWorld, the app's simulation panel) against real stepped worlds: a sleeping pair, an
// awake pair, a speculative contact with a gap. Each fact is computed here from the world itself: which bodies were
// awake as the step began, the overlap or gap of each pair by Collide on the bodies as the step began, each body's
// centre of mass and velocity, the time as steps times dt; the words must agree with them at their printed digits.
#include "render/painter_support.h"

#include <satviz/collide.h>
#include <satviz/render/describe.h>
#include <satviz/render/response_steps.h>
#include <satviz/render/world_words.h>

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <string>
#include <vector>

using namespace satviz;

namespace
{

using painter_test::SteppedScene;
using painter_test::StepScene;

// The numbers of a text, in order, each with the unit of its last printed digit.
struct Number
{
    double value;
    double unit;
};

std::vector<Number> Numbers(const std::string& text)
{
    std::vector<Number> numbers;
    size_t i = 0;
    while (i < text.size())
    {
        const bool sign =
            text[i] == '-' && i + 1 < text.size() && std::isdigit(static_cast<unsigned char>(text[i + 1]));
        if (!sign && !std::isdigit(static_cast<unsigned char>(text[i])))
        {
            ++i;
            continue;
        }
        // A digit inside a name ("crate 6" is a name's number too: the caller picks the numbers it needs).
        size_t end = i + 1;
        while (end < text.size() && (std::isdigit(static_cast<unsigned char>(text[end])) || text[end] == '.' ||
                                     text[end] == 'e' || (text[end] == '-' && text[end - 1] == 'e')))
        {
            ++end;
        }
        std::string word = text.substr(i, end - i);
        while (!word.empty() && (word.back() == '.' || word.back() == 'e'))
        {
            word.pop_back();
        }
        const size_t e = word.find('e');
        const std::string mantissa = word.substr(0, e);
        const size_t point = mantissa.find('.');
        const int decimals = point == std::string::npos ? 0 : static_cast<int>(mantissa.size() - point - 1);
        const int exponent = e == std::string::npos ? 0 : std::atoi(word.c_str() + e + 1);
        numbers.push_back({std::strtod(word.c_str(), nullptr), std::pow(10.0, exponent - decimals)});
        i = i + word.size();
    }
    return numbers;
}

// The outline of a body in world space: a polygon's vertices, or a circle's centre (with its radius).
std::vector<Vec2> Outline(const RigidBody& body, double& radius)
{
    std::vector<Vec2> points;
    radius = 0.0;
    if (body.shape.type == ShapeType::Circle)
    {
        radius = body.shape.circle.radius;
        points.push_back(TransformPoint(body.Xf(), body.shape.circle.center));
        return points;
    }
    const Vec2Span<double> v = body.shape.polygon.Vertices();
    for (int i = 0; i < v.count; ++i)
    {
        points.push_back(TransformPoint(body.Xf(), v.data[i]));
    }
    return points;
}

double PointToSegment(Vec2 p, Vec2 a, Vec2 b)
{
    const Vec2 ab = b - a;
    const double t = std::clamp(Dot(p - a, ab) / Dot(ab, ab), 0.0, 1.0);
    return Length(p - (a + t * ab));
}

// The distance between two convex bodies that do not overlap, by brute force: every vertex (or centre) of one to
// every edge (or point) of the other, less the radii.
double Distance(const RigidBody& a, const RigidBody& b)
{
    double ra = 0.0, rb = 0.0;
    const std::vector<Vec2> pa = Outline(a, ra);
    const std::vector<Vec2> pb = Outline(b, rb);
    double best = 1e300;
    auto sweep = [&](const std::vector<Vec2>& points, const std::vector<Vec2>& other) {
        for (const Vec2 p : points)
        {
            for (size_t k = 0; k < other.size(); ++k)
            {
                best = std::min(best, PointToSegment(p, other[k], other[(k + 1) % other.size()]));
            }
        }
    };
    sweep(pa, pb);
    sweep(pb, pa);
    return best - ra - rb;
}

// A printed number agrees with a value: within half its last digit, and a little for the value's own rounding.
bool Agrees(const Number& printed, double value)
{
    return std::fabs(printed.value - value) <= 0.5 * printed.unit * (1.0 + 1e-9) + 1e-12;
}

// The line of a pair in the contact list, or null.
const WorldContactWords* LineOf(const WorldWords& words, int a, int b)
{
    for (const WorldContactWords& c : words.contacts)
    {
        if (c.a == a && c.b == b)
        {
            return &c;
        }
    }
    return nullptr;
}

// Checks every line of the words against the world it describes.
void CheckAgainstWorld(const SteppedScene& s)
{
    const SimRecord& r = s.record;
    const WorldWords words = DescribeWorld(s.scene, r);
    INFO(words.contactsTitle);
    // The time: steps times dt.
    const std::vector<Number> time = Numbers(words.time);
    REQUIRE(time.size() == 3);
    CHECK(time[0].value == r.steps);
    CHECK(Agrees(time[1], r.steps * r.dt));
    CHECK(Agrees(time[2], r.dt));
    // One line per contact that is not a guard, each pair once.
    size_t held = 0;
    for (const WorldContact& c : r.world.contacts)
    {
        held += c.guard ? 0 : 1;
    }
    CHECK(words.contacts.size() == held);
    CHECK(words.contactsTitle == "Contacts held after step " + std::to_string(r.steps) + ": " + std::to_string(held));
    for (const WorldContactWords& line : words.contacts)
    {
        INFO(line.text);
        const RigidBody& a = r.before[static_cast<size_t>(line.a)];
        const RigidBody& b = r.before[static_cast<size_t>(line.b)];
        // Kept: no body of the pair was awake as the step began.
        const auto resting = [](const RigidBody& body) { return body.type == BodyType::Static || !body.awake; };
        CHECK(line.kept == (resting(a) && resting(b)));
        CHECK((line.text.find("(kept)") != std::string::npos) == line.kept);
        CHECK(line.text.rfind(s.scene.bodies[static_cast<size_t>(line.a)].name + " and " +
                                  s.scene.bodies[static_cast<size_t>(line.b)].name + ": ",
                              0) == 0);
        // The deepest overlap, or the gap, of the pair as the step began: by Collide, not from the contact.
        if (line.kept || a.IsConcave() || b.IsConcave())
        {
            continue; // a kept contact is an older step's
        }
        const Manifold m = Collide(a.shape, a.Xf(), b.shape, b.Xf());
        const std::string tail = line.text.substr(line.text.find(": ") + 2);
        const std::vector<Number> numbers = Numbers(tail); // the count of points, then one number per point
        if (tail.find("touching") != std::string::npos && tail.find("overlap") == std::string::npos &&
            tail.find("gap") == std::string::npos)
        {
            CHECK(m.overlap);
            CHECK(m.depth == 0.0);
            continue;
        }
        REQUIRE(numbers.size() >= 2);
        const bool gap = tail.find("gap") != std::string::npos && tail.find("overlap") == std::string::npos;
        CHECK(gap == !m.overlap);
        if (gap)
        {
            // The SAT gap is a lower bound of the distance: the speculative point's gap is not below it, and is the
            // distance between the shapes.
            CHECK(numbers[1].value + 0.5 * numbers[1].unit >= m.gap - 1e-12);
            INFO("Collide's gap " << m.gap << ", the distance " << Distance(a, b));
            CHECK(Agrees(numbers[1], Distance(a, b)));
        }
        else
        {
            double deepest = 0.0;
            for (size_t k = 1; k < numbers.size(); ++k)
            {
                deepest = std::max(deepest, numbers[k].value);
            }
            CHECK(std::fabs(deepest - m.depth) <= 0.5 * numbers[1].unit + 1e-9);
        }
    }
    // One line per body: static, asleep (at rest), or awake with its centre of mass, velocity and spin.
    REQUIRE(words.bodies.size() == r.world.bodies.size());
    for (size_t i = 0; i < r.world.bodies.size(); ++i)
    {
        const RigidBody& body = r.world.bodies[i];
        const std::string& line = words.bodies[i];
        INFO(line);
        CHECK(line.rfind(s.scene.bodies[i].name + ": ", 0) == 0);
        const std::string tail = line.substr(s.scene.bodies[i].name.size() + 2);
        if (body.type == BodyType::Static)
        {
            CHECK(tail == "static");
            continue;
        }
        CHECK(tail.rfind(body.awake ? "awake" : "asleep", 0) == 0);
        const std::vector<Number> numbers = Numbers(tail);
        const Vec2 centre = body.WorldCenter();
        REQUIRE(numbers.size() >= 2);
        CHECK(Agrees(numbers[0], centre.x));
        CHECK(Agrees(numbers[1], centre.y));
        if (body.awake)
        {
            REQUIRE(numbers.size() == 5);
            CHECK(Agrees(numbers[2], body.velocity.x));
            CHECK(Agrees(numbers[3], body.velocity.y));
            CHECK(Agrees(numbers[4], body.angularVelocity));
        }
        else
        {
            CHECK(body.velocity.x == 0.0);
            CHECK(body.angularVelocity == 0.0);
        }
    }
}

} // namespace

TEST_CASE("The world in words: a sleeping pair's contact is kept, and its body says it sleeps", "[world][words]")
{
    SteppedScene s = StepScene("l15_slope.json", 82);
    REQUIRE_FALSE(s.record.before[1].awake);
    const WorldWords words = DescribeWorld(s.scene, s.record);
    const WorldContactWords* line = LineOf(words, 0, 1);
    REQUIRE(line != nullptr);
    CHECK(line->kept);
    CHECK(words.bodies[1].find("asleep") != std::string::npos);
    CheckAgainstWorld(s);
}

TEST_CASE("The world in words: an awake pair's contact is this step's, with each point's overlap", "[world][words]")
{
    SteppedScene s = StepScene("l14_slide.json", 3);
    REQUIRE(s.record.before[1].awake);
    const WorldWords words = DescribeWorld(s.scene, s.record);
    const WorldContactWords* line = LineOf(words, 0, 1);
    REQUIRE(line != nullptr);
    INFO(line->text);
    CHECK_FALSE(line->kept);
    CHECK(line->text.find("2 points") != std::string::npos);
    CHECK(words.bodies[1].find("awake") != std::string::npos);
    CheckAgainstWorld(s);
}

TEST_CASE("The world in words: a speculative contact gives its gap", "[world][words]")
{
    // Lesson 17's crates: in step 38 the ball is a small gap from crate 6, closer than it moves in the step.
    SteppedScene s = StepScene("l17_skips.json", 38);
    const WorldWords words = DescribeWorld(s.scene, s.record);
    bool speculative = false;
    for (const WorldContactWords& c : words.contacts)
    {
        speculative = speculative || c.text.find("gap") != std::string::npos;
    }
    CHECK(speculative);
    CheckAgainstWorld(s);
    // Every step of the lesson scenes with a world, too.
    for (const char* name : {"l14_head_on.json", "l16_plank_corner.json", "l17_spinner.json"})
    {
        for (const int steps : {1, 12, 24, 40})
        {
            INFO(name << " after " << steps << " steps");
            CheckAgainstWorld(StepScene(name, steps));
        }
    }
}

TEST_CASE("The world in words writes a large whole speed in groups of three digits, as the figures' labels do",
          "[world][words]")
{
    // l17_bullet's bullet flies at 100 000 m/s; its arrow's label reads "v = 100 000 m/s".
    SteppedScene s = StepScene("l17_bullet.json", 0);
    const WorldWords words = DescribeWorld(s.scene, s.record);
    size_t i = 0;
    while (i < s.scene.bodies.size() && s.scene.bodies[i].name != "bullet")
    {
        ++i;
    }
    REQUIRE(i < s.scene.bodies.size());
    const std::string& line = words.bodies[i];
    INFO(line);
    // As the scene begins, before its first step.
    REQUIRE(s.record.world.bodies[i].velocity.x == 100000.0);
    REQUIRE(s.record.world.bodies[i].velocity.y == 0.0);
    CHECK(line.find("v (100 000, 0.00) m/s") != std::string::npos);
    CHECK(line.find("100000") == std::string::npos);
    CHECK(FormatResponseNumber(-250000.0) == "-250 000");
    CHECK(FormatResponseNumber(12345.5) == FormatNumber(12345.5, kResponseDigits));
    CHECK(FormatResponseVector({2.5, 100000.0}) == "(" + FormatNumber(2.5, kResponseDigits) + ", 100 000)");
}
