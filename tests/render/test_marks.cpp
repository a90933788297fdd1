// SPDX-License-Identifier: MIT
// No figure hides its own marks: a dot (a vertex axis's vertex, a contact, the origin of the Minkowski inset) or a
// small arrow head (a normal, a velocity, the axis line, a time marker) is not drawn under a later line, fill or
// head that covers it, and each moving body of a figure that draws motion has its velocity arrow. Labels over
// marks are the label test's (test_labels.cpp); this one checks the drawing order and placement of the marks.

#include "painter_support.h"

#include <satviz/render/palette.h>
#include <satviz/render/view.h>
#include <satviz/scene_world.h>

#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

using namespace satviz;

namespace
{

// Paints every figure of the course as the figures target draws it (tutorials/figures.cmake: each figure at its own
// step, every step of the stepped figures, every step of the face-view figures) on a recording canvas, and hands each
// to `check(stem, faces, setup, step, canvas)`; `faces` is true for the face view. The canvas is the check's to
// measure text on.
template <typename Check>
void ForEachCourseFigure(Check&& check)
{
    const auto lists = painter_test::CourseFigureLists();
    for (const char* list : {"SATVIZ_FIGURE_SCENES", "SATVIZ_STEP_SCENES", "SATVIZ_FACE_STEP_SCENES"})
    {
        const bool allSteps = std::string(list) != "SATVIZ_FIGURE_SCENES";
        const bool faces = std::string(list) == "SATVIZ_FACE_STEP_SCENES";
        for (const std::string& stem : lists.at(list))
        {
            const Scene scene = painter_test::LessonScene(stem);
            FigureOptions options;
            options.setSteps = faces;
            options.steps = StepView::Faces;
            FigureSetup setup = SetUpFigure(scene, options);
            REQUIRE(setup.Ok());
            const int first = allSteps ? 0 : setup.figure.step;
            const int last = allSteps ? FigureStepCount(scene, setup) - 1 : setup.figure.step;
            for (int k = first; k <= last; ++k)
            {
                RecordingCanvas canvas = painter_test::PaintStep(scene, setup, k);
                check(stem, faces, setup, k, canvas);
            }
        }
    }
}

float Alpha(Color color)
{
    return static_cast<float>(color & 0xFFu) / 255.0f;
}

float SegmentDistance(ScreenPoint a, ScreenPoint b, ScreenPoint p)
{
    const float dx = b.x - a.x;
    const float dy = b.y - a.y;
    const float length2 = dx * dx + dy * dy;
    float t = length2 > 0.0f ? ((p.x - a.x) * dx + (p.y - a.y) * dy) / length2 : 0.0f;
    t = std::fmax(0.0f, std::fmin(1.0f, t));
    return std::hypot(a.x + t * dx - p.x, a.y + t * dy - p.y);
}

// Whether the drawing call paints the point p.
bool Paints(const DrawCommand& c, ScreenPoint p, RecordingCanvas& canvas)
{
    switch (c.kind)
    {
    case DrawCommand::Kind::Segment:
        return SegmentDistance(c.points[0], c.points[1], p) < 0.5f * c.thickness;
    case DrawCommand::Kind::Polyline:
    {
        const size_t n = c.points.size();
        for (size_t i = 0; i + 1 < n + (c.closed ? 1 : 0); ++i)
        {
            if (SegmentDistance(c.points[i], c.points[(i + 1) % n], p) < 0.5f * c.thickness)
            {
                return true;
            }
        }
        return false;
    }
    case DrawCommand::Kind::FillConvex:
    {
        const size_t n = c.points.size();
        int sign = 0;
        for (size_t i = 0; i < n; ++i)
        {
            const ScreenPoint a = c.points[i];
            const ScreenPoint b = c.points[(i + 1) % n];
            const float cross = (b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x);
            const int s = cross > 0.0f ? 1 : (cross < 0.0f ? -1 : 0);
            if (s != 0 && sign != 0 && s != sign)
            {
                return false;
            }
            sign = sign == 0 ? s : sign;
        }
        return true;
    }
    case DrawCommand::Kind::FillCircle:
        return std::hypot(p.x - c.points[0].x, p.y - c.points[0].y) < c.radius;
    case DrawCommand::Kind::Circle:
        return std::fabs(std::hypot(p.x - c.points[0].x, p.y - c.points[0].y) - c.radius) < 0.5f * c.thickness;
    case DrawCommand::Kind::FillRect:
        return p.x > c.points[0].x && p.x < c.points[1].x && p.y > c.points[0].y && p.y < c.points[1].y;
    case DrawCommand::Kind::Text:
    {
        const ScreenPoint size = canvas.MeasureText(c.text, c.style);
        return p.x > c.points[0].x && p.x < c.points[0].x + size.x && p.y > c.points[0].y &&
               p.y < c.points[0].y + size.y;
    }
    }
    return false;
}

// A mark: an opaque dot of a few pixels or an opaque triangle of at most 20 pixels (an arrow head, a time marker),
// with the points of it that must stay in sight: its middle and halfway out from it.
bool MarkSamples(const DrawCommand& c, std::vector<ScreenPoint>& samples)
{
    samples.clear();
    if (Alpha(c.color) < 0.75f)
    {
        return false;
    }
    if (c.kind == DrawCommand::Kind::FillCircle && c.radius >= 3.0f && c.radius <= 8.0f)
    {
        const ScreenPoint m = c.points[0];
        const float r = 0.5f * c.radius;
        samples = {m, {m.x + r, m.y}, {m.x - r, m.y}, {m.x, m.y + r}, {m.x, m.y - r}};
        return true;
    }
    if (c.kind == DrawCommand::Kind::FillConvex && c.points.size() == 3)
    {
        float minX = INFINITY, maxX = -INFINITY, minY = INFINITY, maxY = -INFINITY;
        ScreenPoint m{0.0f, 0.0f};
        for (const ScreenPoint& p : c.points)
        {
            minX = std::fmin(minX, p.x);
            maxX = std::fmax(maxX, p.x);
            minY = std::fmin(minY, p.y);
            maxY = std::fmax(maxY, p.y);
            m = {m.x + p.x / 3.0f, m.y + p.y / 3.0f};
        }
        if (maxX - minX > 20.0f || maxY - minY > 20.0f)
        {
            return false;
        }
        samples.push_back(m);
        for (const ScreenPoint& p : c.points)
        {
            samples.push_back({0.5f * (m.x + p.x), 0.5f * (m.y + p.y)});
        }
        return true;
    }
    return false;
}

// The marks of a recorded figure that later calls hide: two or more of a mark's points painted over by a later
// call of another group, or of another colour, at least 40% opaque. Labels are left to the label test, the key
// draws its own swatches, and a contact point drawn on a vertex axis's vertex (the contact is that vertex) is the
// same point marked twice.
std::vector<std::string> HiddenMarks(RecordingCanvas& canvas)
{
    std::vector<std::string> hidden;
    const std::vector<DrawCommand>& commands = canvas.commands;
    std::vector<ScreenPoint> samples;
    for (size_t i = 0; i < commands.size(); ++i)
    {
        const DrawCommand& mark = commands[i];
        if (mark.group == "labels" || mark.group == "legend" || !MarkSamples(mark, samples))
        {
            continue;
        }
        int covered = 0;
        std::string by;
        for (const ScreenPoint& p : samples)
        {
            for (size_t j = i + 1; j < commands.size(); ++j)
            {
                const DrawCommand& later = commands[j];
                if (later.group == "labels" || later.group == "legend" || Alpha(later.color) < 0.4f ||
                    (later.group == mark.group && later.color == mark.color))
                {
                    continue;
                }
                // A ring of the background round a dot, drawn with it, sets it off.
                if (later.group == mark.group && j <= i + 2 && (later.color | 0xFFu) == (palette::kBackground | 0xFFu))
                {
                    continue;
                }
                if (later.group == "contacts" && mark.group == "projection" &&
                    later.kind == DrawCommand::Kind::FillCircle && mark.kind == DrawCommand::Kind::FillCircle)
                {
                    continue;
                }
                if (Paints(later, p, canvas))
                {
                    ++covered;
                    by = later.group;
                    break;
                }
            }
        }
        if (covered >= 2)
        {
            std::ostringstream text;
            text << (mark.kind == DrawCommand::Kind::FillCircle ? "a dot" : "a head") << " of " << mark.group << " at ("
                 << mark.points[0].x << ", " << mark.points[0].y << ") is hidden by " << by << " (" << covered << " of "
                 << samples.size() << " points)";
            hidden.push_back(text.str());
        }
    }
    return hidden;
}

} // namespace

