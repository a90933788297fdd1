// SPDX-License-Identifier: MIT
// Every figure of the course, drawn through a recording canvas: no text covers another text, an arrow head or a
// mark, nothing drawn after a text covers it, and every text lies inside the image. The figures are those that
// tutorials/figures.cmake lists, drawn as satviz-render draws them; the checks look only at what was drawn.
#include "render/painter_support.h"
#include "support/scene_files.h"

#include <satviz/render/figure.h>
#include <satviz/render/recording_canvas.h>
#include <satviz/scene_world.h>

#include <catch2/catch.hpp>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <sstream>
#include <set>
#include <tuple>

using namespace satviz;

namespace
{

struct Box
{
    float minX, minY, maxX, maxY;
    bool Overlaps(const Box& o) const { return minX < o.maxX && o.minX < maxX && minY < o.maxY && o.minY < maxY; }
};

bool Opaque(Color color)
{
    return (color & 0xFFu) >= 0xC0u;
}

Box Bounds(const std::vector<ScreenPoint>& points)
{
    Box box{INFINITY, INFINITY, -INFINITY, -INFINITY};
    for (const ScreenPoint& p : points)
    {
        box = {std::min(box.minX, p.x), std::min(box.minY, p.y), std::max(box.maxX, p.x), std::max(box.maxY, p.y)};
    }
    return box;
}

// A mark a label must leave visible: an arrow head or a time marker (a small opaque triangle), a contact point or
// a vertex dot (an opaque disc of a few pixels).
bool IsMark(const DrawCommand& c)
{
    if (c.kind == DrawCommand::Kind::FillConvex && c.points.size() == 3 && Opaque(c.color))
    {
        const Box b = Bounds(c.points);
        return b.maxX - b.minX <= 20.0f && b.maxY - b.minY <= 20.0f;
    }
    return c.kind == DrawCommand::Kind::FillCircle && c.radius >= 3.5f && Opaque(c.color);
}

// Whether the segment ab, `thickness` wide, crosses the box (touching its border does not count).
bool SegmentCovers(ScreenPoint a, ScreenPoint b, float thickness, const Box& box)
{
    const float r = 0.5f * thickness - 0.5f;
    const double x0 = box.minX - r, y0 = box.minY - r, x1 = box.maxX + r, y1 = box.maxY + r;
    double t0 = 0.0, t1 = 1.0;
    const double dx = b.x - a.x, dy = b.y - a.y;
    const double p[4] = {-dx, dx, -dy, dy};
    const double q[4] = {a.x - x0, x1 - a.x, a.y - y0, y1 - a.y};
    for (int i = 0; i < 4; ++i)
    {
        if (p[i] == 0.0)
        {
            if (q[i] <= 0.0)
            {
                return false;
            }
            continue;
        }
        const double t = q[i] / p[i];
        if (p[i] < 0.0)
        {
            t0 = std::max(t0, t);
        }
        else
        {
            t1 = std::min(t1, t);
        }
    }
    return t0 < t1;
}

// Whether a convex polygon shares interior with the box: no separating axis among the box's and the polygon's.
bool ConvexCovers(const std::vector<ScreenPoint>& points, const Box& box)
{
    const Box b = Bounds(points);
    if (!b.Overlaps(box))
    {
        return false;
    }
    const ScreenPoint corners[4] = {
        {box.minX, box.minY}, {box.maxX, box.minY}, {box.maxX, box.maxY}, {box.minX, box.maxY}};
    for (size_t i = 0; i < points.size(); ++i)
    {
        const ScreenPoint& p = points[i];
        const ScreenPoint& q = points[(i + 1) % points.size()];
        const double nx = q.y - p.y, ny = p.x - q.x;
        double lo = INFINITY, hi = -INFINITY, clo = INFINITY, chi = -INFINITY;
        for (const ScreenPoint& v : points)
        {
            lo = std::min(lo, nx * v.x + ny * v.y);
            hi = std::max(hi, nx * v.x + ny * v.y);
        }
        for (const ScreenPoint& v : corners)
        {
            clo = std::min(clo, nx * v.x + ny * v.y);
            chi = std::max(chi, nx * v.x + ny * v.y);
        }
        if (hi - lo > 0.0 && (chi <= lo || hi <= clo))
        {
            return false;
        }
    }
    return true;
}

// Whether a command drawn after a text covers the box of that text.
bool Covers(const DrawCommand& c, const Box& box)
{
    switch (c.kind)
    {
    case DrawCommand::Kind::Segment:
        return SegmentCovers(c.points[0], c.points[1], c.thickness, box);
    case DrawCommand::Kind::Polyline:
        for (size_t i = 0; i + 1 < c.points.size() + (c.closed ? 1 : 0); ++i)
        {
            if (SegmentCovers(c.points[i], c.points[(i + 1) % c.points.size()], c.thickness, box))
            {
                return true;
            }
        }
        return false;
    case DrawCommand::Kind::FillConvex:
        return ConvexCovers(c.points, box);
    case DrawCommand::Kind::Circle:
    case DrawCommand::Kind::FillCircle:
    {
        const float x = std::clamp(c.points[0].x, box.minX, box.maxX);
        const float y = std::clamp(c.points[0].y, box.minY, box.maxY);
        return std::hypot(x - c.points[0].x, y - c.points[0].y) < c.radius;
    }
    case DrawCommand::Kind::FillRect:
        return Box{c.points[0].x, c.points[0].y, c.points[1].x, c.points[1].y}.Overlaps(box);
    case DrawCommand::Kind::Text:
        return false;
    }
    return false;
}

std::string Describe(const DrawCommand& c)
{
    static const char* kinds[] = {"segment", "polyline", "fill", "circle", "disc", "rectangle", "text"};
    std::string s = std::string(kinds[static_cast<int>(c.kind)]) + " in \"" + c.group + "\"";
    if (c.kind == DrawCommand::Kind::Text)
    {
        s += " \"" + c.text + "\"";
    }
    if (!c.points.empty())
    {
        s += " at (" + std::to_string(static_cast<int>(c.points[0].x)) + ", " +
             std::to_string(static_cast<int>(c.points[0].y)) + ")";
    }
    return s;
}

// How far a text keeps from the image's edge: a glyph's ink can reach a pixel or two past its advance box, and a
// word flush with the edge reads as cut.
constexpr float kEdgeMargin = 4.0f;
// How far apart two texts keep: stacked texts that touch read as one block, and two numbers on one line closer
// than two spaces read as one ("-3.00 -3.00"). Two labels in the scene, stacked closer than a few pixels, read as
// one phrase ("plank" over "incident edge"): they keep farther apart than lines of one caption.
constexpr float kStackGap = 2.0f;
constexpr float kLabelStackGap = 6.0f;
constexpr float kLineGap = 8.0f;
// Two labels in the scene side by side on one line, closer than about three spaces, read as one phrase ("c2 e2",
// "c1 pitfall 0.20 c2"): they keep farther apart than words of the number line.
constexpr float kLabelLineGap = 16.0f;
// And two of different things (different colours) closer than about four spaces read as naming one thing ("c2 e2"
// with the floor's e2 beside the plank's contact, "c1 pitfall 0.20 c2" in a row).
constexpr float kOtherLabelLineGap = 22.0f;

Box Grown(const Box& b, float dx, float dy)
{
    return {b.minX - dx, b.minY - dy, b.maxX + dx, b.maxY + dy};
}

// An arrow head: a small filled triangle, opaque or nearly (a faint one is a body's fill, not a mark).
bool IsArrowHead(const DrawCommand& c)
{
    if (c.kind != DrawCommand::Kind::FillConvex || c.points.size() != 3 || (c.color & 0xFFu) < 0x80u)
    {
        return false;
    }
    const Box b = Bounds(c.points);
    return b.maxX - b.minX <= 24.0f && b.maxY - b.minY <= 24.0f;
}

// Whether an opaque command drawn over an arrow head hides most of it: its tip and the middle of its base.
bool HidesHead(const DrawCommand& c, const DrawCommand& head)
{
    if ((c.color & 0xFFu) < 0xC0u || (c.color >> 8) == (head.color >> 8) || c.kind == DrawCommand::Kind::Text)
    {
        return false;
    }
    // A line much thinner than the head crosses it and leaves it readable (the hit's time through its entry mark).
    const float width = std::hypot(head.points[1].x - head.points[2].x, head.points[1].y - head.points[2].y);
    if ((c.kind == DrawCommand::Kind::Segment || c.kind == DrawCommand::Kind::Polyline) && c.thickness < 0.4f * width)
    {
        return false;
    }
    const ScreenPoint tip = head.points[0];
    const ScreenPoint base{0.5f * (head.points[1].x + head.points[2].x), 0.5f * (head.points[1].y + head.points[2].y)};
    const ScreenPoint middle{0.5f * (tip.x + base.x), 0.5f * (tip.y + base.y)};
    const Box spot{middle.x - 1.0f, middle.y - 1.0f, middle.x + 1.0f, middle.y + 1.0f};
    return Covers(c, spot);
}

// Every way the texts of a recording are hidden or cut: one line each.
std::vector<std::string> HiddenTexts(const RecordingCanvas& canvas, int width, int height)
{
    RecordingCanvas measure;
    std::vector<std::string> problems;
    const std::vector<DrawCommand>& commands = canvas.commands;
    std::vector<std::pair<size_t, Box>> texts;
    for (size_t i = 0; i < commands.size(); ++i)
    {
        const DrawCommand& c = commands[i];
        if (c.kind != DrawCommand::Kind::Text)
        {
            continue;
        }
        const ScreenPoint size = measure.MeasureText(c.text, c.style);
        const Box box{c.points[0].x, c.points[0].y, c.points[0].x + size.x, c.points[0].y + size.y};
        if (box.minX < kEdgeMargin || box.minY < 0.0f || box.maxX > static_cast<float>(width) - kEdgeMargin ||
            box.maxY > static_cast<float>(height))
        {
            problems.push_back(Describe(c) + " leaves the image or touches its edge");
        }
        texts.push_back({i, box});
    }
    for (size_t a = 0; a < texts.size(); ++a)
    {
        for (size_t b = a + 1; b < texts.size(); ++b)
        {
            const Box& p = texts[a].second;
            const Box& q = texts[b].second;
            // Side by side on one line (sharing most of their height), or stacked.
            const float shared = std::min(p.maxY, q.maxY) - std::max(p.minY, q.minY);
            const bool oneLine = shared > 0.5f * std::min(p.maxY - p.minY, q.maxY - q.minY);
            const bool labels = commands[texts[a].first].group == "labels" && commands[texts[b].first].group == "labels";
            const float stack = labels ? kLabelStackGap : kStackGap;
            const bool others = (commands[texts[a].first].color >> 8) != (commands[texts[b].first].color >> 8);
            const float line = labels ? (others ? kOtherLabelLineGap : kLabelLineGap) : kLineGap;
            if (Grown(p, oneLine ? 0.5f * line : 0.5f * kStackGap, 0.5f * stack).Overlaps(
                    Grown(q, oneLine ? 0.5f * line : 0.5f * kStackGap, 0.5f * stack)))
            {
                problems.push_back(Describe(commands[texts[a].first]) + " and " + Describe(commands[texts[b].first]) +
                                   (p.Overlaps(q) ? " overlap" : " touch"));
            }
        }
    }
    for (const auto& [index, box] : texts)
    {
        for (size_t j = 0; j < commands.size(); ++j)
        {
            const DrawCommand& c = commands[j];
            // A thick opaque bar (a projection interval, a marked face) drawn before a label is what its halo would hide.
            const bool bar = c.kind == DrawCommand::Kind::Segment && c.thickness >= 4.0f && Opaque(c.color) &&
                             commands[index].group == "labels" && Covers(c, box);
            const bool mark = (IsMark(c) || IsArrowHead(c) || bar) && Covers(c, box);
            const bool later = j > index && Covers(c, box);
            if (mark || later)
            {
                problems.push_back(Describe(commands[index]) + (mark ? " lies on the mark " : " lies under ") +
                                   Describe(c));
            }
        }
    }
    // A leader line runs from its anchor to its own label only: over another text, the text's halo hides it and
    // the text seems to be the one it leads to.
    for (const DrawCommand& c : commands)
    {
        if (c.kind != DrawCommand::Kind::Segment || c.group != "labels")
        {
            continue;
        }
        for (const auto& [index, box] : texts)
        {
            const ScreenPoint end = c.points[1];
            const bool own = end.x >= box.minX - 0.5f && end.x <= box.maxX + 0.5f && end.y >= box.minY - 0.5f &&
                             end.y <= box.maxY + 0.5f;
            if (!own && SegmentCovers(c.points[0], c.points[1], c.thickness, Grown(box, 2.0f, 0.0f)))
            {
                problems.push_back("the leader line at (" + std::to_string(static_cast<int>(c.points[0].x)) + ", " +
                                   std::to_string(static_cast<int>(c.points[0].y)) + ") crosses " +
                                   Describe(commands[index]));
            }
        }
    }
    // Two leader lines that cross read as leading each to the other's label.
    std::vector<const DrawCommand*> leaders;
    for (const DrawCommand& c : commands)
    {
        if (c.kind == DrawCommand::Kind::Segment && c.group == "labels")
        {
            leaders.push_back(&c);
        }
    }
    for (size_t i = 0; i < leaders.size(); ++i)
    {
        for (size_t j = i + 1; j < leaders.size(); ++j)
        {
            const ScreenPoint a = leaders[i]->points[0], b = leaders[i]->points[1];
            const ScreenPoint u = leaders[j]->points[0], v = leaders[j]->points[1];
            auto side = [](ScreenPoint p, ScreenPoint q, ScreenPoint r) {
                return (q.x - p.x) * (r.y - p.y) - (q.y - p.y) * (r.x - p.x);
            };
            if (side(a, b, u) * side(a, b, v) < 0.0f && side(u, v, a) * side(u, v, b) < 0.0f)
            {
                problems.push_back("the leader lines at (" + std::to_string(static_cast<int>(a.x)) + ", " +
                                   std::to_string(static_cast<int>(a.y)) + ") and (" +
                                   std::to_string(static_cast<int>(u.x)) + ", " + std::to_string(static_cast<int>(u.y)) +
                                   ") cross");
            }
        }
    }
    // An arrow head stays in sight: no opaque line or fill of another colour drawn over it (an arrow over an arrow).
    for (size_t i = 0; i < commands.size(); ++i)
    {
        if (!IsArrowHead(commands[i]))
        {
            continue;
        }
        for (size_t j = i + 1; j < commands.size(); ++j)
        {
            if (HidesHead(commands[j], commands[i]))
            {
                problems.push_back("the arrow head " + Describe(commands[i]) + " lies under " + Describe(commands[j]));
                break;
            }
        }
    }
    return problems;
}

// Whether a world point lies strictly inside a placed polygon body (a circle: inside its radius).
bool InsideBody(const Body& body, Vec2 p)
{
    const Vec2 local = InvTransformPoint(body.Xf(), p);
    if (body.shape.type == ShapeType::Circle)
    {
        return Length(local - body.shape.circle.center) < body.shape.circle.radius;
    }
    const Polygon& poly = body.shape.polygon;
    for (int i = 0; i < poly.Count(); ++i)
    {
        if (Dot(poly.Normal(i), local - poly.Vertices()[i]) >= 0.0)
        {
            return false;
        }
    }
    return true;
}

// Labels of one body of a touching pair (no interpenetration: no vertex or face of one lies inside the other) that
// sit inside the other body, where they read as the other's: in its colour, their middle inside the other body.
std::vector<std::string> LabelsInOtherBody(const RecordingCanvas& canvas, const Scene& scene, const PairStudy& study,
                                           const View& view)
{
    std::vector<std::string> problems;
    if (study.sweep || !study.manifold.overlap || study.manifold.depth > 1e-9)
    {
        return problems;
    }
    RecordingCanvas measure;
    const Body* bodies[2] = {&scene.bodies[static_cast<size_t>(study.bodyA)],
                             &scene.bodies[static_cast<size_t>(study.bodyB)]};
    const Color inks[2] = {palette::kShapeA, palette::kShapeBInk};
    for (const DrawCommand* c : canvas.InGroup("labels"))
    {
        if (c->kind != DrawCommand::Kind::Text)
        {
            continue;
        }
        for (int s = 0; s < 2; ++s)
        {
            if ((c->color >> 8) != (inks[s] >> 8))
            {
                continue;
            }
            const ScreenPoint size = measure.MeasureText(c->text, c->style);
            const Vec2 middle = ToWorld(view, {c->points[0].x + 0.5f * size.x, c->points[0].y + 0.5f * size.y});
            if (InsideBody(*bodies[1 - s], middle))
            {
                problems.push_back(Describe(*c) + ", of " + bodies[s]->name + ", lies inside " + bodies[1 - s]->name);
            }
        }
    }
    return problems;
}

// Vertex numbers of one body of the pair drawn inside the other body, where they read as the other's: "2" in B's
// colour inside A. A body wholly inside the other (a box in a box) has its numbers there, as it has no outside near
// its corners; every other corner, even one pushed into the other body, is numbered outside it or left out.
std::vector<std::string> VertexNumbersInOtherBody(const RecordingCanvas& canvas, const Scene& scene,
                                                  const PairStudy& study, const View& view)
{
    std::vector<std::string> problems;
    RecordingCanvas measure;
    const Body* bodies[2] = {&scene.bodies[static_cast<size_t>(study.bodyA)],
                             &scene.bodies[static_cast<size_t>(study.bodyB)]};
    const Color inks[2] = {palette::kShapeA, palette::kShapeBInk};
    for (const DrawCommand* c : canvas.InGroup("labels"))
    {
        if (c->kind != DrawCommand::Kind::Text || !painter_test::IsVertexNumber(c->text))
        {
            continue;
        }
        for (int s = 0; s < 2; ++s)
        {
            if ((c->color >> 8) != (inks[s] >> 8) || bodies[s]->shape.type != ShapeType::Polygon)
            {
                continue;
            }
            bool contained = true;
            for (const Vec2& v : bodies[s]->shape.polygon.Vertices())
            {
                contained = contained && InsideBody(*bodies[1 - s], TransformPoint(bodies[s]->Xf(), v));
            }
            const ScreenPoint size = measure.MeasureText(c->text, c->style);
            const Vec2 middle = ToWorld(view, {c->points[0].x + 0.5f * size.x, c->points[0].y + 0.5f * size.y});
            if (!contained && InsideBody(*bodies[1 - s], middle))
            {
                problems.push_back(Describe(*c) + ", a vertex number of " + bodies[s]->name + ", lies inside " +
                                   bodies[1 - s]->name);
            }
        }
    }
    return problems;
}

// A body's velocity "v" inside the other body where the figure shows it at the hit (its dashed ghost): there it
// reads as the velocity of that ghost.
std::vector<std::string> VelocityInOtherGhost(const RecordingCanvas& canvas, const Scene& scene, const PairStudy& study,
                                              const View& view, LayerMask layers)
{
    std::vector<std::string> problems;
    if (!study.sweep || study.sweepResult.status != SweepStatus::Hit || !(layers & kLayerGhost))
    {
        return problems;
    }
    RecordingCanvas measure;
    const Body* bodies[2] = {&scene.bodies[static_cast<size_t>(study.bodyA)],
                             &scene.bodies[static_cast<size_t>(study.bodyB)]};
    const Color inks[2] = {palette::kShapeA, palette::kShapeBInk};
    for (const DrawCommand* c : canvas.InGroup("labels"))
    {
        if (c->kind != DrawCommand::Kind::Text || c->text != "v")
        {
            continue;
        }
        for (int s = 0; s < 2; ++s)
        {
            const Body& other = *bodies[1 - s];
            if ((c->color >> 8) != (inks[s] >> 8) || other.velocity == Vec2{})
            {
                continue;
            }
            Body ghost = other;
            const Transform at = BodyTransformAt(other, study.sweepResult.toi);
            ghost.position = at.p;
            ghost.angle = std::atan2(at.q.s, at.q.c);
            const ScreenPoint size = measure.MeasureText(c->text, c->style);
            if (InsideBody(ghost, ToWorld(view, {c->points[0].x + 0.5f * size.x, c->points[0].y + 0.5f * size.y})))
            {
                problems.push_back(Describe(*c) + ", " + bodies[s]->name + "'s velocity, lies inside " + other.name +
                                   " at the hit");
            }
        }
    }
    return problems;
}

// A body's velocity "v" inside the other body as it stands, where it reads as that body's (l09_landing's "v" by the
// floor's head of the arrow, inside the floor, beside the floor's name), when the arrow runs into that body and the
// part of its shaft between the two bodies has room for the name beside it (48 pixels: clear of the marks at both
// ends, the body's outline and the other body's face).
std::vector<std::string> VelocityInOtherBody(const RecordingCanvas& canvas, const Scene& scene, const PairStudy& study,
                                             const View& view)
{
    std::vector<std::string> problems;
    RecordingCanvas measure;
    const Body* bodies[2] = {&scene.bodies[static_cast<size_t>(study.bodyA)],
                             &scene.bodies[static_cast<size_t>(study.bodyB)]};
    const Color inks[2] = {palette::kShapeA, palette::kShapeBInk};
    for (const DrawCommand* c : canvas.InGroup("labels"))
    {
        if (c->kind != DrawCommand::Kind::Text || c->text != "v")
        {
            continue;
        }
        for (int s = 0; s < 2; ++s)
        {
            const Body& body = *bodies[s];
            const Body& other = *bodies[1 - s];
            if ((c->color >> 8) != (inks[s] >> 8) || body.velocity == Vec2{})
            {
                continue;
            }
            const ScreenPoint size = measure.MeasureText(c->text, c->style);
            if (!InsideBody(other, ToWorld(view, {c->points[0].x + 0.5f * size.x, c->points[0].y + 0.5f * size.y})))
            {
                continue;
            }
            // The arrow from the centre over one step's displacement: the length of its shaft outside both bodies
            // before it enters the other, on screen.
            const Vec2 from = TransformPoint(body.Xf(), body.shape.type == ShapeType::Polygon
                                                            ? body.shape.polygon.Centroid()
                                                            : body.shape.circle.center);
            const Vec2 to = from + body.velocity;
            const ScreenPoint a = ToScreen(view, from), b = ToScreen(view, to);
            const float length = std::hypot(b.x - a.x, b.y - a.y);
            if (!InsideBody(other, to) || InsideBody(other, from))
            {
                continue;
            }
            const int samples = 400;
            int between = 0;
            for (int k = 0; k < samples; ++k)
            {
                const Vec2 p = from + ((k + 0.5) / samples) * body.velocity;
                if (InsideBody(other, p))
                {
                    break;
                }
                between += InsideBody(body, p) ? 0 : 1;
            }
            const float room = length * static_cast<float>(between) / samples;
            if (room >= 48.0f)
            {
                problems.push_back(Describe(*c) + ", " + body.name + "'s velocity, lies inside " + other.name +
                                   " where " + std::to_string(static_cast<int>(room)) +
                                   " px of its shaft run between the two");
            }
        }
    }
    return problems;
}

// Leader lines across the separating line: the label lands on the other body's side of the line that parts the
// two, among that body's labels (an edge's name led over the line beside its face).
std::vector<std::string> LeadersAcrossSeparatingLine(const RecordingCanvas& canvas)
{
    std::vector<std::string> problems;
    // The line is drawn dashed: a leader through a gap between two dashes crosses it as well, so the dashes are
    // joined into one segment, from the first dash's start to the farthest end along them.
    std::vector<ScreenPoint> ends;
    for (const DrawCommand* d : canvas.InGroup("exit"))
    {
        if (d->kind == DrawCommand::Kind::Segment)
        {
            ends.push_back(d->points[0]);
            ends.push_back(d->points[1]);
        }
    }
    if (ends.size() < 2)
    {
        return problems;
    }
    ScreenPoint u = ends.front();
    ScreenPoint v = ends.front();
    for (const ScreenPoint& p : ends)
    {
        if (std::hypot(p.x - u.x, p.y - u.y) > std::hypot(v.x - u.x, v.y - u.y))
        {
            v = p;
        }
    }
    for (const ScreenPoint& p : ends)
    {
        if (std::hypot(p.x - v.x, p.y - v.y) > std::hypot(u.x - v.x, u.y - v.y))
        {
            u = p;
        }
    }
    auto side = [](ScreenPoint p, ScreenPoint q, ScreenPoint r) {
        return (q.x - p.x) * (r.y - p.y) - (q.y - p.y) * (r.x - p.x);
    };
    for (const DrawCommand* leader : canvas.InGroup("labels"))
    {
        const ScreenPoint a = leader->kind == DrawCommand::Kind::Segment ? leader->points[0] : ScreenPoint{};
        const ScreenPoint b = leader->kind == DrawCommand::Kind::Segment ? leader->points[1] : ScreenPoint{};
        if (leader->kind == DrawCommand::Kind::Segment && side(a, b, u) * side(a, b, v) < 0.0f &&
            side(u, v, a) * side(u, v, b) < 0.0f)
        {
            problems.push_back(Describe(*leader) + ", a leader line, crosses the separating line");
        }
    }
    return problems;
}

// A body of the pair as drawn: its outline on screen (a circle as a polygon of many sides).
std::vector<ScreenPoint> Outline(const Body& body, const View& view)
{
    std::vector<ScreenPoint> points;
    if (body.shape.type == ShapeType::Circle)
    {
        const Vec2 c = TransformPoint(body.Xf(), body.shape.circle.center);
        for (int i = 0; i < 64; ++i)
        {
            const double a = 2.0 * 3.14159265358979323846 * i / 64.0;
            points.push_back(ToScreen(view, c + body.shape.circle.radius * Vec2{std::cos(a), std::sin(a)}));
        }
        return points;
    }
    for (const Vec2& v : body.shape.polygon.Vertices())
    {
        points.push_back(ToScreen(view, TransformPoint(body.Xf(), v)));
    }
    return points;
}

// Labels that sit astride the outline of a body of the pair: the outline runs through the text, whose halo hides
// it, so the body seems cut (a ball's name over the ball), and the label reads as either body's.
std::vector<std::string> LabelsOnOutlines(const RecordingCanvas& canvas, const Scene& scene, const PairStudy& study,
                                          const View& view)
{
    std::vector<std::string> problems;
    RecordingCanvas measure;
    for (int body : {study.bodyA, study.bodyB})
    {
        const Body& b = scene.bodies[static_cast<size_t>(body)];
        const std::vector<ScreenPoint> outline = Outline(b, view);
        for (const DrawCommand* c : canvas.InGroup("labels"))
        {
            if (c->kind != DrawCommand::Kind::Text)
            {
                continue;
            }
            const ScreenPoint size = measure.MeasureText(c->text, c->style);
            // The text's ink, a pixel in from its box: an outline that grazes the box runs beside the text.
            const Box ink{c->points[0].x + 1.0f, c->points[0].y + 2.0f, c->points[0].x + size.x - 1.0f,
                          c->points[0].y + size.y - 2.0f};
            for (size_t i = 0; i < outline.size(); ++i)
            {
                if (SegmentCovers(outline[i], outline[(i + 1) % outline.size()], 1.0f, ink))
                {
                    problems.push_back(Describe(*c) + " lies on the outline of " + b.name);
                    break;
                }
            }
        }
    }
    return problems;
}

// Leader lines that run along an edge of a body of the pair: merged with the outline, the line seems to be part
// of it and the label to name that edge, or the corner where the line leaves it (on the app's canvas beside a
// lesson, l13_overlap's "reference face" was led down A's right edge to A's corner 1). Measured as the stretch of
// the leader lying within 3 pixels of the edge.
std::vector<std::string> LeadersAlongOutlines(const RecordingCanvas& canvas, const Scene& scene,
                                              const PairStudy& study, const View& view)
{
    std::vector<std::string> problems;
    for (int body : {study.bodyA, study.bodyB})
    {
        const Body& b = scene.bodies[static_cast<size_t>(body)];
        const std::vector<ScreenPoint> outline = Outline(b, view);
        for (const DrawCommand* c : canvas.InGroup("labels"))
        {
            if (c->kind != DrawCommand::Kind::Segment)
            {
                continue;
            }
            const ScreenPoint p = c->points[0];
            const ScreenPoint q = c->points[1];
            const float length = std::hypot(q.x - p.x, q.y - p.y);
            for (size_t i = 0; i < outline.size() && length > 0.0f; ++i)
            {
                const ScreenPoint u = outline[i];
                const ScreenPoint v = outline[(i + 1) % outline.size()];
                const float edge = std::hypot(v.x - u.x, v.y - u.y);
                if (edge <= 0.0f)
                {
                    continue;
                }
                // Sample the leader every half pixel; count the samples near the edge, between its ends.
                int near = 0;
                const int samples = static_cast<int>(length * 2.0f);
                for (int k = 0; k <= samples; ++k)
                {
                    const float t = samples > 0 ? static_cast<float>(k) / static_cast<float>(samples) : 0.0f;
                    const ScreenPoint r{p.x + (q.x - p.x) * t, p.y + (q.y - p.y) * t};
                    const float along = ((r.x - u.x) * (v.x - u.x) + (r.y - u.y) * (v.y - u.y)) / edge;
                    const float across = std::abs((r.x - u.x) * (v.y - u.y) - (r.y - u.y) * (v.x - u.x)) / edge;
                    near += along >= 0.0f && along <= edge && across <= 3.0f ? 1 : 0;
                }
                if (near * 0.5f > 20.0f)
                {
                    problems.push_back("the leader line at (" + std::to_string(static_cast<int>(p.x)) + ", " +
                                       std::to_string(static_cast<int>(p.y)) + ") runs along an edge of " + b.name);
                    break;
                }
            }
        }
    }
    return problems;
}

// Labels other than vertex numbers and edge names drawn over a dashed outline of where the MTV or a pitfall's push
// leaves a body, or of a moving body at another time (the short segments of the "mtv" and "ghost" groups): the
// label's halo breaks the outline, and the words read as crossed out.
std::vector<std::string> LabelsOnDashedOutlines(const RecordingCanvas& canvas)
{
    std::vector<std::string> problems;
    RecordingCanvas measure;
    std::vector<const DrawCommand*> dashes;
    for (const DrawCommand& c : canvas.commands)
    {
        if (c.kind == DrawCommand::Kind::Segment && (c.group == "mtv" || c.group == "ghost"))
        {
            dashes.push_back(&c);
            continue;
        }
        if (c.kind != DrawCommand::Kind::Text || c.group != "labels")
        {
            continue;
        }
        const std::string& t = c.text;
        const bool digits = painter_test::IsVertexNumber(t);
        const bool edge = painter_test::IsEdgeName(t);
        if (digits || edge)
        {
            continue;
        }
        const ScreenPoint size = measure.MeasureText(t, c.style);
        const Box ink{c.points[0].x + 1.0f, c.points[0].y + 2.0f, c.points[0].x + size.x - 1.0f,
                      c.points[0].y + size.y - 2.0f};
        for (const DrawCommand* d : dashes)
        {
            if (SegmentCovers(d->points[0], d->points[1], d->thickness, ink))
            {
                problems.push_back(Describe(c) + " lies on a dashed line at (" +
                                   std::to_string(static_cast<int>(d->points[0].x)) + ", " +
                                   std::to_string(static_cast<int>(d->points[0].y)) + ")");
                break;
            }
        }
    }
    return problems;
}

// Labels on a body outside the tested pair (drawn grey), where they read as that body's: a velocity's "v" inside a
// grey cushion, a vertex number on a grey wall.
std::vector<std::string> LabelsOnOtherBodies(const RecordingCanvas& canvas, const Scene& scene, const PairStudy& study,
                                             const View& view)
{
    std::vector<std::string> problems;
    RecordingCanvas measure;
    for (size_t i = 0; i < scene.bodies.size(); ++i)
    {
        const Body& b = scene.bodies[i];
        if (static_cast<int>(i) == study.bodyA || static_cast<int>(i) == study.bodyB || b.IsConcave())
        {
            continue;
        }
        const std::vector<ScreenPoint> outline = Outline(b, view);
        for (const DrawCommand* c : canvas.InGroup("labels"))
        {
            if (c->kind != DrawCommand::Kind::Text)
            {
                continue;
            }
            const ScreenPoint size = measure.MeasureText(c->text, c->style);
            const Box box{c->points[0].x, c->points[0].y, c->points[0].x + size.x, c->points[0].y + size.y};
            if (ConvexCovers(outline, box))
            {
                problems.push_back(Describe(*c) + " lies on " + b.name + ", a body outside the pair");
            }
        }
    }
    return problems;
}

// Labels drawn over a line of the scene drawn before them: a body's outline, a piece's seam, a dashed projection
// line, a separating line, an axis. The label's halo cuts the line, and the words read as part of it (an edge name
// on the separating line, a vertex number on the dashed line from its corner to the axis). The faint grid and the
// candidate axes under everything are the only lines a label may cross, and a translucent line (a dashed projection
// line, a ghost's outline) only a label wider than a glyph or two ("c2", "v", a number, an edge name), which is not
// read as the name of its end.
std::vector<std::string> LabelsOnLines(const RecordingCanvas& canvas)
{
    std::vector<std::string> problems;
    RecordingCanvas measure;
    const std::vector<DrawCommand>& commands = canvas.commands;
    for (size_t i = 0; i < commands.size(); ++i)
    {
        const DrawCommand& c = commands[i];
        if (c.kind != DrawCommand::Kind::Text || c.group != "labels")
        {
            continue;
        }
        const std::string& t = c.text;
        const bool digits = painter_test::IsVertexNumber(t);
        const bool edge = painter_test::IsEdgeName(t);
        const ScreenPoint size = measure.MeasureText(c.text, c.style);
        const Box ink{c.points[0].x + 1.0f, c.points[0].y + 2.0f, c.points[0].x + size.x - 1.0f,
                      c.points[0].y + size.y - 2.0f};
        for (size_t j = 0; j < i; ++j)
        {
            const DrawCommand& d = commands[j];
            if (d.group == "background" || d.group == "axes" || d.group == "labels" || (d.color & 0xFFu) < 0x40u ||
                (!Opaque(d.color) && !digits && !edge && size.x >= 18.0f))
            {
                continue;
            }
            bool on = false;
            if (d.kind == DrawCommand::Kind::Segment)
            {
                on = SegmentCovers(d.points[0], d.points[1], std::max(d.thickness, 1.0f), ink);
            }
            else if (d.kind == DrawCommand::Kind::Polyline)
            {
                for (size_t k = 0; k + 1 < d.points.size() + (d.closed ? 1 : 0) && !on; ++k)
                {
                    on = SegmentCovers(d.points[k], d.points[(k + 1) % d.points.size()], std::max(d.thickness, 1.0f),
                                       ink);
                }
            }
            else if (d.kind == DrawCommand::Kind::Circle)
            {
                float nearest = INFINITY, farthest = 0.0f;
                for (const ScreenPoint p : {ScreenPoint{ink.minX, ink.minY}, ScreenPoint{ink.maxX, ink.minY},
                                            ScreenPoint{ink.minX, ink.maxY}, ScreenPoint{ink.maxX, ink.maxY}})
                {
                    farthest = std::max(farthest, std::hypot(p.x - d.points[0].x, p.y - d.points[0].y));
                }
                const float x = std::clamp(d.points[0].x, ink.minX, ink.maxX);
                const float y = std::clamp(d.points[0].y, ink.minY, ink.maxY);
                nearest = std::hypot(x - d.points[0].x, y - d.points[0].y);
                on = nearest < d.radius && farthest > d.radius;
            }
            if (on)
            {
                problems.push_back(Describe(c) + " lies on the line " + Describe(d));
                break;
            }
        }
    }
    return problems;
}

// How many pixels of the segment ab lie inside the box.
float LengthIn(ScreenPoint a, ScreenPoint b, const Box& box)
{
    double t0 = 0.0, t1 = 1.0;
    const double dx = b.x - a.x, dy = b.y - a.y;
    const double p[4] = {-dx, dx, -dy, dy};
    const double q[4] = {a.x - box.minX, box.maxX - a.x, a.y - box.minY, box.maxY - a.y};
    for (int i = 0; i < 4; ++i)
    {
        if (p[i] == 0.0)
        {
            if (q[i] < 0.0)
            {
                return 0.0f;
            }
            continue;
        }
        const double t = q[i] / p[i];
        if (p[i] < 0.0)
        {
            t0 = std::max(t0, t);
        }
        else
        {
            t1 = std::min(t1, t);
        }
    }
    return t0 < t1 ? static_cast<float>((t1 - t0) * std::hypot(dx, dy)) : 0.0f;
}

// The part of the image where the scene shows, as drawn: below the caption's band and above the number line's panel
// (the first filled rectangle of each).
Box SceneInSight(const RecordingCanvas& canvas, const View& view)
{
    Box sight{0.0f, 0.0f, static_cast<float>(view.width), static_cast<float>(view.height)};
    for (const DrawCommand* c : canvas.InGroup("caption"))
    {
        if (c->kind == DrawCommand::Kind::FillRect)
        {
            sight.minY = std::max(sight.minY, c->points[1].y);
            break;
        }
    }
    for (const DrawCommand* c : canvas.InGroup("panel"))
    {
        if (c->kind == DrawCommand::Kind::FillRect)
        {
            sight.maxY = std::min(sight.maxY, c->points[0].y);
            break;
        }
    }
    return sight;
}

// The distance from p to the segment ab.
float ToSegment(ScreenPoint p, ScreenPoint a, ScreenPoint b)
{
    const float dx = b.x - a.x;
    const float dy = b.y - a.y;
    const float length2 = dx * dx + dy * dy;
    const float t = length2 > 0.0f ? std::clamp(((p.x - a.x) * dx + (p.y - a.y) * dy) / length2, 0.0f, 1.0f) : 0.0f;
    return std::hypot(a.x + dx * t - p.x, a.y + dy * t - p.y);
}

// Whether a face's name with its middle at `middle` reads as the rival body's: nearer the rival's outline than the
// face ab it names, less a lead of a few pixels and half its distance from the face (a name farther out is read by
// what lies nearest around it). A rival's edge flush along the face (a box standing on the floor) is where the face
// is, and does not count.
bool ReadsAsRivals(ScreenPoint middle, ScreenPoint a, ScreenPoint b, const std::vector<ScreenPoint>& rival)
{
    const float own = ToSegment(middle, a, b);
    const float length = std::hypot(b.x - a.x, b.y - a.y);
    for (size_t i = 0; i < rival.size() && length > 0.0f; ++i)
    {
        const ScreenPoint& u = rival[i];
        const ScreenPoint& v = rival[(i + 1) % rival.size()];
        const auto off = [&](ScreenPoint p) {
            return std::fabs((b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x)) / length;
        };
        if (off(u) < 2.0f && off(v) < 2.0f)
        {
            continue;
        }
        if (ToSegment(middle, u, v) < own + std::max(4.0f, 0.5f * own))
        {
            return true;
        }
    }
    return false;
}

// Edge names on the wrong side of their edge: an edge's name "eN" whose middle lies behind the line of that edge,
// where it names the face opposite (on a thin wall, the other face).
std::vector<std::string> EdgeNamesBehind(const RecordingCanvas& canvas, const Scene& scene, const PairStudy& study,
                                         const View& view)
{
    constexpr float kSeparatingRoom = 16.0f; // a label's width and its room from the line
    const Box sight = SceneInSight(canvas, view);
    std::vector<std::string> problems;
    RecordingCanvas measure;
    const Color inks[2] = {palette::kShapeA, palette::kShapeBInk};
    const int bodies[2] = {study.bodyA, study.bodyB};
    std::vector<const DrawCommand*> separating;
    for (const DrawCommand* d : canvas.InGroup("exit"))
    {
        if (d->kind == DrawCommand::Kind::Segment)
        {
            separating.push_back(d);
        }
    }
    for (const DrawCommand* c : canvas.InGroup("labels"))
    {
        if (c->kind != DrawCommand::Kind::Text || !painter_test::IsEdgeName(c->text))
        {
            continue;
        }
        for (int s = 0; s < 2; ++s)
        {
            const Body& body = scene.bodies[static_cast<size_t>(bodies[s])];
            const int edge = std::stoi(c->text.substr(1));
            if ((c->color >> 8) != (inks[s] >> 8) || body.shape.type != ShapeType::Polygon ||
                edge >= body.shape.polygon.Count())
            {
                continue;
            }
            const ScreenPoint size = measure.MeasureText(c->text, c->style);
            const Vec2 middle = ToWorld(view, {c->points[0].x + 0.5f * size.x, c->points[0].y + 0.5f * size.y});
            const Vec2 local = InvTransformPoint(body.Xf(), middle);
            const Polygon& poly = body.shape.polygon;
            // Just inside its own body is where a face with no room outside it is named: flush against the other
            // body (a box standing on the floor), or facing the image's side. Its mirror across the face's line
            // lies in that body or out of sight.
            const double behind = Dot(poly.Normal(edge), local - poly.Vertices()[edge]);
            const Vec2 mirror = TransformPoint(body.Xf(), local - 2.0 * behind * poly.Normal(edge));
            const ScreenPoint mirrorOnScreen = ToScreen(view, mirror);
            // Or the separating line runs so close outside the face that a name there would sit on it or
            // beyond it, among the other body's labels.
            const bool lineOutside = std::any_of(separating.begin(), separating.end(), [&](const DrawCommand* d) {
                return SegmentCovers(d->points[0], d->points[1], 2.0f * kSeparatingRoom,
                                     {mirrorOnScreen.x, mirrorOnScreen.y, mirrorOnScreen.x, mirrorOnScreen.y});
            });
            // A body outside the pair flush against the face (a wall standing on a floor's end) leaves no room
            // either: a name there would read as that body's.
            bool otherBody = false;
            for (size_t b = 0; b < scene.bodies.size(); ++b)
            {
                otherBody = otherBody || (static_cast<int>(b) != bodies[s] && !scene.bodies[b].IsConcave() &&
                                          InsideBody(scene.bodies[b], mirror));
            }
            // Or the place outside reads as the other body of the pair's, nearer its outline than the face.
            const Body& rival = scene.bodies[static_cast<size_t>(bodies[1 - s])];
            const std::vector<ScreenPoint> face = Outline(body, view);
            const bool rivals = ReadsAsRivals(mirrorOnScreen, face[static_cast<size_t>(edge)],
                                              face[static_cast<size_t>(edge + 1) % face.size()], Outline(rival, view));
            // Or other labels fill the place outside (the body's name, led out beside the face's normal).
            const Box there{mirrorOnScreen.x - 0.5f * size.x - 3.0f, mirrorOnScreen.y - 0.5f * size.y - 3.0f,
                            mirrorOnScreen.x + 0.5f * size.x + 3.0f, mirrorOnScreen.y + 0.5f * size.y + 3.0f};
            bool taken = false;
            for (const DrawCommand* o : canvas.InGroup("labels"))
            {
                if (o != c && o->kind == DrawCommand::Kind::Text)
                {
                    const ScreenPoint other = measure.MeasureText(o->text, o->style);
                    taken = taken || (o->points[0].x < there.maxX && o->points[0].x + other.x > there.minX &&
                                      o->points[0].y < there.maxY && o->points[0].y + other.y > there.minY);
                }
            }
            const bool noRoomOutside = otherBody || rivals || taken ||
                mirrorOnScreen.x < sight.minX || mirrorOnScreen.x > sight.maxX || mirrorOnScreen.y < sight.minY ||
                mirrorOnScreen.y > sight.maxY || lineOutside;
            if (behind <= 0.0 && !(InsideBody(body, middle) && noRoomOutside))
            {
                problems.push_back(Describe(*c) + " lies behind edge " + std::to_string(edge) + " of " + body.name);
            }
        }
    }
    return problems;
}

// Corners of the tested pair drawn so close to the image's left or right edge that their numbers and edge names
// crowd against the border (a corner beyond the edge is a body that runs on out of the picture, and is fine).
std::vector<std::string> CornersAtTheSides(const Scene& scene, const PairStudy& study, const View& view,
                                           LayerMask layers)
{
    constexpr float kRoom = 24.0f;
    std::vector<std::string> problems;
    for (int body : {study.bodyA, study.bodyB})
    {
        const Body& b = scene.bodies[static_cast<size_t>(body)];
        // Only corners the figure draws and numbers: a polygon of many sides has no numbers to crowd.
        if (!(layers & kLayerShapes) || b.shape.type != ShapeType::Polygon || b.shape.polygon.Count() > 24)
        {
            continue;
        }
        for (const Vec2& v : b.shape.polygon.Vertices())
        {
            const ScreenPoint p = ToScreen(view, TransformPoint(b.Xf(), v));
            const float width = static_cast<float>(view.width);
            if ((p.x >= 0.0f && p.x < kRoom) || (p.x <= width && p.x > width - kRoom))
            {
                problems.push_back("a corner of " + b.name + " lies " + std::to_string(static_cast<int>(p.x)) +
                                   " pixels across, against the image's side");
                break;
            }
        }
    }
    return problems;
}

// A face the figure's sentences name ("slab's edge 2") that the picture does not name: no "e2" in that body's colour
// among the labels, though some of the face is in sight (a long floor's far end beyond the image's side, the top of
// a large disc under the caption, have nowhere to be named).
std::vector<std::string> NamedFacesUnnamed(const RecordingCanvas& canvas, const Scene& scene, const PairStudy& study,
                                           LayerMask layers, const View& view)
{
    const Box sight = SceneInSight(canvas, view);
    std::vector<std::string> problems;
    if (!(layers & kLayerLabels))
    {
        return problems; // a figure without labels names no edge in its picture
    }
    std::string sentences;
    for (const DrawCommand& c : canvas.commands)
    {
        if (c.kind == DrawCommand::Kind::Text && c.group != "labels")
        {
            sentences += c.text + " ";
        }
    }
    const Color inks[2] = {palette::kShapeA, palette::kShapeBInk};
    const int bodies[2] = {study.bodyA, study.bodyB};
    for (int s = 0; s < 2; ++s)
    {
        const Body& body = scene.bodies[static_cast<size_t>(bodies[s])];
        if (body.shape.type != ShapeType::Polygon)
        {
            continue;
        }
        // The body's edge names the picture shows: a face the sentence names is among them however small the
        // body is drawn.
        std::vector<int> shown;
        for (const DrawCommand* c : canvas.InGroup("labels"))
        {
            if (c->kind == DrawCommand::Kind::Text && (c->color >> 8) == (inks[s] >> 8) &&
                painter_test::IsEdgeName(c->text))
            {
                shown.push_back(std::stoi(c->text.substr(1)));
            }
        }
        for (int edge = 0; edge < body.shape.polygon.Count(); ++edge)
        {
            const std::string phrase = body.name + "'s edge " + std::to_string(edge);
            const size_t at = sentences.find(phrase);
            const bool named = at != std::string::npos &&
                               (at + phrase.size() == sentences.size() || !std::isdigit(static_cast<unsigned char>(
                                                                              sentences[at + phrase.size()])));
            const Vec2 a = TransformPoint(body.Xf(), body.shape.polygon.Vertices()[static_cast<size_t>(edge)]);
            const Vec2 b = TransformPoint(
                body.Xf(), body.shape.polygon.Vertices()[static_cast<size_t>((edge + 1) % body.shape.polygon.Count())]);
            const bool inSight = LengthIn(ToScreen(view, a), ToScreen(view, b), sight) >= 1.0f;
            if (named && inSight && std::find(shown.begin(), shown.end(), edge) == shown.end())
            {
                problems.push_back("the sentence names " + phrase + ", which the picture does not label");
            }
        }
        // And a corner it names ("the axis from box's vertex 2 to ball's centre") by its number.
        for (int vertex = 0; vertex < body.shape.polygon.Count(); ++vertex)
        {
            const std::string phrase = body.name + "'s vertex " + std::to_string(vertex);
            const size_t at = sentences.find(phrase);
            const bool named = at != std::string::npos &&
                               (at + phrase.size() == sentences.size() || !std::isdigit(static_cast<unsigned char>(
                                                                              sentences[at + phrase.size()])));
            const bool labelled = std::any_of(canvas.commands.begin(), canvas.commands.end(), [&](const DrawCommand& c) {
                return c.kind == DrawCommand::Kind::Text && c.group == "labels" && (c.color >> 8) == (inks[s] >> 8) &&
                       c.text == std::to_string(vertex);
            });
            if (named && !labelled)
            {
                problems.push_back("the sentence names " + phrase + ", which the picture does not number");
            }
        }
    }
    return problems;
}

bool OnLeader(const RecordingCanvas& canvas, const DrawCommand& text);

// The name of one of two contact points ("c1", "c2", no leader line) whose middle lies between the two dots, in the
// middle half of the way from one to the other and closer to their line than to either dot's far side: it could be
// either's (l09_landing's "c2" below the floor's face, between its dot and c1's).
std::vector<std::string> ContactNamesBetweenDots(const RecordingCanvas& canvas)
{
    std::vector<std::string> problems;
    RecordingCanvas measure;
    std::vector<ScreenPoint> dots;
    for (const DrawCommand* c : canvas.InGroup("contacts"))
    {
        if (c->kind == DrawCommand::Kind::FillCircle && c->color == palette::kResult)
        {
            dots.push_back(c->points[0]);
        }
    }
    if (dots.size() != 2)
    {
        return problems;
    }
    const ScreenPoint p = dots[0];
    const ScreenPoint q = dots[1];
    const float length = std::hypot(q.x - p.x, q.y - p.y);
    if (length < 16.0f)
    {
        return problems;
    }
    for (const DrawCommand* c : canvas.InGroup("labels"))
    {
        if (c->kind != DrawCommand::Kind::Text || (c->text != "c1" && c->text != "c2") || OnLeader(canvas, *c))
        {
            continue;
        }
        const ScreenPoint size = measure.MeasureText(c->text, c->style);
        const ScreenPoint m{c->points[0].x + 0.5f * size.x, c->points[0].y + 0.5f * size.y};
        const float along = ((m.x - p.x) * (q.x - p.x) + (m.y - p.y) * (q.y - p.y)) / (length * length);
        const float across = std::abs((q.x - p.x) * (m.y - p.y) - (q.y - p.y) * (m.x - p.x)) / length;
        if (along > 0.25f && along < 0.75f && across < 0.5f * length)
        {
            problems.push_back(Describe(*c) + " lies between the two contact points, " +
                               std::to_string(static_cast<int>(along * 100.0f)) + " % of the way from one to the other");
        }
    }
    return problems;
}

// A face's name ("reference face", "incident edge", "e2") in a row with a contact's dot, just past the dot's side,
// with no leader line: it reads as the dot's name (l06_tilted_plank's "reference face" ending 8 px left of c1).
std::vector<std::string> FaceNamesByDots(const RecordingCanvas& canvas)
{
    std::vector<std::string> problems;
    RecordingCanvas measure;
    std::vector<ScreenPoint> dots;
    for (const DrawCommand* c : canvas.InGroup("contacts"))
    {
        if (c->kind == DrawCommand::Kind::FillCircle && c->color == palette::kResult)
        {
            dots.push_back(c->points[0]);
        }
    }
    for (const DrawCommand* c : canvas.InGroup("labels"))
    {
        const std::string& t = c->text;
        if (c->kind != DrawCommand::Kind::Text ||
            !(t == "reference face" || t == "incident edge" || painter_test::IsEdgeName(t)) || OnLeader(canvas, *c))
        {
            continue;
        }
        const ScreenPoint size = measure.MeasureText(t, c->style);
        const float top = c->points[0].y, bottom = c->points[0].y + size.y;
        const float left = c->points[0].x, right = c->points[0].x + size.x;
        for (const ScreenPoint& dot : dots)
        {
            const float gap = std::max(left - dot.x, dot.x - right);
            if (dot.y >= top - 2.0f && dot.y <= bottom + 2.0f && gap >= 0.0f && gap < 26.0f)
            {
                problems.push_back(Describe(*c) + " lies in a row with the contact's dot at (" +
                                   std::to_string(static_cast<int>(dot.x)) + ", " +
                                   std::to_string(static_cast<int>(dot.y)) + "), " +
                                   std::to_string(static_cast<int>(gap)) + " px past its end");
            }
        }
    }
    return problems;
}

// A "reference face" label far from the contact: a textbook names the face where the incident edge is clipped
// against it, beside the contact points (or between them), not at the far end of a long face (a floor's free
// stretch). Far is more than a label's width and a half from the stretch between the contact points.
std::vector<std::string> ReferenceFaceFar(const RecordingCanvas& canvas)
{
    constexpr float kNear = 120.0f;
    std::vector<std::string> problems;
    RecordingCanvas measure;
    std::vector<ScreenPoint> contacts;
    for (const DrawCommand* c : canvas.InGroup("contacts"))
    {
        if (c->kind == DrawCommand::Kind::FillCircle && c->color == palette::kResult)
        {
            contacts.push_back(c->points[0]);
        }
    }
    if (contacts.empty())
    {
        return problems;
    }
    const ScreenPoint a = contacts.front();
    const ScreenPoint b = contacts.back();
    for (const DrawCommand* c : canvas.InGroup("labels"))
    {
        if (c->kind != DrawCommand::Kind::Text || c->text != "reference face")
        {
            continue;
        }
        const ScreenPoint size = measure.MeasureText(c->text, c->style);
        const Box box{c->points[0].x, c->points[0].y, c->points[0].x + size.x, c->points[0].y + size.y};
        // The distance from the stretch ab to the label's box, sampled along the stretch.
        float nearest = INFINITY;
        for (int i = 0; i <= 64; ++i)
        {
            const float t = static_cast<float>(i) / 64.0f;
            const ScreenPoint p{a.x + (b.x - a.x) * t, a.y + (b.y - a.y) * t};
            const float x = std::clamp(p.x, box.minX, box.maxX);
            const float y = std::clamp(p.y, box.minY, box.maxY);
            nearest = std::min(nearest, std::hypot(x - p.x, y - p.y));
        }
        if (nearest > kNear)
        {
            problems.push_back(Describe(*c) + " lies " + std::to_string(static_cast<int>(nearest)) +
                               " pixels from the contact points");
        }
    }
    return problems;
}

// The leader line that ends at the text's box, or null when the label sits beside its mark without one.
const DrawCommand* LeaderTo(const RecordingCanvas& canvas, const DrawCommand& text)
{
    RecordingCanvas measure;
    const ScreenPoint size = measure.MeasureText(text.text, text.style);
    for (const DrawCommand* line : canvas.InGroup("labels"))
    {
        const ScreenPoint end = line->kind == DrawCommand::Kind::Segment ? line->points[1] : ScreenPoint{-1e9f, -1e9f};
        if (end.x >= text.points[0].x - 0.5f && end.x <= text.points[0].x + size.x + 0.5f &&
            end.y >= text.points[0].y - 0.5f && end.y <= text.points[0].y + size.y + 0.5f)
        {
            return line;
        }
    }
    return nullptr;
}

// The velocities' shafts: each a solid segment in "swept" drawn just before its head.
std::vector<const DrawCommand*> VelocityShafts(const RecordingCanvas& canvas)
{
    std::vector<const DrawCommand*> shafts;
    for (size_t k = 0; k + 1 < canvas.commands.size(); ++k)
    {
        const DrawCommand& c = canvas.commands[k];
        if (c.group == "swept" && c.kind == DrawCommand::Kind::Segment && c.thickness >= 2.0f &&
            IsArrowHead(canvas.commands[k + 1]) && canvas.commands[k + 1].color == c.color)
        {
            shafts.push_back(&c);
        }
    }
    return shafts;
}

// A face's name ("e2", "reference face", "incident edge") on a leader line that starts where a velocity's shaft
// crosses the face: the line names the path's meeting with the face (l10_round_bullet's crate "e2", led to where the
// bullet's path enters it).
std::vector<std::string> FaceLeadersFromPaths(const RecordingCanvas& canvas)
{
    std::vector<std::string> problems;
    const std::vector<const DrawCommand*> shafts = VelocityShafts(canvas);
    for (const DrawCommand* c : canvas.InGroup("labels"))
    {
        const std::string& t = c->text;
        if (c->kind != DrawCommand::Kind::Text ||
            !(t == "reference face" || t == "incident edge" || painter_test::IsEdgeName(t)))
        {
            continue;
        }
        const DrawCommand* line = LeaderTo(canvas, *c);
        if (line == nullptr)
        {
            continue;
        }
        for (const DrawCommand* shaft : shafts)
        {
            if (ToSegment(line->points[0], shaft->points[0], shaft->points[1]) < 6.0f)
            {
                problems.push_back(Describe(*c) + " is led from where a velocity's shaft crosses its face, at (" +
                                   std::to_string(static_cast<int>(line->points[0].x)) + ", " +
                                   std::to_string(static_cast<int>(line->points[0].y)) + ")");
            }
        }
    }
    return problems;
}

// A reference face's name on a leader line that starts at a corner of the pair (the very end of the face) rather
// than on the face: the line names the corner, an unnumbered one where a vertex number is left out.
std::vector<std::string> ReferenceFaceAtCorner(const RecordingCanvas& canvas, const Scene& scene,
                                               const PairStudy& study, const View& view)
{
    std::vector<std::string> problems;
    std::vector<ScreenPoint> corners;
    for (int body : {study.bodyA, study.bodyB})
    {
        const Body& b = scene.bodies[static_cast<size_t>(body)];
        if (b.shape.type == ShapeType::Polygon)
        {
            for (const ScreenPoint& p : Outline(b, view))
            {
                corners.push_back(p);
            }
        }
    }
    for (const DrawCommand* c : canvas.InGroup("labels"))
    {
        if (c->kind != DrawCommand::Kind::Text || c->text != "reference face")
        {
            continue;
        }
        if (const DrawCommand* line = LeaderTo(canvas, *c))
        {
            const ScreenPoint start = line->points[0];
            for (const ScreenPoint& corner : corners)
            {
                if (std::hypot(corner.x - start.x, corner.y - start.y) < 8.0f)
                {
                    problems.push_back(Describe(*c) + " is led from a corner, at (" +
                                       std::to_string(static_cast<int>(corner.x)) + ", " +
                                       std::to_string(static_cast<int>(corner.y)) + "), not from its face");
                    break;
                }
            }
        }
    }
    return problems;
}

// A reference face's name wholly past an end of its face (every corner of its box, taken along the face, beyond
// the same end), but for one on a leader line that leaves the face steeply: it sits beside the corner and the next
// face, where it reads as that face's (l15_slope's "reference face" beside the slope's end e1), or its leader line
// runs nearly along the face into the body beside it and ends short of the face (overlapping_boxes). The face is
// the first thick line of the contacts' group.
std::vector<std::string> ReferenceFaceBeyondEnd(const RecordingCanvas& canvas)
{
    std::vector<std::string> problems;
    RecordingCanvas measure;
    const std::vector<const DrawCommand*> contacts = canvas.InGroup("contacts");
    const auto face = std::find_if(contacts.begin(), contacts.end(), [](const DrawCommand* c) {
        return c->kind == DrawCommand::Kind::Segment && c->thickness >= 5.0f;
    });
    if (face == contacts.end())
    {
        return problems;
    }
    const ScreenPoint a = (*face)->points[0];
    const ScreenPoint b = (*face)->points[1];
    const float length2 = (b.x - a.x) * (b.x - a.x) + (b.y - a.y) * (b.y - a.y);
    for (const DrawCommand* c : canvas.InGroup("labels"))
    {
        if (c->kind != DrawCommand::Kind::Text || c->text != "reference face" || length2 <= 0.0f)
        {
            continue;
        }
        const ScreenPoint size = measure.MeasureText(c->text, c->style);
        float low = INFINITY;
        float high = -INFINITY;
        for (const ScreenPoint& p : {c->points[0], ScreenPoint{c->points[0].x + size.x, c->points[0].y},
                                     ScreenPoint{c->points[0].x, c->points[0].y + size.y},
                                     ScreenPoint{c->points[0].x + size.x, c->points[0].y + size.y}})
        {
            const float t = ((p.x - a.x) * (b.x - a.x) + (p.y - a.y) * (b.y - a.y)) / length2;
            low = std::min(low, t);
            high = std::max(high, t);
        }
        // Past an end only on a leader line that leaves the face at 30 degrees or more.
        bool steep = false;
        if (const DrawCommand* line = LeaderTo(canvas, *c))
        {
            const float lx = line->points[1].x - line->points[0].x;
            const float ly = line->points[1].y - line->points[0].y;
            steep = std::abs(lx * (b.y - a.y) - ly * (b.x - a.x)) >= 0.5f * std::hypot(lx, ly) * std::sqrt(length2);
        }
        if ((high < 0.0f || low > 1.0f) && !steep)
        {
            problems.push_back(Describe(*c) + " lies wholly past an end of its face");
        }
    }
    return problems;
}

bool OnLeader(const RecordingCanvas& canvas, const DrawCommand& text);

// Names of a face ("e2", "reference face", "incident edge") that do not sit clearly nearer the face they name than
// the other body of the pair (ReadsAsRivals): beside the other body's corner or over its edge the name reads as that
// body's (the floor's "e2" at the plank's corner, "reference face" over the small box inside the large one, beside
// the large one's face). Measured from the middle of the label; one on a leader line is joined to its face.
std::vector<std::string> FaceNamesAstray(const RecordingCanvas& canvas, const Scene& scene, const PairStudy& study,
                                         const View& view)
{
    std::vector<std::string> problems;
    RecordingCanvas measure;
    const Body* bodies[2] = {&scene.bodies[static_cast<size_t>(study.bodyA)],
                             &scene.bodies[static_cast<size_t>(study.bodyB)]};
    const Color inks[2] = {palette::kShapeA, palette::kShapeBInk};
    const std::vector<ScreenPoint> outlines[2] = {Outline(*bodies[0], view), Outline(*bodies[1], view)};
    // The ghosts: a moving body drawn where it is at another time, a pale fill under a dashed outline.
    std::vector<std::vector<ScreenPoint>> ghosts;
    for (const DrawCommand* d : canvas.InGroup("ghost"))
    {
        if (d->kind == DrawCommand::Kind::FillConvex && d->points.size() >= 3)
        {
            ghosts.push_back(d->points);
        }
    }
    // And a moving polygon's dashed outline where the step ends (sliding_past's box), when one is drawn: taken
    // from the scene, at t = 1.
    const std::vector<const DrawCommand*> swept = canvas.InGroup("swept");
    const bool dashedEnd = std::any_of(swept.begin(), swept.end(), [](const DrawCommand* d) {
        return d->kind == DrawCommand::Kind::Segment && d->thickness > 1.1f && d->thickness < 1.3f;
    });
    for (int k = 0; k < 2 && dashedEnd; ++k)
    {
        if (bodies[k]->velocity == Vec2{} || bodies[k]->shape.type != ShapeType::Polygon)
        {
            continue;
        }
        const Transform end = BodyTransformAt(*bodies[k], 1.0);
        std::vector<ScreenPoint> outline;
        for (const Vec2& v : bodies[k]->shape.polygon.Vertices())
        {
            outline.push_back(ToScreen(view, TransformPoint(end, v)));
        }
        ghosts.push_back(std::move(outline));
    }
    // And B where a pitfall's push leaves it, dashed in ink beside the MTV's outline (pitfall_unnormalised's
    // crate), when drawn: B moved by the pitfall's depth along its normal.
    const std::vector<const DrawCommand*> mtv = canvas.InGroup("mtv");
    const bool pushedOutline = std::any_of(mtv.begin(), mtv.end(), [](const DrawCommand* d) {
        return d->kind == DrawCommand::Kind::Segment && d->color == palette::kInk && d->thickness > 1.1f &&
               d->thickness < 1.3f;
    });
    if (pushedOutline && study.pitfall.ran && bodies[1]->shape.type == ShapeType::Polygon)
    {
        Transform pushed = bodies[1]->Xf();
        pushed.p = pushed.p + study.pitfall.depth * study.pitfall.normal;
        std::vector<ScreenPoint> outline;
        for (const Vec2& v : bodies[1]->shape.polygon.Vertices())
        {
            outline.push_back(ToScreen(view, TransformPoint(pushed, v)));
        }
        ghosts.push_back(std::move(outline));
    }
    for (const DrawCommand* c : canvas.InGroup("labels"))
    {
        if (c->kind != DrawCommand::Kind::Text || OnLeader(canvas, *c))
        {
            continue;
        }
        const std::string& t = c->text;
        const bool edge = painter_test::IsEdgeName(t);
        const bool clip = t == "reference face" || t == "incident edge";
        int s = -1;
        for (int k = 0; k < 2; ++k)
        {
            s = (c->color >> 8) == (inks[k] >> 8) ? k : s;
        }
        if ((!edge && !clip) || s < 0)
        {
            continue;
        }
        ScreenPoint a{}, b{};
        bool found = false;
        if (edge)
        {
            const size_t n = static_cast<size_t>(std::stoi(t.substr(1)));
            if (bodies[s]->shape.type != ShapeType::Polygon || n >= outlines[s].size())
            {
                continue;
            }
            a = outlines[s][n];
            b = outlines[s][(n + 1) % outlines[s].size()];
            found = true;
        }
        for (const DrawCommand* d : canvas.InGroup("contacts"))
        {
            if (clip && !found && d->kind == DrawCommand::Kind::Segment && d->thickness >= 4.5f && d->color == c->color)
            {
                a = d->points[0];
                b = d->points[1];
                found = true;
            }
        }
        if (!found)
        {
            continue;
        }
        const ScreenPoint size = measure.MeasureText(t, c->style);
        const ScreenPoint middle{c->points[0].x + 0.5f * size.x, c->points[0].y + 0.5f * size.y};
        if (ReadsAsRivals(middle, a, b, outlines[1 - s]) ||
            std::any_of(ghosts.begin(), ghosts.end(),
                        [&](const std::vector<ScreenPoint>& ghost) { return ReadsAsRivals(middle, a, b, ghost); }))
        {
            problems.push_back(Describe(*c) + " lies " + std::to_string(static_cast<int>(ToSegment(middle, a, b))) +
                               " pixels from the face it names, as near " + bodies[1 - s]->name +
                               "'s outline or a ghost's");
        }
    }
    return problems;
}

// Edge names "eN" beside the other body's corner while their face has room well away from it: there the name reads
// as naming the corner (the floor's "e2" under the raised corner of a tilted plank, where the floor runs on free
// for hundreds of pixels). Flagged when the name's middle lies within 60 pixels of a corner of the other body and
// some point of the face in the image lies farther from the other body, and from the face's own ends, than twice
// that distance and 20 pixels more. Names on a leader line are joined to their face and are left out.
std::vector<std::string> EdgeNamesByRivalCorners(const RecordingCanvas& canvas, const Scene& scene,
                                                 const PairStudy& study, const View& view)
{
    std::vector<std::string> problems;
    RecordingCanvas measure;
    const Body* bodies[2] = {&scene.bodies[static_cast<size_t>(study.bodyA)],
                             &scene.bodies[static_cast<size_t>(study.bodyB)]};
    const Color inks[2] = {palette::kShapeA, palette::kShapeBInk};
    const std::vector<ScreenPoint> outlines[2] = {Outline(*bodies[0], view), Outline(*bodies[1], view)};
    for (const DrawCommand* c : canvas.InGroup("labels"))
    {
        if (c->kind != DrawCommand::Kind::Text || OnLeader(canvas, *c))
        {
            continue;
        }
        const std::string& t = c->text;
        const bool edge = painter_test::IsEdgeName(t);
        int s = -1;
        for (int k = 0; k < 2; ++k)
        {
            s = (c->color >> 8) == (inks[k] >> 8) ? k : s;
        }
        if (!edge || s < 0 || bodies[s]->shape.type != ShapeType::Polygon ||
            bodies[1 - s]->shape.type != ShapeType::Polygon)
        {
            continue;
        }
        const size_t n = static_cast<size_t>(std::stoi(t.substr(1)));
        if (n >= outlines[s].size())
        {
            continue;
        }
        const ScreenPoint a = outlines[s][n];
        const ScreenPoint b = outlines[s][(n + 1) % outlines[s].size()];
        const std::vector<ScreenPoint>& rival = outlines[1 - s];
        const ScreenPoint size = measure.MeasureText(t, c->style);
        const ScreenPoint middle{c->points[0].x + 0.5f * size.x, c->points[0].y + 0.5f * size.y};
        // Only corners on the name's side of the face's line compete with it (a box inside a larger one has its
        // corners behind the larger one's faces).
        const auto side = [&](ScreenPoint p) { return (b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x); };
        float corner = 1e9f;
        for (const ScreenPoint& v : rival)
        {
            if (side(v) * side(middle) > 0.0f)
            {
                corner = std::min(corner, std::hypot(v.x - middle.x, v.y - middle.y));
            }
        }
        if (corner >= 60.0f)
        {
            continue;
        }
        const auto fromRival = [&](ScreenPoint p) {
            float d = 1e9f;
            for (size_t i = 0; i < rival.size(); ++i)
            {
                d = std::min(d, ToSegment(p, rival[i], rival[(i + 1) % rival.size()]));
            }
            return d;
        };
        float room = 0.0f;
        for (int i = 0; i <= 64; ++i)
        {
            const float u = static_cast<float>(i) / 64.0f;
            const ScreenPoint p{a.x + (b.x - a.x) * u, a.y + (b.y - a.y) * u};
            if (p.x < 0.0f || p.y < 0.0f || p.x > static_cast<float>(view.width) ||
                p.y > static_cast<float>(view.height))
            {
                continue;
            }
            room = std::max(room, std::min({fromRival(p), std::hypot(p.x - a.x, p.y - a.y),
                                            std::hypot(p.x - b.x, p.y - b.y)}));
        }
        if (room >= 2.0f * corner + 20.0f)
        {
            problems.push_back(Describe(*c) + " lies " + std::to_string(static_cast<int>(corner)) + " pixels from a corner of " +
                               bodies[1 - s]->name + ", where its face has a point " +
                               std::to_string(static_cast<int>(room)) + " pixels clear of it");
        }
    }
    return problems;
}

// Vertex numbers and edge names with an arrow's shaft between them and what they name: the arrow cuts the number
// off from its corner (A's "2" above the velocity arrow that runs past A's corner), and it reads as the arrow's.
// Measured from the middle of the label to its corner, or to the nearest point of its edge; a label on a leader
// line is joined to what it names.
std::vector<std::string> ArrowsBetween(const RecordingCanvas& canvas, const Scene& scene, const PairStudy& study,
                                       const View& view)
{
    std::vector<std::string> problems;
    RecordingCanvas measure;
    std::vector<const DrawCommand*> shafts;
    const std::vector<DrawCommand>& commands = canvas.commands;
    for (size_t i = 0; i + 1 < commands.size(); ++i)
    {
        if (commands[i].kind == DrawCommand::Kind::Segment && commands[i].group != "labels" &&
            commands[i].group != "legend" && IsArrowHead(commands[i + 1]))
        {
            shafts.push_back(&commands[i]);
        }
    }
    const Body* bodies[2] = {&scene.bodies[static_cast<size_t>(study.bodyA)],
                             &scene.bodies[static_cast<size_t>(study.bodyB)]};
    const Color inks[2] = {palette::kShapeA, palette::kShapeBInk};
    const std::vector<ScreenPoint> outlines[2] = {Outline(*bodies[0], view), Outline(*bodies[1], view)};
    for (const DrawCommand* c : canvas.InGroup("labels"))
    {
        if (c->kind != DrawCommand::Kind::Text || OnLeader(canvas, *c))
        {
            continue;
        }
        const std::string& t = c->text;
        const bool digits = t.size() <= 3 && painter_test::IsVertexNumber(t);
        const bool edge = painter_test::IsEdgeName(t);
        if (!digits && !edge)
        {
            continue;
        }
        const ScreenPoint size = measure.MeasureText(t, c->style);
        const ScreenPoint middle{c->points[0].x + 0.5f * size.x, c->points[0].y + 0.5f * size.y};
        for (int s = 0; s < 2; ++s)
        {
            const size_t n = static_cast<size_t>(std::stoi(edge ? t.substr(1) : t));
            if ((c->color >> 8) != (inks[s] >> 8) || bodies[s]->shape.type != ShapeType::Polygon ||
                n >= outlines[s].size())
            {
                continue;
            }
            ScreenPoint to = outlines[s][n];
            if (edge)
            {
                const ScreenPoint a = outlines[s][n];
                const ScreenPoint b = outlines[s][(n + 1) % outlines[s].size()];
                const float dx = b.x - a.x;
                const float dy = b.y - a.y;
                const float length2 = dx * dx + dy * dy;
                const float u = length2 > 0.0f
                                    ? std::clamp(((middle.x - a.x) * dx + (middle.y - a.y) * dy) / length2, 0.0f, 1.0f)
                                    : 0.0f;
                to = {a.x + dx * u, a.y + dy * u};
            }
            auto side = [](ScreenPoint p, ScreenPoint q, ScreenPoint r) {
                return (q.x - p.x) * (r.y - p.y) - (q.y - p.y) * (r.x - p.x);
            };
            for (const DrawCommand* d : shafts)
            {
                const ScreenPoint u = d->points[0], v = d->points[1];
                if (side(middle, to, u) * side(middle, to, v) < 0.0f && side(u, v, middle) * side(u, v, to) < 0.0f)
                {
                    problems.push_back(Describe(*c) + " has the arrow " + Describe(*d) +
                                       " between it and what it names");
                    break;
                }
            }
        }
    }
    return problems;
}

// Whether the sentences name `number` in a list of a body's edges ("box's edges 0 and 2", "B's edges 0, 1 and 3").
bool InEdgeList(const std::string& sentences, const std::string& name, const std::string& number)
{
    const std::string head = name + "'s edges ";
    for (size_t at = sentences.find(head); at != std::string::npos; at = sentences.find(head, at + 1))
    {
        size_t k = at + head.size();
        while (k < sentences.size() && std::isdigit(static_cast<unsigned char>(sentences[k])))
        {
            size_t end = k;
            while (end < sentences.size() && std::isdigit(static_cast<unsigned char>(sentences[end])))
            {
                ++end;
            }
            if (sentences.compare(k, end - k, number) == 0 && end - k == number.size())
            {
                return true;
            }
            k = end;
            if (sentences.compare(k, 2, ", ") == 0)
            {
                k += 2;
            }
            else if (sentences.compare(k, 5, " and ") == 0)
            {
                k += 5;
            }
            else
            {
                break;
            }
        }
    }
    return false;
}

// Vertex numbers and edge names hung on leader lines (a number at the end of a line, among the outlines, reads as
// any corner's: the floor's "3" led into the box standing on it), unless a sentence names them and they must show.
std::vector<std::string> NamesAstray(const RecordingCanvas& canvas, const Scene& scene, const PairStudy& study)
{
    std::vector<std::string> problems;
    RecordingCanvas measure;
    std::string sentences;
    for (const DrawCommand& c : canvas.commands)
    {
        if (c.kind == DrawCommand::Kind::Text && c.group != "labels")
        {
            sentences += c.text + " ";
        }
    }
    const Body* bodies[2] = {&scene.bodies[static_cast<size_t>(study.bodyA)],
                             &scene.bodies[static_cast<size_t>(study.bodyB)]};
    const Color inks[2] = {palette::kShapeA, palette::kShapeBInk};
    std::vector<std::pair<const DrawCommand*, Box>> labels;
    for (const DrawCommand* c : canvas.InGroup("labels"))
    {
        if (c->kind == DrawCommand::Kind::Text)
        {
            const ScreenPoint size = measure.MeasureText(c->text, c->style);
            labels.push_back({c, {c->points[0].x, c->points[0].y, c->points[0].x + size.x, c->points[0].y + size.y}});
        }
    }
    for (const DrawCommand* line : canvas.InGroup("labels"))
    {
        if (line->kind != DrawCommand::Kind::Segment)
        {
            continue;
        }
        for (const auto& [c, box] : labels)
        {
            const ScreenPoint end = line->points[1];
            const bool own = end.x >= box.minX - 0.5f && end.x <= box.maxX + 0.5f && end.y >= box.minY - 0.5f &&
                             end.y <= box.maxY + 0.5f;
            const std::string& t = c->text;
            const bool digits = painter_test::IsVertexNumber(t);
            const bool edge =
                painter_test::IsEdgeName(t);
            if (!own || !(digits || edge))
            {
                continue;
            }
            for (int s = 0; s < 2; ++s)
            {
                if ((c->color >> 8) != (inks[s] >> 8))
                {
                    continue;
                }
                const std::string phrase =
                    bodies[s]->name + (edge ? "'s edge " + t.substr(1) : "'s vertex " + t);
                const size_t at = sentences.find(phrase);
                const bool named = (at != std::string::npos &&
                                    (at + phrase.size() == sentences.size() ||
                                     !std::isdigit(static_cast<unsigned char>(sentences[at + phrase.size()])))) ||
                                   (edge && InEdgeList(sentences, bodies[s]->name, t.substr(1)));
                if (!named)
                {
                    problems.push_back(Describe(*c) + " hangs on a leader line");
                }
            }
        }
    }
    return problems;
}

// Whether a leader line ends at the text's box: the line shows what the label names.
bool OnLeader(const RecordingCanvas& canvas, const DrawCommand& text)
{
    return LeaderTo(canvas, text) != nullptr;
}

// The corners of the dashed outlines (where the MTV or a pitfall's push leaves a body, a moving body at another
// time): each side is drawn as dashes from its first corner on, so a corner is where a dash starts in a new
// direction. A round outline, whose every dash turns, has no corners.
std::vector<ScreenPoint> DashedCorners(const RecordingCanvas& canvas)
{
    std::vector<ScreenPoint> corners;
    for (const char* group : {"mtv", "ghost", "pitfall"})
    {
        std::vector<ScreenPoint> found;
        ScreenPoint last{0.0f, 0.0f};
        bool any = false;
        for (const DrawCommand* d : canvas.InGroup(group))
        {
            // A dash: short and thin (not an arrow's shaft, nor the dashes of a pitfall's push, 2 pixels wide).
            if (d->kind != DrawCommand::Kind::Segment || d->thickness >= 1.9f)
            {
                continue;
            }
            const float length = std::hypot(d->points[1].x - d->points[0].x, d->points[1].y - d->points[0].y);
            if (length < 1.0f || length > 7.0f)
            {
                continue;
            }
            const ScreenPoint u{(d->points[1].x - d->points[0].x) / length, (d->points[1].y - d->points[0].y) / length};
            if (!any || std::fabs(u.x * last.y - u.y * last.x) > 0.02f || u.x * last.x + u.y * last.y < 0.0f)
            {
                found.push_back(d->points[0]);
            }
            last = u;
            any = true;
        }
        if (found.size() <= 12)
        {
            corners.insert(corners.end(), found.begin(), found.end());
        }
    }
    return corners;
}

// Labels that sit nearer another mark of their kind than their own, where which mark they name is a guess: a
// contact point's name "cN" nearer another contact point than the Nth (or clearly nearer a corner of the pair than
// its own), a vertex number nearer another corner of the pair (or of a dashed outline of where a body is moved to)
// than its own. Measured from the middle of the label; a label on a leader line is joined to what it names.
std::vector<std::string> LabelsNearerAnotherMark(const RecordingCanvas& canvas, const Scene& scene,
                                                 const PairStudy& study, const View& view)
{
    std::vector<std::string> problems;
    RecordingCanvas measure;
    std::vector<ScreenPoint> dots;
    for (const DrawCommand* c : canvas.InGroup("contacts"))
    {
        if (c->kind == DrawCommand::Kind::FillCircle && c->color == palette::kResult)
        {
            dots.push_back(c->points[0]);
        }
    }
    const Body* bodies[2] = {&scene.bodies[static_cast<size_t>(study.bodyA)],
                             &scene.bodies[static_cast<size_t>(study.bodyB)]};
    const Color inks[2] = {palette::kShapeA, palette::kShapeBInk};
    std::vector<ScreenPoint> corners[2];
    for (int s = 0; s < 2; ++s)
    {
        if (bodies[s]->shape.type == ShapeType::Polygon)
        {
            for (const Vec2& v : bodies[s]->shape.polygon.Vertices())
            {
                corners[s].push_back(ToScreen(view, TransformPoint(bodies[s]->Xf(), v)));
            }
        }
    }
    const std::vector<ScreenPoint> dashed = DashedCorners(canvas);
    auto distance = [](ScreenPoint p, ScreenPoint q) { return std::hypot(p.x - q.x, p.y - q.y); };
    for (const DrawCommand* c : canvas.InGroup("labels"))
    {
        if (c->kind != DrawCommand::Kind::Text)
        {
            continue;
        }
        const std::string& t = c->text;
        const ScreenPoint size = measure.MeasureText(t, c->style);
        const ScreenPoint middle{c->points[0].x + 0.5f * size.x, c->points[0].y + 0.5f * size.y};
        if (OnLeader(canvas, *c))
        {
            continue;
        }
        if (c->color == palette::kResult && t.size() == 2 && t[0] == 'c' && std::isdigit(static_cast<unsigned char>(t[1])))
        {
            const size_t own = static_cast<size_t>(t[1] - '1');
            for (size_t j = 0; j < dots.size() && own < dots.size(); ++j)
            {
                if (j != own && distance(middle, dots[j]) <= distance(middle, dots[own]))
                {
                    problems.push_back(Describe(*c) + " lies nearer contact point " + std::to_string(j + 1) +
                                       " than its own");
                    break;
                }
            }
            // Nor clearly nearer a corner of the pair, where it reads as that corner's name (containment's "c2"
            // beside the triangle's corner 1): a corner under the dot is where the contact is.
            for (int s = 0; s < 2 && own < dots.size(); ++s)
            {
                for (const ScreenPoint& corner : corners[s])
                {
                    if (distance(corner, dots[own]) > 5.0f &&
                        distance(middle, corner) + 4.0f < distance(middle, dots[own]))
                    {
                        problems.push_back(Describe(*c) + " lies nearer a corner of " + bodies[s]->name +
                                           " than its contact point");
                        s = 2;
                        break;
                    }
                }
            }
            continue;
        }
        if (!painter_test::IsVertexNumber(t))
        {
            continue;
        }
        for (int s = 0; s < 2; ++s)
        {
            const size_t own = static_cast<size_t>(std::stoi(t));
            if ((c->color >> 8) != (inks[s] >> 8) || own >= corners[s].size())
            {
                continue;
            }
            const float mine = distance(middle, corners[s][own]);
            std::vector<ScreenPoint> others = dashed;
            for (int o = 0; o < 2; ++o)
            {
                for (size_t k = 0; k < corners[o].size(); ++k)
                {
                    // A corner at the same place as its own (a corner resting on the other's) is no other mark.
                    if ((o != s || k != own) && distance(corners[o][k], corners[s][own]) > 3.0f)
                    {
                        others.push_back(corners[o][k]);
                    }
                }
            }
            for (const ScreenPoint& p : others)
            {
                if (distance(p, corners[s][own]) > 3.0f && distance(middle, p) <= mine)
                {
                    problems.push_back(Describe(*c) + ", a vertex number of " + bodies[s]->name +
                                       ", lies nearer the corner at (" + std::to_string(static_cast<int>(p.x)) + ", " +
                                       std::to_string(static_cast<int>(p.y)) + ") than its own");
                    break;
                }
            }
            // Nor as near a contact's dot as its corner, where it reads as the dot's name (ex05_inside's "3" half
            // way from its corner to c1): a dot at the corner is where the corner is.
            for (const ScreenPoint& dot : dots)
            {
                if (distance(dot, corners[s][own]) > 5.0f && distance(middle, dot) <= mine)
                {
                    problems.push_back(Describe(*c) + ", a vertex number of " + bodies[s]->name +
                                       ", lies nearer the contact point at (" + std::to_string(static_cast<int>(dot.x)) +
                                       ", " + std::to_string(static_cast<int>(dot.y)) + ") than its corner");
                    break;
                }
            }
            // Nor with another label between it and its corner, cut off from it (pitfall_one_shape's "2" above
            // "pitfall 0.257", which sat on the diamond's top corner).
            for (const DrawCommand* other : canvas.InGroup("labels"))
            {
                if (other == c || other->kind != DrawCommand::Kind::Text)
                {
                    continue;
                }
                const ScreenPoint o = measure.MeasureText(other->text, other->style);
                const Box box{other->points[0].x, other->points[0].y, other->points[0].x + o.x, other->points[0].y + o.y};
                if (SegmentCovers(middle, corners[s][own], 0.0f, box))
                {
                    problems.push_back(Describe(*c) + ", a vertex number of " + bodies[s]->name + ", has " +
                                       Describe(*other) + " between it and its corner");
                    break;
                }
            }
        }
    }
    return problems;
}

// Labels that name an arrow ("v", "v = 2.00 m/s", "MTV 0.20") clearly nearer (by 6 pixels, to the nearest corner of
// each head) the head of an arrow of another colour than any arrow of their own colour, its head or its shaft:
// beside a face's normal, the velocity's "v" reads as that normal's name. A label on a leader line is joined to its
// arrow.
std::vector<std::string> ArrowLabelsAstray(const RecordingCanvas& canvas)
{
    std::vector<std::string> problems;
    RecordingCanvas measure;
    std::vector<const DrawCommand*> heads;
    std::vector<const DrawCommand*> shafts; // each head's shaft, drawn just before it (null: none)
    for (size_t k = 0; k < canvas.commands.size(); ++k)
    {
        const DrawCommand& c = canvas.commands[k];
        if (IsArrowHead(c) && c.group != "labels" && c.group != "legend" && c.group != "panel" &&
            c.group != "timebar" && c.group != "caption")
        {
            heads.push_back(&c);
            const DrawCommand* before = k > 0 ? &canvas.commands[k - 1] : nullptr;
            shafts.push_back(before != nullptr && before->kind == DrawCommand::Kind::Segment &&
                                     before->color == c.color && before->group == c.group
                                 ? before
                                 : nullptr);
        }
    }
    for (const DrawCommand* c : canvas.InGroup("labels"))
    {
        const std::string& t = c->text;
        if (c->kind != DrawCommand::Kind::Text || !(t == "v" || t.rfind("v = ", 0) == 0 || t.rfind("MTV ", 0) == 0) ||
            OnLeader(canvas, *c))
        {
            continue;
        }
        const ScreenPoint size = measure.MeasureText(t, c->style);
        const ScreenPoint middle{c->points[0].x + 0.5f * size.x, c->points[0].y + 0.5f * size.y};
        float own = INFINITY, other = INFINITY;
        const DrawCommand* nearest = nullptr;
        for (size_t k = 0; k < heads.size(); ++k)
        {
            const DrawCommand* h = heads[k];
            float d = INFINITY;
            for (const ScreenPoint& p : h->points)
            {
                d = std::min(d, std::hypot(p.x - middle.x, p.y - middle.y));
            }
            if ((h->color >> 8) == (c->color >> 8))
            {
                // Its own arrow, head or shaft: a name beside the shaft, away from a crowded head, is the arrow's.
                own = std::min(own, d);
                if (shafts[k] != nullptr)
                {
                    own = std::min(own, ToSegment(middle, shafts[k]->points[0], shafts[k]->points[1]));
                }
            }
            else if (d < other)
            {
                other = d;
                nearest = h;
            }
        }
        if (own < INFINITY && other + 6.0f < own)
        {
            problems.push_back(Describe(*c) + " lies nearer the arrow head " + Describe(*nearest) +
                               " than its own arrow's");
        }
    }
    return problems;
}

// A band's size ("overlap 0.525", "gap 0.45", "0.13 behind") written inside a body of the pair: it reads as that
// body's and hides its outline and the projection's guides (overlapping_boxes' axis 1 on the app's narrowest canvas).
std::vector<std::string> BandSizesInBodies(const RecordingCanvas& canvas, const Scene& scene, const PairStudy& study,
                                           const View& view)
{
    std::vector<std::string> problems;
    RecordingCanvas measure;
    for (int body : {study.bodyA, study.bodyB})
    {
        const Body& b = scene.bodies[static_cast<size_t>(body)];
        for (const DrawCommand* c : canvas.InGroup("labels"))
        {
            const std::string& t = c->text;
            const bool band = t.rfind("overlap ", 0) == 0 || t.rfind("gap ", 0) == 0 ||
                              (t.size() > 7 && t.compare(t.size() - 7, 7, " behind") == 0) ||
                              (t.size() > 7 && t.compare(t.size() - 7, 7, " beyond") == 0);
            if (c->kind != DrawCommand::Kind::Text || !band)
            {
                continue;
            }
            const ScreenPoint size = measure.MeasureText(t, c->style);
            if (InsideBody(b, ToWorld(view, {c->points[0].x + 0.5f * size.x, c->points[0].y + 0.5f * size.y})))
            {
                problems.push_back(Describe(*c) + " lies inside " + b.name);
            }
        }
    }
    return problems;
}

// Edge names just ahead of another arrow's head, on its line: there an arrow's name is written, and the name reads
// as the arrow's (B's "e0" past the tip of A's e1 normal, which points into B along B's bottom face). An arrow
// square to the named edge, from a point of it, is that face's own normal.
std::vector<std::string> EdgeNamesAheadOfArrows(const RecordingCanvas& canvas, const Scene& scene,
                                                const PairStudy& study, const View& view)
{
    std::vector<std::string> problems;
    RecordingCanvas measure;
    const Body* bodies[2] = {&scene.bodies[static_cast<size_t>(study.bodyA)],
                             &scene.bodies[static_cast<size_t>(study.bodyB)]};
    const Color inks[2] = {palette::kShapeA, palette::kShapeBInk};
    const std::vector<ScreenPoint> outlines[2] = {Outline(*bodies[0], view), Outline(*bodies[1], view)};
    for (const DrawCommand* c : canvas.InGroup("labels"))
    {
        if (c->kind != DrawCommand::Kind::Text || OnLeader(canvas, *c) || !painter_test::IsEdgeName(c->text))
        {
            continue;
        }
        int s = -1;
        for (int k = 0; k < 2; ++k)
        {
            s = (c->color >> 8) == (inks[k] >> 8) ? k : s;
        }
        if (s < 0 || bodies[s]->shape.type != ShapeType::Polygon)
        {
            continue;
        }
        const size_t n = static_cast<size_t>(std::stoi(c->text.substr(1)));
        if (n >= outlines[s].size())
        {
            continue;
        }
        const ScreenPoint a = outlines[s][n];
        const ScreenPoint b = outlines[s][(n + 1) % outlines[s].size()];
        const float length = std::hypot(b.x - a.x, b.y - a.y);
        const ScreenPoint size = measure.MeasureText(c->text, c->style);
        const ScreenPoint middle{c->points[0].x + 0.5f * size.x, c->points[0].y + 0.5f * size.y};
        for (const DrawCommand& h : canvas.commands)
        {
            if (!IsArrowHead(h) || h.group == "labels" || h.group == "legend" || h.group == "panel" ||
                h.group == "timebar" || h.group == "caption" || length <= 0.0f)
            {
                continue;
            }
            // The tip is the corner opposite the shortest side.
            size_t tip = 0;
            float shortest = INFINITY;
            for (size_t k = 0; k < 3; ++k)
            {
                const ScreenPoint u = h.points[(k + 1) % 3];
                const ScreenPoint v = h.points[(k + 2) % 3];
                if (std::hypot(v.x - u.x, v.y - u.y) < shortest)
                {
                    shortest = std::hypot(v.x - u.x, v.y - u.y);
                    tip = k;
                }
            }
            const ScreenPoint base{0.5f * (h.points[(tip + 1) % 3].x + h.points[(tip + 2) % 3].x),
                                   0.5f * (h.points[(tip + 1) % 3].y + h.points[(tip + 2) % 3].y)};
            const ScreenPoint t = h.points[tip];
            const float reach = std::hypot(t.x - base.x, t.y - base.y);
            if (reach <= 0.0f)
            {
                continue;
            }
            const ScreenPoint d{(t.x - base.x) / reach, (t.y - base.y) / reach};
            const float along = ((t.x - a.x) * (b.x - a.x) + (t.y - a.y) * (b.y - a.y)) / length;
            const float slant = std::fabs(d.x * (b.x - a.x) + d.y * (b.y - a.y)) / length;
            const bool own = along >= 0.0f && along <= length && slant < 0.3f;
            const float ahead = (middle.x - t.x) * d.x + (middle.y - t.y) * d.y;
            const float aside = std::fabs((middle.x - t.x) * d.y - (middle.y - t.y) * d.x);
            if (!own && ahead > 0.0f && ahead < 30.0f && aside < 8.0f)
            {
                problems.push_back(Describe(*c) + " lies just ahead of the arrow head " + Describe(h));
                break;
            }
        }
    }
    return problems;
}

// Leader lines across a projection bar or a marked face (a thick opaque line): the label seems to name the bar.
// Only away from the anchor: the first 24 pixels lead a contact point on a face out across that face, or a band's
// size out past the bars beside it.
std::vector<std::string> LeadersAcrossBars(const RecordingCanvas& canvas)
{
    std::vector<std::string> problems;
    for (const DrawCommand* leader : canvas.InGroup("labels"))
    {
        const float length = leader->kind == DrawCommand::Kind::Segment
                                 ? std::hypot(leader->points[1].x - leader->points[0].x,
                                              leader->points[1].y - leader->points[0].y)
                                 : 0.0f;
        if (length <= 24.0f)
        {
            continue;
        }
        for (const DrawCommand& d : canvas.commands)
        {
            if (d.kind != DrawCommand::Kind::Segment || d.group == "labels" || d.thickness < 4.0f || !Opaque(d.color))
            {
                continue;
            }
            auto side = [](ScreenPoint p, ScreenPoint q, ScreenPoint r) {
                return (q.x - p.x) * (r.y - p.y) - (q.y - p.y) * (r.x - p.x);
            };
            const ScreenPoint b = leader->points[1], u = d.points[0], v = d.points[1];
            const ScreenPoint a{leader->points[0].x + (b.x - leader->points[0].x) * 24.0f / length,
                                leader->points[0].y + (b.y - leader->points[0].y) * 24.0f / length};
            if (side(a, b, u) * side(a, b, v) < 0.0f && side(u, v, a) * side(u, v, b) < 0.0f)
            {
                problems.push_back("the leader line at (" + std::to_string(static_cast<int>(a.x)) + ", " +
                                   std::to_string(static_cast<int>(a.y)) + ") crosses the bar " + Describe(d));
                break;
            }
        }
    }
    return problems;
}

// A leader line that leaves the image leads to nothing the reader sees: it starts at a mark in sight.
std::vector<std::string> LeadersOutOfImage(const RecordingCanvas& canvas, int width, int height)
{
    std::vector<std::string> problems;
    for (const DrawCommand* leader : canvas.InGroup("labels"))
    {
        if (leader->kind != DrawCommand::Kind::Segment)
        {
            continue;
        }
        for (const ScreenPoint& p : leader->points)
        {
            if (p.x < 0.0f || p.y < 0.0f || p.x > static_cast<float>(width) || p.y > static_cast<float>(height))
            {
                problems.push_back("a leader line ends out of the image, at (" + std::to_string(static_cast<int>(p.x)) +
                                   ", " + std::to_string(static_cast<int>(p.y)) + ")");
                break;
            }
        }
    }
    return problems;
}

// A long leader line (a label placed away from its mark) drawn along a line of the grid (within 2 pixels of it for
// more than 16): the grid line hides it, and the label seems to hang on nothing (l16_plank_corner's "plank" on the
// y axis). A label beside its mark reads as its mark's without its short line.
std::vector<std::string> LeadersAlongGrid(const RecordingCanvas& canvas)
{
    std::vector<std::string> problems;
    for (const DrawCommand* leader : canvas.InGroup("labels"))
    {
        if (leader->kind != DrawCommand::Kind::Segment)
        {
            continue;
        }
        const ScreenPoint p = leader->points[0];
        const ScreenPoint q = leader->points[1];
        const float length = std::hypot(q.x - p.x, q.y - p.y);
        for (const DrawCommand* grid : canvas.InGroup("background"))
        {
            if (grid->kind != DrawCommand::Kind::Segment || length <= 32.0f)
            {
                continue;
            }
            int near = 0;
            for (int k = 0; k <= static_cast<int>(length); ++k)
            {
                const float t = static_cast<float>(k) / length;
                near += ToSegment({p.x + (q.x - p.x) * t, p.y + (q.y - p.y) * t}, grid->points[0], grid->points[1]) < 2.0f
                            ? 1
                            : 0;
            }
            // Along it, not across it at a slant.
            const float gx = grid->points[1].x - grid->points[0].x;
            const float gy = grid->points[1].y - grid->points[0].y;
            const float sine = std::abs((q.x - p.x) * gy - (q.y - p.y) * gx) / (length * std::max(std::hypot(gx, gy), 1e-3f));
            if (near > 16 && sine < 0.1f)
            {
                problems.push_back("the leader line at (" + std::to_string(static_cast<int>(p.x)) + ", " +
                                   std::to_string(static_cast<int>(p.y)) + ") runs along a grid line");
                break;
            }
        }
    }
    return problems;
}

// A piece pair's push drawn on a piece's edge (both ends of its shaft within 2 pixels of the edge's line, beside
// the edge): the arrow and the edge become one stroke (l18_across's box centred over the corner of the L).
std::vector<std::string> PushesOnEdges(const RecordingCanvas& canvas)
{
    std::vector<std::string> problems;
    for (const DrawCommand* push : canvas.InGroup("push"))
    {
        if (push->kind != DrawCommand::Kind::Segment)
        {
            continue;
        }
        for (const DrawCommand* edge : canvas.InGroup("pieces"))
        {
            if (edge->kind != DrawCommand::Kind::Segment)
            {
                continue;
            }
            const ScreenPoint u = edge->points[0];
            const ScreenPoint v = edge->points[1];
            const float length = std::hypot(v.x - u.x, v.y - u.y);
            if (length < 1.0f)
            {
                continue;
            }
            const auto off = [&](ScreenPoint p) { return std::abs((p.x - u.x) * (v.y - u.y) - (p.y - u.y) * (v.x - u.x)) / length; };
            const auto along = [&](ScreenPoint p) { return ((p.x - u.x) * (v.x - u.x) + (p.y - u.y) * (v.y - u.y)) / length; };
            const ScreenPoint a = push->points[0];
            const ScreenPoint b = push->points[1];
            if (off(a) < 2.0f && off(b) < 2.0f && std::max(along(a), along(b)) > 0.0f &&
                std::min(along(a), along(b)) < length)
            {
                problems.push_back("the push from (" + std::to_string(static_cast<int>(a.x)) + ", " +
                                   std::to_string(static_cast<int>(a.y)) + ") is drawn on " + Describe(*edge));
                break;
            }
        }
    }
    return problems;
}

// A leader line that starts at the tail of the MTV's arrow, the pitfall's push, a piece pair's push or a velocity (the
// middle of the body it moves, where a body's name is led from when the arrow takes its place): it reads as naming
// the arrow (l02_box_and_triangle's "triangle", l18_seam's "box", l17_corner's "ball", pitfall_one_shape's
// "diamond").
std::vector<std::string> LeadersFromArrowTails(const RecordingCanvas& canvas)
{
    std::vector<std::string> problems;
    // The MTV's shaft (3 pixels thick) and the first dash of the pitfall's push (2), from its tail.
    std::vector<const DrawCommand*> shafts;
    bool pitfallTail = false;
    for (const DrawCommand* c : canvas.InGroup("mtv"))
    {
        if (c->kind == DrawCommand::Kind::Segment && (c->thickness >= 3.0f || (c->thickness >= 2.0f && !pitfallTail)))
        {
            pitfallTail = pitfallTail || c->thickness < 3.0f;
            shafts.push_back(c);
        }
    }
    for (const DrawCommand* push : canvas.InGroup("push"))
    {
        shafts.push_back(push);
    }
    for (const DrawCommand* velocity : VelocityShafts(canvas))
    {
        shafts.push_back(velocity);
    }
    for (const DrawCommand* shaft : shafts)
    {
        if (shaft->kind != DrawCommand::Kind::Segment || shaft->thickness < 2.0f)
        {
            continue;
        }
        const ScreenPoint tail = shaft->points[0];
        for (const DrawCommand* leader : canvas.InGroup("labels"))
        {
            if (leader->kind == DrawCommand::Kind::Segment &&
                std::hypot(leader->points[0].x - tail.x, leader->points[0].y - tail.y) < 10.0f)
            {
                problems.push_back("a leader line starts at the tail of the " +
                                   std::string(shaft->group == "swept" ? "velocity's" : "MTV's") + " arrow, at (" +
                                   std::to_string(static_cast<int>(tail.x)) + ", " +
                                   std::to_string(static_cast<int>(tail.y)) + ")");
            }
        }
    }
    return problems;
}

// The MTV's or a pitfall's name beside its arrow (no leader line, or a short one) that lies nearer another arrow's shaft, a face's
// normal, than its own arrow: it reads as naming that normal (pitfall_direction's "pitfall 0.20" between its short
// dashed arrow and the block's own bottom normal, which points the same way).
std::vector<std::string> ArrowNamesNearerOtherArrows(const RecordingCanvas& canvas)
{
    // Every arrow: the shaft drawn just before its head.
    struct DrawnArrow
    {
        const DrawCommand* shaft;
        const DrawCommand* head;
    };
    std::vector<DrawnArrow> arrows;
    for (size_t k = 1; k < canvas.commands.size(); ++k)
    {
        const DrawCommand& c = canvas.commands[k];
        const DrawCommand& before = canvas.commands[k - 1];
        if (IsArrowHead(c) && before.kind == DrawCommand::Kind::Segment && before.color == c.color &&
            before.group == c.group)
        {
            arrows.push_back({&before, &c});
        }
    }
    std::vector<std::string> problems;
    RecordingCanvas measure;
    for (const DrawCommand* c : canvas.InGroup("labels"))
    {
        const bool mtv = c->text.rfind("MTV ", 0) == 0;
        const bool pitfall = c->text.rfind("pitfall ", 0) == 0;
        if (c->kind != DrawCommand::Kind::Text || (!mtv && !pitfall))
        {
            continue;
        }
        // A long leader line shows what it names; a short one is drawn for a label a few pixels off its arrow.
        if (const DrawCommand* line = LeaderTo(canvas, *c))
        {
            if (std::hypot(line->points[1].x - line->points[0].x, line->points[1].y - line->points[0].y) > 20.0f)
            {
                continue;
            }
        }
        const ScreenPoint size = measure.MeasureText(c->text, c->style);
        const ScreenPoint middle{c->points[0].x + 0.5f * size.x, c->points[0].y + 0.5f * size.y};
        // Its own arrow: the MTV's solid one, or the pitfall's dashes, in the ink of each.
        const Color ink = mtv ? palette::kResult : palette::kInk;
        float own = INFINITY;
        for (const DrawCommand* d : canvas.InGroup("mtv"))
        {
            if (d->color == ink && (d->kind == DrawCommand::Kind::Segment || d->kind == DrawCommand::Kind::FillConvex))
            {
                for (size_t k = 0; k < d->points.size(); ++k)
                {
                    own = std::min(own, ToSegment(middle, d->points[k], d->points[(k + 1) % d->points.size()]));
                }
            }
        }
        for (const DrawnArrow& arrow : arrows)
        {
            // A round-off MTV draws no arrow: its name is a note above its body.
            if (own < INFINITY && arrow.head->group != "mtv" &&
                ToSegment(middle, arrow.shaft->points[0], arrow.shaft->points[1]) < own)
            {
                problems.push_back(Describe(*c) + " lies nearer the arrow from (" +
                                   std::to_string(static_cast<int>(arrow.shaft->points[0].x)) + ", " +
                                   std::to_string(static_cast<int>(arrow.shaft->points[0].y)) + ") than its own");
                break;
            }
        }
    }
    return problems;
}

// A body's name on a leader line that starts on an arrow's shaft away from its tail, where the arrow leaves the
// body: it reads as naming the arrow (pitfall_tunnel's "bullet", led from where its velocity leaves its right side).
std::vector<std::string> NameLeadersFromShafts(const RecordingCanvas& canvas)
{
    std::vector<const DrawCommand*> shafts;
    for (size_t k = 1; k < canvas.commands.size(); ++k)
    {
        const DrawCommand& c = canvas.commands[k];
        const DrawCommand& before = canvas.commands[k - 1];
        if (IsArrowHead(c) && before.kind == DrawCommand::Kind::Segment && before.color == c.color &&
            before.group == c.group && before.group != "labels")
        {
            shafts.push_back(&before);
        }
    }
    std::vector<std::string> problems;
    for (const DrawCommand* c : canvas.InGroup("labels"))
    {
        // Body names are the headings that name no arrow; the pitfall's note names where its push leaves B, and
        // no arrow's tail is there.
        const bool note = c->kind == DrawCommand::Kind::Text && c->text.rfind("after the pitfall's push", 0) == 0;
        if (!note && (c->kind != DrawCommand::Kind::Text || c->style != TextStyle::Heading ||
                      c->text.rfind("MTV", 0) == 0 || c->text == "v" || c->text.rfind("v ", 0) == 0))
        {
            continue;
        }
        if (const DrawCommand* line = LeaderTo(canvas, *c))
        {
            const ScreenPoint start = line->points[0];
            for (const DrawCommand* shaft : shafts)
            {
                // From the arrow's tail, the middle of a body its velocity starts from, it names the body.
                if (ToSegment(start, shaft->points[0], shaft->points[1]) < 0.5f * shaft->thickness + 5.0f &&
                    (note || std::hypot(start.x - shaft->points[0].x, start.y - shaft->points[0].y) > 8.0f))
                {
                    problems.push_back(Describe(*c) + " is led from (" + std::to_string(static_cast<int>(start.x)) +
                                       ", " + std::to_string(static_cast<int>(start.y)) + "), on an arrow's shaft");
                    break;
                }
            }
        }
    }
    return problems;
}

// A band's size ("overlap 0.20", "gap 0.45") on a leader line that starts away from its band, the thick bar between
// the two intervals on the axis: the line leads from nothing (pitfall_unnormalised's, from beyond the bars by the
// image's edge).
std::vector<std::string> BandLeadersAstray(const RecordingCanvas& canvas)
{
    std::vector<std::string> problems;
    std::vector<const DrawCommand*> bands;
    for (const DrawCommand* d : canvas.InGroup("projection"))
    {
        if (d->kind == DrawCommand::Kind::Segment && d->thickness >= 3.0f &&
            ((d->color >> 8) == (palette::kOverlap >> 8) || (d->color >> 8) == (palette::kGap >> 8)))
        {
            bands.push_back(d);
        }
    }
    for (const DrawCommand* c : canvas.InGroup("labels"))
    {
        if (c->kind != DrawCommand::Kind::Text || bands.empty() ||
            (c->text.rfind("overlap ", 0) != 0 && c->text.rfind("gap ", 0) != 0))
        {
            continue;
        }
        if (const DrawCommand* line = LeaderTo(canvas, *c))
        {
            const ScreenPoint start = line->points[0];
            const bool onBand = std::any_of(bands.begin(), bands.end(), [&](const DrawCommand* band) {
                return ToSegment(start, band->points[0], band->points[1]) < 0.5f * band->thickness + 2.0f;
            });
            if (!onBand)
            {
                problems.push_back(Describe(*c) + " is led from (" + std::to_string(static_cast<int>(start.x)) + ", " +
                                   std::to_string(static_cast<int>(start.y)) + "), away from its band");
            }
        }
    }
    return problems;
}

// A face's name ("reference face", "incident edge") on a leader line that starts at a contact's dot or another
// face's normal's tail: the line reads as naming the contact or the arrow, or the edge as a point (overlapping_boxes' "incident
// edge" and "c1" led to one dot).
std::vector<std::string> FaceLeadersFromMarks(const RecordingCanvas& canvas, Vec2 normal)
{
    std::vector<std::string> problems;
    std::vector<ScreenPoint> dots;
    for (const DrawCommand* c : canvas.InGroup("contacts"))
    {
        if (c->kind == DrawCommand::Kind::FillCircle && c->color == palette::kResult)
        {
            dots.push_back(c->points[0]);
        }
    }
    // And the tails of the faces' normals, which start on their faces: a leader from there reads as naming the
    // arrow (l11_decimal_touch's "reference face", led to where the other body's normal leaves the shared face).
    // A face's own normal is left out: it points along the pair's normal (from A to B) when the face is A's (the
    // name in A's ink), against it when B's.
    std::vector<std::pair<ScreenPoint, ScreenPoint>> tails; // tail, and the arrow's end
    for (size_t k = 1; k < canvas.commands.size(); ++k)
    {
        const DrawCommand& c = canvas.commands[k];
        const DrawCommand& before = canvas.commands[k - 1];
        // The faces' normals, and the deciding face's drawn with its axis.
        if ((c.group == "normals" || c.group == "projection") && IsArrowHead(c) &&
            before.kind == DrawCommand::Kind::Segment && before.group == c.group)
        {
            tails.emplace_back(before.points[0], before.points[1]);
        }
    }
    for (const DrawCommand* c : canvas.InGroup("labels"))
    {
        if (c->kind != DrawCommand::Kind::Text || (c->text != "reference face" && c->text != "incident edge"))
        {
            continue;
        }
        if (const DrawCommand* line = LeaderTo(canvas, *c))
        {
            for (const ScreenPoint& dot : dots)
            {
                if (std::hypot(line->points[0].x - dot.x, line->points[0].y - dot.y) < 7.0f)
                {
                    problems.push_back(Describe(*c) + " is led from the contact point at (" +
                                       std::to_string(static_cast<int>(dot.x)) + ", " +
                                       std::to_string(static_cast<int>(dot.y)) + ")");
                    break;
                }
            }
            const float sign = c->color == palette::kShapeA ? 1.0f : -1.0f;
            const ScreenPoint out{sign * static_cast<float>(normal.x), -sign * static_cast<float>(normal.y)};
            for (const auto& [tail, end] : tails)
            {
                const float length = std::hypot(end.x - tail.x, end.y - tail.y);
                // Its own face's normal starts on the face, where the leader starts: the other body's normal that
                // points the same way starts off the face's line (l05_naive_push's B's top face, below A's).
                const ScreenPoint start = line->points[0];
                const bool own = (end.x - tail.x) * out.x + (end.y - tail.y) * out.y > 0.9f * length &&
                                 std::abs((tail.x - start.x) * out.x + (tail.y - start.y) * out.y) < 6.0f;
                if (!own && std::hypot(start.x - tail.x, start.y - tail.y) < 7.0f)
                {
                    problems.push_back(Describe(*c) + " is led from the tail of the normal at (" +
                                       std::to_string(static_cast<int>(tail.x)) + ", " +
                                       std::to_string(static_cast<int>(tail.y)) + ")");
                    break;
                }
                // Nor from beside the shaft of another face's normal that crosses the face there: the leader reads
                // as naming the arrow.
                if (!own && ToSegment(start, tail, end) < 6.0f)
                {
                    problems.push_back(Describe(*c) + " is led from beside the normal from (" +
                                       std::to_string(static_cast<int>(tail.x)) + ", " +
                                       std::to_string(static_cast<int>(tail.y)) + ")");
                    break;
                }
            }
        }
    }
    return problems;
}

// The reference face's name on a leader line that starts where the other body's outline crosses the face: it
// names either body's edge there (l13_overlap's, led to where B's face crosses A's right side).
std::vector<std::string> FaceLeadersAtCrossings(const RecordingCanvas& canvas, const Scene& scene,
                                                const PairStudy& study, const View& view)
{
    std::vector<std::string> problems;
    const Body* bodies[2] = {&scene.bodies[static_cast<size_t>(study.bodyA)],
                             &scene.bodies[static_cast<size_t>(study.bodyB)]};
    const Color inks[2] = {palette::kShapeA, palette::kShapeBInk};
    for (const DrawCommand* c : canvas.InGroup("labels"))
    {
        if (c->kind != DrawCommand::Kind::Text || c->text != "reference face")
        {
            continue;
        }
        const DrawCommand* line = LeaderTo(canvas, *c);
        if (line == nullptr)
        {
            continue;
        }
        for (int s = 0; s < 2; ++s)
        {
            // The other body: not the one whose ink the name is in.
            if ((c->color >> 8) == (inks[s] >> 8) || bodies[s]->shape.type != ShapeType::Polygon)
            {
                continue;
            }
            const std::vector<ScreenPoint> outline = Outline(*bodies[s], view);
            for (size_t i = 0; i < outline.size(); ++i)
            {
                if (ToSegment(line->points[0], outline[i], outline[(i + 1) % outline.size()]) < 3.0f)
                {
                    problems.push_back(Describe(*c) + " is led from " + bodies[s]->name + "'s outline");
                    break;
                }
            }
        }
    }
    return problems;
}

// The incident edge's name on a leader line that crosses the reference face on its way, where the edge runs on past
// the face: it ends beside that face and reads as naming it, or the contact where the two meet (overlapping_boxes'
// leader across B's left face to A's right edge, 4 px beyond it).
std::vector<std::string> IncidentLeadersAcrossReference(const RecordingCanvas& canvas)
{
    const auto side = [](ScreenPoint a, ScreenPoint b, ScreenPoint p) {
        return (b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x);
    };
    std::vector<std::string> problems;
    for (const DrawCommand* c : canvas.InGroup("labels"))
    {
        if (c->kind != DrawCommand::Kind::Text || c->text != "incident edge")
        {
            continue;
        }
        const DrawCommand* line = LeaderTo(canvas, *c);
        if (line == nullptr)
        {
            continue;
        }
        const ScreenPoint p = line->points[0];
        const ScreenPoint q = line->points[1];
        // The incident edge: the thick stroke in its body's ink.
        const DrawCommand* edge = nullptr;
        for (const DrawCommand* d : canvas.InGroup("contacts"))
        {
            if (d->kind == DrawCommand::Kind::Segment && d->thickness >= 4.5f && (d->color >> 8) == (c->color >> 8))
            {
                edge = d;
            }
        }
        for (const DrawCommand* face : canvas.InGroup("contacts"))
        {
            // The reference face: the thick stroke in the other body's ink.
            if (edge == nullptr || face->kind != DrawCommand::Kind::Segment || face->thickness < 4.5f ||
                (face->color >> 8) == (c->color >> 8))
            {
                continue;
            }
            const ScreenPoint a = face->points[0];
            const ScreenPoint b = face->points[1];
            // Only where the edge runs on past the face (by 6 px along it), so that a leader can reach it without
            // crossing; an edge wholly beside the face (many_sides' short one) is reached across it.
            const float length = std::max(std::hypot(b.x - a.x, b.y - a.y), 1e-3f);
            bool past = false;
            for (const ScreenPoint& e : edge->points)
            {
                const float along = ((e.x - a.x) * (b.x - a.x) + (e.y - a.y) * (b.y - a.y)) / length;
                past = past || along < -6.0f || along > length + 6.0f;
            }
            if (past && side(a, b, p) * side(a, b, q) < 0.0f && side(p, q, a) * side(p, q, b) < 0.0f)
            {
                problems.push_back(Describe(*c) + " is led across the reference face");
                break;
            }
        }
    }
    return problems;
}

// A ghost's label ("t = 0.30") led from a corner of the ghost across an edge of a body of the pair as drawn where
// the sweep starts, when the ghost has a corner clear of both bodies: the label lies beyond that body's edge and
// reads as one of its marks (l13_sweep's "t = 0.30" above the triangle's top edge, led down across it to the ghost's
// corner inside the triangle).
std::vector<std::string> GhostLeadersAcrossBodies(const RecordingCanvas& canvas, const Scene& scene,
                                                  const PairStudy& study, const View& view)
{
    std::vector<std::string> problems;
    RecordingCanvas measure;
    const std::vector<ScreenPoint> outlines[2] = {Outline(scene.bodies[static_cast<size_t>(study.bodyA)], view),
                                                  Outline(scene.bodies[static_cast<size_t>(study.bodyB)], view)};
    // Whether p lies inside a convex outline (either way round), or within `near` pixels of it.
    const auto within = [](ScreenPoint p, const std::vector<ScreenPoint>& outline, float near) {
        float area = 0.0f;
        for (size_t i = 0; i < outline.size(); ++i)
        {
            const ScreenPoint u = outline[i];
            const ScreenPoint v = outline[(i + 1) % outline.size()];
            area += u.x * v.y - v.x * u.y;
        }
        for (size_t i = 0; i < outline.size(); ++i)
        {
            const ScreenPoint u = outline[i];
            const ScreenPoint v = outline[(i + 1) % outline.size()];
            const float length = std::hypot(v.x - u.x, v.y - u.y);
            const float cross = (v.x - u.x) * (p.y - u.y) - (v.y - u.y) * (p.x - u.x);
            if (length > 0.0f && (area > 0.0f ? -cross : cross) / length >= near)
            {
                return false;
            }
        }
        return outline.size() >= 3 && area != 0.0f;
    };
    // Whether segments pq and uv cross.
    const auto cross = [](ScreenPoint p, ScreenPoint q, ScreenPoint u, ScreenPoint v) {
        const auto side = [](ScreenPoint a, ScreenPoint b, ScreenPoint c) {
            return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
        };
        return side(p, q, u) * side(p, q, v) < 0.0f && side(u, v, p) * side(u, v, q) < 0.0f;
    };
    for (const DrawCommand* ghost : canvas.InGroup("ghost"))
    {
        if (ghost->kind != DrawCommand::Kind::FillConvex || ghost->points.size() < 3 || ghost->points.size() > 16)
        {
            continue;
        }
        const bool clearCorner = std::any_of(ghost->points.begin(), ghost->points.end(), [&](ScreenPoint p) {
            return !within(p, outlines[0], 4.0f) && !within(p, outlines[1], 4.0f);
        });
        if (!clearCorner)
        {
            continue;
        }
        for (const DrawCommand* leader : canvas.InGroup("labels"))
        {
            if (leader->kind != DrawCommand::Kind::Segment)
            {
                continue;
            }
            const ScreenPoint p = leader->points[0];
            const ScreenPoint q = leader->points[1];
            const bool fromCorner = std::any_of(ghost->points.begin(), ghost->points.end(), [&](ScreenPoint c) {
                return std::hypot(c.x - p.x, c.y - p.y) < 5.0f;
            });
            // The leader's label: a time ("t = 0.30", "bullet at t = 0.50") whose box its far end touches.
            bool timeLabel = false;
            for (const DrawCommand* text : canvas.InGroup("labels"))
            {
                if (text->kind != DrawCommand::Kind::Text || text->text.find("t = ") == std::string::npos)
                {
                    continue;
                }
                const ScreenPoint size = measure.MeasureText(text->text, text->style);
                const ScreenPoint at = text->points[0];
                timeLabel = timeLabel || (q.x >= at.x - 3.0f && q.x <= at.x + size.x + 3.0f && q.y >= at.y - 3.0f &&
                                          q.y <= at.y + size.y + 3.0f);
            }
            if (!timeLabel)
            {
                continue;
            }
            bool across = false;
            for (int k = 0; k < 2 && fromCorner && !across; ++k)
            {
                for (size_t i = 0; i < outlines[k].size() && !across; ++i)
                {
                    across = cross(p, q, outlines[k][i], outlines[k][(i + 1) % outlines[k].size()]);
                }
            }
            if (across)
            {
                problems.push_back("a ghost's label is led from its corner at (" +
                                   std::to_string(static_cast<int>(p.x)) + ", " + std::to_string(static_cast<int>(p.y)) +
                                   ") across a body's edge, though a corner of the ghost is clear");
            }
        }
    }
    return problems;
}

// Two arrows of one ink that point opposite ways from tails a few pixels apart on one line (the normals of a thin
// wall's two faces, each from its face's middle): they read as one double-headed arrow across the body.
std::vector<std::string> ArrowsTailToTail(const RecordingCanvas& canvas)
{
    struct Shaft
    {
        ScreenPoint tail, head;
        Color color;
    };
    std::vector<Shaft> arrows;
    for (size_t k = 1; k < canvas.commands.size(); ++k)
    {
        const DrawCommand& c = canvas.commands[k];
        const DrawCommand& before = canvas.commands[k - 1];
        if (IsArrowHead(c) && before.kind == DrawCommand::Kind::Segment && before.color == c.color &&
            before.group == c.group)
        {
            arrows.push_back({before.points[0], before.points[1], c.color});
        }
    }
    std::vector<std::string> problems;
    for (size_t i = 0; i < arrows.size(); ++i)
    {
        for (size_t j = i + 1; j < arrows.size(); ++j)
        {
            if (arrows[i].color != arrows[j].color)
            {
                continue;
            }
            const ScreenPoint a0 = arrows[i].tail, a1 = arrows[i].head;
            const ScreenPoint b0 = arrows[j].tail, b1 = arrows[j].head;
            const float la = std::hypot(a1.x - a0.x, a1.y - a0.y);
            const float lb = std::hypot(b1.x - b0.x, b1.y - b0.y);
            if (la < 1.0f || lb < 1.0f)
            {
                continue;
            }
            const float cosine = ((a1.x - a0.x) * (b1.x - b0.x) + (a1.y - a0.y) * (b1.y - b0.y)) / (la * lb);
            // How far b's tail lies off a's line.
            const float off = std::abs((a1.x - a0.x) * (b0.y - a0.y) - (a1.y - a0.y) * (b0.x - a0.x)) / la;
            if (cosine < -0.95f && std::hypot(b0.x - a0.x, b0.y - a0.y) < 10.0f && off < 3.0f)
            {
                problems.push_back("two arrows point opposite ways from tails at (" +
                                   std::to_string(static_cast<int>(a0.x)) + ", " + std::to_string(static_cast<int>(a0.y)) +
                                   ") and (" + std::to_string(static_cast<int>(b0.x)) + ", " +
                                   std::to_string(static_cast<int>(b0.y)) + "): one double-headed arrow");
            }
        }
    }
    return problems;
}

// An edge's name ("e3") inside a ghost, the moving body drawn at another time, when the face it names lies outside
// that ghost: it reads as the ghost's (ex14_wall's "e3" on the app's narrow canvas, inside the puck at the time of
// impact, led to the wall's face).
std::vector<std::string> EdgeNamesInGhosts(const RecordingCanvas& canvas)
{
    std::vector<std::string> problems;
    RecordingCanvas measure;
    // Whether p lies inside a convex outline (either way round).
    const auto inside = [](ScreenPoint p, const std::vector<ScreenPoint>& outline) {
        float area = 0.0f;
        for (size_t i = 0; i < outline.size(); ++i)
        {
            const ScreenPoint u = outline[i];
            const ScreenPoint v = outline[(i + 1) % outline.size()];
            area += u.x * v.y - v.x * u.y;
        }
        for (size_t i = 0; i < outline.size(); ++i)
        {
            const ScreenPoint u = outline[i];
            const ScreenPoint v = outline[(i + 1) % outline.size()];
            const float cross = (v.x - u.x) * (p.y - u.y) - (v.y - u.y) * (p.x - u.x);
            if ((area > 0.0f ? -cross : cross) >= 0.0f)
            {
                return false;
            }
        }
        return outline.size() >= 3 && area != 0.0f;
    };
    for (const DrawCommand* ghost : canvas.InGroup("ghost"))
    {
        if (ghost->kind != DrawCommand::Kind::FillConvex || ghost->points.size() < 3)
        {
            continue;
        }
        for (const DrawCommand* c : canvas.InGroup("labels"))
        {
            if (c->kind != DrawCommand::Kind::Text || !painter_test::IsEdgeName(c->text))
            {
                continue;
            }
            const ScreenPoint size = measure.MeasureText(c->text, c->style);
            const ScreenPoint middle{c->points[0].x + 0.5f * size.x, c->points[0].y + 0.5f * size.y};
            if (!inside(middle, ghost->points))
            {
                continue;
            }
            // Where its leader line ends (on its face), or, with none, the label itself.
            const DrawCommand* leader = LeaderTo(canvas, *c);
            if (leader != nullptr && !inside(leader->points[0], ghost->points))
            {
                problems.push_back(Describe(*c) + " lies inside a ghost, led to a face outside it at (" +
                                   std::to_string(static_cast<int>(leader->points[0].x)) + ", " +
                                   std::to_string(static_cast<int>(leader->points[0].y)) + ")");
            }
        }
    }
    return problems;
}

// A velocity that runs through the other body of the pair and out beyond it, named past that body: its "v" reads
// as the other body's velocity pointing the wrong way (l14_head_on's A at 3 m/s, through ball B, named right of B).
std::vector<std::string> VelocityNamedPastBody(const RecordingCanvas& canvas, const Scene& scene,
                                               const PairStudy& study, const View& view)
{
    std::vector<std::string> problems;
    RecordingCanvas measure;
    const Body* bodies[2] = {&scene.bodies[static_cast<size_t>(study.bodyA)],
                             &scene.bodies[static_cast<size_t>(study.bodyB)]};
    for (const DrawCommand* shaft : VelocityShafts(canvas))
    {
        const ScreenPoint a = shaft->points[0];
        // The arrow's tip: the point of its head (drawn next) farthest along the shaft.
        ScreenPoint b = shaft->points[1];
        const DrawCommand& head = canvas.commands[static_cast<size_t>(shaft - canvas.commands.data()) + 1];
        for (const ScreenPoint& p : head.points)
        {
            if ((p.x - b.x) * (b.x - a.x) + (p.y - b.y) * (b.y - a.y) > 0.0f)
            {
                b = p;
            }
        }
        const auto at = [&](float f) { return ScreenPoint{a.x + (b.x - a.x) * f, a.y + (b.y - a.y) * f}; };
        // Inside by more than 2 pixels: a head that ends on the far side's outline (l14_head_on's A, reaching B's
        // right side) has run through.
        const auto inside = [&](const Body& body, ScreenPoint p) {
            for (const ScreenPoint d : {ScreenPoint{2, 0}, ScreenPoint{-2, 0}, ScreenPoint{0, 2}, ScreenPoint{0, -2}})
            {
                if (!InsideBody(body, ToWorld(view, {p.x + d.x, p.y + d.y})))
                {
                    return false;
                }
            }
            return true;
        };
        for (const Body* other : bodies)
        {
            // A head that ends inside it is by it, not past it (VelocityInOtherBody's concern).
            if (inside(*other, a) || inside(*other, b))
            {
                continue;
            }
            float exit = -1.0f;
            for (int k = 1; k < 256; ++k)
            {
                const float f = static_cast<float>(k) / 256.0f;
                exit = inside(*other, at(f)) ? f : exit;
            }
            if (exit < 0.0f)
            {
                continue;
            }
            const float length2 = (b.x - a.x) * (b.x - a.x) + (b.y - a.y) * (b.y - a.y);
            for (const DrawCommand* c : canvas.InGroup("labels"))
            {
                if (c->kind != DrawCommand::Kind::Text || c->text != "v" || (c->color >> 8) != (shaft->color >> 8) ||
                    OnLeader(canvas, *c))
                {
                    continue;
                }
                const ScreenPoint size = measure.MeasureText(c->text, c->style);
                const ScreenPoint m{c->points[0].x + 0.5f * size.x, c->points[0].y + 0.5f * size.y};
                const float f = ((m.x - a.x) * (b.x - a.x) + (m.y - a.y) * (b.y - a.y)) / length2;
                if (f > exit)
                {
                    problems.push_back(Describe(*c) + " is named past " + other->name +
                                       ", which its velocity runs through");
                }
            }
        }
    }
    return problems;
}

// Arrow heads drawn too small to read as heads: under 6 pixels from the tip to the base, the arrow reads as a line
// that stops (a pitfall's push had a head of 4 pixels, drawn from a point just short of its tip).
std::vector<std::string> TinyArrowHeads(const RecordingCanvas& canvas)
{
    std::vector<std::string> problems;
    for (const DrawCommand& c : canvas.commands)
    {
        if (!IsArrowHead(c) || c.group == "labels" || c.group == "legend")
        {
            continue;
        }
        const ScreenPoint base{0.5f * (c.points[1].x + c.points[2].x), 0.5f * (c.points[1].y + c.points[2].y)};
        const float length = std::hypot(c.points[0].x - base.x, c.points[0].y - base.y);
        if (length < 6.0f)
        {
            problems.push_back("the arrow head at (" + std::to_string(static_cast<int>(c.points[0].x)) + ", " +
                               std::to_string(static_cast<int>(c.points[0].y)) + ") in \"" + c.group + "\" is " +
                               std::to_string(length) + " pixels long");
        }
    }
    return problems;
}

// A pitfall's push as drawn: the dashed black shaft in "mtv", from its first dash to its head's tip. False when
// the figure draws none.
bool PitfallArrow(const RecordingCanvas& canvas, ScreenPoint& tail, ScreenPoint& tip)
{
    bool any = false;
    for (const DrawCommand* c : canvas.InGroup("mtv"))
    {
        if (c->kind == DrawCommand::Kind::Segment && c->color == palette::kInk && c->thickness == 2.0f && !any)
        {
            tail = c->points[0];
            any = true;
        }
        if (any && c->kind == DrawCommand::Kind::FillConvex && c->color == palette::kInk && IsArrowHead(*c))
        {
            tip = c->points[0];
            return true;
        }
    }
    return false;
}

// The MTV's arrow as drawn: the thick vermillion shaft in "mtv". False when the figure draws none.
bool MtvShaft(const RecordingCanvas& canvas, ScreenPoint& from, ScreenPoint& to)
{
    for (const DrawCommand* c : canvas.InGroup("mtv"))
    {
        if (c->kind == DrawCommand::Kind::Segment && c->color == palette::kResult && c->thickness >= 3.0f)
        {
            from = c->points[0];
            to = c->points[1];
            return true;
        }
    }
    return false;
}

// A pitfall's push drawn on the MTV's line: the two arrows, one up and one down from B's centre, read as one line
// through it, and the wrong push's head as the MTV's tail (pitfall_direction, where the block's own bottom normal
// below it read as the pitfall's head).
std::vector<std::string> PitfallOnMtvLine(const RecordingCanvas& canvas)
{
    ScreenPoint tail{}, tip{}, from{}, to{};
    if (!PitfallArrow(canvas, tail, tip) || !MtvShaft(canvas, from, to))
    {
        return {};
    }
    const float length = std::hypot(to.x - from.x, to.y - from.y);
    if (length <= 0.0f)
    {
        return {};
    }
    const auto off = [&](ScreenPoint p) {
        return std::fabs((to.x - from.x) * (p.y - from.y) - (to.y - from.y) * (p.x - from.x)) / length;
    };
    if (off(tail) < 5.0f && off(tip) < 5.0f)
    {
        return {"the pitfall's push, from (" + std::to_string(static_cast<int>(tail.x)) + ", " +
                std::to_string(static_cast<int>(tail.y)) + "), lies on the MTV's line"};
    }
    return {};
}

// An arrow's name (the MTV's, a pitfall's) led a long way through a body of the pair to a place outside it: the
// line reads as a mark of that body, across its inside and its outline (pitfall_direction's "MTV 0.20", led 82
// pixels across the block from the arrow in its middle to a place beyond its side). Over 60 pixels: a shorter way
// in, from an arrow whose head lies near the outline, still reads as the arrow's.
std::vector<std::string> ArrowNamesLedThroughBodies(const RecordingCanvas& canvas, const Scene& scene,
                                                    const PairStudy& study, const View& view)
{
    std::vector<std::string> problems;
    const auto inside = [](const std::vector<ScreenPoint>& polygon, ScreenPoint p) {
        bool in = false;
        for (size_t i = 0, j = polygon.size() - 1; i < polygon.size(); j = i++)
        {
            const ScreenPoint& u = polygon[i];
            const ScreenPoint& v = polygon[j];
            if ((u.y > p.y) != (v.y > p.y) && p.x < u.x + (p.y - u.y) * (v.x - u.x) / (v.y - u.y))
            {
                in = !in;
            }
        }
        return in;
    };
    for (const DrawCommand* c : canvas.InGroup("labels"))
    {
        if (c->kind != DrawCommand::Kind::Text || (c->text.rfind("MTV ", 0) != 0 && c->text.rfind("pitfall ", 0) != 0))
        {
            continue;
        }
        const DrawCommand* line = LeaderTo(canvas, *c);
        if (line == nullptr)
        {
            continue;
        }
        const ScreenPoint a = line->points[0];
        const ScreenPoint b = line->points[1];
        const float length = std::hypot(b.x - a.x, b.y - a.y);
        for (const int index : {study.bodyA, study.bodyB})
        {
            const Body& body = scene.bodies[static_cast<size_t>(index)];
            const std::vector<ScreenPoint> outline = Outline(body, view);
            int in = 0;
            const int samples = static_cast<int>(length) + 1;
            for (int k = 0; k < samples; ++k)
            {
                const float t = static_cast<float>(k) / static_cast<float>(samples);
                in += inside(outline, {a.x + (b.x - a.x) * t, a.y + (b.y - a.y) * t}) ? 1 : 0;
            }
            const float through = length * static_cast<float>(in) / static_cast<float>(samples);
            if (through > 60.0f)
            {
                problems.push_back(Describe(*c) + " is led " + std::to_string(static_cast<int>(through)) +
                                   " pixels through " + body.name);
            }
        }
    }
    return problems;
}

// The pitfall's name on a leader line that leaves its head along the arrow's line: the line carries the shaft on
// past the head, which it hides (pitfall_one_shape's "pitfall 0.257" led straight up through the diamond's top
// corner), or runs back over it.
std::vector<std::string> PitfallLeaderOnArrow(const RecordingCanvas& canvas)
{
    ScreenPoint tail{}, tip{};
    if (!PitfallArrow(canvas, tail, tip))
    {
        return {};
    }
    std::vector<std::string> problems;
    const float length = std::hypot(tip.x - tail.x, tip.y - tail.y);
    for (const DrawCommand* c : canvas.InGroup("labels"))
    {
        if (c->kind != DrawCommand::Kind::Text || c->text.rfind("pitfall ", 0) != 0 || length <= 0.0f)
        {
            continue;
        }
        const DrawCommand* line = LeaderTo(canvas, *c);
        if (line == nullptr)
        {
            continue;
        }
        const ScreenPoint a = line->points[0];
        const ScreenPoint b = line->points[1];
        const float leader = std::hypot(b.x - a.x, b.y - a.y);
        const float along = ((b.x - a.x) * (tip.x - tail.x) + (b.y - a.y) * (tip.y - tail.y)) / (leader * length);
        if (std::hypot(a.x - tip.x, a.y - tip.y) < 8.0f && leader > 0.0f && std::fabs(along) > 0.866f)
        {
            problems.push_back(Describe(*c) + " is led along its arrow's line from its head");
        }
    }
    return problems;
}

// A vertex number not clearly nearer its own corner than any other corner of the pair: between two corners, or
// beside the edge that joins them, it names either (pitfall_one_shape's "2" beside the diamond's upper-left edge,
// 34 pixels from its top corner and 39 from the left one). Measured from the label's middle, as
// LabelsNearerAnotherMark measures it: farther than 30 pixels from its corner, where it no longer reads as that
// corner's at a glance, its own corner must be at most 4/5 as far as any other.
std::vector<std::string> VertexNumbersBetweenCorners(const RecordingCanvas& canvas, const Scene& scene,
                                                     const PairStudy& study, const View& view)
{
    std::vector<std::string> problems;
    RecordingCanvas measure;
    const Body* bodies[2] = {&scene.bodies[static_cast<size_t>(study.bodyA)],
                             &scene.bodies[static_cast<size_t>(study.bodyB)]};
    const Color inks[2] = {palette::kShapeA, palette::kShapeBInk};
    std::vector<ScreenPoint> corners[2];
    for (int s = 0; s < 2; ++s)
    {
        if (bodies[s]->shape.type == ShapeType::Polygon)
        {
            corners[s] = Outline(*bodies[s], view);
        }
    }
    const auto distance = [](ScreenPoint p, ScreenPoint q) { return std::hypot(p.x - q.x, p.y - q.y); };
    for (const DrawCommand* c : canvas.InGroup("labels"))
    {
        if (c->kind != DrawCommand::Kind::Text || !painter_test::IsVertexNumber(c->text) || OnLeader(canvas, *c))
        {
            continue;
        }
        const ScreenPoint size = measure.MeasureText(c->text, c->style);
        const ScreenPoint middle{c->points[0].x + 0.5f * size.x, c->points[0].y + 0.5f * size.y};
        const size_t own = static_cast<size_t>(std::stoi(c->text));
        for (int s = 0; s < 2; ++s)
        {
            if ((c->color >> 8) != (inks[s] >> 8) || own >= corners[s].size())
            {
                continue;
            }
            const float mine = distance(middle, corners[s][own]);
            for (int o = 0; o < 2; ++o)
            {
                for (size_t k = 0; k < corners[o].size(); ++k)
                {
                    // A corner at the same place as its own (resting on the other body's) is the same place.
                    if ((o == s && k == own) || distance(corners[o][k], corners[s][own]) <= 3.0f)
                    {
                        continue;
                    }
                    if (mine > 30.0f && mine > 0.8f * distance(middle, corners[o][k]))
                    {
                        problems.push_back(Describe(*c) + ", a vertex number of " + bodies[s]->name + ", lies " +
                                           std::to_string(static_cast<int>(mine)) + " pixels from its corner and " +
                                           std::to_string(static_cast<int>(distance(middle, corners[o][k]))) +
                                           " from the corner at (" + std::to_string(static_cast<int>(corners[o][k].x)) +
                                           ", " + std::to_string(static_cast<int>(corners[o][k].y)) + ")");
                        o = 2;
                        break;
                    }
                }
            }
        }
    }
    return problems;
}

// The labels and marks of a disc-cast figure (a disc's centre moved along a path, drawn at its start, at the hit
// and at its end) that a reader would attach to the wrong thing:
// - "start" or "end" inside the target, or farther than 25 pixels beyond the rim of its disc: circle_and_polygon_cast's
//   "end" sat in the pentagon, well left of the dashed disc, and read as naming the pentagon's corner;
// - "contact" inside the disc at the hit or at the end, where it reads as that disc's name (circle_and_polygon_cast);
// - the time's name led across the target's outline: disc_cast_cup's "t = 0.74" was led across the whole right arm;
// - the normal at the hit run along the path for more than 10 pixels, where the two black lines merge into one
//   (disc_cast_cup's, nearly parallel to the steep path).
std::vector<std::string> DiscCastMarksAstray(const RecordingCanvas& canvas)
{
    std::vector<std::string> problems;
    const std::vector<const DrawCommand*> path = canvas.InGroup("path");
    const std::vector<const DrawCommand*> hit = canvas.InGroup("hit");
    const std::vector<const DrawCommand*> target = canvas.InGroup("target");
    // The path's shafts (a thin black line, one piece or more) and its head's tip; the start disc's rim.
    std::vector<std::pair<ScreenPoint, ScreenPoint>> shafts;
    ScreenPoint start{}, end{};
    float radius = 0.0f;
    bool head = false;
    for (const DrawCommand* c : path)
    {
        if (c->kind == DrawCommand::Kind::Segment && c->color == palette::kInk)
        {
            shafts.push_back({c->points[0], c->points[1]});
        }
        if (IsArrowHead(*c) && c->color == palette::kInk)
        {
            end = c->points[0];
            head = true;
        }
        if (c->kind == DrawCommand::Kind::Circle && radius == 0.0f)
        {
            start = c->points[0];
            radius = c->radius;
        }
    }
    if (shafts.empty() || !head || radius == 0.0f)
    {
        return problems;
    }
    // The disc at the hit: its rim in "hit"; the normal: the thick black line in "hit", drawn before its head.
    ScreenPoint centre{};
    bool hitDisc = false;
    std::vector<std::pair<ScreenPoint, ScreenPoint>> normals;
    for (const DrawCommand* c : hit)
    {
        if (c->kind == DrawCommand::Kind::Circle)
        {
            centre = c->points[0];
            hitDisc = true;
        }
        if (c->kind == DrawCommand::Kind::Segment && c->color == palette::kInk)
        {
            normals.push_back({c->points[0], c->points[1]});
        }
    }
    // The target's outline: the closed lines in "target" (a concave body's seams are dashed segments).
    std::vector<std::vector<ScreenPoint>> outlines;
    for (const DrawCommand* c : target)
    {
        if (c->kind == DrawCommand::Kind::Polyline)
        {
            outlines.push_back(c->points);
        }
    }
    const auto inside = [](const std::vector<ScreenPoint>& polygon, ScreenPoint p) {
        bool in = false;
        for (size_t i = 0, j = polygon.size() - 1; i < polygon.size(); j = i++)
        {
            const ScreenPoint& u = polygon[i];
            const ScreenPoint& v = polygon[j];
            if ((u.y > p.y) != (v.y > p.y) && p.x < u.x + (p.y - u.y) * (v.x - u.x) / (v.y - u.y))
            {
                in = !in;
            }
        }
        return in;
    };
    const auto crosses = [](ScreenPoint p, ScreenPoint q, ScreenPoint u, ScreenPoint v) {
        const auto side = [](ScreenPoint a, ScreenPoint b, ScreenPoint c) {
            return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
        };
        return side(p, q, u) * side(p, q, v) < 0.0f && side(u, v, p) * side(u, v, q) < 0.0f;
    };
    RecordingCanvas measure;
    for (const DrawCommand* c : canvas.InGroup("labels"))
    {
        if (c->kind != DrawCommand::Kind::Text)
        {
            continue;
        }
        const ScreenPoint size = measure.MeasureText(c->text, c->style);
        const ScreenPoint middle{c->points[0].x + 0.5f * size.x, c->points[0].y + 0.5f * size.y};
        const auto far = [&](ScreenPoint from) { return std::hypot(middle.x - from.x, middle.y - from.y); };
        if (c->text == "start" || c->text == "end")
        {
            const ScreenPoint own = c->text == "start" ? start : end;
            for (const std::vector<ScreenPoint>& outline : outlines)
            {
                if (inside(outline, middle))
                {
                    problems.push_back(Describe(*c) + " lies inside the target");
                }
            }
            if (far(own) > radius + 25.0f + 0.5f * size.x)
            {
                problems.push_back(Describe(*c) + " lies " + std::to_string(static_cast<int>(far(own) - radius)) +
                                   " pixels beyond the rim of its disc");
            }
        }
        if (c->text == "contact" && (far(end) < radius || (hitDisc && far(centre) < radius)))
        {
            problems.push_back(Describe(*c) + " lies inside a disc");
        }
        if (c->text.rfind("t = ", 0) == 0)
        {
            const DrawCommand* line = LeaderTo(canvas, *c);
            for (size_t k = 0; line != nullptr && k < outlines.size(); ++k)
            {
                const std::vector<ScreenPoint>& outline = outlines[k];
                for (size_t i = 0; i < outline.size(); ++i)
                {
                    if (crosses(line->points[0], line->points[1], outline[i], outline[(i + 1) % outline.size()]))
                    {
                        problems.push_back(Describe(*c) + " is led across the target's outline");
                        k = outlines.size();
                        break;
                    }
                }
            }
        }
    }
    for (const auto& [a, b] : normals)
    {
        const float length = std::hypot(b.x - a.x, b.y - a.y);
        float along = 0.0f;
        for (float s = 0.0f; s <= length; s += 1.0f)
        {
            const ScreenPoint p{a.x + (b.x - a.x) * s / length, a.y + (b.y - a.y) * s / length};
            const bool near = std::any_of(shafts.begin(), shafts.end(), [&](const auto& shaft) {
                return ToSegment(p, shaft.first, shaft.second) < 2.5f;
            });
            along += near ? 1.0f : 0.0f;
        }
        if (along > 10.0f)
        {
            problems.push_back("the normal at the hit runs " + std::to_string(static_cast<int>(along)) +
                               " pixels along the path");
        }
    }
    return problems;
}

// A label over the centre of a circle of the pair where a dashed axis line ends (the axis from a vertex, or from
// the other centre): it hides where the axis comes from (l07_near_miss's "ball", centred in the small ball).
std::vector<std::string> LabelsOverAxisCentres(const RecordingCanvas& canvas, const Scene& scene,
                                               const PairStudy& study, const View& view)
{
    std::vector<std::string> problems;
    RecordingCanvas measure;
    for (const int index : {study.bodyA, study.bodyB})
    {
        const Body& body = scene.bodies[static_cast<size_t>(index)];
        if (body.shape.type != ShapeType::Circle)
        {
            continue;
        }
        const ScreenPoint centre = ToScreen(view, TransformPoint(body.Xf(), body.shape.circle.center));
        // A dash of the line ends a few pixels short of the centre, on a line through it.
        bool ends = false;
        for (const DrawCommand* c : canvas.InGroup("projection"))
        {
            if (c->kind != DrawCommand::Kind::Segment)
            {
                continue;
            }
            const ScreenPoint p = c->points[0];
            const ScreenPoint q = c->points[1];
            const float length = std::hypot(q.x - p.x, q.y - p.y);
            const float off = length > 0.0f
                                  ? std::abs((q.x - p.x) * (centre.y - p.y) - (q.y - p.y) * (centre.x - p.x)) / length
                                  : INFINITY;
            ends = ends || (off < 1.5f && std::min(std::hypot(p.x - centre.x, p.y - centre.y),
                                                   std::hypot(q.x - centre.x, q.y - centre.y)) < 8.0f);
        }
        if (!ends)
        {
            continue;
        }
        for (const DrawCommand* c : canvas.InGroup("labels"))
        {
            if (c->kind != DrawCommand::Kind::Text)
            {
                continue;
            }
            const ScreenPoint size = measure.MeasureText(c->text, c->style);
            // The centre's dot, 2.5 pixels across its middle, and the last dash's end beside it.
            if (centre.x >= c->points[0].x - 3.0f && centre.x <= c->points[0].x + size.x + 3.0f &&
                centre.y >= c->points[0].y - 3.0f && centre.y <= c->points[0].y + size.y + 3.0f)
            {
                problems.push_back(Describe(*c) + " covers " + body.name + "'s centre, where the axis line ends");
            }
        }
    }
    return problems;
}

// A velocity's "v" inside its own body's dashed outline where the step ends, drawn when the sweep finds no hit: the
// arrow's head is that outline's centre, and a name beside it reads as the outline's (fly_by's "v" in the dashed
// box, sliding_past's, l17_corner_after's in the dashed ball).
std::vector<std::string> VelocityInOwnEnd(const RecordingCanvas& canvas, const Scene& scene, const PairStudy& study,
                                          const View& view)
{
    std::vector<std::string> problems;
    const std::vector<const DrawCommand*> swept = canvas.InGroup("swept");
    const bool dashedEnd = std::any_of(swept.begin(), swept.end(), [](const DrawCommand* d) {
        return d->kind == DrawCommand::Kind::Segment && d->thickness > 1.1f && d->thickness < 1.3f;
    });
    if (!dashedEnd)
    {
        return problems;
    }
    RecordingCanvas measure;
    const Color inks[2] = {palette::kShapeA, palette::kShapeBInk};
    const int indices[2] = {study.bodyA, study.bodyB};
    for (int k = 0; k < 2; ++k)
    {
        Body end = scene.bodies[static_cast<size_t>(indices[k])];
        if (end.velocity == Vec2{})
        {
            continue;
        }
        end.position = end.position + end.velocity;
        for (const DrawCommand* c : canvas.InGroup("labels"))
        {
            if (c->kind != DrawCommand::Kind::Text || c->text != "v" || (c->color >> 8) != (inks[k] >> 8))
            {
                continue;
            }
            const ScreenPoint size = measure.MeasureText(c->text, c->style);
            const ScreenPoint middle{c->points[0].x + 0.5f * size.x, c->points[0].y + 0.5f * size.y};
            if (InsideBody(end, ToWorld(view, middle)))
            {
                problems.push_back(Describe(*c) + " lies inside " + end.name + "'s dashed outline where the step ends");
            }
        }
    }
    return problems;
}

struct Drawn
{
    std::string name;
    std::vector<std::string> problems;
};

// Every check of one drawn figure: its texts against each other, the marks and the image, and, for a pair, its
// labels against the pair's bodies and (with namedFaces) the faces its sentences name.
// Appends the problems one check found to the figure's.
void Append(std::vector<std::string>& problems, std::vector<std::string> more)
{
    for (std::string& p : more)
    {
        problems.push_back(std::move(p));
    }
}

std::vector<std::string> FigureProblems(const RecordingCanvas& canvas, const Scene& scene, const FigureSetup& setup,
                                        bool namedFaces = true)
{
    std::vector<std::string> problems = HiddenTexts(canvas, setup.figure.view.width, setup.figure.view.height);
    Append(problems, LabelsOnLines(canvas));
    Append(problems, LeadersOutOfImage(canvas, setup.figure.view.width, setup.figure.view.height));
    Append(problems, LeadersAlongGrid(canvas));
    Append(problems, PushesOnEdges(canvas));
    Append(problems, LeadersFromArrowTails(canvas));
    Append(problems, BandLeadersAstray(canvas));
    Append(problems, ArrowNamesNearerOtherArrows(canvas));
    Append(problems, NameLeadersFromShafts(canvas));
    Append(problems, IncidentLeadersAcrossReference(canvas));
    Append(problems, FaceLeadersFromMarks(canvas, setup.study.manifold.normal));
    Append(problems, TinyArrowHeads(canvas));
    Append(problems, PitfallOnMtvLine(canvas));
    Append(problems, PitfallLeaderOnArrow(canvas));
    Append(problems, DiscCastMarksAstray(canvas));
    Append(problems, ArrowsTailToTail(canvas));
    // A figure of its own (a decomposition, ...) draws no pair: the checks of labels against the pair's bodies
    // are for the pair's figures.
    if (setup.figure.kind == FigureKind::Pair)
    {
        Append(problems, LabelsInOtherBody(canvas, scene, setup.study, setup.figure.view));
        Append(problems, VelocityInOtherGhost(canvas, scene, setup.study, setup.figure.view, setup.figure.layers));
        Append(problems, VelocityInOtherBody(canvas, scene, setup.study, setup.figure.view));
        Append(problems, LeadersAcrossSeparatingLine(canvas));
        Append(problems, VertexNumbersInOtherBody(canvas, scene, setup.study, setup.figure.view));
        Append(problems, LabelsOnOutlines(canvas, scene, setup.study, setup.figure.view));
        Append(problems, LeadersAlongOutlines(canvas, scene, setup.study, setup.figure.view));
        Append(problems, FaceLeadersAtCrossings(canvas, scene, setup.study, setup.figure.view));
        Append(problems, EdgeNamesAheadOfArrows(canvas, scene, setup.study, setup.figure.view));
        if (namedFaces)
        {
            Append(problems, EdgeNamesBehind(canvas, scene, setup.study, setup.figure.view));
        }
        Append(problems, LabelsOnOtherBodies(canvas, scene, setup.study, setup.figure.view));
        if (namedFaces)
        {
            Append(problems, NamedFacesUnnamed(canvas, scene, setup.study, setup.figure.layers, setup.figure.view));
        }
        Append(problems, NamesAstray(canvas, scene, setup.study));
        Append(problems, LabelsOnDashedOutlines(canvas));
        Append(problems, ReferenceFaceFar(canvas));
        Append(problems, FaceNamesByDots(canvas));
        Append(problems, ContactNamesBetweenDots(canvas));
        Append(problems, FaceLeadersFromPaths(canvas));
        Append(problems, ReferenceFaceAtCorner(canvas, scene, setup.study, setup.figure.view));
        Append(problems, ReferenceFaceBeyondEnd(canvas));
        Append(problems, FaceNamesAstray(canvas, scene, setup.study, setup.figure.view));
        Append(problems, EdgeNamesByRivalCorners(canvas, scene, setup.study, setup.figure.view));
        Append(problems, ArrowsBetween(canvas, scene, setup.study, setup.figure.view));
        Append(problems, CornersAtTheSides(scene, setup.study, setup.figure.view, setup.figure.layers));
        Append(problems, LabelsNearerAnotherMark(canvas, scene, setup.study, setup.figure.view));
        Append(problems, ArrowLabelsAstray(canvas));
        Append(problems, LeadersAcrossBars(canvas));
        Append(problems, ArrowNamesLedThroughBodies(canvas, scene, setup.study, setup.figure.view));
        Append(problems, VertexNumbersBetweenCorners(canvas, scene, setup.study, setup.figure.view));
        Append(problems, GhostLeadersAcrossBodies(canvas, scene, setup.study, setup.figure.view));
        Append(problems, EdgeNamesInGhosts(canvas));
        Append(problems, VelocityNamedPastBody(canvas, scene, setup.study, setup.figure.view));
        Append(problems, LabelsOverAxisCentres(canvas, scene, setup.study, setup.figure.view));
        Append(problems, VelocityInOwnEnd(canvas, scene, setup.study, setup.figure.view));
    }
    return problems;
}

// Draws one scene as satviz-render does (its view's sim_steps first), every step or the view's step.
std::vector<Drawn> DrawFigures(const std::string& stem, bool allSteps, bool faces)
{
    const Scene scene = painter_test::LessonScene(stem);
    FigureOptions options;
    if (faces)
    {
        options.setSteps = true;
        options.steps = StepView::Faces;
    }
    FigureSetup setup = SetUpFigure(scene, options);
    REQUIRE(setup.Ok());
    std::vector<int> steps;
    for (int k = allSteps ? 0 : setup.figure.step; k < (allSteps ? FigureStepCount(scene, setup) : setup.figure.step + 1);
         ++k)
    {
        steps.push_back(k);
    }
    std::vector<Drawn> drawn;
    for (int k : steps)
    {
        const RecordingCanvas canvas = painter_test::PaintStep(scene, setup, k);
        std::vector<std::string> problems = FigureProblems(canvas, scene, setup);
        drawn.push_back({(faces ? "faces/" : "") + stem + (allSteps ? "-step" + std::to_string(k + 1) : "") + ".png",
                         std::move(problems)});
    }
    return drawn;
}

} // namespace

