// SPDX-License-Identifier: MIT
// The disc-cast figure: a thick bullet, a disc whose centre moves along a segment, and where it first touches a
// shape: where its centre meets the shape's outline pushed out by the radius.
#include "concave_views.h"

#include <satviz/disc_cast.h>
#include <satviz/render/describe.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace satviz
{

namespace
{

constexpr float kMargin = 36.0f; // room around the drawing, for the labels
constexpr double kTau = 6.283185307179586;

// A point as the figure writes it: "(-0.661, 0.750)".
std::string Point(Vec2 p)
{
    return FormatPair(p.x, p.y);
}

// A vector as Point prints it, read back: the numbers a reader works with.
Vec2 Printed(Vec2 p)
{
    return {std::stod(FormatNumber(p.x)), std::stod(FormatNumber(p.y))};
}

// x rounded to the given decimals, and written with them: the normal of a check that three decimals would round
// away from the centre it gives.
double Rounded(double x, int decimals)
{
    const double scale = std::pow(10.0, decimals);
    return std::round(x * scale) / scale;
}

std::string Fixed(double x, int decimals)
{
    char buffer[48];
    std::snprintf(buffer, sizeof(buffer), "%.*f", decimals, x);
    return buffer;
}

// A piece of a concave body named so that a reader finds it in the figure, which draws the seams but numbers no
// piece: by where its middle lies in the body's box ("cup's bottom piece"), when no other piece lies there too;
// else by its corners.
std::string PieceWhere(const Body& body, int piece)
{
    const Transform xf = body.Xf();
    const auto middleOf = [&](const ConcavePart& part) {
        Vec2 sum{};
        for (const Vec2& v : part.shape.polygon.Vertices())
        {
            sum = sum + TransformPoint(xf, v);
        }
        return (1.0 / part.shape.polygon.Count()) * sum;
    };
    Vec2 low{1e300, 1e300};
    Vec2 high{-1e300, -1e300};
    for (const ConcavePart& part : body.concave.parts)
    {
        for (const Vec2& local : part.shape.polygon.Vertices())
        {
            const Vec2 v = TransformPoint(xf, local);
            low = {std::min(low.x, v.x), std::min(low.y, v.y)};
            high = {std::max(high.x, v.x), std::max(high.y, v.y)};
        }
    }
    // The box in thirds each way: "bottom-left", "top", "right", "middle".
    const auto region = [&](Vec2 m) {
        const auto third = [](double x, double lo, double hi) {
            const double f = hi > lo ? (x - lo) / (hi - lo) : 0.5;
            return f < 1.0 / 3.0 ? 0 : f > 2.0 / 3.0 ? 2 : 1;
        };
        const char* rows[] = {"bottom", "", "top"};
        const char* columns[] = {"left", "", "right"};
        const std::string row = rows[third(m.y, low.y, high.y)];
        const std::string column = columns[third(m.x, low.x, high.x)];
        if (row.empty() && column.empty())
        {
            return std::string("middle");
        }
        return row.empty() || column.empty() ? row + column : row + "-" + column;
    };
    const std::vector<ConcavePart>& parts = body.concave.parts;
    const std::string where = region(middleOf(parts[static_cast<size_t>(piece)]));
    bool alone = true;
    for (size_t i = 0; i < parts.size(); ++i)
    {
        alone = alone && (static_cast<int>(i) == piece || region(middleOf(parts[i])) != where);
    }
    if (alone)
    {
        return body.name + "'s " + where + " piece";
    }
    const Polygon& polygon = parts[static_cast<size_t>(piece)].shape.polygon;
    std::string corners;
    for (int i = 0; i < polygon.Count(); ++i)
    {
        corners += (i == 0                     ? ""
                    : i + 1 == polygon.Count() ? " and "
                                               : ", ") +
                   Point(TransformPoint(xf, polygon.Vertices()[i]));
    }
    return "the piece of " + body.name + " with corners " + corners;
}

// The target's outline in the world, counter-clockwise: a concave body's as written, a polygon's vertices; empty for
// a circle.
std::vector<Vec2> WorldRing(const Body& body)
{
    std::vector<Vec2> ring = BodyOutline(body);
    const Transform xf = body.Xf();
    double area2 = 0.0;
    for (size_t i = 0; i < ring.size(); ++i)
    {
        area2 += Cross(ring[i], ring[(i + 1) % ring.size()]);
    }
    for (Vec2& v : ring)
    {
        v = TransformPoint(xf, v);
    }
    if (area2 < 0.0)
    {
        std::reverse(ring.begin(), ring.end());
    }
    return ring;
}

// The outline pushed out by r: each edge moved out along its normal, an arc of radius r around each convex corner,
// and at each reflex corner the two moved edges cut where they cross. World points, one closed chain.
std::vector<Vec2> PushedOut(const std::vector<Vec2>& ring, double r)
{
    const size_t n = ring.size();
    std::vector<Vec2> normals(n);
    for (size_t i = 0; i < n; ++i)
    {
        const Vec2 e = Normalize(ring[(i + 1) % n] - ring[i]);
        normals[i] = {e.y, -e.x};
    }
    std::vector<Vec2> chain;
    for (size_t i = 0; i < n; ++i)
    {
        // Corner i joins edge i - 1 (normal m) and edge i (normal k).
        const Vec2 m = normals[(i + n - 1) % n];
        const Vec2 k = normals[i];
        const Vec2 v = ring[i];
        if (Cross(m, k) >= 0.0)
        {
            const double a0 = std::atan2(m.y, m.x);
            double a1 = std::atan2(k.y, k.x);
            while (a1 < a0)
            {
                a1 += kTau;
            }
            const int steps = std::max(1, static_cast<int>(std::ceil((a1 - a0) / 0.1)));
            for (int s = 0; s <= steps; ++s)
            {
                const double a = a0 + (a1 - a0) * s / steps;
                chain.push_back(v + r * Vec2{std::cos(a), std::sin(a)});
            }
        }
        else
        {
            // The moved edges meet at v + r (m + k) / (1 + m.k), the point r from both lines.
            chain.push_back(v + (r / (1.0 + Dot(m, k))) * (m + k));
        }
    }
    return chain;
}

} // namespace

std::string DescribeDiscCast(const Body& target, const Body& disc, const DiscHit& hit)
{
    const double r = disc.shape.circle.radius;
    const Vec2 p1 = TransformPoint(disc.Xf(), disc.shape.circle.center);
    const Vec2 p2 = p1 + disc.velocity;
    std::string text = "A disc of radius " + FormatNumber(r) + " (" + disc.name + ") moves its centre from " +
                       Point(p1) + " to " + Point(p2) + ". ";
    if (hit.startsInside)
    {
        return text + "It overlaps " + target.name + " at the start already: t = 0, and the way out is along " +
               Point(hit.normal) + ".";
    }
    if (!hit.hit)
    {
        return text + "Its centre's path never enters " + target.name +
               "'s outline pushed out by the radius (dashed), so the disc passes " + target.name +
               " without touching it.";
    }
    const std::string piece = hit.piece >= 0 ? ", on " + PieceWhere(target, hit.piece) : "";
    // The check a reader makes, from the numbers as printed. Where the normal's three decimals round the sum away
    // from the centre printed, the check writes the normal with as many more decimals as it takes to agree.
    const Vec2 point = Printed(hit.point);
    const double printedR = std::stod(FormatNumber(r));
    std::string normalInCheck = Point(hit.normal);
    std::string check = Point(point + printedR * Printed(hit.normal));
    for (int decimals = 4; check != Point(hit.center) && decimals <= 6; ++decimals)
    {
        const Vec2 finer{Rounded(hit.normal.x, decimals), Rounded(hit.normal.y, decimals)};
        normalInCheck = "(" + Fixed(finer.x, decimals) + ", " + Fixed(finer.y, decimals) + ")";
        check = Point(point + printedR * finer);
    }
    if (check != Point(hit.center))
    {
        normalInCheck = Point(hit.normal);
        check = Point(point + printedR * Printed(hit.normal)) + ", the centre but for rounding";
    }
    return text + "It first touches " + target.name + " when its centre meets " + target.name +
           "'s outline pushed out by the radius (dashed), at t = " + FormatNumber(hit.fraction) +
           " of the way: centre " + Point(hit.center) + ". The contact point is " + Point(hit.point) + piece +
           ", where the outward normal is " + Point(hit.normal) + ": the centre lies one radius out along it, " +
           Point(hit.point) + " + " + FormatNumber(r) + " \xC3\x97 " + normalInCheck + " = " + check + ".";
}

DiscHit CastFigureDisc(const Body& target, const Body& disc)
{
    const Vec2 p1 = TransformPoint(disc.Xf(), disc.shape.circle.center);
    const Vec2 p2 = p1 + disc.velocity;
    return target.IsConcave() ? CastDisc(target.concave, target.Xf(), p1, p2, disc.shape.circle.radius)
                              : CastDisc(target.shape, target.Xf(), p1, p2, disc.shape.circle.radius);
}

void PaintDiscCast(Canvas& surface, const Scene& scene, int targetIndex, int discIndex, const Figure& figure)
{
    // Every line is drawn through the watch, so that the labels keep off it.
    LabelPlacer labels(surface, figure);
    LineWatch canvas(surface, labels);
    const Body& target = scene.bodies[static_cast<size_t>(targetIndex)];
    const Body& disc = scene.bodies[static_cast<size_t>(discIndex)];
    const float width = static_cast<float>(figure.view.width);
    const float height = static_cast<float>(figure.view.height);
    const double r = disc.shape.circle.radius;
    const Vec2 p1 = TransformPoint(disc.Xf(), disc.shape.circle.center);
    const Vec2 p2 = p1 + disc.velocity;
    const DiscHit hit = CastFigureDisc(target, disc);

    const float top = DrawBackgroundAndCaption(canvas, labels, figure, DescribeDiscCast(target, disc, hit));

    // The target, the pushed-out outline and both discs in the frame.
    const std::vector<Vec2> ring = WorldRing(target);
    std::vector<Vec2> pushed;
    if (ring.empty())
    {
        const Vec2 c = TransformPoint(target.Xf(), target.shape.circle.center);
        const double reach = target.shape.circle.radius + r;
        for (int s = 0; s < 96; ++s)
        {
            const double a = kTau * s / 96;
            pushed.push_back(c + reach * Vec2{std::cos(a), std::sin(a)});
        }
    }
    else
    {
        pushed = PushedOut(ring, r);
    }
    Vec2 low{std::min(p1.x, p2.x) - r, std::min(p1.y, p2.y) - r};
    Vec2 high{std::max(p1.x, p2.x) + r, std::max(p1.y, p2.y) + r};
    for (const Vec2& p : pushed)
    {
        low = {std::min(low.x, p.x), std::min(low.y, p.y)};
        high = {std::max(high.x, p.x), std::max(high.y, p.y)};
    }
    const ScreenRect rect{0.0f, top, width, height};
    const View view = figure.framesItself
                          ? FramePanel(rect, low, high, figure.view.width, figure.view.height, kMargin).view
                          : figure.view;
    const float radius = ToPixels(view, r);

    canvas.BeginGroup("target");
    const Transform xf = target.Xf();
    if (target.IsConcave())
    {
        for (const ConcavePart& part : target.concave.parts)
        {
            std::vector<ScreenPoint> points;
            for (const Vec2& v : part.shape.polygon.Vertices())
            {
                points.push_back(ToScreen(view, TransformPoint(xf, v)));
            }
            canvas.FillConvex(points.data(), static_cast<int>(points.size()), WithAlpha(palette::kShapeA, 0.22f));
        }
        std::set<std::pair<std::pair<double, double>, std::pair<double, double>>> drawn;
        for (const ConcavePart& part : target.concave.parts)
        {
            const Vec2Span<double> v = part.shape.polygon.Vertices();
            for (int e = 0; e < v.count; ++e)
            {
                const Vec2 a = v[e];
                const Vec2 b = v[(e + 1) % v.count];
                if (!part.internal[static_cast<size_t>(e)] || drawn.count({{b.x, b.y}, {a.x, a.y}}) > 0)
                {
                    continue;
                }
                drawn.insert({{a.x, a.y}, {b.x, b.y}});
                DashedSegment(canvas, ToScreen(view, TransformPoint(xf, a)), ToScreen(view, TransformPoint(xf, b)),
                              WithAlpha(palette::kShapeA, 0.6f), 1.0f, rect, 6.0f, 6.0f);
            }
        }
    }
    if (!ring.empty())
    {
        std::vector<ScreenPoint> outline;
        for (const Vec2& v : ring)
        {
            outline.push_back(ToScreen(view, v));
        }
        if (!target.IsConcave())
        {
            canvas.FillConvex(outline.data(), static_cast<int>(outline.size()), WithAlpha(palette::kShapeA, 0.22f));
        }
        canvas.Polyline(outline.data(), static_cast<int>(outline.size()), true, palette::kShapeA, 2.0f);
        // A leader line along or across the target's outline reads as naming an edge of it.
        for (size_t i = 0; i < outline.size(); ++i)
        {
            labels.ReserveEdge(outline[i], outline[(i + 1) % outline.size()]);
        }
    }
    else
    {
        const ScreenPoint c = ToScreen(view, TransformPoint(xf, target.shape.circle.center));
        canvas.FillCircle(c, ToPixels(view, target.shape.circle.radius), WithAlpha(palette::kShapeA, 0.22f));
        canvas.Circle(c, ToPixels(view, target.shape.circle.radius), palette::kShapeA, 2.0f);
    }
    canvas.BeginGroup("pushed out");
    std::vector<ScreenPoint> dashed;
    for (const Vec2& p : pushed)
    {
        dashed.push_back(ToScreen(view, p));
    }
    DashedOutline(canvas, dashed, palette::kMuted, 1.2f, rect);

    // The disc at the hit is drawn before the centre's path: the path runs through it, and its arrow head (where the
    // end lies about a radius from the hit, circle_and_polygon_cast's) stays in sight over the disc's fill and rim.
    if (hit.hit)
    {
        canvas.BeginGroup("hit");
        canvas.FillCircle(ToScreen(view, hit.center), radius, WithAlpha(palette::kShapeB, 0.35f));
        canvas.Circle(ToScreen(view, hit.center), radius, palette::kShapeBInk, 2.0f);
    }
    canvas.BeginGroup("path");
    const ScreenPoint s1 = ToScreen(view, p1);
    const ScreenPoint s2 = ToScreen(view, p2);
    const Vec2 along = Normalize(p2 - p1);
    const Vec2 side{-along.y, along.x};
    for (const double sign : {-1.0, 1.0})
    {
        canvas.Segment(ToScreen(view, p1 + sign * r * side), ToScreen(view, p2 + sign * r * side),
                       WithAlpha(palette::kShapeB, 0.45f), 1.0f);
    }
    labels.ReserveLine(s1, s2, 1.5f);
    // The normal at the hit runs from the contact point through the centre, which lies on the path: nearly along
    // the path (a steep path onto a flat face, disc_cast_cup's) the two black lines would merge into one. The path
    // then leaves off over the disc at the hit, as far from its centre as the normal reaches, either side.
    const float gap = hit.hit && std::fabs(Dot(hit.normal, along)) > std::cos(0.5) ? radius + 26.0f : 0.0f;
    const ScreenPoint sc = hit.hit ? ToScreen(view, hit.center) : s1;
    const float run = std::hypot(s2.x - s1.x, s2.y - s1.y);
    const float at = ((sc.x - s1.x) * (s2.x - s1.x) + (sc.y - s1.y) * (s2.y - s1.y)) / std::max(run, 1e-3f);
    ScreenRect head{};
    if (gap > 0.0f && at - gap > 0.0f && at + gap + 12.0f < run)
    {
        const auto point = [&](float d) {
            return ScreenPoint{s1.x + (s2.x - s1.x) * d / run, s1.y + (s2.y - s1.y) * d / run};
        };
        canvas.Segment(s1, point(at - gap), palette::kInk, 1.5f);
        head = Arrow(canvas, point(at + gap), s2, palette::kInk, 1.5f);
    }
    else
    {
        head = Arrow(canvas, s1, s2, palette::kInk, 1.5f);
    }
    labels.Reserve(head);
    canvas.Circle(s1, radius, palette::kShapeBInk, 2.0f);
    canvas.FillCircle(s1, 3.0f, palette::kInk);
    DashedOutline(canvas, ShapeOutline(view, MakeShape(Circle{p2, r}), MakeTransform(Vec2{}, 0.0)),
                  WithAlpha(palette::kShapeBInk, 0.6f), 1.2f, rect);
    // Each beside its disc and out of the target, where it would read as naming a corner of it
    // (circle_and_polygon_cast's "end", whose disc overlaps the pentagon).
    std::vector<std::vector<ScreenPoint>> targetParts;
    for (const ConcavePart& part : target.concave.parts)
    {
        std::vector<ScreenPoint> outline;
        for (const Vec2& v : part.shape.polygon.Vertices())
        {
            outline.push_back(ToScreen(view, TransformPoint(xf, v)));
        }
        targetParts.push_back(std::move(outline));
    }
    if (target.concave.parts.empty())
    {
        targetParts.push_back(ShapeOutline(view, target.shape, xf));
    }
    labels.Place(s1, "start", TextStyle::Label, palette::kShapeBInk, s1.x - s2.x, s1.y - s2.y, radius + 6.0f,
                 LabelRank::Note);
    for (const std::vector<ScreenPoint>& part : targetParts)
    {
        labels.KeepOutOf(part);
    }
    // The end's disc may overlap the target: its name goes on the side away from the target's middle, and out
    // of the disc at the hit too, whose name it would read as.
    ScreenPoint targetMiddle{};
    for (const std::vector<ScreenPoint>& part : targetParts)
    {
        for (const ScreenPoint& q : part)
        {
            targetMiddle = {targetMiddle.x + q.x / static_cast<float>(part.size() * targetParts.size()),
                            targetMiddle.y + q.y / static_cast<float>(part.size() * targetParts.size())};
        }
    }
    labels.Place(s2, "end", TextStyle::Label, palette::kShapeBInk, s2.x - targetMiddle.x, s2.y - targetMiddle.y,
                 radius + 6.0f, LabelRank::Note);
    for (const std::vector<ScreenPoint>& part : targetParts)
    {
        labels.KeepOutOf(part);
    }
    if (hit.hit)
    {
        labels.KeepOutOf(ShapeOutline(view, MakeShape(Circle{hit.center, r}), MakeTransform(Vec2{}, 0.0)));
    }
    // The target's name inside it: at its largest piece's middle (a concave outline's own middle may lie outside).
    Vec2 middle = TransformPoint(xf, target.shape.type == ShapeType::Circle ? target.shape.circle.center : Vec2{});
    if (target.shape.type == ShapeType::Polygon)
    {
        const Polygon* largest = &target.shape.polygon;
        double most = -1.0;
        for (const ConcavePart& part : target.concave.parts)
        {
            const Polygon& polygon = part.shape.polygon;
            double area2 = 0.0;
            for (int i = 0; i < polygon.Count(); ++i)
            {
                area2 += Cross(polygon.Vertices()[i], polygon.Vertices()[(i + 1) % polygon.Count()]);
            }
            if (area2 > most)
            {
                most = area2;
                largest = &polygon;
            }
        }
        Vec2 sum{};
        for (const Vec2& v : largest->Vertices())
        {
            sum = sum + v;
        }
        middle = TransformPoint(xf, (1.0 / largest->Count()) * sum);
    }
    labels.Place(ToScreen(view, middle), target.name, TextStyle::Heading, palette::kShapeA, 0.0f, 0.0f, 0.0f,
                 LabelRank::Name);

    if (hit.hit)
    {
        canvas.BeginGroup("hit");
        const ScreenPoint c = ToScreen(view, hit.center);
        const ScreenPoint p = ToScreen(view, hit.point);
        // The normal from the contact point through the centre and beyond: the centre lies one radius along it,
        // its dot drawn over the arrow. Black, as a face's normal is: vermillion arrows are MTVs.
        const ScreenPoint tip = ToScreen(view, hit.point + (r + 22.0 / view.zoom) * hit.normal);
        labels.Reserve(Arrow(canvas, p, tip, palette::kInk, 2.0f));
        canvas.FillCircle(c, 3.0f, palette::kInk);
        canvas.FillCircle(p, 4.5f, palette::kResult);
        labels.Reserve({p.x - 5.0f, p.y - 5.0f, p.x + 5.0f, p.y + 5.0f});
        labels.Reserve({c.x - 4.0f, c.y - 4.0f, c.x + 4.0f, c.y + 4.0f});
        // On the side of the path with the more room before the target (disc_cast_cup's open middle, not the arm
        // beside the disc).
        const auto room = [&](Vec2 d) {
            double nearest = 1e300;
            for (size_t i = 0; i < ring.size(); ++i)
            {
                const Vec2 a = ring[i];
                const Vec2 e = ring[(i + 1) % ring.size()] - a;
                const double den = Cross(d, e);
                if (std::fabs(den) < 1e-12)
                {
                    continue;
                }
                const double t = Cross(a - hit.center, e) / den;
                const double u = Cross(a - hit.center, d) / den;
                if (t > 0.0 && u >= 0.0 && u <= 1.0)
                {
                    nearest = std::min(nearest, t);
                }
            }
            return nearest;
        };
        const Vec2 away = room(-1.0 * side) > room(side) ? -1.0 * side : side;
        labels.Place(c, "t = " + FormatNumber(hit.fraction), TextStyle::Label, palette::kInk,
                     static_cast<float>(away.x), static_cast<float>(-away.y), radius + 6.0f, LabelRank::Verdict);
        // The time names the disc where it stops, not the target: it keeps out of the target's pieces (a cup's arm
        // beside the disc), where it would read as a note on that piece, and its leader line off their edges.
        for (const ConcavePart& part : target.concave.parts)
        {
            std::vector<ScreenPoint> outline;
            for (const Vec2& v : part.shape.polygon.Vertices())
            {
                outline.push_back(ToScreen(view, TransformPoint(xf, v)));
            }
            labels.KeepOutOf(std::move(outline));
        }
        labels.LeadsOffEdges();
        labels.Place(p, "contact", TextStyle::Label, palette::kResult, static_cast<float>(-hit.normal.y),
                     static_cast<float>(-hit.normal.x), 8.0f, LabelRank::Verdict);
        // Out of the discs at the hit and at the end, whose names it would read as.
        for (const Vec2& disc : {hit.center, p2})
        {
            labels.KeepOutOf(ShapeOutline(view, MakeShape(Circle{disc, r}), MakeTransform(Vec2{}, 0.0)));
        }
    }
    labels.Flush(palette::kBackground);
}

} // namespace satviz