TEST_CASE("The hidden-mark check finds a dot or a head under a later line, and not one drawn over it", "[marks]")
{
    RecordingCanvas under;
    under.BeginGroup("projection");
    under.FillCircle({50.0f, 50.0f}, 4.0f, palette::kInk);
    under.BeginGroup("exit");
    under.Segment({40.0f, 48.0f}, {60.0f, 52.0f}, palette::kGap, 2.5f);
    CHECK(HiddenMarks(under).size() == 1);

    RecordingCanvas over;
    over.BeginGroup("exit");
    over.Segment({40.0f, 48.0f}, {60.0f, 52.0f}, palette::kGap, 2.5f);
    over.BeginGroup("projection");
    over.FillCircle({50.0f, 50.0f}, 4.0f, palette::kInk);
    CHECK(HiddenMarks(over).empty());

    // A head on a bar of a like colour drawn after it is lost; a faint fill over it is not a cover.
    RecordingCanvas bar;
    bar.BeginGroup("best");
    const ScreenPoint head[3] = {{50.0f, 60.0f}, {45.0f, 51.0f}, {55.0f, 51.0f}};
    bar.FillConvex(head, 3, palette::kBest);
    bar.BeginGroup("projection");
    bar.Segment({20.0f, 55.0f}, {90.0f, 55.0f}, palette::kShapeA, 6.0f);
    CHECK(HiddenMarks(bar).size() == 1);
    RecordingCanvas faint;
    faint.BeginGroup("best");
    faint.FillConvex(head, 3, palette::kBest);
    faint.BeginGroup("shapes");
    faint.FillRect({0.0f, 0.0f}, {100.0f, 100.0f}, WithAlpha(palette::kShapeA, 0.22f));
    CHECK(HiddenMarks(faint).empty());
}

TEST_CASE("No figure of the course draws a mark under a later line, fill or head that hides it", "[marks]")
{
    int figures = 0;
    int failing = 0;
    ForEachCourseFigure([&](const std::string& stem, bool faces, const FigureSetup&, int k, RecordingCanvas& canvas) {
        const std::vector<std::string> hidden = HiddenMarks(canvas);
        INFO((faces ? "faces/" : "") << stem << " step " << k + 1);
        for (const std::string& problem : hidden)
        {
            UNSCOPED_INFO(problem);
        }
        CHECK(hidden.empty());
        failing += hidden.empty() ? 0 : 1;
        ++figures;
    });
    INFO(failing << " of " << figures << " figures");
    CHECK(figures > 100);
    CHECK(failing == 0);
}

TEST_CASE("A figure that draws motion draws each moving body's velocity, in a static figure too", "[marks]")
{
    // l16_peg tests the plank against the peg at one instant (a static query): its velocity, 2 m/s down, is drawn
    // from its centre, pointing down, and named with its speed.
    Scene scene = painter_test::Load(std::string(SATVIZ_SOURCE_DIR) + "/tutorials/scenes/l16_peg.json");
    FigureSetup setup = SetUpFigure(scene, {});
    REQUIRE(setup.Ok());
    REQUIRE(!setup.study.sweep);
    REQUIRE((setup.figure.layers & kLayerSwept) != 0);
    RecordingCanvas canvas;
    PaintFigure(canvas, scene, setup.study, setup.figure);
    const Body& plank = scene.bodies[static_cast<size_t>(setup.study.bodyB)];
    REQUIRE(plank.name == "plank");
    const ScreenPoint centre = ToScreen(setup.figure.view, plank.position);
    bool arrow = false;
    for (const DrawCommand* c : canvas.InGroup("swept"))
    {
        if (c->kind == DrawCommand::Kind::Segment &&
            std::hypot(c->points[0].x - centre.x, c->points[0].y - centre.y) < 1.0f)
        {
            arrow = std::fabs(c->points[1].x - centre.x) < 1.0f && c->points[1].y > centre.y + 40.0f;
        }
    }
    CHECK(arrow);
    bool named = false;
    for (const std::string& text : canvas.Texts())
    {
        named = named || text == "v = 2.00 m/s";
    }
    CHECK(named);

    // Without the swept layer, no arrow.
    setup.figure.layers &= ~kLayerSwept;
    RecordingCanvas plain;
    PaintFigure(plain, scene, setup.study, setup.figure);
    CHECK(plain.InGroup("swept").empty());
}