TEST_CASE("The label check finds a label on a label, on an arrow head, under a later line and cut at the edge",
          "[labels]")
{
    RecordingCanvas canvas;
    canvas.Text({10.0f, 10.0f}, "e1", TextStyle::Label, palette::kInk);
    canvas.Text({18.0f, 12.0f}, "box", TextStyle::Heading, palette::kInk);
    CHECK(HiddenTexts(canvas, 200, 100).size() == 1);

    RecordingCanvas head;
    head.Text({50.0f, 50.0f}, "axis 2", TextStyle::Label, palette::kInk);
    const ScreenPoint tip[3] = {{60.0f, 55.0f}, {52.0f, 60.0f}, {52.0f, 50.0f}};
    head.FillConvex(tip, 3, palette::kInk);
    CHECK(HiddenTexts(head, 200, 100).size() == 1);
    RecordingCanvas faint;
    faint.Text({50.0f, 50.0f}, "axis 2", TextStyle::Label, palette::kInk);
    faint.FillConvex(tip, 3, WithAlpha(palette::kShapeA, 0.2f)); // a body's translucent fill, drawn after: covers
    CHECK(HiddenTexts(faint, 200, 100).size() == 1);
    RecordingCanvas under;
    under.FillConvex(tip, 3, WithAlpha(palette::kShapeA, 0.2f)); // ... but not drawn before
    under.Text({50.0f, 50.0f}, "axis 2", TextStyle::Label, palette::kInk);
    CHECK(HiddenTexts(under, 200, 100).empty());

    RecordingCanvas line;
    line.Text({50.0f, 50.0f}, "MTV 0.10", TextStyle::Heading, palette::kInk);
    line.Segment({40.0f, 40.0f}, {120.0f, 70.0f}, palette::kResult, 3.0f);
    line.Segment({40.0f, 80.0f}, {120.0f, 80.0f}, palette::kResult, 3.0f); // below it: clear
    CHECK(HiddenTexts(line, 200, 100).size() == 1);

    RecordingCanvas edge;
    edge.Text({190.0f, 40.0f}, "e1", TextStyle::Label, palette::kInk);
    CHECK(HiddenTexts(edge, 200, 100).size() == 1);
    CHECK(HiddenTexts(edge, 220, 100).empty());
    // Flush with the edge, inside it by a pixel: it reads as cut.
    CHECK(HiddenTexts(edge, 190 + static_cast<int>(FontTextSize("e1", TextStyle::Label).x) + 1, 100).size() == 1);

    // Two numbers on one line, 6 pixels apart, read as one; 10 apart they do not.
    const float width = FontTextSize("-3.00", TextStyle::Label).x;
    RecordingCanvas pair;
    pair.Text({20.0f, 20.0f}, "-3.00", TextStyle::Label, palette::kInk);
    pair.Text({26.0f + width, 20.0f}, "-3.00", TextStyle::Label, palette::kInk);
    CHECK(HiddenTexts(pair, 200, 100).size() == 1);
    RecordingCanvas apart;
    apart.Text({20.0f, 20.0f}, "-3.00", TextStyle::Label, palette::kInk);
    apart.Text({30.0f + width, 20.0f}, "-3.00", TextStyle::Label, palette::kInk);
    CHECK(HiddenTexts(apart, 200, 100).empty());
    // Stacked texts that touch read as one block; 3 pixels apart they do not.
    RecordingCanvas stacked;
    stacked.Text({20.0f, 20.0f}, "gap 0.60", TextStyle::Label, palette::kInk);
    stacked.Text({40.0f, 20.0f + TextSize(TextStyle::Label)}, "0", TextStyle::Label, palette::kInk);
    CHECK(HiddenTexts(stacked, 200, 100).size() == 1);
    RecordingCanvas spaced;
    spaced.Text({20.0f, 20.0f}, "gap 0.60", TextStyle::Label, palette::kInk);
    spaced.Text({40.0f, 23.0f + TextSize(TextStyle::Label)}, "0", TextStyle::Label, palette::kInk);
    CHECK(HiddenTexts(spaced, 200, 100).empty());

    // Two labels of the scene stacked 3 pixels apart read as one phrase; 7 apart they do not.
    RecordingCanvas phrase;
    phrase.BeginGroup("labels");
    phrase.Text({20.0f, 20.0f}, "plank", TextStyle::Heading, palette::kInk);
    phrase.Text({20.0f, 23.0f + TextSize(TextStyle::Heading)}, "incident edge", TextStyle::Label, palette::kInk);
    CHECK(HiddenTexts(phrase, 200, 100).size() == 1);
    RecordingCanvas apartStack;
    apartStack.BeginGroup("labels");
    apartStack.Text({20.0f, 20.0f}, "plank", TextStyle::Heading, palette::kInk);
    apartStack.Text({20.0f, 27.0f + TextSize(TextStyle::Heading)}, "incident edge", TextStyle::Label, palette::kInk);
    CHECK(HiddenTexts(apartStack, 200, 100).empty());

    // A leader line under another label; one that ends at its own label is fine.
    RecordingCanvas leader;
    leader.BeginGroup("labels");
    leader.Segment({10.0f, 50.0f}, {100.0f, 50.0f}, palette::kInk, 1.0f);
    leader.Text({40.0f, 44.0f}, "c1", TextStyle::Label, palette::kInk);
    leader.Text({100.0f, 44.0f}, "MTV", TextStyle::Label, palette::kInk);
    CHECK(HiddenTexts(leader, 200, 100).size() == 1);

    // An arrow head under a later opaque disc of another colour; a thin line across it leaves it readable.
    const ScreenPoint arrow[3] = {{60.0f, 55.0f}, {50.0f, 60.0f}, {50.0f, 50.0f}};
    RecordingCanvas hidden;
    hidden.FillConvex(arrow, 3, palette::kShapeBInk);
    hidden.FillCircle({56.0f, 55.0f}, 5.5f, palette::kResult);
    CHECK(HiddenTexts(hidden, 200, 100).size() == 1);
    RecordingCanvas crossed;
    crossed.FillConvex(arrow, 3, palette::kShapeBInk);
    crossed.Segment({40.0f, 55.0f}, {80.0f, 55.0f}, palette::kResult, 2.0f);
    CHECK(HiddenTexts(crossed, 200, 100).empty());

    // A label over a thick bar drawn before it hides the interval.
    RecordingCanvas bar;
    bar.BeginGroup("projection");
    bar.Segment({20.0f, 50.0f}, {150.0f, 50.0f}, palette::kShapeA, 8.0f);
    bar.BeginGroup("labels");
    bar.Text({60.0f, 44.0f}, "e0", TextStyle::Label, palette::kInk);
    CHECK(HiddenTexts(bar, 200, 100).size() == 1);
}

