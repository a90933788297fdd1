// SPDX-License-Identifier: MIT
// The world's layers through a recording canvas: the broadphase's boxes and pairs, the response's steps and arrows,
// the hits and the plots, each checked against numbers computed here from the bodies (lesson 14's worked example
// for the response) rather than read back from the record the layers draw.
#include "render/painter_support.h"

#include <satviz/render/describe.h>
#include <satviz/render/figure.h>
#include <satviz/render/recording_canvas.h>
#include <satviz/render/response_steps.h>

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>

using namespace satviz;

namespace
{

using painter_test::SteppedScene;
using painter_test::StepScene;

RecordingCanvas Paint(SteppedScene& s, LayerMask layers, int width = 900, int height = 1000)
{
    FigureOptions options;
    options.setLayers = true;
    options.layers = layers;
    options.width = width;
    options.height = height;
    options.sim = &s.record;
    s.setup = SetUpFigure(s.scene, options);
    REQUIRE(s.setup.Ok());
    RecordingCanvas canvas;
    PaintFigure(canvas, s.scene, s.setup.study, s.setup.figure);
    return canvas;
}

// The text of a group, its lines joined by spaces (sentences are wrapped over several lines).
std::string GroupText(const RecordingCanvas& canvas, const std::string& group)
{
    std::string text;
    for (const DrawCommand* c : canvas.InGroup(group))
    {
        if (c->kind == DrawCommand::Kind::Text)
        {
            text += c->text + " ";
        }
    }
    return text;
}

bool AnyTextContains(const RecordingCanvas& canvas, const std::string& part)
{
    const std::vector<std::string> texts = canvas.Texts();
    return std::any_of(texts.begin(), texts.end(),
                       [&](const std::string& t) { return t.find(part) != std::string::npos; });
}

bool Contains(const std::string& text, const std::string& part)
{
    return text.find(part) != std::string::npos;
}

struct Box
{
    float minX, minY, maxX, maxY;
};

Box TextBox(const DrawCommand& c)
{
    const ScreenPoint size = FontTextSize(c.text, c.style);
    return {c.points[0].x, c.points[0].y, c.points[0].x + size.x, c.points[0].y + size.y};
}

} // namespace

TEST_CASE("World layers: the response of lesson 14's head-on hit, step by step, with the lesson's numbers",
          "[painter][world]")
{
    SteppedScene s = StepScene("l14_head_on.json", 23);
    const RecordingCanvas canvas = Paint(s, kLayerShapes | kLayerLabels | kLayerResponse, 1400, 900);
    const std::string panel = GroupText(canvas, "response panel");
    INFO(panel);
    // The lesson, by hand: mA = 2 pi 0.5^2 = pi / 2, mB = pi / 4; the effective mass 1 / (2/pi + 4/pi) = pi / 6; the
    // impulse (pi / 6) (3.2 + 4) = 1.2 pi; A leaves at 3 - 1.2 pi / (pi / 2) = 0.6, B at -1 + 1.2 pi / (pi / 4) = 3.8.
    const double pi = 3.141592653589793;
    CHECK(Contains(panel, "= " + FormatNumber(pi / 6.0) + " kg"));
    const std::string zero = FormatNumber(0.0);
    CHECK(Contains(panel, "1 / (" + FormatNumber(2.0 / pi) + " + " + FormatNumber(4.0 / pi) + " + " + zero + ")"));
    CHECK(Contains(panel, "they approach at " + FormatNumber(4.0) + " m/s"));
    CHECK(Contains(panel, "e x " + FormatNumber(4.0) + " = " + FormatNumber(3.2) + " m/s"));
    CHECK(Contains(panel, "= " + FormatNumber(1.2 * pi) + " N s."));
    auto pair = [&](double x) { return "(" + FormatNumber(x) + ", " + zero + ")"; };
    CHECK(Contains(panel, pair(3.0) + " -> " + pair(0.6) + " m/s"));
    CHECK(Contains(panel, pair(-1.0) + " -> " + pair(3.8) + " m/s"));
    // The arrow of the impulse on B, along the normal (1, 0) from the contact point, labelled with it.
    CHECK(AnyTextContains(canvas, "j = " + FormatNumber(1.2 * pi) + " N s"));
    bool arrow = false;
    for (const DrawCommand* c : canvas.InGroup("response"))
    {
        if (c->kind == DrawCommand::Kind::Segment && c->color == palette::kResult)
        {
            arrow = arrow || (c->points[1].x > c->points[0].x && std::fabs(c->points[1].y - c->points[0].y) < 0.5f);
        }
    }
    CHECK(arrow);
    // Every step of DescribeResponse is drawn, its title in the panel.
    for (const ResponseStep& step : DescribeResponse(s.scene, s.record))
    {
        CHECK(Contains(panel, step.title));
    }
    // The passes' table: ten passes.
    CHECK(ResponsePassesOf(s.record, 0).kept.size() == 10);
}