TEST_CASE("A face's normal arrow keeps its head off the axis line's bars, where it would merge with them", "[marks]")
{
    // fly_by's verdict: the best axis so far is the normal of block's edge 0, which faces the axis line a short way
    // below the block; a head of light blue on the block's dark blue bar could not be told from it.
    Scene scene = painter_test::Load(std::string(SATVIZ_SOURCE_DIR) + "/tutorials/scenes/fly_by.json");
    FigureSetup setup = SetUpFigure(scene, {});
    REQUIRE(setup.Ok());
    RecordingCanvas canvas;
    PaintFigure(canvas, scene, setup.study, setup.figure);
    std::vector<const DrawCommand*> bars;
    for (const DrawCommand* c : canvas.InGroup("projection"))
    {
        if (c->kind == DrawCommand::Kind::Segment && c->thickness >= 5.0f)
        {
            bars.push_back(c);
        }
    }
    REQUIRE(bars.size() >= 2);
    int heads = 0;
    std::vector<ScreenPoint> samples;
    for (const char* group : {"best", "projection"})
    {
        for (const DrawCommand* c : canvas.InGroup(group))
        {
            if (!MarkSamples(*c, samples) || c->kind != DrawCommand::Kind::FillConvex)
            {
                continue;
            }
            ++heads;
            for (const ScreenPoint& p : samples)
            {
                for (const DrawCommand* bar : bars)
                {
                    INFO(group << " head at (" << p.x << ", " << p.y << ")");
                    CHECK(SegmentDistance(bar->points[0], bar->points[1], p) >= 0.5f * bar->thickness + 1.0f);
                }
            }
        }
    }
    CHECK(heads >= 2);
}

TEST_CASE("A vermillion dot in a figure of the course is a contact point, as the key says", "[marks]")
{
    // The key gives the vermillion dot one meaning, a contact point: l07_voronoi drew the ball's centre so. A
    // slice's cut is drawn vermillion, its ends and its crossings of the outline as dots on that line, named by
    // their coordinates: they are the cut's. In the Minkowski inset the dot is where the origin's path first
    // touches the difference, the first contact seen there.
    int contacts = 0;
    ForEachCourseFigure(
        [&](const std::string& stem, bool faces, const FigureSetup& setup, int k, const RecordingCanvas& canvas) {
            for (const DrawCommand& c : canvas.commands)
            {
                if (c.kind != DrawCommand::Kind::FillCircle || (c.color | 0xFFu) != palette::kResult ||
                    (c.color & 0xFFu) < 0xC0u || c.group == "legend")
                {
                    continue;
                }
                INFO((faces ? "faces/" : "") << stem << " step " << k + 1 << ": a vermillion dot in \"" << c.group
                                             << "\" at (" << c.points[0].x << ", " << c.points[0].y << ")");
                const bool contact = c.group == "contacts" || c.group == "push" || c.group == "hit" ||
                                     c.group == "hits" || c.group == "response" || c.group == "minkowski";
                const bool cut = setup.figure.kind == FigureKind::Slice && c.group == "before";
                CHECK((contact || cut));
                contacts += contact ? 1 : 0;
            }
        });
    CHECK(contacts > 20);
}

TEST_CASE("Every fill colour a figure of the course draws is a body's colour or explained by lesson 1's key",
          "[marks][legend]")
{
    // slice_u filled its parts sky blue, orange and green, l18_decompose its fourth piece yellow, and no key said
    // what a fill in those colours means. The oracle is lesson 1's key as drawn: the colours of its swatches' fills
    // (a band is paler on the number line than in the key), beside the pair's own colours (blue A, orange B, grey for
    // the other bodies), which lesson 1 explains in words. The Voronoi regions are named in their own figure's title
    // and labels.
    std::set<Color> keyed;
    {
        const Scene scene = painter_test::LessonScene("l01_legend");
        FigureSetup setup = SetUpFigure(scene, FigureOptions{});
        REQUIRE(setup.Ok());
        const RecordingCanvas key = painter_test::PaintStep(scene, setup, setup.figure.step);
        const std::vector<const DrawCommand*> legend = key.InGroup("legend");
        REQUIRE(legend.size() > 20);
        for (size_t i = 1; i < legend.size(); ++i) // the first is the key's panel
        {
            const DrawCommand& c = *legend[i];
            if (c.kind == DrawCommand::Kind::FillRect || c.kind == DrawCommand::Kind::FillConvex ||
                c.kind == DrawCommand::Kind::FillCircle)
            {
                keyed.insert(c.color >> 8);
            }
        }
    }
    const auto bodyColour = [](Color c) {
        const Color rgb = c | 0xFFu;
        return rgb == palette::kShapeA || rgb == palette::kShapeB || rgb == palette::kShapeBInk ||
               rgb == palette::kOther || rgb == palette::kBackground || rgb == palette::kPanel || rgb == palette::kInk;
    };
    std::set<std::string> unexplained;
    int fills = 0;
    ForEachCourseFigure(
        [&](const std::string& stem, bool faces, const FigureSetup&, int, const RecordingCanvas& canvas) {
            for (const DrawCommand& c : canvas.commands)
            {
                const bool fill = c.kind == DrawCommand::Kind::FillRect || c.kind == DrawCommand::Kind::FillConvex ||
                                  c.kind == DrawCommand::Kind::FillCircle;
                // An arrow's head is filled in its line's colour: the line is the mark.
                bool head = c.kind == DrawCommand::Kind::FillConvex && c.points.size() == 3;
                for (size_t i = 0; head && i < 3; ++i)
                {
                    const ScreenPoint& p = c.points[i];
                    const ScreenPoint& q = c.points[(i + 1) % 3];
                    head = std::hypot(q.x - p.x, q.y - p.y) <= 24.0f;
                }
                if (!fill || head || c.group == "legend" || c.group == "voronoi" || bodyColour(c.color))
                {
                    continue;
                }
                ++fills;
                if (keyed.count(c.color >> 8) == 0)
                {
                    std::ostringstream what;
                    what << (faces ? "faces/" : "") << stem << ": a fill " << std::hex << c.color << " in \"" << c.group
                         << "\"";
                    unexplained.insert(what.str());
                }
            }
        });
    for (const std::string& u : unexplained)
    {
        UNSCOPED_INFO(u);
    }
    CHECK(unexplained.empty());
    CHECK(fills > 100);
}