TEST_CASE("No label of any figure of the course covers another, an arrow head or a mark, or leaves the image",
          "[labels]")
{
    const auto lists = painter_test::CourseFigureLists();
    REQUIRE(lists.count("SATVIZ_FIGURE_SCENES") == 1);
    REQUIRE(lists.count("SATVIZ_STEP_SCENES") == 1);
    REQUIRE(lists.count("SATVIZ_FACE_STEP_SCENES") == 1);
    std::vector<Drawn> drawn;
    for (const std::string& stem : lists.at("SATVIZ_FIGURE_SCENES"))
    {
        for (Drawn& d : DrawFigures(stem, false, false))
        {
            drawn.push_back(std::move(d));
        }
    }
    for (const std::string& stem : lists.at("SATVIZ_STEP_SCENES"))
    {
        for (Drawn& d : DrawFigures(stem, true, false))
        {
            drawn.push_back(std::move(d));
        }
    }
    for (const std::string& stem : lists.at("SATVIZ_FACE_STEP_SCENES"))
    {
        for (Drawn& d : DrawFigures(stem, true, true))
        {
            drawn.push_back(std::move(d));
        }
    }
    // As many figures as tutorials/figures/ holds.
    size_t committed = 0;
    for (const auto& dir : {"/tutorials/figures", "/tutorials/figures/faces"})
    {
        for (const auto& entry : std::filesystem::directory_iterator(std::string(SATVIZ_SOURCE_DIR) + dir))
        {
            committed += entry.path().extension() == ".png" ? 1 : 0;
        }
    }
    CHECK(drawn.size() == committed);
    int failing = 0;
    for (const Drawn& d : drawn)
    {
        INFO(d.name);
        for (const std::string& problem : d.problems)
        {
            UNSCOPED_INFO(problem);
        }
        CHECK(d.problems.empty());
        failing += d.problems.empty() ? 0 : 1;
    }
    INFO(failing << " of " << drawn.size() << " figures");
    CHECK(failing == 0);
}

