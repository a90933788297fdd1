// SPDX-License-Identifier: MIT
// The figures of concave shapes, through a recording canvas: what each panel draws agrees with the shapes measured
// on their own (areas, reflex corners, counts) and with the sentence above it.
#include "render/painter_support.h"
#include "support/random_concave.h"

#include <satviz/collide.h>
#include <satviz/concave.h>
#include <satviz/render/describe.h>
#include <satviz/render/figure.h>
#include <satviz/render/recording_canvas.h>

#include <catch2/catch.hpp>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

using namespace satviz;

namespace
{

Scene LoadConcave(const std::string& text)
{
    SceneOptions options;
    options.concave = true;
    SceneResult result = ParseScene(text, "s.json", options);
    INFO(result.error);
    REQUIRE(result.Ok());
    return result.scene;
}

RecordingCanvas PaintScene(const Scene& scene)
{
    FigureSetup setup = SetUpFigure(scene, {});
    INFO(setup.error);
    REQUIRE(setup.Ok());
    RecordingCanvas canvas;
    PaintFigure(canvas, scene, setup.study, setup.figure);
    return canvas;
}

// Twice the signed area of a screen polygon (y down: clockwise on screen is counter-clockwise in the world).
double ScreenArea2(const std::vector<ScreenPoint>& p)
{
    double sum = 0.0;
    for (size_t i = 0; i < p.size(); ++i)
    {
        const ScreenPoint& a = p[i];
        const ScreenPoint& b = p[(i + 1) % p.size()];
        sum += static_cast<double>(a.x) * b.y - static_cast<double>(b.x) * a.y;
    }
    return sum;
}

// Every turn of the screen polygon goes the same way: convex.
bool ScreenConvex(const std::vector<ScreenPoint>& p)
{
    int sign = 0;
    for (size_t i = 0; i < p.size(); ++i)
    {
        const ScreenPoint& a = p[i];
        const ScreenPoint& b = p[(i + 1) % p.size()];
        const ScreenPoint& c = p[(i + 2) % p.size()];
        const double cross = (static_cast<double>(b.x) - a.x) * (static_cast<double>(c.y) - b.y) -
                             (static_cast<double>(b.y) - a.y) * (static_cast<double>(c.x) - b.x);
        const int s = cross > 1e-3 ? 1 : (cross < -1e-3 ? -1 : 0);
        if (s != 0 && sign != 0 && s != sign)
        {
            return false;
        }
        sign = s != 0 ? s : sign;
    }
    return true;
}

// The whole number after `prefix` in `text`, or -1.
int NumberAfter(const std::string& text, const std::string& prefix)
{
    const size_t at = text.find(prefix);
    return at == std::string::npos ? -1 : std::atoi(text.c_str() + at + prefix.size());
}

std::string Caption(const RecordingCanvas& canvas)
{
    std::string text;
    for (const DrawCommand* c : canvas.InGroup("caption"))
    {
        if (c->kind == DrawCommand::Kind::Text && c->style == TextStyle::Body)
        {
            text += (text.empty() ? "" : " ") + c->text;
        }
    }
    return text;
}

const std::string kFlag = R"({"bodies": [{"name": "flag", "polygon": [[4, 2], [2, 4], [-1, 2], [-3, 1], [-4, -2],
    [0, -1], [1, -2], [4, -2]]}], "view": {"figure": "decomposition", "size": [900, 480]}})";

// The figure of `scene` painted on `canvas` through its camera, as the app draws it, so that screen points map back
// to the world through setup.figure.view.
void PaintThroughCamera(const Scene& scene, FigureSetup& setup, RecordingCanvas& canvas)
{
    setup = SetUpFigure(scene, {});
    REQUIRE(setup.Ok());
    setup.figure.framesItself = false;
    PaintFigure(canvas, scene, setup.study, setup.figure);
}

} // namespace