TEST_CASE("Lesson 1's key draws each line of the projection layer as the figures draw it, the axis's grey arrow, the "
          "intervals' bars and their dashed guides",
          "[marks][legend]")
{
    // Every step figure draws the axis tested as a grey arrow named "axis N", each shape's interval as a bar along it
    // and thin dashed lines from the shape to the bar's ends; the key had no row for any of them, and its only grey
    // arrow was "a push through a seam". The oracle is lesson 1's key as drawn: each line the projection layer draws
    // in the grey of the axis or in a body's colour (the bars opaque, the guides translucent) has a swatch line of
    // the same colour and width. Lines drawn faint (a face decided without evaluation) are the same marks, paler.
    const auto style = [](const DrawCommand& c) {
        return std::pair<Color, int>{c.color >> 8, static_cast<int>(std::lround(c.thickness * 10.0f))};
    };
    std::set<std::pair<Color, int>> keyed;
    {
        const Scene scene = painter_test::LessonScene("l01_legend");
        FigureSetup setup = SetUpFigure(scene, FigureOptions{});
        REQUIRE(setup.Ok());
        const RecordingCanvas key = painter_test::PaintStep(scene, setup, setup.figure.step);
        for (const DrawCommand* c : key.InGroup("legend"))
        {
            if (c->kind == DrawCommand::Kind::Segment)
            {
                keyed.insert(style(*c));
            }
        }
    }
    const Color lines[] = {palette::kMuted >> 8, palette::kShapeA >> 8, palette::kShapeB >> 8,
                           palette::kShapeBInk >> 8};
    std::map<std::pair<Color, int>, std::string> unexplained; // each line's style, and the first figure that draws it
    int seen = 0;
    ForEachCourseFigure([&](const std::string& stem, bool faces, const FigureSetup&, int, const RecordingCanvas& canvas) {
        for (const DrawCommand* c : canvas.InGroup("projection"))
        {
            const bool ours = std::find(std::begin(lines), std::end(lines), c->color >> 8) != std::end(lines);
            // Opaque (a bar, the arrow's shaft) or as translucent as a guide; not a faint face's or the swept bar.
            const Color alpha = c->color & 0xFFu;
            if (c->kind != DrawCommand::Kind::Segment || !ours || (alpha < 0xC0u && (alpha < 0x80u || alpha > 0x90u)))
            {
                continue;
            }
            ++seen;
            if (keyed.count(style(*c)) == 0 && unexplained.count(style(*c)) == 0)
            {
                std::ostringstream what;
                what << "a line " << std::hex << c->color << std::dec << ", " << c->thickness << " wide, in "
                     << (faces ? "faces/" : "") << stem << " and on";
                unexplained[style(*c)] = what.str();
            }
        }
    });
    for (const auto& [line, what] : unexplained)
    {
        UNSCOPED_INFO(what);
    }
    CHECK(unexplained.empty());
    CHECK(seen > 500);
}

TEST_CASE("No end value of a number line runs into its band, and no tick value of a time bar is crowded by a marker",
          "[marks]")
{
    // bullet_wall: the wall's 0.010 sat on the top of the gap band, and the time bar's 0.5 sat squeezed between the
    // latest entry's triangle (0.482) and the earliest exit's (0.517).
    RecordingCanvas measure;
    int bands = 0;
    ForEachCourseFigure([&](const std::string& stem, bool faces, const FigureSetup&, int k,
                            const RecordingCanvas& canvas) {
        const auto box = [&](const DrawCommand& t) {
            const ScreenPoint size = measure.MeasureText(t.text, t.style);
            return std::array<float, 4>{t.points[0].x, t.points[0].y, t.points[0].x + size.x, t.points[0].y + size.y};
        };
        const auto meet = [](const std::array<float, 4>& a, const std::array<float, 4>& b, float grow) {
            return a[0] - grow < b[2] && b[0] < a[2] + grow && a[1] - grow < b[3] && b[1] < a[3] + grow;
        };
        std::vector<std::array<float, 4>> bandRects, triangles;
        for (const DrawCommand* c : canvas.InGroup("panel"))
        {
            if (c->kind == DrawCommand::Kind::FillRect && c->color != palette::kPanel)
            {
                bandRects.push_back({c->points[0].x, c->points[0].y, c->points[1].x, c->points[1].y});
            }
        }
        for (const DrawCommand* c : canvas.InGroup("timebar"))
        {
            if (c->kind == DrawCommand::Kind::FillConvex && c->points.size() == 3)
            {
                float x0 = INFINITY, y0 = INFINITY, x1 = -INFINITY, y1 = -INFINITY;
                for (const ScreenPoint& p : c->points)
                {
                    x0 = std::min(x0, p.x);
                    y0 = std::min(y0, p.y);
                    x1 = std::max(x1, p.x);
                    y1 = std::max(y1, p.y);
                }
                triangles.push_back({x0, y0, x1, y1});
            }
        }
        bands += static_cast<int>(bandRects.size());
        for (const DrawCommand* c : canvas.InGroup("panel"))
        {
            // An end value is a number alone; the band's own size ("0.96 behind") is written inside it.
            const bool number = c->kind == DrawCommand::Kind::Text && !c->text.empty() &&
                                std::all_of(c->text.begin(), c->text.end(), [](char ch) {
                                    return std::isdigit(static_cast<unsigned char>(ch)) != 0 || ch == '.' || ch == '-';
                                });
            for (const auto& band : bandRects)
            {
                INFO((faces ? "faces/" : "") << stem << " step " << k + 1 << ": \"" << c->text << "\"");
                CHECK(!(number && meet(box(*c), band, 0.0f)));
            }
        }
        for (const DrawCommand* c : canvas.InGroup("timebar"))
        {
            if (c->kind != DrawCommand::Kind::Text || c->text != "0.5")
            {
                continue;
            }
            for (const auto& tri : triangles)
            {
                INFO((faces ? "faces/" : "") << stem << " step " << k + 1 << ": the time bar's 0.5");
                CHECK(!meet(box(*c), tri, 3.0f));
            }
        }
    });
    CHECK(bands > 50);
}

TEST_CASE("An MTV of round-off size is named as touching, with no arrow or outline showing a push", "[marks]")
{
    // A depth within 1e-12 of the size of the coordinates (l11_decimal_touch's 2.78e-17) is round-off: the sentence
    // says the shapes touch, so the picture must not draw a push of visible length. Any other MTV keeps its arrow.
    int roundOff = 0;
    int arrows = 0;
    ForEachCourseFigure(
        [&](const std::string& stem, bool faces, const FigureSetup& setup, int k, const RecordingCanvas& canvas) {
            const std::vector<const DrawCommand*> mtv = canvas.InGroup("mtv");
            const auto named = std::find_if(canvas.commands.begin(), canvas.commands.end(), [](const DrawCommand& c) {
                return c.kind == DrawCommand::Kind::Text && c.text.rfind("MTV ", 0) == 0;
            });
            if (named == canvas.commands.end() || setup.study.sweep || !setup.study.manifold.overlap)
            {
                return;
            }
            double size = 0.0;
            for (const Body& body : painter_test::LessonScene(stem).bodies)
            {
                size = std::max({size, std::fabs(body.position.x), std::fabs(body.position.y)});
            }
            const bool tiny = std::fabs(setup.study.manifold.depth) <= 1e-12 * std::max(1.0, size);
            const bool arrow = std::any_of(mtv.begin(), mtv.end(), [](const DrawCommand* c) {
                return c->kind == DrawCommand::Kind::Segment && c->color == palette::kResult;
            });
            const bool dashed = std::any_of(mtv.begin(), mtv.end(), [](const DrawCommand* c) {
                return c->kind == DrawCommand::Kind::Segment && c->color != palette::kResult;
            });
            INFO((faces ? "faces/" : "") << stem << " step " << k + 1 << ": " << named->text << ", depth "
                                         << setup.study.manifold.depth);
            if (tiny)
            {
                CHECK_FALSE(arrow);
                CHECK_FALSE(dashed);
                CHECK(named->text.find("touch") != std::string::npos);
                ++roundOff;
            }
            else
            {
                CHECK(arrow);
                ++arrows;
            }
        });
    CHECK(roundOff > 0);
    CHECK(arrows > 10);
}