TEST_CASE("World layers: the caption explains the world's step, not a SAT test of the pair it left behind",
          "[painter][world]")
{
    // After step 23 of lesson 14's head-on hit the pair moves apart, so a sweep of it finds no hit; the step itself
    // bounced them on a speculative contact.
    SteppedScene s = StepScene("l14_head_on.json", 23);
    const RecordingCanvas response = Paint(s, kLayerShapes | kLayerCaption | kLayerResponse, 1400, 900);
    const std::string withPanel = GroupText(response, "caption");
    INFO(withPanel);
    CHECK(Contains(withPanel, "solver's response to A and B in step 23"));
    CHECK_FALSE(Contains(withPanel, "no hit"));
    const RecordingCanvas hits = Paint(s, kLayerShapes | kLayerCaption | kLayerHits, 1400, 900);
    const std::string alone = GroupText(hits, "caption");
    INFO(alone);
    CHECK(Contains(alone, "speculative"));
    CHECK_FALSE(Contains(alone, "no hit"));
}

TEST_CASE("World layers: the response before the pair meets says there was no contact", "[painter][world]")
{
    SteppedScene s = StepScene("l14_head_on.json", 5);
    const RecordingCanvas canvas = Paint(s, kLayerShapes | kLayerResponse);
    CHECK(AnyTextContains(canvas, "had no contact"));
    CHECK(canvas.InGroup("response").empty());
    // Before the hit the balls approach (A at 3 m/s towards B at -1 m/s); long after it they part, and the sentence
    // must not speak of closing a gap then. The direction is read from the world, apart from the sentence.
    for (const int steps : {5, 40})
    {
        SteppedScene t = StepScene("l14_head_on.json", steps);
        const std::vector<RigidBody>& bodies = t.record.world.bodies;
        const bool parting =
            (bodies[1].velocity.x - bodies[0].velocity.x) * (bodies[1].position.x - bodies[0].position.x) > 0.0;
        CHECK(parting == (steps == 40));
        const RecordingCanvas painted = Paint(t, kLayerShapes | kLayerResponse);
        INFO("step " << steps);
        CHECK(AnyTextContains(painted, "had no contact"));
        CHECK(AnyTextContains(painted, "could close") == !parting);
        CHECK(AnyTextContains(painted, "moving apart") == parting);
    }
}

TEST_CASE("World layers: the response of a sleeping pair says it sleeps, not that it had no contact",
          "[painter][world]")
{
    SteppedScene s = StepScene("l15_slope.json", 82);
    // The box fell asleep on the slope: its contact is kept, but the solver did not see it in the step.
    REQUIRE_FALSE(s.record.world.bodies[1].awake);
    REQUIRE(std::any_of(s.record.world.contacts.begin(), s.record.world.contacts.end(),
                        [](const WorldContact& c) { return c.a == 0 && c.b == 1 && !c.guard; }));
    REQUIRE_FALSE(s.record.contact.found);
    const std::vector<ResponseStep> steps = DescribeResponse(s.scene, s.record);
    REQUIRE(steps.size() == 1);
    CHECK(steps[0].sentence.find("asleep") != std::string::npos);
    CHECK(steps[0].sentence.find("had no contact") == std::string::npos);
}