TEST_CASE("The decomposition figure fills pieces that cover the outline, and counts them as its words do",
          "[concave-views]")
{
    for (const std::string& text :
         {kFlag, std::string(R"({"bodies": [{"name": "E", "polygon": [[0, 0], [3, 0], [3, 1], [1, 1], [1, 2], [3, 2],
              [3, 3], [1, 3], [1, 4], [3, 4], [3, 5], [0, 5]]}, {"name": "ball", "circle": {"radius": 1}}],
              "view": {"figure": "decomposition"}})")})
    {
        const Scene scene = LoadConcave(text);
        const std::vector<Vec2> outline = scene.bodies[0].IsConcave()
                                              ? scene.bodies[0].outline
                                              : std::vector<Vec2>(scene.bodies[0].shape.polygon.Vertices().begin(),
                                                                  scene.bodies[0].shape.polygon.Vertices().end());
        const long double area2 = std::fabs(testing::Area2(outline));
        int reflex = 0;
        for (size_t i = 0; i < outline.size(); ++i)
        {
            const size_t n = outline.size();
            reflex += testing::TurnSign(outline[(i + n - 1) % n], outline[i], outline[(i + 1) % n]) < 0 ? 1 : 0;
        }
        const RecordingCanvas canvas = PaintScene(scene);
        const std::string caption = Caption(canvas);
        INFO(caption);
        CHECK(NumberAfter(caption, "An outline of ") == static_cast<int>(outline.size()));
        CHECK(NumberAfter(caption, "vertices, ") == reflex);
        // Ear clipping of a simple outline without straight corners gives n - 2 triangles and n - 3 seams.
        CHECK(NumberAfter(caption, "clips ") == static_cast<int>(outline.size()) - 2);
        CHECK(NumberAfter(caption, "joined by ") == static_cast<int>(outline.size()) - 3);
        const int bound = NumberAfter(caption, "rounded up + 1 = ");
        CHECK(bound == (reflex + 1) / 2 + 1);

        int counts[2] = {0, 0};
        double scale = 0.0;
        for (int side = 0; side < 2; ++side)
        {
            const std::string group = side == 0 ? "fast" : "fewest";
            int fills = 0;
            int rings = 0;
            int dashes = 0;
            double area = 0.0;
            std::vector<ScreenPoint> ringCentres;
            for (const DrawCommand* c : canvas.InGroup(group))
            {
                if (c->kind == DrawCommand::Kind::FillConvex)
                {
                    ++fills;
                    CHECK(ScreenConvex(c->points));
                    area += std::fabs(ScreenArea2(c->points));
                }
                rings += c->kind == DrawCommand::Kind::Circle ? 1 : 0;
                dashes += c->kind == DrawCommand::Kind::Segment && c->thickness == 1.5f ? 1 : 0;
                if (c->kind == DrawCommand::Kind::Circle)
                {
                    ringCentres.push_back(c->points[0]);
                }
            }
            counts[side] = NumberAfter(caption, side == 0 ? "stay, " : "Fewest: ");
            const std::vector<std::string> texts = canvas.Texts();
            CHECK(std::find(texts.begin(), texts.end(),
                            (side == 0 ? "Fast: " : "Fewest: ") + std::to_string(fills) + " pieces") != texts.end());
            CHECK(fills == counts[side]);
            CHECK(rings == reflex);
            CHECK((dashes > 0) == (fills > 1));
            // The pieces cover the outline once: their areas sum to its area, at the panel's scale (both panels
            // draw at one scale, so their sums agree).
            if (side == 0)
            {
                scale = area / static_cast<double>(area2);
            }
            else
            {
                CHECK(area == Approx(scale * static_cast<double>(area2)).epsilon(1e-4));
            }
        }
        CHECK(counts[1] <= counts[0]);
        CHECK(counts[1] >= bound);
    }
}

TEST_CASE("A decomposition figure of a scene with one body needs no pair, and a convex outline is one piece",
          "[concave-views]")
{
    const Scene scene = LoadConcave(R"({"bodies": [{"name": "hex", "regular": {"sides": 6, "radius": 1}}],
        "view": {"figure": "decomposition"}})");
    const FigureSetup setup = SetUpFigure(scene, {});
    INFO(setup.error);
    REQUIRE(setup.Ok());
    CHECK(setup.study.StepCount() == 1);
    const RecordingCanvas canvas = PaintScene(scene);
    CHECK(Caption(canvas) == "An outline of 6 vertices, 0 of them reflex (ringed). It is convex: one piece, cut by "
                             "neither method.");
    CHECK(canvas.InGroup("fast").size() > 0);
}

namespace
{

// Sum of the areas of the group's filled polygons, in square pixels.
double FilledArea(const RecordingCanvas& canvas, const std::string& group, int* count = nullptr)
{
    double area = 0.0;
    int fills = 0;
    for (const DrawCommand* c : canvas.InGroup(group))
    {
        if (c->kind == DrawCommand::Kind::FillConvex)
        {
            CHECK(ScreenConvex(c->points));
            area += 0.5 * std::fabs(ScreenArea2(c->points));
            ++fills;
        }
    }
    if (count != nullptr)
    {
        *count = fills;
    }
    return area;
}

} // namespace