TEST_CASE("No arrow head of a face's normal lies on a velocity arrow's shaft or beside its head", "[marks]")
{
    // sliding_past drew the floor's normal from the middle of its face, its head on the sliding box's velocity;
    // bullet_wall and pitfall_tunnel drew the bullet's front normal along its own velocity.
    int heads = 0;
    int failing = 0;
    ForEachCourseFigure(
        [&](const std::string& stem, bool faces, const FigureSetup&, int k, const RecordingCanvas& canvas) {
            std::vector<std::pair<ScreenPoint, ScreenPoint>> shafts;
            std::vector<ScreenPoint> tips;
            for (const DrawCommand* c : canvas.InGroup("swept"))
            {
                if (c->kind == DrawCommand::Kind::Segment && c->thickness >= 1.9f && c->thickness <= 2.1f)
                {
                    shafts.emplace_back(c->points[0], c->points[1]);
                }
                if (c->kind == DrawCommand::Kind::FillConvex && c->points.size() == 3)
                {
                    tips.push_back(c->points[0]);
                }
            }
            for (const DrawCommand& c : canvas.commands)
            {
                if (c.kind != DrawCommand::Kind::FillConvex || c.points.size() != 3 ||
                    (c.group != "normals" && c.group != "projection" && c.group != "axes"))
                {
                    continue;
                }
                ++heads;
                const ScreenPoint centre{(c.points[0].x + c.points[1].x + c.points[2].x) / 3.0f,
                                         (c.points[0].y + c.points[1].y + c.points[2].y) / 3.0f};
                bool hidden = false;
                for (const auto& [a, b] : shafts)
                {
                    hidden = hidden || SegmentDistance(a, b, centre) < 4.0f;
                }
                for (const ScreenPoint& tip : tips)
                {
                    hidden = hidden || std::hypot(tip.x - c.points[0].x, tip.y - c.points[0].y) < 12.0f;
                }
                INFO((faces ? "faces/" : "") << stem << " step " << k + 1 << ": a head in \"" << c.group << "\" at ("
                                             << centre.x << ", " << centre.y << ")");
                CHECK_FALSE(hidden);
                failing += hidden ? 1 : 0;
            }
        });
    INFO(failing << " heads on a velocity");
    CHECK(heads > 100);
}

namespace
{
// The tested pair of a figure as the painter draws it: each body's outline on screen (empty for a circle), its
// ink (the colour of its numbers and names) and its name.
struct PairOnScreen
{
    std::vector<ScreenPoint> outlines[2];
    Color inks[2] = {palette::kShapeA, palette::kShapeBInk};
    std::string names[2];
};

PairOnScreen PairOf(const std::string& stem, const FigureSetup& setup)
{
    const Scene scene = painter_test::LessonScene(stem);
    PairOnScreen pair;
    const int ids[2] = {setup.study.bodyA, setup.study.bodyB};
    for (int s = 0; s < 2; ++s)
    {
        const Body& body = scene.bodies[static_cast<size_t>(ids[s])];
        pair.names[s] = body.name;
        for (size_t i = 0; body.shape.type == ShapeType::Polygon && i < body.shape.polygon.Vertices().size(); ++i)
        {
            pair.outlines[s].push_back(
                ToScreen(setup.figure.view, TransformPoint(body.Xf(), body.shape.polygon.Vertices()[i])));
        }
    }
    return pair;
}

// Whether p lies inside the convex outline (screen y points down), `depth` pixels in at least.
bool InsideOutline(const std::vector<ScreenPoint>& outline, ScreenPoint p, float depth)
{
    if (outline.size() < 3)
    {
        return false;
    }
    for (size_t i = 0; i < outline.size(); ++i)
    {
        const ScreenPoint a = outline[i];
        const ScreenPoint b = outline[(i + 1) % outline.size()];
        const float length = std::hypot(b.x - a.x, b.y - a.y);
        if (length > 0.0f && ((b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x)) / length > -depth)
        {
            return false;
        }
    }
    return true;
}
} // namespace

TEST_CASE("An edge's name inside its own body lies nearer that edge than any other edge of the body", "[marks]")
{
    // With no room outside a face (the separating line and the normal beside it), its name sits just inside its
    // body: lesson 1's triangle had "e1" nearer its bottom edge, e0, than the slanted edge it names.
    int inside = 0;
    ForEachCourseFigure(
        [&](const std::string& stem, bool faces, const FigureSetup& setup, int k, const RecordingCanvas& canvas) {
            if (setup.figure.kind != FigureKind::Pair)
            {
                return;
            }
            const PairOnScreen pair = PairOf(stem, setup);
            RecordingCanvas measure;
            for (const DrawCommand* c : canvas.InGroup("labels"))
            {
                const std::string& t = c->text;
                if (c->kind != DrawCommand::Kind::Text || !painter_test::IsEdgeName(t))
                {
                    continue;
                }
                for (int s = 0; s < 2; ++s)
                {
                    const std::vector<ScreenPoint>& outline = pair.outlines[s];
                    if ((c->color >> 8) != (pair.inks[s] >> 8) || outline.empty())
                    {
                        continue;
                    }
                    const size_t n = static_cast<size_t>(std::stoi(t.substr(1)));
                    if (n >= outline.size())
                    {
                        continue;
                    }
                    const ScreenPoint size = measure.MeasureText(t, c->style);
                    const ScreenPoint m{c->points[0].x + 0.5f * size.x, c->points[0].y + 0.5f * size.y};
                    // Inside: on the inner side of every edge (screen y points down, which turns the sign).
                    bool in = true;
                    for (size_t i = 0; i < outline.size(); ++i)
                    {
                        const ScreenPoint a = outline[i];
                        const ScreenPoint b = outline[(i + 1) % outline.size()];
                        in = in && (b.x - a.x) * (m.y - a.y) - (b.y - a.y) * (m.x - a.x) < 0.0f;
                    }
                    if (!in)
                    {
                        continue;
                    }
                    ++inside;
                    const float own = SegmentDistance(outline[n], outline[(n + 1) % outline.size()], m);
                    for (size_t i = 0; i < outline.size(); ++i)
                    {
                        if (i == n)
                        {
                            continue;
                        }
                        INFO((faces ? "faces/" : "") << stem << " step " << k + 1 << ": " << pair.names[s] << "'s "
                                                     << t << " at (" << m.x << ", " << m.y << ") against e" << i);
                        CHECK(own < SegmentDistance(outline[i], outline[(i + 1) % outline.size()], m));
                    }
                }
            }
        });
    CHECK(inside > 5);
}