TEST_CASE("World layers: the broadphase draws a pair line between the boxes' centres for every pair tested, the "
          "counts, and hatches the sleeping bodies",
          "[painter][world]")
{
    SteppedScene s = StepScene("l17_skips.json", 60);
    const RecordingCanvas canvas = Paint(s, kLayerShapes | kLayerBroadphase, 900, 700);
    const View& view = s.setup.figure.view;
    // The pairs: each a line from one box's centre to the other's; the centre of a box grown equally on every side
    // is the centre of the body's own box at the start of the step.
    std::vector<std::pair<ScreenPoint, ScreenPoint>> expected;
    for (const auto& [i, j] : s.record.lastStep.candidates)
    {
        const RigidBody& a = s.record.before[static_cast<size_t>(i)];
        const RigidBody& b = s.record.before[static_cast<size_t>(j)];
        const Aabb boxA = ComputeAabb(a.shape, a.Xf());
        const Aabb boxB = ComputeAabb(b.shape, b.Xf());
        expected.push_back({ToScreen(view, 0.5 * (boxA.min + boxA.max)), ToScreen(view, 0.5 * (boxB.min + boxB.max))});
    }
    std::vector<const DrawCommand*> lines;
    for (const DrawCommand* c : canvas.InGroup("broadphase"))
    {
        if (c->kind == DrawCommand::Kind::Segment && (c->color >> 8) == (palette::kGap >> 8))
        {
            lines.push_back(c);
        }
    }
    REQUIRE(lines.size() == expected.size());
    for (size_t k = 0; k < lines.size(); ++k)
    {
        CHECK(lines[k]->points[0].x == Approx(expected[k].first.x).margin(0.01));
        CHECK(lines[k]->points[0].y == Approx(expected[k].first.y).margin(0.01));
        CHECK(lines[k]->points[1].x == Approx(expected[k].second.x).margin(0.01));
    }
    const StepCounts& c = s.record.world.counts;
    CHECK(AnyTextContains(canvas, std::to_string(c.tested) + " tested, " + std::to_string(c.touching) + " touching"));
    CHECK(AnyTextContains(canvas, std::to_string(c.sleepingPairs) + " sleeping"));
    // The sleeping crates are hatched: each hatch line lies within a sleeping body's box, and there are some.
    int sleeping = 0;
    for (const RigidBody& body : s.record.world.bodies)
    {
        sleeping += body.type == BodyType::Dynamic && !body.awake;
    }
    REQUIRE(sleeping > 0);
    int hatches = 0;
    for (const DrawCommand* cmd : canvas.InGroup("sleeping"))
    {
        REQUIRE(cmd->kind == DrawCommand::Kind::Segment);
        const Vec2 mid =
            ToWorld(view, {0.5f * (cmd->points[0].x + cmd->points[1].x), 0.5f * (cmd->points[0].y + cmd->points[1].y)});
        bool inside = false;
        for (const RigidBody& body : s.record.world.bodies)
        {
            if (body.type == BodyType::Dynamic && !body.awake)
            {
                const Aabb box = ComputeAabb(body.shape, body.Xf());
                const double slack = 1.0 / view.zoom;
                inside = inside || (mid.x >= box.min.x - slack && mid.x <= box.max.x + slack &&
                                    mid.y >= box.min.y - slack && mid.y <= box.max.y + slack);
            }
        }
        CHECK(inside);
        ++hatches;
    }
    CHECK(hatches >= sleeping);
}

TEST_CASE("World layers: a bullet's hit on the time bar and where the bodies were at it", "[painter][world]")
{
    SteppedScene s = StepScene("l17_bullet.json", 1);
    REQUIRE(s.record.lastStep.hits.size() == 1);
    const RecordingCanvas canvas = Paint(s, kLayerShapes | kLayerLabels | kLayerHits);
    // The bullet starts 0.945 m from the wall's face and covers 100 000 / 60 m in the step: it hits at 0.945 / that.
    const double t = 0.945 / (100000.0 / 60.0);
    CHECK(AnyTextContains(canvas, "1: wall-bullet at " + FormatNumber(t)));
    CHECK(AnyTextContains(canvas, "hit 1"));
    int dots = 0;
    for (const DrawCommand* c : canvas.InGroup("hits panel"))
    {
        dots += c->kind == DrawCommand::Kind::FillCircle;
    }
    CHECK(dots == 1);
}