TEST_CASE("The slice figure marks where the cut crosses the outline, and the parts keep the body's area",
          "[concave-views]")
{
    // A U cut across both arms: three parts, the arms' tops (1 each) and the rest (6).
    const std::vector<Vec2> u = {{0, 0}, {4, 0}, {4, 3}, {3, 3}, {3, 1}, {1, 1}, {1, 3}, {0, 3}};
    const Scene scene = LoadConcave(R"({"bodies": [{"name": "U", "polygon": [[0, 0], [4, 0], [4, 3], [3, 3], [3, 1],
        [1, 1], [1, 3], [0, 3]], "position": [1, -1]}], "view": {"figure": "slice", "cut": [[0.5, 1], [5.5, 1]]}})");
    const RecordingCanvas canvas = PaintScene(scene);
    const std::string caption = Caption(canvas);
    INFO(caption);
    // The cut, moved into the U's frame, crosses each of the four arms' sides once (an independent count).
    const Vec2 a{-0.5, 2.0};
    const Vec2 b{4.5, 2.0};
    int crossings = 0;
    for (size_t i = 0; i < u.size(); ++i)
    {
        crossings += testing::ProperlyCross(a, b, u[i], u[(i + 1) % u.size()]) ? 1 : 0;
    }
    CHECK(crossings == 4);
    int dots = 0;
    for (const DrawCommand* c : canvas.InGroup("before"))
    {
        dots += c->kind == DrawCommand::Kind::FillCircle && c->radius > 4.0f ? 1 : 0;
    }
    CHECK(dots == crossings);
    // In the world: the arms' sides at x = 1, 2, 4, 5 on the line y = 1.
    CHECK(caption.find("at (1.00, 1.00), (2.00, 1.00), (4.00, 1.00) and (5.00, 1.00)") != std::string::npos);
    CHECK(caption.find("into 3 parts of areas 6.00, 1.00 and 1.00, which sum to 8.00, U's area 8.00") !=
          std::string::npos);
    const std::vector<std::string> texts = canvas.Texts();
    CHECK(std::find(texts.begin(), texts.end(), "After: 3 parts") != texts.end());
    // The parts cover what the body covered: the same filled area before and after, at one scale, and the body's
    // area from its outline measured apart.
    int before = 0;
    int after = 0;
    const double whole = FilledArea(canvas, "before", &before);
    const double parts = FilledArea(canvas, "after", &after);
    CHECK(parts == Approx(whole).epsilon(1e-4));
    CHECK(after > before);
    int areas = 0;
    for (const std::string& t : texts)
    {
        areas += t.rfind("area ", 0) == 0 ? 1 : 0;
    }
    CHECK(areas == 3);
    CHECK(std::fabs(testing::Area2(u)) == 16.0L);
}