TEST_CASE("On the app's narrower canvas beside a lesson, every face the sentences name is still named, no leader "
          "runs along an edge and no edge name sits ahead of another arrow",
          "[labels]")
{
    // Beside the lesson column a 1280 x 800 window leaves the canvas 460 x 758 pixels, and the scene's framing
    // shrinks with it: l17_skips' right wall drew too small to have its edges named, while the verdict spoke of
    // "right wall's edge 3". The app's smallest window, about 1180 x 640 with a lesson open, leaves 360 x 600
    // (kMinCanvasWidth x kMinCanvasHeight), where they must still be named.
    const auto lists = painter_test::CourseFigureLists();
    int drawn = 0;
    for (const char* list : {"SATVIZ_FIGURE_SCENES", "SATVIZ_STEP_SCENES"})
    {
        for (const std::string& stem : lists.at(list))
        {
            const Scene scene = painter_test::LessonScene(stem);
            FigureSetup setup = SetUpFigure(scene, FigureOptions{});
            REQUIRE(setup.Ok());
            if (scene.view.fit || setup.figure.kind != FigureKind::Pair)
            {
                continue;
            }
            for (const auto& [width, height] : {std::pair{460, 758}, std::pair{360, 600}})
            {
                if (!FrameScene(scene.view, setup.study, setup.figure.layers, width, height, setup.figure.view))
                {
                    setup.figure.view = FitFigure(scene, setup.study, setup.figure.layers, width, height);
                }
                for (int k = 0; k < FigureStepCount(scene, setup); ++k)
                {
                    const RecordingCanvas canvas = painter_test::PaintStep(scene, setup, k);
                    INFO(stem << " step " << k + 1 << " at " << width << " x " << height);
                    std::vector<std::string> problems =
                        NamedFacesUnnamed(canvas, scene, setup.study, setup.figure.layers, setup.figure.view);
                    for (std::string& p : LeadersAlongOutlines(canvas, scene, setup.study, setup.figure.view))
                    {
                        problems.push_back(std::move(p));
                    }
                    for (std::string& p : EdgeNamesAheadOfArrows(canvas, scene, setup.study, setup.figure.view))
                    {
                        problems.push_back(std::move(p));
                    }
                    for (const std::string& problem : problems)
                    {
                        UNSCOPED_INFO(problem);
                    }
                    CHECK(problems.empty());
                    ++drawn;
                }
            }
        }
    }
    CHECK(drawn > 100);
}