TEST_CASE("A speed beside its arrow is written as the captions write it: 100 000 m/s, not 100000.00", "[painter]")
{
    // The bullet's arrow runs 1667 m out of the figure: drawn shorter, it is named with its speed.
    SteppedScene s = StepScene("l17_bullet.json", 0);
    const RecordingCanvas canvas = Paint(s, kLayerShapes | kLayerLabels | kLayerSwept);
    CHECK(Contains(s.scene.view.caption, "100 000 m/s"));
    CHECK(AnyTextContains(canvas, "v = 100 000 m/s"));
    CHECK_FALSE(AnyTextContains(canvas, "100000"));
    CHECK(FormatLabelNumber(100000.0) == "100 000");
    CHECK(FormatLabelNumber(-1234567.0) == "-1 234 567");
    CHECK(FormatLabelNumber(1667.0) == FormatNumber(1667.0));
    CHECK(FormatLabelNumber(100000.5) == FormatNumber(100000.5));
    CHECK(FormatLabelNumber(3.0) == FormatNumber(3.0));
}

TEST_CASE("World layers: a hit chosen on the time bar draws its bodies where they touch, at its instant",
          "[painter][world]")
{
    // Lesson 17's corner: the ball from (0, 1) at (2, -1) per step (dt = 1) reaches the bottom cushion's top (y = 0)
    // with its radius 0.25 at t = 0.75, at (1.5, 0.25); bouncing elastically it leaves at (2, 1) and reaches the
    // right cushion's face (x = 2) at t = 0.875, at (1.75, 0.375).
    SteppedScene s = StepScene("l17_corner.json", 1);
    REQUIRE(s.record.lastStep.hits.size() == 2);
    const RecordingCanvas all = Paint(s, kLayerShapes | kLayerLabels | kLayerHits);
    Figure figure = s.setup.figure;
    RecordingCanvas measure;
    const std::vector<HitMark> marks = HitMarks(measure, s.scene, s.setup.study, figure);
    REQUIRE(marks.size() == 2);
    // The marks are where the panel draws its dots and labels, in time order along the bar.
    std::vector<ScreenPoint> dots;
    for (const DrawCommand* c : all.InGroup("hits panel"))
    {
        if (c->kind == DrawCommand::Kind::FillCircle)
        {
            dots.push_back(c->points[0]);
        }
        if (c->kind == DrawCommand::Kind::Text && c->text == marks[1].text)
        {
            CHECK(c->points[0].x == marks[1].labelMin.x);
        }
    }
    REQUIRE(dots.size() == 2);
    for (size_t h = 0; h < 2; ++h)
    {
        CHECK(dots[h].x == marks[h].dot.x);
        CHECK(dots[h].y == marks[h].dot.y);
    }
    CHECK(marks[0].dot.x < marks[1].dot.x);
    CHECK(marks[1].text == "2: right-ball at 0.875");

    figure.hit = 1;
    RecordingCanvas one;
    PaintFigure(one, s.scene, s.setup.study, figure);
    int outlines = 0;
    for (const DrawCommand* c : one.InGroup("hits"))
    {
        if (c->kind != DrawCommand::Kind::Polyline || !c->closed)
        {
            continue;
        }
        ++outlines;
        // The ball's outline about (1.75, 0.375), 0.25 m out.
        const ScreenPoint center = ToScreen(figure.view, {1.75, 0.375});
        for (const ScreenPoint& p : c->points)
        {
            CHECK(std::hypot(p.x - center.x, p.y - center.y) == Approx(0.25 * figure.view.zoom).margin(0.01));
        }
    }
    CHECK(outlines == 1); // the cushions are static: the ball alone
    CHECK(AnyTextContains(one, "hit 2 at t = 0.875"));
    CHECK_FALSE(AnyTextContains(one, "hit 1"));
    CHECK(Contains(GroupText(one, "hits panel"),
                   "Hit 2 of step 1: right and ball touch at t = 0.875 of the step (time 0.875)"));
}