TEST_CASE("A part's area is written inside the part, centred, where it fits, and otherwise just beside it",
          "[concave-views]")
{
    // Lesson 19's bar cut at x = 0.5: the part on the left is wide enough for its label, the one on the right not.
    std::ifstream file(std::string(SATVIZ_SOURCE_DIR) + "/tutorials/scenes/concave/l19_bar_cut.json");
    std::stringstream text;
    text << file.rdbuf();
    const Scene scene = LoadConcave(text.str());
    RecordingCanvas canvas = PaintScene(scene);
    // Each part is one convex piece, a rectangle: its box on screen from what the after panel fills.
    struct Box
    {
        float minX, minY, maxX, maxY;
    };
    std::vector<Box> parts;
    for (const DrawCommand* c : canvas.InGroup("after"))
    {
        if (c->kind == DrawCommand::Kind::FillConvex)
        {
            Box box{INFINITY, INFINITY, -INFINITY, -INFINITY};
            for (const ScreenPoint& p : c->points)
            {
                box = {std::min(box.minX, p.x), std::min(box.minY, p.y), std::max(box.maxX, p.x),
                       std::max(box.maxY, p.y)};
            }
            parts.push_back(box);
        }
    }
    REQUIRE(parts.size() == 2);
    int inside = 0;
    int beside = 0;
    for (const DrawCommand* c : canvas.InGroup("labels"))
    {
        if (c->kind != DrawCommand::Kind::Text || c->text.rfind("area ", 0) != 0)
        {
            continue;
        }
        const ScreenPoint size = canvas.MeasureText(c->text, c->style);
        const Box label{c->points[0].x, c->points[0].y, c->points[0].x + size.x, c->points[0].y + size.y};
        INFO(c->text << " at " << label.minX << "," << label.minY);
        // The part it names: the one whose box holds the label's middle, or else the nearest across a gap.
        const float mx = 0.5f * (label.minX + label.maxX);
        const float my = 0.5f * (label.minY + label.maxY);
        bool within = false;
        for (const Box& part : parts)
        {
            if (mx > part.minX && mx < part.maxX && my > part.minY && my < part.maxY)
            {
                within = true;
                // Wholly inside, centred on the part's middle (a rectangle's centroid).
                CHECK(label.minX > part.minX);
                CHECK(label.maxX < part.maxX);
                CHECK(std::fabs(mx - 0.5f * (part.minX + part.maxX)) <= 1.0f);
                CHECK(std::fabs(my - 0.5f * (part.minY + part.maxY)) <= 1.0f);
                ++inside;
            }
        }
        if (!within)
        {
            // Beside a part: on no part, a few pixels from one edge, level with that part's middle.
            float gap = INFINITY;
            const Box* nearest = nullptr;
            for (const Box& part : parts)
            {
                const bool overlaps = label.minX < part.maxX && part.minX < label.maxX && label.minY < part.maxY &&
                                      part.minY < label.maxY;
                CHECK_FALSE(overlaps);
                const float dx = std::max({part.minX - label.maxX, label.minX - part.maxX, 0.0f});
                const float dy = std::max({part.minY - label.maxY, label.minY - part.maxY, 0.0f});
                if (std::hypot(dx, dy) < gap)
                {
                    gap = std::hypot(dx, dy);
                    nearest = &part;
                }
            }
            REQUIRE(nearest != nullptr);
            CHECK(gap <= 10.0f);
            CHECK(my > nearest->minY);
            CHECK(my < nearest->maxY);
            ++beside;
        }
    }
    CHECK(inside == 1); // area 1.50 in the wide part
    CHECK(beside == 1); // area 0.50 beside the narrow one
}

TEST_CASE("A cut that stops inside the body leaves it whole, and the figure says why", "[concave-views]")
{
    const Scene scene = LoadConcave(
        R"({"bodies": [{"name": "box", "box": [2, 1]}], "view": {"figure": "slice", "cut": [[-2, 0.2], [0.3, 0.2]]}})");
    const RecordingCanvas canvas = PaintScene(scene);
    const std::string caption = Caption(canvas);
    CHECK(caption == "The cut runs from (-2.00, 0.20) to (0.30, 0.20) and meets box's outline at (-1.00, 0.20), but "
                     "does not run through box from one side to another: a segment that stops inside is no cut, and "
                     "box stays whole, area 2.00.");
    const std::vector<std::string> texts = canvas.Texts();
    CHECK(std::find(texts.begin(), texts.end(), "After: 1 part") != texts.end());
    CHECK(FilledArea(canvas, "after") == Approx(FilledArea(canvas, "before")).epsilon(1e-4));
}