TEST_CASE("A ghost's dashed outline is dashed all round, a small circle's too", "[marks]")
{
    // The dashes restarted on every chord of a circle's outline, each shorter than one dash, which drew a small
    // ghost ball (l10_round_bullet's) as a solid line where the key says dashed.
    int ghosts = 0;
    int small = 0;
    ForEachCourseFigure([&](const std::string& stem, bool faces, const FigureSetup&, int k, const RecordingCanvas& canvas) {
        float perimeter = 0.0f;
        float drawn = 0.0f;
        float longest = 0.0f;
        for (const DrawCommand* c : canvas.InGroup("ghost"))
        {
            if (c->kind == DrawCommand::Kind::FillConvex && c->points.size() > 8)
            {
                float around = 0.0f;
                for (size_t i = 0; i < c->points.size(); ++i)
                {
                    const ScreenPoint a = c->points[i];
                    const ScreenPoint b = c->points[(i + 1) % c->points.size()];
                    around += std::hypot(b.x - a.x, b.y - a.y);
                }
                // A point's ghost (a ray's) is a dot, not an outline.
                if (around < 10.0f)
                {
                    continue;
                }
                perimeter += around;
                longest = std::max(longest, around);
            }
            if (c->kind == DrawCommand::Kind::Segment && perimeter > 0.0f)
            {
                drawn += std::hypot(c->points[1].x - c->points[0].x, c->points[1].y - c->points[0].y);
            }
        }
        if (perimeter == 0.0f)
        {
            return;
        }
        ++ghosts;
        small += longest < 150.0f ? 1 : 0;
        INFO((faces ? "faces/" : "") << stem << " step " << k + 1 << ": " << drawn << " px of dashes around "
                                     << perimeter << " px of round ghosts");
        // Six pixels drawn in every ten; a solid outline draws all of it.
        CHECK(drawn < 0.7f * perimeter);
        CHECK(drawn > 0.4f * perimeter);
    });
    CHECK(ghosts > 5);
    CHECK(small > 0);
}

TEST_CASE("A vertex number or an edge name lies on its own body's side of the separating line", "[marks]")
{
    // pitfall_one_shape numbered the diamond's corner 3 below the separating line, beside the box's corner 2,
    // where it read as the box's.
    int named = 0;
    ForEachCourseFigure(
        [&](const std::string& stem, bool faces, const FigureSetup& setup, int k, const RecordingCanvas& canvas) {
            if (setup.figure.kind != FigureKind::Pair)
            {
                return;
            }
            std::vector<ScreenPoint> dashes;
            for (const DrawCommand* c : canvas.InGroup("exit"))
            {
                if (c->kind == DrawCommand::Kind::Segment && (c->color >> 8) == (palette::kGap >> 8))
                {
                    dashes.push_back(c->points[0]);
                    dashes.push_back(c->points[1]);
                }
            }
            if (dashes.size() < 4)
            {
                return;
            }
            const ScreenPoint a = dashes.front();
            const ScreenPoint b = dashes.back();
            const float length = std::hypot(b.x - a.x, b.y - a.y);
            const auto side = [&](ScreenPoint p) { return ((b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x)) / length; };
            const PairOnScreen pair = PairOf(stem, setup);
            RecordingCanvas measure;
            for (const DrawCommand* c : canvas.InGroup("labels"))
            {
                const std::string& t = c->text;
                const bool edge = painter_test::IsEdgeName(t);
                const bool vertex = painter_test::IsVertexNumber(t);
                if (c->kind != DrawCommand::Kind::Text || (!edge && !vertex))
                {
                    continue;
                }
                for (int s = 0; s < 2; ++s)
                {
                    const std::vector<ScreenPoint>& outline = pair.outlines[s];
                    const size_t n = static_cast<size_t>(std::stoi(edge ? t.substr(1) : t));
                    if ((c->color >> 8) != (pair.inks[s] >> 8) || n >= outline.size())
                    {
                        continue;
                    }
                    // What it names: the corner, or the middle of the edge.
                    const ScreenPoint at = vertex ? outline[n]
                                                  : ScreenPoint{0.5f * (outline[n].x + outline[(n + 1) % outline.size()].x),
                                                                0.5f * (outline[n].y + outline[(n + 1) % outline.size()].y)};
                    const float own = side(at);
                    if (std::abs(own) < 1.0f)
                    {
                        continue;
                    }
                    ++named;
                    const ScreenPoint size = measure.MeasureText(t, c->style);
                    const ScreenPoint middle{c->points[0].x + 0.5f * size.x, c->points[0].y + 0.5f * size.y};
                    INFO((faces ? "faces/" : "") << stem << " step " << k + 1 << ": " << pair.names[s] << "'s " << t
                                                 << " at (" << middle.x << ", " << middle.y << ")");
                    CHECK(side(middle) * own > 0.0f);
                }
            }
        });
    CHECK(named > 50);
}

TEST_CASE("A tested face's normal points its head into the other body only from a face that meets it", "[marks]")
{
    // pitfall_one_shape drew the diamond's face normal from the middle of its face, 13 pixels from the box, its head
    // on the box's corner, where it seemed to point at that corner; l03_corner_gap did the same with B's.
    int heads = 0;
    ForEachCourseFigure(
        [&](const std::string& stem, bool faces, const FigureSetup& setup, int k, const RecordingCanvas& canvas) {
            if (setup.figure.kind != FigureKind::Pair)
            {
                return;
            }
            const PairOnScreen pair = PairOf(stem, setup);
            const std::vector<const DrawCommand*> drawn = canvas.InGroup("projection");
            for (size_t i = 1; i < drawn.size(); ++i)
            {
                const DrawCommand& head = *drawn[i];
                const DrawCommand& shaft = *drawn[i - 1];
                if (head.kind != DrawCommand::Kind::FillConvex || head.points.size() != 3 ||
                    shaft.kind != DrawCommand::Kind::Segment)
                {
                    continue;
                }
                // The body whose face the shaft starts from.
                for (int s = 0; s < 2; ++s)
                {
                    const std::vector<ScreenPoint>& own = pair.outlines[s];
                    const std::vector<ScreenPoint>& other = pair.outlines[1 - s];
                    for (size_t f = 0; f < own.size() && other.size() >= 3; ++f)
                    {
                        const ScreenPoint f0 = own[f];
                        const ScreenPoint f1 = own[(f + 1) % own.size()];
                        if (SegmentDistance(f0, f1, shaft.points[0]) > 1.5f)
                        {
                            continue;
                        }
                        ++heads;
                        if (!InsideOutline(other, head.points[0], 2.0f))
                        {
                            continue;
                        }
                        // How near the face comes to the other body: inside it, or touching it.
                        float nearest = INFINITY;
                        for (int j = 0; j <= 20; ++j)
                        {
                            const float t = static_cast<float>(j) / 20.0f;
                            const ScreenPoint p{f0.x + t * (f1.x - f0.x), f0.y + t * (f1.y - f0.y)};
                            for (size_t e = 0; e < other.size(); ++e)
                            {
                                nearest = std::min(nearest, InsideOutline(other, p, 0.0f)
                                                                ? 0.0f
                                                                : SegmentDistance(other[e], other[(e + 1) % other.size()], p));
                            }
                        }
                        INFO((faces ? "faces/" : "") << stem << " step " << k + 1 << ": " << pair.names[s]
                                                     << "'s e" << f << " normal's head in " << pair.names[1 - s]);
                        CHECK(nearest < 3.0f);
                    }
                }
            }
        });
    CHECK(heads > 100);
}