TEST_CASE("World layers: the plots follow the energy over the steps, the current step marked", "[painter][world]")
{
    SteppedScene s = StepScene("l14_head_on.json", 30);
    const RecordingCanvas canvas = Paint(s, kLayerShapes | kLayerPlots);
    // Kinetic energy before and after the hit, by hand: 1/2 (pi/2) 3^2 + 1/2 (pi/4) 1^2 = 7.461 J before,
    // 1/2 (pi/2) 0.6^2 + 1/2 (pi/4) 3.8^2 = 5.953 J after. On the plot, heights above the frame's bottom in that ratio.
    const double pi = 3.141592653589793;
    const double before = 0.5 * (pi / 2.0) * 9.0 + 0.5 * (pi / 4.0);
    const double after = 0.5 * (pi / 2.0) * 0.36 + 0.5 * (pi / 4.0) * 3.8 * 3.8;
    const DrawCommand* kinetic = nullptr;
    const DrawCommand* frame = nullptr;
    for (const DrawCommand* c : canvas.InGroup("plots"))
    {
        if (c->kind == DrawCommand::Kind::Polyline && c->closed && frame == nullptr)
        {
            frame = c;
        }
        if (c->kind == DrawCommand::Kind::Polyline && !c->closed && c->color == palette::kShapeA && kinetic == nullptr)
        {
            kinetic = c;
        }
    }
    REQUIRE(frame != nullptr);
    REQUIRE(kinetic != nullptr);
    REQUIRE(kinetic->points.size() == 31);
    const float bottom = frame->points[2].y;
    const float h0 = bottom - kinetic->points.front().y;
    const float h1 = bottom - kinetic->points.back().y;
    CHECK(h1 / h0 == Approx(after / before).epsilon(1e-3));
    CHECK(AnyTextContains(canvas, "step 30"));
    CHECK(AnyTextContains(canvas, FormatNumber(before)));
}

TEST_CASE("World layers: no label of the world's layers overlaps another label of a simulation figure",
          "[painter][world]")
{
    for (const auto& [name, steps] : std::vector<std::pair<std::string, int>>{
             {"l14_head_on.json", 23}, {"l17_skips.json", 60}, {"l17_bullet.json", 1}, {"l14_slide.json", 10}})
    {
        INFO(name);
        SteppedScene s = StepScene(name, steps);
        const RecordingCanvas canvas = Paint(s, kLayerShapes | kLayerLabels | kLayerBroadphase | kLayerResponse |
                                                    kLayerHits | kLayerPlots | kLayerCaption);
        std::vector<const DrawCommand*> texts;
        for (const DrawCommand& c : canvas.commands)
        {
            if (c.kind == DrawCommand::Kind::Text)
            {
                texts.push_back(&c);
            }
        }
        const auto world = [](const DrawCommand* c) {
            return c->group != "labels" && c->group != "caption" && c->group != "background";
        };
        for (size_t i = 0; i < texts.size(); ++i)
        {
            for (size_t j = i + 1; j < texts.size(); ++j)
            {
                if (!world(texts[i]) && !world(texts[j]))
                {
                    continue; // the pair's own labels are the painter's tests' concern
                }
                const Box a = TextBox(*texts[i]);
                const Box b = TextBox(*texts[j]);
                const bool overlap = a.minX < b.maxX - 0.5f && b.minX < a.maxX - 0.5f && a.minY < b.maxY - 0.5f &&
                                     b.minY < a.maxY - 0.5f;
                INFO("\"" << texts[i]->text << "\" and \"" << texts[j]->text << "\"");
                CHECK(!overlap);
            }
        }
    }
}

TEST_CASE("World layers: a moving body out of the picture is named beside its speed", "[painter][world]")
{
    // After lesson 14's head-on hit B leaves at 3.8 m/s and A follows at 0.6; on the canvas beside the lesson column
    // (480 x 808) B is soon out of sight, and a bare "v = 3.80 m/s" at the picture's edge, beside A's own arrow, read
    // as A's speed.
    SteppedScene s = StepScene("l14_head_on.json", 186);
    FigureOptions options;
    options.width = 480;
    options.height = 808;
    options.sim = &s.record;
    s.setup = SetUpFigure(s.scene, options);
    REQUIRE(s.setup.Ok());
    RecordingCanvas canvas;
    PaintFigure(canvas, s.scene, s.setup.study, s.setup.figure);
    const Body& b = s.scene.bodies[static_cast<size_t>(s.setup.study.bodyB)];
    REQUIRE(b.name == "B");
    REQUIRE(b.velocity.x > 3.0);
    const ScreenPoint center = ToScreen(s.setup.figure.view, TransformPoint(b.Xf(), b.shape.circle.center));
    REQUIRE(center.x - ToPixels(s.setup.figure.view, b.shape.circle.radius) > 480.0f); // out of the picture
    const std::string speed = "v = " + FormatNumber(3.8) + " m/s";
    bool named = false;
    for (const DrawCommand& c : canvas.commands)
    {
        if (c.kind == DrawCommand::Kind::Text)
        {
            CHECK(c.text != speed);
            named = named || c.text == "B: " + speed;
        }
    }
    CHECK(named);
}