TEST_CASE("The disc-cast figure stops the disc where its rim first meets the shape, as worked out by hand",
          "[concave-views]")
{
    SECTION("A disc dropped between the arms of a cup lands on the floor of the notch")
    {
        // The floor of the notch is y = 1 and the disc's radius 0.3: the centre stops at y = 1.3, (5 - 1.3) / 5 of
        // the way down, at x = 1.6 + 1.2 t. A convex hull would have stopped it on the arms' tops, at y = 3.3.
        const Scene scene = LoadConcave(R"({"bodies": [{"name": "cup", "polygon": [[0, 0], [4, 0], [4, 3], [3, 3],
            [3, 1], [1, 1], [1, 3], [0, 3]]}, {"name": "ball", "circle": {"radius": 0.3}, "position": [1.6, 5],
            "velocity": [1.2, -5]}], "view": {"figure": "disc-cast"}})");
        const double t = (5.0 - 1.3) / 5.0;
        const RecordingCanvas canvas = PaintScene(scene);
        const std::string caption = Caption(canvas);
        INFO(caption);
        CHECK(caption.find("at t = " + FormatNumber(t) + " of the way: centre (" + FormatNumber(1.6 + 1.2 * t) +
                           ", 1.300)") != std::string::npos);
        CHECK(caption.find("where the outward normal is (0.00, 1.00)") != std::string::npos);
        // The figure numbers no piece: the header names the one the disc lands on by where it lies in the cup, the
        // floor below the notch, whose middle is in the bottom third of the cup's box.
        CHECK(caption.find("The contact point is (2.488, 1.000), on cup's bottom piece,") != std::string::npos);
        // On the figure: the disc drawn at the hit touches the contact point with its rim.
        std::vector<ScreenPoint> discs;
        float radius = 0.0f;
        ScreenPoint contact{};
        for (const DrawCommand* c : canvas.InGroup("hit"))
        {
            if (c->kind == DrawCommand::Kind::Circle)
            {
                discs.push_back(c->points[0]);
                radius = c->radius;
            }
            if (c->kind == DrawCommand::Kind::FillCircle && c->radius == 4.5f)
            {
                contact = c->points[0];
            }
        }
        REQUIRE(discs.size() == 1);
        CHECK(std::hypot(discs[0].x - contact.x, discs[0].y - contact.y) == Approx(radius).margin(0.01));
    }
    SECTION("A disc whose centre passes above a wall catches its corner with its rim")
    {
        // The corner (-0.5, 1.5) lies 0.3 below the centre's path y = 1.8; the rim, radius 0.4, meets it when the
        // centre is sqrt(0.4^2 - 0.3^2) short of it in x.
        const Scene scene = LoadConcave(R"({"bodies": [{"name": "wall", "box": [1, 3]}, {"name": "bullet",
            "circle": {"radius": 0.4}, "position": [-3, 1.8], "velocity": [6, 0]}], "view": {"figure": "disc-cast"}})");
        const double x = -0.5 - std::sqrt(0.4 * 0.4 - 0.3 * 0.3);
        const std::string caption = Caption(PaintScene(scene));
        INFO(caption);
        CHECK(caption.find("at t = " + FormatNumber((x + 3.0) / 6.0) + " of the way") != std::string::npos);
        CHECK(caption.find("The contact point is (-0.50, 1.50)") != std::string::npos);
        // The check adds the printed contact point and radius times the normal, and gives the centre as printed:
        // with the normal's three decimals, 0.40 x -0.661 would give -0.764 beside the centre's -0.765.
        // Four decimals of the normal, ((x + 0.5) / 0.4, 0.3 / 0.4), are enough for the sum to agree.
        char normal[64];
        std::snprintf(normal, sizeof(normal), "(%.4f, %.4f)", (x + 0.5) / 0.4, 0.3 / 0.4);
        CHECK(caption.find("centre (" + FormatNumber(x) + ", 1.800)") != std::string::npos);
        CHECK(caption.find("(-0.50, 1.50) + 0.40 \xC3\x97 " + std::string(normal) + " = (" + FormatNumber(x) +
                           ", 1.800).") != std::string::npos);
        CHECK(caption.find("but for rounding") == std::string::npos);
    }
    SECTION("A disc that passes a radius clear of the wall misses it")
    {
        const Scene scene = LoadConcave(R"({"bodies": [{"name": "wall", "box": [1, 3]}, {"name": "bullet",
            "circle": {"radius": 0.4}, "position": [-3, 1.95], "velocity": [6, 0]}], "view": {"figure": "disc-cast"}})");
        const RecordingCanvas canvas = PaintScene(scene);
        CHECK(Caption(canvas).find("never enters wall's outline pushed out by the radius") != std::string::npos);
        CHECK(canvas.InGroup("hit").empty());
    }
}