TEST_CASE("On the app's narrower canvas beside a lesson, the face view names every face the sentences name",
          "[labels][faces]")
{
    // The face view at 460 x 758 and 360 x 600: a small body whose named face rests on the other body has no room
    // outside that face and little inside it (l09_stuck's box on the floor, its arrow and ghost beside it), and
    // must still have the face named.
    // A small body's name gives way to such a face (l03_corner_gap's B, the separating line just outside its e3,
    // has its name moved out of it); a body too small to hold its name has it on the side away from such a face
    // (pitfall_tunnel's bullet, some 20 pixels wide, its e0 and that face's normal below it). Left out, with no
    // room yet at 360 x 600: the reference face of l04_wrong_way's and overlapping_boxes' verdicts (B's e3, flush
    // against A, among "reference face", c1 and c2; "reference face" names it there, beside the face).
    const std::set<std::string> crowded = {"l04_wrong_way 9 360", "overlapping_boxes 9 360"};
    const auto lists = painter_test::CourseFigureLists();
    int drawn = 0;
    int failing = 0;
    for (const char* list : {"SATVIZ_FIGURE_SCENES", "SATVIZ_STEP_SCENES"})
    {
        for (const std::string& stem : lists.at(list))
        {
            const Scene scene = painter_test::LessonScene(stem);
            for (const auto& [width, height] : {std::pair{460, 758}, std::pair{360, 600}})
            {
                FigureOptions options;
                options.setSteps = true;
                options.steps = StepView::Faces;
                options.width = width;
                options.height = height;
                FigureSetup setup = SetUpFigure(scene, options);
                if (!setup.Ok() || setup.figure.kind != FigureKind::Pair)
                {
                    continue;
                }
                for (int k = 0; k < FigureStepCount(scene, setup); ++k)
                {
                    const RecordingCanvas canvas = painter_test::PaintStep(scene, setup, k);
                    INFO(stem << " face step " << k + 1 << " at " << width << " x " << height);
                    if (crowded.count(stem + " " + std::to_string(k + 1) + " " + std::to_string(width)) == 1)
                    {
                        continue;
                    }
                    std::vector<std::string> problems =
                        NamedFacesUnnamed(canvas, scene, setup.study, setup.figure.layers, setup.figure.view);
                    for (std::string& p : LeadersAlongOutlines(canvas, scene, setup.study, setup.figure.view))
                    {
                        problems.push_back(std::move(p));
                    }
                    for (std::string& p : EdgeNamesAheadOfArrows(canvas, scene, setup.study, setup.figure.view))
                    {
                        problems.push_back(std::move(p));
                    }
                    for (const std::string& problem : problems)
                    {
                        UNSCOPED_INFO(problem);
                    }
                    CHECK(problems.empty());
                    failing += problems.empty() ? 0 : 1;
                    ++drawn;
                }
            }
        }
    }
    INFO(failing << " of " << drawn);
    CHECK(drawn > 100);
}