TEST_CASE("A body's name is written only where some of the body is in the picture", "[marks]")
{
    // bullet_wall_close, a close-up at the wall, wrote "bullet" at the image's left edge for a bullet far out of the
    // picture, beside nothing; the bullet is seen there only as its ghost, which now carries its name.
    int names = 0;
    ForEachCourseFigure(
        [&](const std::string& stem, bool faces, const FigureSetup& setup, int k, const RecordingCanvas& canvas) {
            if (setup.figure.kind != FigureKind::Pair)
            {
                return;
            }
            const Scene scene = painter_test::LessonScene(stem);
            const int ids[2] = {setup.study.bodyA, setup.study.bodyB};
            for (const DrawCommand* c : canvas.InGroup("labels"))
            {
                for (int s = 0; s < 2; ++s)
                {
                    const Body& body = scene.bodies[static_cast<size_t>(ids[s])];
                    if (c->kind != DrawCommand::Kind::Text || c->text != body.name)
                    {
                        continue;
                    }
                    ++names;
                    // Points of the body (along its edges, or a circle's centre and rim), on screen:
                    // one of them in the picture.
                    std::vector<Vec2> points;
                    if (body.shape.type == ShapeType::Polygon)
                    {
                        const auto& v = body.shape.polygon.Vertices();
                        for (size_t i = 0; i < v.size(); ++i)
                        {
                            for (int j = 0; j < 64; ++j)
                            {
                                const double t = j / 64.0;
                                points.push_back(TransformPoint(body.Xf(), (1.0 - t) * v[i] + t * v[(i + 1) % v.size()]));
                            }
                        }
                    }
                    else
                    {
                        const Vec2 centre = TransformPoint(body.Xf(), body.shape.circle.center);
                        points.push_back(centre);
                        for (int i = 0; i < 8; ++i)
                        {
                            const double a = 0.25 * 3.14159265358979 * i;
                            points.push_back(centre + body.shape.circle.radius * Vec2{std::cos(a), std::sin(a)});
                        }
                    }
                    bool seen = false;
                    for (const Vec2& p : points)
                    {
                        const ScreenPoint at = ToScreen(setup.figure.view, p);
                        seen = seen || (at.x >= 0.0f && at.x <= static_cast<float>(setup.figure.view.width) &&
                                        at.y >= 0.0f && at.y <= static_cast<float>(setup.figure.view.height));
                    }
                    INFO((faces ? "faces/" : "") << stem << " step " << k + 1 << ": \"" << body.name << "\"");
                    CHECK(seen);
                }
            }
        });
    CHECK(names > 100);
}

TEST_CASE("A corner with a contact point's dot on it has no number beside it, as lesson 1 says", "[marks]")
{
    // l08_throw's c2 lies on the block's corner 2: its "2" sat between the two dots, nearer c2's dot than "c2" was;
    // l15_slope kept the box's "1" beside c2 on corner 1 while leaving corner 0, under c1, unnumbered.
    int dots = 0;
    ForEachCourseFigure(
        [&](const std::string& stem, bool faces, const FigureSetup& setup, int k, const RecordingCanvas& canvas) {
            if (setup.figure.kind != FigureKind::Pair)
            {
                return;
            }
            std::vector<ScreenPoint> contacts;
            for (const DrawCommand* c : canvas.InGroup("contacts"))
            {
                if (c->kind == DrawCommand::Kind::FillCircle && (c->color >> 8) == (palette::kResult >> 8))
                {
                    contacts.push_back(c->points[0]);
                }
            }
            if (contacts.empty())
            {
                return;
            }
            const PairOnScreen pair = PairOf(stem, setup);
            for (const DrawCommand* c : canvas.InGroup("labels"))
            {
                if (c->kind != DrawCommand::Kind::Text || !painter_test::IsVertexNumber(c->text))
                {
                    continue;
                }
                for (int s = 0; s < 2; ++s)
                {
                    const size_t n = static_cast<size_t>(std::stoi(c->text));
                    if ((c->color >> 8) != (pair.inks[s] >> 8) || n >= pair.outlines[s].size())
                    {
                        continue;
                    }
                    const ScreenPoint corner = pair.outlines[s][n];
                    for (const ScreenPoint& dot : contacts)
                    {
                        const bool on = std::hypot(dot.x - corner.x, dot.y - corner.y) < 5.0f;
                        dots += on ? 1 : 0;
                        INFO((faces ? "faces/" : "") << stem << " step " << k + 1 << ": " << pair.names[s] << "'s "
                                                     << c->text << " beside a contact's dot on its corner");
                        CHECK_FALSE(on);
                    }
                }
            }
        });
    INFO(dots << " numbers beside a dot on their corner");
    CHECK(dots == 0);
}

TEST_CASE("The number line's end values read from left to right in the order of the ends", "[marks]")
{
    // l03_corner_gap's verdict wrote A's -1.10 left of its tick and B's -1.30 right of its own, across a gap of 20
    // pixels: read from left to right, -1.10 came before -1.30.
    int pairs = 0;
    ForEachCourseFigure([&](const std::string& stem, bool faces, const FigureSetup&, int k, const RecordingCanvas& canvas) {
        struct End
        {
            double value;
            float x;
        };
        std::vector<End> ends;
        RecordingCanvas measure;
        for (const DrawCommand* c : canvas.InGroup("panel"))
        {
            if (c->kind != DrawCommand::Kind::Text || c->text.empty())
            {
                continue;
            }
            std::string digits;
            for (const char ch : c->text)
            {
                if (ch != ' ')
                {
                    digits += ch;
                }
            }
            char* stop = nullptr;
            const double value = std::strtod(digits.c_str(), &stop);
            if (stop == digits.c_str() || *stop != '\0')
            {
                continue; // not a number alone: a title, a name, "gap 0.20", "bound 0.5"
            }
            const ScreenPoint size = measure.MeasureText(c->text, c->style);
            ends.push_back({value, c->points[0].x + 0.5f * size.x});
        }
        for (const End& a : ends)
        {
            for (const End& b : ends)
            {
                if (a.value < b.value)
                {
                    ++pairs;
                    INFO((faces ? "faces/" : "") << stem << " step " << k + 1 << ": " << a.value << " at x " << a.x
                                                 << ", " << b.value << " at x " << b.x);
                    CHECK(a.x < b.x);
                }
            }
        }
    });
    CHECK(pairs > 300);
}