TEST_CASE("The pieces figure tests the pairs of pieces whose boxes overlap, one a step, then merges them",
          "[concave-views]")
{
    // An L of two pieces and a box across the seam between them, nothing turned: each piece's box is the box of its
    // corners, which this test takes from the pieces themselves.
    const Scene scene = LoadConcave(R"({"bodies": [{"name": "L", "polygon": [[0, 0], [4, 0], [4, 1], [1, 1], [1, 3],
        [0, 3]]}, {"name": "box", "box": [1.2, 0.6], "position": [1.0, 1.2]}], "view": {"figure": "pieces"}})");
    const Body& l = scene.bodies[0];
    const Body& box = scene.bodies[1];
    REQUIRE(l.concave.parts.size() == 2);
    int overlapping = 0;
    for (const ConcavePart& part : l.concave.parts)
    {
        double lo[2] = {INFINITY, INFINITY};
        double hi[2] = {-INFINITY, -INFINITY};
        for (const Vec2& v : part.shape.polygon.Vertices())
        {
            lo[0] = std::min(lo[0], v.x);
            lo[1] = std::min(lo[1], v.y);
            hi[0] = std::max(hi[0], v.x);
            hi[1] = std::max(hi[1], v.y);
        }
        // The box spans [0.4, 1.6] x [0.9, 1.5].
        overlapping += lo[0] <= 1.6 && hi[0] >= 0.4 && lo[1] <= 1.5 && hi[1] >= 0.9 ? 1 : 0;
    }
    FigureSetup setup = SetUpFigure(scene, {});
    INFO(setup.error);
    REQUIRE(setup.Ok());
    const int steps = FigureStepCount(scene, setup);
    CHECK(steps == overlapping + 2);
    CHECK(setup.figure.step == steps - 1);
    std::vector<std::string> captions;
    for (int k = 0; k < steps; ++k)
    {
        const RecordingCanvas canvas = painter_test::PaintStep(scene, setup, k);
        captions.push_back(Caption(canvas));
        INFO(captions.back());
        CHECK(captions.back().rfind("Step " + std::to_string(k + 1) + " of " + std::to_string(steps) + ": ", 0) == 0);
    }
    CHECK(captions[0].find("L has 2 pieces and box 1, so there are 2 pairs of pieces; " + std::to_string(overlapping) +
                           (overlapping == 1 ? " has" : " have")) != std::string::npos);
    // The verdict is the concave Collide's, whose own count of pairs tested agrees with the steps.
    const ConcaveManifold m = Collide(l.concave, l.Xf(), box.shape, box.Xf());
    CHECK(m.pairsTested == overlapping);
    REQUIRE(m.manifold.overlap);
    INFO(captions.back());
    CHECK(captions.back().find("overlap by " + FormatNumber(m.manifold.depth)) != std::string::npos);
    // The box spans x from 0.4 to 1.6: it reaches 0.6 into the L's arm (x < 1), whose push is 0.6 to the right,
    // deeper than the foot's 0.1 up (the foot's top is y = 1, the box's bottom 0.9), so the arm's pair decides.
    CHECK(m.manifold.depth == Approx(0.6));
    CHECK(captions.back().find("along (1.00, 0.00)") != std::string::npos);
}

TEST_CASE("A gap too thin to see as a bar is marked by ticks and arrows at its true ends, and named", "[concave-views]")
{
    // The box 0.002 above the L's foot: a bar of a fraction of a pixel. It stays its true length; two arrow heads
    // point at its ends from outside and span several pixels, and its number names it.
    const Scene scene = LoadConcave(R"({"bodies": [{"name": "L", "polygon": [[0, 0], [4, 0], [4, 1], [1, 1], [1, 3],
        [0, 3]]}, {"name": "box", "box": [1, 1], "position": [2, 1.502]}], "view": {"figure": "pieces"}})");
    FigureSetup setup;
    RecordingCanvas canvas;
    PaintThroughCamera(scene, setup, canvas);
    const View& view = setup.figure.view;
    int heads = 0;
    double low = INFINITY;
    double high = -INFINITY;
    for (const DrawCommand* c : canvas.InGroup("gap"))
    {
        if (c->kind == DrawCommand::Kind::Segment && c->thickness >= 3.0f)
        {
            // The bar: the gap's true length.
            CHECK(std::fabs(ToWorld(view, c->points[0]).y - ToWorld(view, c->points[1]).y) ==
                  Approx(0.002).margin(1.0 / view.zoom));
        }
        if (c->kind == DrawCommand::Kind::FillConvex)
        {
            ++heads;
            for (const ScreenPoint& p : c->points)
            {
                low = std::min(low, static_cast<double>(p.y));
                high = std::max(high, static_cast<double>(p.y));
            }
        }
    }
    CHECK(heads == 2);
    CHECK(high - low >= 8.0);
    bool named = false;
    for (const DrawCommand* c : canvas.InGroup("labels"))
    {
        named = named || (c->kind == DrawCommand::Kind::Text && c->text.find("0.002") != std::string::npos);
    }
    CHECK(named);
}