TEST_CASE("In the face view of every pair of the course, every face the sentences name is labelled", "[labels]")
{
    // The face view can be chosen for any pair in the app, so every figure of a pair is drawn in it, every step: a
    // face a step asks about ("does box lie wholly beyond floor's edge 1?") is named where any of it is in sight,
    // outside its body or, with no room there, just inside it.
    const auto lists = painter_test::CourseFigureLists();
    int drawn = 0;
    int failing = 0;
    for (const char* list : {"SATVIZ_FIGURE_SCENES", "SATVIZ_STEP_SCENES"})
    {
        for (const std::string& stem : lists.at(list))
        {
            const Scene scene = painter_test::LessonScene(stem);
            FigureOptions options;
            options.setSteps = true;
            options.steps = StepView::Faces;
            FigureSetup setup = SetUpFigure(scene, options);
            if (!setup.Ok() || setup.figure.kind != FigureKind::Pair)
            {
                continue;
            }
            for (int k = 0; k < FigureStepCount(scene, setup); ++k)
            {
                const RecordingCanvas canvas = painter_test::PaintStep(scene, setup, k);
                INFO(stem << " face step " << k + 1);
                std::vector<std::string> problems =
                    NamedFacesUnnamed(canvas, scene, setup.study, setup.figure.layers, setup.figure.view);
                for (std::string& p : EdgeNamesBehind(canvas, scene, setup.study, setup.figure.view))
                {
                    problems.push_back(std::move(p));
                }

                for (const std::string& problem : problems)
                {
                    UNSCOPED_INFO(problem);
                }
                CHECK(problems.empty());
                failing += problems.empty() ? 0 : 1;
                ++drawn;
            }
        }
    }
    INFO(failing << " of " << drawn);
    CHECK(drawn > 100);
}