namespace
{

// The words of the texts a recording draws in the group "legend", in order.
std::string KeyWords(const RecordingCanvas& canvas)
{
    std::string words;
    for (const DrawCommand* c : canvas.InGroup("legend"))
    {
        if (c->kind == DrawCommand::Kind::Text)
        {
            words += (words.empty() ? "" : " ") + c->text;
        }
    }
    return words;
}

// What of the key a recording draws beyond the canvas's sides (or, when `rows`, above or below it).
std::vector<std::string> KeyOutside(const RecordingCanvas& canvas, float width, float height, bool rows)
{
    std::vector<std::string> out;
    RecordingCanvas measure;
    for (const DrawCommand* c : canvas.InGroup("legend"))
    {
        for (const ScreenPoint& p : c->points)
        {
            float right = p.x;
            float bottom = p.y;
            if (c->kind == DrawCommand::Kind::Text)
            {
                const ScreenPoint size = measure.MeasureText(c->text, c->style);
                right += size.x;
                bottom += size.y;
            }
            if (p.x < 0.0f || right > width || (rows && (p.y < 0.0f || bottom > height)))
            {
                out.push_back(c->kind == DrawCommand::Kind::Text ? c->text : "a swatch");
            }
        }
    }
    return out;
}

} // namespace

TEST_CASE("Lesson 1's key, and a figure's, stay inside a canvas narrowed by the lesson column", "[marks][legend]")
{
    // Beside the lesson column the canvas is 480 x 808 in a 1300 x 850 window and 360 x 608 in the least window (900 x
    // 650 raised to 1180 x 650): the key, one line per mark, ran past both sides. Its meanings wrap between words to
    // fit; the words are those of the key at 800 pixels, in the same order.
    const Scene scene = painter_test::LessonScene("l01_legend");
    FigureSetup wide = SetUpFigure(scene, FigureOptions{});
    REQUIRE(wide.Ok());
    const std::string words = KeyWords(painter_test::PaintStep(scene, wide, wide.figure.step));
    REQUIRE(words.find("candidate axes") != std::string::npos);
    const auto joined = [](std::string text) {
        std::string flat;
        std::istringstream in(text);
        for (std::string word; in >> word;)
        {
            flat += (flat.empty() ? "" : " ") + word;
        }
        return flat;
    };
    for (const auto& [width, height] : {std::pair{480, 808}, std::pair{360, 608}})
    {
        CAPTURE(width, height);
        FigureOptions options;
        options.width = width;
        options.height = height;
        FigureSetup setup = SetUpFigure(scene, options);
        REQUIRE(setup.Ok());
        const RecordingCanvas key = painter_test::PaintStep(scene, setup, setup.figure.step);
        CHECK(joined(KeyWords(key)) == joined(words));
        CHECK(KeyOutside(key, static_cast<float>(width), static_cast<float>(height), height > 700).empty());
        if (height < 700)
        {
            // Too tall for the canvas: it starts with its first row in sight, and the camera dragged up shows its
            // last one.
            const std::vector<const DrawCommand*> legend = key.InGroup("legend");
            REQUIRE(!legend.empty());
            CHECK(legend[0]->points[0].y >= 0.0f);
            Figure dragged = setup.figure;
            dragged.view.center.y -= 2000.0 / dragged.view.zoom;
            RecordingCanvas moved;
            PaintFigure(moved, scene, setup.study, dragged);
            const std::vector<const DrawCommand*> after = moved.InGroup("legend");
            REQUIRE(!after.empty());
            CHECK(after[0]->points[1].y <= static_cast<float>(height));
            CHECK(after[0]->points[1].y >= static_cast<float>(height) - 60.0f);
        }
    }
    // A figure's own key (the legend layer in the app's Layers panel) wraps as well.
    for (const char* stem : {"bullet_wall", "l13_overlap", "concave/l18_seam", "l17_skips"})
    {
        CAPTURE(stem);
        const Scene figureScene = painter_test::LessonScene(stem);
        FigureOptions options;
        options.width = 360;
        options.height = 608;
        FigureSetup setup = SetUpFigure(figureScene, options);
        REQUIRE(setup.Ok());
        const RecordingCanvas canvas =
            painter_test::Paint(figureScene, setup, setup.study.VerdictStep(), setup.figure.layers | kLayerLegend);
        CHECK(!canvas.InGroup("legend").empty());
        CHECK(KeyOutside(canvas, 360.0f, 608.0f, false).empty());
    }
}

TEST_CASE("Lesson 13's verdicts draw a dot on each contact point the app's words and numbers name", "[marks]")
{
    // ex13_boxes said "2 contact points, clipped from the incident edge against the reference face" and its numbers
    // listed c1 and c2, l13_sweep and ex13_sweep listed "contact c1 at impact": none drew a dot. Each point of the
    // query (Collide's contacts, or the sweep's at the time of impact), on the figure at the verdict.
    for (const char* stem : {"ex13_boxes", "l13_sweep", "ex13_sweep", "l13_overlap"})
    {
        CAPTURE(stem);
        const Scene scene = painter_test::LessonScene(stem);
        FigureSetup setup = SetUpFigure(scene, FigureOptions{});
        REQUIRE(setup.Ok());
        const PairStudy& study = setup.study;
        std::vector<Vec2> points;
        if (study.sweep)
        {
            for (int i = 0; i < study.sweepResult.contactCount; ++i)
            {
                points.push_back(study.sweepResult.contacts[i].point);
            }
        }
        else
        {
            for (int i = 0; i < study.manifold.contactCount; ++i)
            {
                points.push_back(study.manifold.contacts[i].point);
            }
        }
        REQUIRE(!points.empty());
        const RecordingCanvas canvas = painter_test::PaintStep(scene, setup, study.VerdictStep());
        for (const Vec2& p : points)
        {
            const ScreenPoint at = ToScreen(setup.figure.view, p);
            bool dot = false;
            for (const DrawCommand* c : canvas.InGroup("contacts"))
            {
                dot = dot || (c->kind == DrawCommand::Kind::FillCircle && c->color == palette::kResult &&
                              std::hypot(c->points[0].x - at.x, c->points[0].y - at.y) < 2.0f);
            }
            CAPTURE(p.x, p.y);
            CHECK(dot);
        }
    }
}