TEST_CASE("The pieces figure's verdict on a pair apart draws the gap, as the convex verdict does", "[concave-views]")
{
    // Lesson 18's box in the notch of the L: the L's foot ends at y = 1 and the box's bottom is at 1.5; no box of a
    // piece overlaps the box, so the gap is the one between the foot's box and the box: 0.5, along (0, 1).
    const Scene scene = LoadConcave(R"({"bodies": [{"name": "L", "polygon": [[0, 0], [4, 0], [4, 1], [1, 1], [1, 3],
        [0, 3]]}, {"name": "box", "box": [1, 1], "position": [2, 2]}], "view": {"figure": "pieces"}})");
    FigureSetup setup;
    RecordingCanvas canvas;
    PaintThroughCamera(scene, setup, canvas);
    const View& view = setup.figure.view;
    // The separating line, dashed in the gap's green: every dash on y = 1.25, the middle of the gap, along the box's
    // width (x from 1.5 to 2.5) where it faces the foot, and clear of the L's arm (x < 1), which it does not part.
    int dashes = 0;
    int bars = 0;
    double left = INFINITY;
    double right = -INFINITY;
    for (const DrawCommand* c : canvas.InGroup("gap"))
    {
        REQUIRE(c->kind == DrawCommand::Kind::Segment);
        CHECK(c->color == palette::kGap);
        const Vec2 p = ToWorld(view, c->points[0]);
        const Vec2 q = ToWorld(view, c->points[1]);
        if (c->thickness < 3.0f)
        {
            ++dashes;
            CHECK(p.y == Approx(1.25).margin(1.0 / view.zoom));
            CHECK(q.y == Approx(1.25).margin(1.0 / view.zoom));
            left = std::min({left, p.x, q.x});
            right = std::max({right, p.x, q.x});
        }
        else
        {
            // The gap itself: from the foot's top to the box's bottom, where both lie across x (1.5 to 2.5).
            ++bars;
            CHECK(std::min(p.y, q.y) == Approx(1.0).margin(1.0 / view.zoom));
            CHECK(std::max(p.y, q.y) == Approx(1.5).margin(1.0 / view.zoom));
            CHECK(p.x == Approx(q.x).margin(1.0 / view.zoom));
            CHECK(p.x > 1.5);
            CHECK(p.x < 2.5);
        }
    }
    CHECK(dashes > 3);
    CHECK(bars == 1);
    CHECK(left <= 1.5);
    CHECK(left > 1.0);
    CHECK(right >= 2.5);
    bool named = false;
    for (const DrawCommand* c : canvas.InGroup("labels"))
    {
        named = named || (c->kind == DrawCommand::Kind::Text && c->text == "gap at least 0.50");
    }
    CHECK(named);
}

TEST_CASE("Where a lesson tells of the outline a circle is swept against, a figure of its section draws that outline",
          "[concave]")
{
    // Lesson 8 told of the polygon's outline pushed out by the radius, then showed circle_and_polygon, whose figure
    // draws the pentagon as it is. A paragraph that speaks of that outline, and the figures after it up to the next
    // heading: one of them draws the outline (the disc-cast figure's dashed "pushed out" group).
    namespace fs = std::filesystem;
    const fs::path tutorials = fs::path(SATVIZ_SOURCE_DIR) / "tutorials";
    // The stems of the figures a paragraph shows: "![alt](figures/STEM.png)", read with a few lines of parsing (not
    // std::regex, whose GCC 12 header the sanitizer build's -Werror rejects).
    const auto figures = [](const std::string& text) {
        std::vector<std::string> found;
        for (size_t at = text.find("!["); at != std::string::npos; at = text.find("![", at + 2))
        {
            const size_t close = text.find(']', at + 2);
            const std::string link = "](figures/";
            if (close == std::string::npos || text.compare(close, link.size(), link) != 0)
            {
                continue;
            }
            size_t end = close + link.size();
            while (end < text.size() && (std::isalnum(static_cast<unsigned char>(text[end])) || text[end] == '_'))
            {
                ++end;
            }
            const size_t begin = close + link.size();
            if (end > begin && text.compare(end, 5, ".png)") == 0)
            {
                found.push_back(text.substr(begin, end - begin));
            }
        }
        return found;
    };
    int told = 0;
    for (const auto& entry : fs::directory_iterator(tutorials))
    {
        if (entry.path().extension() != ".md" || entry.path().filename() == "README.md")
        {
            continue;
        }
        // Paragraphs: runs of lines between blank ones, joined by spaces.
        std::ifstream in(entry.path());
        std::vector<std::string> paragraphs(1);
        for (std::string line; std::getline(in, line);)
        {
            if (line.find_first_not_of(" \t") == std::string::npos)
            {
                paragraphs.emplace_back();
                continue;
            }
            paragraphs.back() += (paragraphs.back().empty() ? "" : " ") + line;
        }
        for (size_t p = 0; p < paragraphs.size(); ++p)
        {
            const std::string& text = paragraphs[p];
            if (text.find("pushed out by the radius") == std::string::npos &&
                text.find("pushed-out outline") == std::string::npos)
            {
                continue;
            }
            std::vector<std::string> stems;
            for (size_t q = p; q < paragraphs.size() && (q == p || paragraphs[q].rfind('#', 0) != 0); ++q)
            {
                for (const std::string& stem : figures(paragraphs[q]))
                {
                    stems.push_back(stem);
                }
            }
            if (stems.empty())
            {
                continue; // a pitfall's line, with no figure to draw it
            }
            ++told;
            INFO(entry.path().filename().string() << ": " << text.substr(0, 160));
            bool drawn = false;
            for (const std::string& stem : stems)
            {
                fs::path scene = tutorials / "scenes" / (stem + ".json");
                if (!fs::exists(scene))
                {
                    scene = tutorials / "scenes" / "concave" / (stem + ".json");
                }
                if (!fs::exists(scene))
                {
                    continue; // a step's figure, SCENE-stepN
                }
                const Scene loaded = painter_test::LoadSimulated(scene.string());
                FigureSetup setup = SetUpFigure(loaded, {});
                REQUIRE(setup.Ok());
                const RecordingCanvas canvas = painter_test::PaintStep(loaded, setup, setup.figure.step);
                drawn = drawn || !canvas.InGroup("pushed out").empty();
            }
            CHECK(drawn);
        }
    }
    CHECK(told >= 1);
}