TEST_CASE("In the face view, every step of every pair of the course keeps its labels apart and in the image",
          "[labels][faces]")
{
    // The app shows any scene in the face view, at any step, on its 800 x 600 canvas or at the scene's own size:
    // every pair scene of the course drawn so keeps its labels off each other, the arrow heads, the marks, the
    // bodies' outlines and the image's edge, and names each face a sentence names, on its outer side, as the
    // committed figures do.
    int drawn = 0;
    int failing = 0;
    const std::vector<std::string> files = testing::TutorialSceneFiles(true);
    REQUIRE(files.size() > 100);
    for (const std::filesystem::path file : files)
    {
        const Scene scene = painter_test::LoadSimulated(file.string());
        for (const bool own : {true, false})
        {
            if (!own && scene.view.width == 800 && scene.view.height == 600)
            {
                continue;
            }
            FigureOptions options;
            options.setSteps = true;
            options.steps = StepView::Faces;
            if (!own)
            {
                options.width = 800;
                options.height = 600;
            }
            FigureSetup setup = SetUpFigure(scene, options);
            if (!setup.Ok() || setup.figure.kind != FigureKind::Pair)
            {
                continue;
            }
            for (int k = 0; k < FigureStepCount(scene, setup); ++k)
            {
                const RecordingCanvas canvas = painter_test::PaintStep(scene, setup, k);
                std::vector<std::string> problems = FigureProblems(canvas, scene, setup);
                // Left to do: two drawings where a band's size or the reference face finds no place but across a
                // bar (l09_landing's band under the floor, against the number line; ex02_hexagon's face among the
                // box's labels).
                const std::string which = file.filename().string() + " " + std::to_string(k + 1);
                if (which == "l09_landing.json 2" || which == "ex02_hexagon.json 11")
                {
                    problems.erase(std::remove_if(problems.begin(), problems.end(),
                                                  [](const std::string& p) {
                                                      return p.find("crosses the bar") != std::string::npos;
                                                  }),
                                   problems.end());
                }
                INFO(file.filename().string() << " face step " << k + 1 << " at " << setup.figure.view.width << " x "
                                              << setup.figure.view.height);
                for (const std::string& problem : problems)
                {
                    UNSCOPED_INFO(problem);
                }
                CHECK(problems.empty());
                failing += problems.empty() ? 0 : 1;
                ++drawn;
            }
        }
    }
    INFO(failing << " of " << drawn << " drawings");
    CHECK(failing == 0);
    CHECK(drawn > 500);
}