TEST_CASE("Where the lessons first show a disc-cast figure, the text by it says what each of its marks is", "[concave]")
{
    // Lesson 8 showed circle_and_polygon_cast and named only its dashed outline: its black path arrow, the short black
    // normal, the two pale lines bounding the swept band and the three discs were explained only in lesson 19. The
    // first disc-cast figure in reading order (the figures whose picture draws the "pushed out" group): the words
    // for each mark in its paragraph, the one before it or the ones after it up to the next figure or heading.
    namespace fs = std::filesystem;
    const fs::path tutorials = fs::path(SATVIZ_SOURCE_DIR) / "tutorials";
    std::vector<fs::path> lessons;
    for (const auto& entry : fs::directory_iterator(tutorials))
    {
        const std::string name = entry.path().filename().string();
        if (entry.path().extension() == ".md" && name.size() > 3 && std::isdigit(static_cast<unsigned char>(name[0])))
        {
            lessons.push_back(entry.path());
        }
    }
    std::sort(lessons.begin(), lessons.end());
    const auto discCast = [&](const std::string& stem) {
        const fs::path scene = tutorials / "scenes" / "concave" / (stem + ".json");
        if (!fs::exists(scene))
        {
            return false;
        }
        const Scene loaded = painter_test::LoadSimulated(scene.string());
        FigureSetup setup = SetUpFigure(loaded, {});
        REQUIRE(setup.Ok());
        return !painter_test::PaintStep(loaded, setup, setup.figure.step).InGroup("pushed out").empty();
    };
    bool found = false;
    for (size_t l = 0; l < lessons.size() && !found; ++l)
    {
        std::ifstream in(lessons[l]);
        std::vector<std::string> paragraphs(1);
        for (std::string line; std::getline(in, line);)
        {
            if (line.find_first_not_of(" \t") == std::string::npos)
            {
                paragraphs.emplace_back();
                continue;
            }
            paragraphs.back() += (paragraphs.back().empty() ? "" : " ") + line;
        }
        for (size_t p = 0; p < paragraphs.size() && !found; ++p)
        {
            const std::string& text = paragraphs[p];
            const std::string link = "](figures/";
            const size_t at = text.rfind("![", 0) == 0 ? text.find(link) : std::string::npos;
            if (at == std::string::npos)
            {
                continue;
            }
            const size_t begin = at + link.size();
            const std::string stem = text.substr(begin, text.find(".png", begin) - begin);
            if (!discCast(stem))
            {
                continue;
            }
            found = true;
            std::string around = p > 0 ? paragraphs[p - 1] : "";
            for (size_t q = p + 1; q < paragraphs.size() && paragraphs[q].rfind('#', 0) != 0 &&
                                   paragraphs[q].rfind("![", 0) != 0;
                 ++q)
            {
                around += " " + paragraphs[q];
            }
            INFO(lessons[l].filename().string() << ", " << stem);
            for (const char* words : {"ring", "filled", "dashed", "pale lines", "path", "normal"})
            {
                INFO("the words \"" << words << "\"");
                CHECK(around.find(words) != std::string::npos);
            }
        }
    }
    CHECK(found);
}