TEST_CASE("On the app's narrower canvas the number line's and time bar's labels keep apart wherever the body is dragged",
          "[labels]")
{
    // Lesson 8's bullet_wall beside the lesson column (460 x 758, and the smallest window's 360 x 600), in both
    // views, the bullet dragged over a grid of places around where it starts, the camera kept as the scene framed it
    // (as a drag keeps it): the interval ends of the number line (the thin wall's -0.010 and 0.010 sat on each other
    // once the bullet's swept interval widened the line) and the entry, exit, tick and window labels of the time bar
    // never sit on each other nor leave the canvas.
    const Scene authored = painter_test::LessonScene("bullet_wall");
    int drawn = 0;
    for (const auto& [width, height, view] : {std::tuple{460, 758, StepView::Textbook}, std::tuple{360, 600, StepView::Textbook},
                                        std::tuple{460, 758, StepView::Faces}, std::tuple{360, 600, StepView::Faces}})
    {
        FigureOptions options;
        options.setSteps = true;
        options.steps = view;
        FigureSetup framed = SetUpFigure(authored, options);
        REQUIRE(framed.Ok());
        REQUIRE(FrameScene(authored.view, framed.study, framed.figure.layers, width, height, framed.figure.view));
        const View camera = framed.figure.view;
        for (double dx = -1.2; dx <= 1.21; dx += 0.1)
        {
            for (double dy = -0.6; dy <= 0.61; dy += 0.2)
            {
                Scene scene = authored;
                Body& bullet = scene.bodies[static_cast<size_t>(framed.study.bodyB)];
                bullet.position = bullet.position + Vec2{dx, dy};
                FigureSetup setup = SetUpFigure(scene, options);
                REQUIRE(setup.Ok());
                setup.figure.view = camera;
                for (int k = 0; k < FigureStepCount(scene, setup); ++k)
                {
                    const RecordingCanvas canvas = painter_test::PaintStep(scene, setup, k);
                    INFO("bullet moved by (" << dx << ", " << dy << "), step " << k + 1 << " at " << width << " x "
                                             << height << (view == StepView::Faces ? " (faces)" : ""));
                    // The problems of the panel's texts (number line and time bar), against every text of the figure.
                    std::vector<std::string> problems;
                    for (const std::string& problem : HiddenTexts(canvas, width, height))
                    {
                        if (problem.find("in \"timebar\"") != std::string::npos || problem.find("in \"panel\"") != std::string::npos)
                        {
                            problems.push_back(problem);
                        }
                    }
                    for (const std::string& problem : problems)
                    {
                        UNSCOPED_INFO(problem);
                    }
                    CHECK(problems.empty());
                    ++drawn;
                }
            }
        }
    }
    CHECK(drawn > 100);
}

TEST_CASE("A velocity arrow whose step runs out of the scene keeps its head in sight and names its speed", "[labels]")
{
    // l17_bullet's bullet moves 1667 m in a step, on a canvas a few metres wide: swept, with the swept layer, its
    // arrow ran off the canvas, head and all, beside the lesson column (460 x 758) as on the wide canvas (900 x 758).
    Scene scene = painter_test::LessonScene("l17_bullet");
    scene.view.query = ViewQuery::Sweep;
    scene.view.layers.push_back("swept");
    for (const auto& [width, height] : {std::pair{460, 758}, std::pair{900, 758}, std::pair{360, 600}})
    {
        INFO(width << " x " << height);
        FigureSetup setup = SetUpFigure(scene, FigureOptions{});
        REQUIRE(setup.Ok());
        REQUIRE((setup.figure.layers & kLayerSwept) != 0);
        REQUIRE(FrameScene(scene.view, setup.study, setup.figure.layers, width, height, setup.figure.view));
        const bool titled = !scene.view.caption.empty();
        const FigureLayout layout = LayoutFigure(setup.study, setup.figure.layers, width, height, titled);
        for (int k = 0; k < FigureStepCount(scene, setup); ++k)
        {
            INFO("step " << k + 1);
            const RecordingCanvas canvas = painter_test::PaintStep(scene, setup, k);
            // The bullet's arrow: a head (a filled triangle) of the swept group, and its label naming the speed.
            int heads = 0;
            for (const DrawCommand* c : canvas.InGroup("swept"))
            {
                if (c->kind == DrawCommand::Kind::FillConvex && c->points.size() == 3)
                {
                    for (const ScreenPoint& p : c->points)
                    {
                        CHECK(p.x >= 0.0f);
                        CHECK(p.x <= static_cast<float>(width));
                        CHECK(p.y >= layout.sceneTop);
                        CHECK(p.y <= layout.sceneBottom);
                    }
                    ++heads;
                }
            }
            CHECK(heads == 1);
            bool named = false;
            for (const DrawCommand& c : canvas.commands)
            {
                // The scene's 100 000 m/s, with the world's unit, written as its caption writes it.
                named = named || (c.kind == DrawCommand::Kind::Text && c.text == "v = 100 000 m/s");
            }
            CHECK(named);
            for (const std::string& problem : HiddenTexts(canvas, width, height))
            {
                CHECK(problem.find("\"v") == std::string::npos);
            }
        }
    }
}

TEST_CASE("With the legend layer, no figure of the course hides a label or a body under its key", "[labels][legend]")
{
    // The key is a panel drawn over the picture: in a pieces figure it covered the L's corner and its name L1. Every
    // figure of the course, drawn with its own layers and the legend, keeps every text, every mark and every body's
    // fill off the key's panel.
    const auto lists = painter_test::CourseFigureLists();
    int keys = 0;
    std::vector<std::string> failing;
    for (const auto& [list, steps, faces] : {std::tuple{"SATVIZ_FIGURE_SCENES", false, false},
                                             std::tuple{"SATVIZ_STEP_SCENES", true, false},
                                             std::tuple{"SATVIZ_FACE_STEP_SCENES", true, true}})
    {
        for (const std::string& stem : lists.at(list))
        {
            const Scene scene = painter_test::LessonScene(stem);
            FigureOptions options;
            if (faces)
            {
                options.setSteps = true;
                options.steps = StepView::Faces;
            }
            FigureSetup setup = SetUpFigure(scene, options);
            REQUIRE(setup.Ok());
            if ((setup.figure.layers & ~kLayerCaption) == kLayerLegend)
            {
                continue; // lesson 1's key alone
            }
            const LayerMask layers = setup.figure.layers | kLayerLegend;
            const int first = steps ? 0 : setup.figure.step;
            const int last = steps ? FigureStepCount(scene, setup) : setup.figure.step + 1;
            for (int k = first; k < last; ++k)
            {
                const RecordingCanvas canvas = painter_test::Paint(scene, setup, k, layers);
                const std::string name = stem + (steps ? " step " + std::to_string(k + 1) : "") + (faces ? " (faces)" : "");
                const std::vector<const DrawCommand*> legend = canvas.InGroup("legend");
                if (legend.empty())
                {
                    continue;
                }
                REQUIRE(legend[0]->kind == DrawCommand::Kind::FillRect);
                const Box key{legend[0]->points[0].x, legend[0]->points[0].y, legend[0]->points[1].x,
                              legend[0]->points[1].y};
                ++keys;
                RecordingCanvas measure;
                std::vector<std::string> problems;
                for (const DrawCommand& c : canvas.commands)
                {
                    if (c.group == "legend")
                    {
                        continue;
                    }
                    if (c.kind == DrawCommand::Kind::Text)
                    {
                        const ScreenPoint size = measure.MeasureText(c.text, c.style);
                        if (key.Overlaps({c.points[0].x, c.points[0].y, c.points[0].x + size.x, c.points[0].y + size.y}))
                        {
                            problems.push_back("the key covers " + Describe(c));
                        }
                    }
                    const bool body = c.group == "shapes" || c.group == "pieces" || c.group == "before" ||
                                      c.group == "after" || c.group == "target";
                    if (body && c.kind == DrawCommand::Kind::FillConvex && ConvexCovers(c.points, key))
                    {
                        problems.push_back("the key covers a body's fill " + Describe(c));
                    }
                    if (body && c.kind == DrawCommand::Kind::FillCircle &&
                        key.Overlaps({c.points[0].x - 0.7f * c.radius, c.points[0].y - 0.7f * c.radius,
                                      c.points[0].x + 0.7f * c.radius, c.points[0].y + 0.7f * c.radius}))
                    {
                        problems.push_back("the key covers a disc " + Describe(c));
                    }
                }
                // The key's own texts and panel against the labels and marks: the rest of the label checks are the
                // course test's, on the figures as the lessons show them.
                for (std::string& p : HiddenTexts(canvas, setup.figure.view.width, setup.figure.view.height))
                {
                    if (p.find("\"legend\"") != std::string::npos)
                    {
                        problems.push_back(std::move(p));
                    }
                }
                if (!problems.empty())
                {
                    failing.push_back(name + ": " + problems.front() + (problems.size() > 1 ? " (and " +
                                      std::to_string(problems.size() - 1) + " more)" : ""));
                }
            }
        }
    }
    for (const std::string& f : failing)
    {
        UNSCOPED_INFO(f);
    }
    CHECK(failing.empty());
    CHECK(keys > 100);
}

TEST_CASE("many_sides is drawn large enough to read, with the triangle's three faces that lesson 12 works with named",
          "[labels]")
{
    // Lesson 12 works the example on the triangle's edge 2 (the smallest overlap) and its edges 0 and 1 (pruned):
    // framed to fit every axis line, the triangle was under 100 pixels across and only e2 was named.
    std::ifstream lesson(std::string(SATVIZ_SOURCE_DIR) + "/tutorials/12-speed.md");
    REQUIRE(lesson);
    const std::string text((std::istreambuf_iterator<char>(lesson)), std::istreambuf_iterator<char>());
    REQUIRE(text.find("figures/many_sides.png") != std::string::npos);
    REQUIRE(text.find("triangle's edge 2") != std::string::npos);
    REQUIRE(text.find("edges 0 and 1") != std::string::npos);
    const Scene scene = painter_test::LessonScene("many_sides");
    FigureSetup setup = SetUpFigure(scene, FigureOptions{});
    REQUIRE(setup.Ok());
    const RecordingCanvas canvas = painter_test::PaintStep(scene, setup, setup.figure.step);
    std::set<std::string> named;
    for (const DrawCommand* c : canvas.InGroup("labels"))
    {
        if (c->kind == DrawCommand::Kind::Text)
        {
            named.insert(c->text);
        }
    }
    for (const char* face : {"e0", "e1", "e2"})
    {
        INFO(face);
        CHECK(named.count(face) == 1);
    }
    // The triangle, the smaller body, at least 150 pixels across on the screen.
    const Body& triangle = scene.bodies[1];
    REQUIRE(triangle.name == "triangle");
    float lo = INFINITY, hi = -INFINITY;
    for (const Vec2& v : triangle.shape.polygon.Vertices())
    {
        const float x = ToScreen(setup.figure.view, TransformPoint(triangle.Xf(), v)).x;
        lo = std::min(lo, x);
        hi = std::max(hi, x);
    }
    CHECK(hi - lo >= 150.0f);
}

TEST_CASE("A corner crowded by a face's name and a contact's still has its number, half way between them",
          "[labels]")
{
    // Each of these corners lost its number to the labels around it, though there was room beside it: B's corner
    // 3 by "e3" (overlapping_boxes), A's corner 2 under the ghost's "e2" (l13_sweep), B's corner 0 by "incident
    // edge" (l05_box_in_box step 3), the triangle's corner 1 that the caption names, by "c2" (containment).
    // l13_sweep draws its contact's dot on that corner, which then has no number (lesson 1): it is drawn here
    // without its contacts layer.
    struct Corner
    {
        const char* stem;
        int step; // from 1; 0: the figure's own step
        int body; // 0: A, 1: B of the pair
        int vertex;
        LayerMask without = 0; // layers of the figure left off
    };
    for (const Corner& corner : {Corner{"overlapping_boxes", 0, 1, 3}, Corner{"l13_sweep", 0, 0, 2, kLayerContacts},
                                 Corner{"l05_box_in_box", 3, 1, 0}, Corner{"containment", 0, 1, 1}})
    {
        const Scene scene = painter_test::LessonScene(corner.stem);
        FigureSetup setup = SetUpFigure(scene, {});
        REQUIRE(setup.Ok());
        const int step = corner.step > 0 ? corner.step - 1 : setup.figure.step;
        const RecordingCanvas canvas =
            painter_test::Paint(scene, setup, step, setup.figure.layers & ~corner.without);
        const Body& body = scene.bodies[static_cast<size_t>(corner.body == 0 ? setup.study.bodyA : setup.study.bodyB)];
        REQUIRE(body.shape.type == ShapeType::Polygon);
        const ScreenPoint at =
            ToScreen(setup.figure.view, TransformPoint(body.Xf(), body.shape.polygon.Vertices()[corner.vertex]));
        const Color ink = corner.body == 0 ? palette::kShapeA : palette::kShapeBInk;
        RecordingCanvas measure;
        bool numbered = false;
        for (const DrawCommand* c : canvas.InGroup("labels"))
        {
            if (c->kind != DrawCommand::Kind::Text || c->text != std::to_string(corner.vertex) ||
                (c->color >> 8) != (ink >> 8))
            {
                continue;
            }
            const ScreenPoint size = measure.MeasureText(c->text, c->style);
            const ScreenPoint middle{c->points[0].x + 0.5f * size.x, c->points[0].y + 0.5f * size.y};
            numbered = numbered || std::hypot(middle.x - at.x, middle.y - at.y) < 40.0f;
        }
        INFO(corner.stem << " step " << step + 1 << ": " << body.name << "'s corner " << corner.vertex << " at (" << at.x
                         << ", " << at.y << ")");
        CHECK(numbered);
    }
}

TEST_CASE("On the app's narrowest canvas a band's size is written out of the bodies where there is room", "[labels]")
{
    // overlapping_boxes beside the lesson column: the bars of axis 1 stand at the picture's left edge, with no room
    // beyond them, and "overlap 0.525" went inside A beside them, over its outline's guides. Below the bars, out of
    // both boxes, there is room.
    const Scene scene = painter_test::LessonScene("overlapping_boxes");
    int drawn = 0;
    for (const auto& [width, height] : {std::pair{460, 758}, std::pair{360, 600}})
    {
        FigureOptions options;
        options.width = width;
        options.height = height;
        FigureSetup setup = SetUpFigure(scene, options);
        REQUIRE(setup.Ok());
        for (int k = 0; k < FigureStepCount(scene, setup); ++k)
        {
            const RecordingCanvas canvas = painter_test::PaintStep(scene, setup, k);
            INFO("step " << k + 1 << " at " << width << " x " << height);
            const std::vector<std::string> problems = BandSizesInBodies(canvas, scene, setup.study, setup.figure.view);
            for (const std::string& problem : problems)
            {
                UNSCOPED_INFO(problem);
            }
            CHECK(problems.empty());
            ++drawn;
        }
    }
    CHECK(drawn >= 8);
}

TEST_CASE("In every pair scene of the course, at the app's canvases too, no corner's number reads as a contact's",
          "[labels]")
{
    // The exercises' and examples' scenes as well as the figures': a vertex number no nearer its corner than a
    // contact point's dot reads as that dot's name (ex05_inside's "3" half way from its corner to c1).
    int drawn = 0;
    std::vector<std::string> failing;
    for (const std::string& file : testing::TutorialSceneFiles(true))
    {
        const Scene scene = painter_test::LoadSimulated(file);
        if (scene.bodies.size() < 2)
        {
            continue;
        }
        for (const auto& [width, height] : {std::pair{0, 0}, std::pair{460, 758}, std::pair{360, 600}})
        {
            FigureOptions options;
            options.width = width;
            options.height = height;
            FigureSetup setup = SetUpFigure(scene, options);
            if (!setup.Ok() || setup.figure.kind != FigureKind::Pair)
            {
                continue;
            }
            const int steps = FigureStepCount(scene, setup);
            const RecordingCanvas canvas = painter_test::PaintStep(scene, setup, steps - 1);
            ++drawn;
            for (const std::string& p : LabelsNearerAnotherMark(canvas, scene, setup.study, setup.figure.view))
            {
                if (p.find("than its corner") != std::string::npos)
                {
                    failing.push_back(file.substr(file.rfind('/') + 1) + " at " + std::to_string(width) + " x " +
                                      std::to_string(height) + ": " + p);
                }
            }
        }
    }
    CHECK(drawn > 100);
    std::string all;
    for (const std::string& f : failing)
    {
        all += f + "\n";
    }
    INFO(all);
    CHECK(failing.empty());
}

TEST_CASE("In every sweep of the course, at the app's canvases too, no edge's name sits inside a ghost", "[labels]")
{
    // A face's name inside the moving body drawn at the time of impact (or at the figure's time), led to a face
    // outside it, reads as the ghost's: ex14_wall's "e3" inside the puck beside the lesson column (460 x 758).
    int drawn = 0;
    std::vector<std::string> failing;
    for (const std::string& file : testing::TutorialSceneFiles(true))
    {
        const Scene scene = painter_test::LoadSimulated(file);
        if (scene.bodies.size() < 2)
        {
            continue;
        }
        for (const auto& [width, height] : {std::pair{0, 0}, std::pair{460, 758}, std::pair{360, 600}})
        {
            FigureOptions options;
            options.width = width;
            options.height = height;
            FigureSetup setup = SetUpFigure(scene, options);
            if (!setup.Ok() || setup.figure.kind != FigureKind::Pair || !setup.study.sweep)
            {
                continue;
            }
            for (int k = 0; k < FigureStepCount(scene, setup); ++k)
            {
                const RecordingCanvas canvas = painter_test::PaintStep(scene, setup, k);
                ++drawn;
                for (const std::string& p : EdgeNamesInGhosts(canvas))
                {
                    failing.push_back(file.substr(file.rfind('/') + 1) + " step " + std::to_string(k + 1) + " at " +
                                      std::to_string(width) + " x " + std::to_string(height) + ": " + p);
                }
            }
        }
    }
    CHECK(drawn > 100);
    std::string all;
    for (const std::string& f : failing)
    {
        all += f + "\n";
    }
    INFO(all);
    CHECK(failing.empty());
}
