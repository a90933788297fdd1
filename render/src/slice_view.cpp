// SPDX-License-Identifier: MIT
// The slice figure: a body before and after a cut along a segment, at one scale, with the points where the cut
// crosses the outline and the parts' areas.
#include "concave_views.h"

#include <satviz/render/describe.h>
#include <satviz/render/figure.h>
#include <satviz/render/recording_canvas.h>
#include <satviz/slice.h>

#include <algorithm>
#include <cmath>

namespace satviz
{

namespace
{

constexpr float kMargin = 34.0f;       // room around the drawing inside a panel, for the crossings' coordinates
constexpr float kApart = 10.0f;        // pixels each part is moved away from the cut in the after panel
constexpr float kRoom = 6.0f;          // pixels a part's area keeps from the part's outline to be written inside it

double Area(const std::vector<Vec2>& ring)
{
    double sum = 0.0;
    for (size_t i = 0; i < ring.size(); ++i)
    {
        sum += Cross(ring[i], ring[(i + 1) % ring.size()]);
    }
    return 0.5 * std::fabs(sum);
}

Vec2 Centroid(const std::vector<Vec2>& ring)
{
    double area2 = 0.0;
    Vec2 sum{};
    for (size_t i = 0; i < ring.size(); ++i)
    {
        const Vec2 a = ring[i];
        const Vec2 b = ring[(i + 1) % ring.size()];
        const double w = Cross(a, b);
        area2 += w;
        sum = sum + w * (a + b);
    }
    return (1.0 / (3.0 * area2)) * sum;
}

// Whether p lies inside the ring (crossing count).
bool InRing(const std::vector<Vec2>& ring, Vec2 p)
{
    bool inside = false;
    for (size_t i = 0, j = ring.size() - 1; i < ring.size(); j = i++)
    {
        if ((ring[i].y > p.y) != (ring[j].y > p.y) &&
            p.x < ring[j].x + (p.y - ring[j].y) * (ring[i].x - ring[j].x) / (ring[i].y - ring[j].y))
        {
            inside = !inside;
        }
    }
    return inside;
}

// A coordinate beside another: an exact 0 as 0.00, like its neighbour.
std::string Coordinate(double value)
{
    return value == 0.0 ? "0.00" : FormatNumber(value);
}

std::string Point(Vec2 p)
{
    return "(" + Coordinate(p.x) + ", " + Coordinate(p.y) + ")";
}

std::string List(const std::vector<std::string>& items)
{
    std::string text;
    for (size_t i = 0; i < items.size(); ++i)
    {
        text += (i == 0 ? "" : (i + 1 == items.size() ? " and " : ", ")) + items[i];
    }
    return text;
}

// The body's outline in the world.
std::vector<Vec2> WorldOutline(const Body& body)
{
    std::vector<Vec2> ring = BodyOutline(body);
    const Transform xf = body.Xf();
    for (Vec2& v : ring)
    {
        v = TransformPoint(xf, v);
    }
    return ring;
}

// Pieces of a part as Decompose gives them, placed in the world (identity transform) moved by `shift`.
void DrawPart(Canvas& canvas, const View& view, const std::vector<ConvexPiece>& pieces, Color color, Vec2 shift,
              const ScreenRect& bounds)
{
    for (const ConvexPiece& piece : pieces)
    {
        std::vector<ScreenPoint> points;
        for (const Vec2& v : piece.polygon.Vertices())
        {
            points.push_back(ToScreen(view, v + shift));
        }
        canvas.FillConvex(points.data(), static_cast<int>(points.size()), WithAlpha(color, 0.45f));
    }
    for (const ConvexPiece& piece : pieces)
    {
        const Vec2Span<double> v = piece.polygon.Vertices();
        for (int e = 0; e < v.count; ++e)
        {
            const ScreenPoint a = ToScreen(view, v[e] + shift);
            const ScreenPoint b = ToScreen(view, v[(e + 1) % v.count] + shift);
            if (!piece.internal[static_cast<size_t>(e)])
            {
                canvas.Segment(a, b, palette::kInk, 2.0f);
            }
            else if (piece.source[static_cast<size_t>(e)] < piece.source[static_cast<size_t>((e + 1) % v.count)])
            {
                DashedSegment(canvas, a, b, palette::kInk, 1.5f, bounds, 6.0f, 4.0f);
            }
        }
    }
}

} // namespace

std::vector<Vec2> CutCrossings(const std::vector<Vec2>& outline, Vec2 a, Vec2 b)
{
    std::vector<std::pair<double, Vec2>> found;
    const Vec2 d = b - a;
    for (size_t i = 0; i < outline.size(); ++i)
    {
        const Vec2 p = outline[i];
        const Vec2 q = outline[(i + 1) % outline.size()];
        const Vec2 e = q - p;
        const double denominator = Cross(d, e);
        if (denominator == 0.0)
        {
            continue; // parallel: an edge along the cut is crossed at its ends, which the neighbours report
        }
        const double t = Cross(p - a, e) / denominator; // along the cut
        const double u = Cross(p - a, d) / denominator; // along the edge
        if (t >= 0.0 && t <= 1.0 && u >= 0.0 && u < 1.0)
        {
            found.push_back({t, a + t * d});
        }
    }
    std::sort(found.begin(), found.end(), [](const auto& x, const auto& y) { return x.first < y.first; });
    std::vector<Vec2> points;
    for (const auto& [t, p] : found)
    {
        if (points.empty() || Length(p - points.back()) > 1e-9 * (1.0 + Length(p)))
        {
            points.push_back(p);
        }
    }
    return points;
}

std::string DescribeSlice(const Body& body, Vec2 a, Vec2 b, const std::vector<std::vector<Vec2>>& parts,
                          const std::vector<Decomposition>& pieces)
{
    const std::vector<Vec2> outline = WorldOutline(body);
    const std::vector<Vec2> crossings = CutCrossings(outline, a, b);
    std::string text = "The cut runs from " + Point(a) + " to " + Point(b);
    std::vector<std::string> at;
    for (const Vec2& p : crossings)
    {
        at.push_back(Point(p));
    }
    if (parts.size() < 2)
    {
        return text +
               (crossings.empty() ? " and never meets " + body.name + "'s outline"
                                  : " and meets " + body.name + "'s outline at " + List(at)) +
               ", but does not run through " + body.name +
               " from one side to another: a segment that stops inside is no cut, and " + body.name +
               " stays whole, area " + FormatNumber(Area(outline)) + ".";
    }
    std::vector<std::string> areas;
    std::vector<std::string> counts;
    double total = 0.0;
    for (size_t i = 0; i < parts.size(); ++i)
    {
        const double area = Area(parts[i]);
        total += area;
        areas.push_back(FormatNumber(area));
        counts.push_back(std::to_string(pieces[i].pieces.size()));
    }
    return text + ". It crosses " + body.name + "'s outline at " + List(at) + " and splits it into " +
           std::to_string(parts.size()) + " parts of areas " + List(areas) + ", which sum to " + FormatNumber(total) +
           ", " + body.name + "'s area " + FormatNumber(Area(outline)) +
           " (the parts are drawn a little apart). Each part is a polygon of its own, cut again into convex pieces: " +
           List(counts) + ".";
}

namespace
{

// The slice figure's two panels below its caption band (whose bottom is `top`), and the one zoom at which both
// hold the body and the cut.
struct SliceLayout
{
    PanelHeader headers[2]; // the before panel's and the after panel's
    ScreenRect rects[2];
    Vec2 low, high; // the world box of the body's outline and the cut
    double zoom = 1.0;
};

// The subtitles of the before and after panels.
std::string BeforeSubtitle(const Body& body)
{
    return body.name + ", and the cut";
}
constexpr const char* kAfterSubtitle = "each part cut into convex pieces";

SliceLayout LayOutSlice(const Body& body, const std::vector<Vec2>& outline, Vec2 a, Vec2 b, float top, float width,
                        float height)
{
    SliceLayout layout;
    // Both panels start below the taller header: a narrow canvas wraps a subtitle to more lines.
    layout.headers[0] = LayOutPanelHeader(BeforeSubtitle(body), 0.5f * width);
    layout.headers[1] = LayOutPanelHeader(kAfterSubtitle, 0.5f * width);
    const float header = std::max(layout.headers[0].height, layout.headers[1].height);
    layout.low = {std::min(a.x, b.x), std::min(a.y, b.y)};
    layout.high = {std::max(a.x, b.x), std::max(a.y, b.y)};
    for (const Vec2& p : outline)
    {
        layout.low = {std::min(layout.low.x, p.x), std::min(layout.low.y, p.y)};
        layout.high = {std::max(layout.high.x, p.x), std::max(layout.high.y, p.y)};
    }
    layout.rects[0] = {0.0f, top + header, 0.5f * width, height};
    layout.rects[1] = {0.5f * width, top + header, width, height};
    layout.zoom = std::min(FitZoom(layout.rects[0], layout.low, layout.high, kMargin + kApart),
                           FitZoom(layout.rects[1], layout.low, layout.high, kMargin + kApart));
    return layout;
}

} // namespace

View FrameSlice(const Scene& scene, int bodyIndex, const Figure& figure)
{
    const Body& body = scene.bodies[static_cast<size_t>(bodyIndex)];
    const float width = static_cast<float>(figure.view.width);
    const Vec2 a = scene.view.cut[0];
    const Vec2 b = scene.view.cut[1];
    const std::vector<Vec2> outline = WorldOutline(body);
    float top = 0.0f;
    if (figure.layers & kLayerCaption)
    {
        // The band's height, from its wrapped lines, measured as the canvas measures them.
        const std::vector<std::vector<Vec2>> parts = SliceAlongSegment(outline, a, b);
        std::vector<Decomposition> pieces;
        for (const std::vector<Vec2>& part : parts)
        {
            pieces.push_back(Decompose(part, body.decompose));
        }
        RecordingCanvas measure;
        top = DrawCaptionBand(measure, figure.caption, DescribeSlice(body, a, b, parts, pieces), width);
    }
    const SliceLayout layout = LayOutSlice(body, outline, a, b, top, width, static_cast<float>(figure.view.height));
    return FramePanel(layout.rects[0], layout.low, layout.high, figure.view.width, figure.view.height, kMargin,
                      layout.zoom)
        .view;
}

void PaintSlice(Canvas& surface, const Scene& scene, int bodyIndex, const Figure& figure)
{
    // Every line is drawn through the watch, so that the labels keep off it.
    LabelPlacer labels(surface, figure);
    LineWatch canvas(surface, labels);
    const Body& body = scene.bodies[static_cast<size_t>(bodyIndex)];
    const float width = static_cast<float>(figure.view.width);
    const float height = static_cast<float>(figure.view.height);
    const Vec2 a = scene.view.cut[0];
    const Vec2 b = scene.view.cut[1];
    const std::vector<Vec2> outline = WorldOutline(body);
    const std::vector<std::vector<Vec2>> parts = SliceAlongSegment(outline, a, b);
    std::vector<Decomposition> pieces;
    for (const std::vector<Vec2>& part : parts)
    {
        pieces.push_back(Decompose(part, body.decompose));
    }
    const Decomposition whole = Decompose(outline, body.decompose);

    const float top = DrawBackgroundAndCaption(canvas, labels, figure, DescribeSlice(body, a, b, parts, pieces));

    const SliceLayout layout = LayOutSlice(body, outline, a, b, top, width, height);
    const ScreenRect(&rects)[2] = layout.rects;
    const Vec2 low = layout.low, high = layout.high;
    const double zoom = layout.zoom;
    // Each panel frames the body itself, or (in the app) the before panel draws it through the camera, by which the
    // pointer is mapped to the world, and the after panel at the same scale half the image to the right.
    auto BodyPanel = [&](int side) {
        if (figure.framesItself)
        {
            return FramePanel(rects[side], low, high, figure.view.width, figure.view.height, kMargin, zoom);
        }
        Panel panel{rects[side], figure.view};
        panel.view.center.x -= side * 0.5 * width / figure.view.zoom;
        return panel;
    };
    canvas.BeginGroup("divider");
    canvas.Segment({0.5f * width, top}, {0.5f * width, height}, palette::kFaint, 1.0f);

    // Before: the body whole, the cut across it, the crossings marked.
    {
        const Panel panel = BodyPanel(0);
        canvas.BeginGroup("before");
        DrawPanelHeader(canvas, 12.0f, top, "Before", layout.headers[0]);
        labels.Reserve({12.0f, top + 4.0f, rects[0].maxX, rects[0].minY});
        DrawPart(canvas, panel.view, whole.pieces, palette::kShapeA, {}, rects[0]);
        const ScreenPoint sa = ToScreen(panel.view, a);
        const ScreenPoint sb = ToScreen(panel.view, b);
        canvas.Segment(sa, sb, palette::kResult, 2.0f);
        labels.ReserveLine(sa, sb, 2.0f);
        canvas.FillCircle(sa, 3.0f, palette::kResult);
        canvas.FillCircle(sb, 3.0f, palette::kResult);
        labels.Place(sa, "cut", TextStyle::Label, palette::kResult, sa.x - sb.x, sa.y - sb.y, 6.0f, LabelRank::Note);
        for (const Vec2& p : CutCrossings(outline, a, b))
        {
            const ScreenPoint s = ToScreen(panel.view, p);
            canvas.FillCircle(s, 4.5f, palette::kResult);
            labels.Reserve({s.x - 5.0f, s.y - 5.0f, s.x + 5.0f, s.y + 5.0f});
            labels.Place(s, Point(p), TextStyle::Label, palette::kInk, -(sb.y - sa.y), sb.x - sa.x, 8.0f,
                         LabelRank::Verdict);
        }
    }
    // After: each part in a colour of its own, moved a little away from the cut, with its area.
    {
        const Panel panel = BodyPanel(1);
        canvas.BeginGroup("after");
        const float x = rects[1].minX + 12.0f;
        DrawPanelHeader(canvas, x, top,
                        "After: " + std::to_string(parts.size()) + (parts.size() == 1 ? " part" : " parts"),
                        layout.headers[1]);
        labels.Reserve({x, top + 4.0f, rects[1].maxX, rects[1].minY});
        const Vec2 along = Normalize(b - a);
        const Vec2 left{-along.y, along.x};
        for (size_t i = 0; i < parts.size(); ++i)
        {
            const Vec2 centre = Centroid(parts[i]);
            const double side = Dot(centre - a, left) >= 0.0 ? 1.0 : -1.0;
            const Vec2 shift = parts.size() < 2 ? Vec2{} : (side * kApart / panel.view.zoom) * left;
            DrawPart(canvas, panel.view, pieces[i].pieces, PieceColor(static_cast<int>(i)), shift, rects[1]);
            // A part's area inside it, centred, where the label fits with room around it; otherwise just beside the
            // part, on its side away from the cut, level with its centre.
            const std::string text = "area " + FormatNumber(Area(parts[i]));
            const ScreenPoint size = canvas.MeasureText(text, TextStyle::Label);
            const double hx = (0.5 * size.x + kRoom) / panel.view.zoom;
            const double hy = (0.5 * size.y + kRoom) / panel.view.zoom;
            bool fits = true;
            for (const Vec2 corner : {Vec2{-hx, -hy}, Vec2{hx, -hy}, Vec2{hx, hy}, Vec2{-hx, hy}})
            {
                fits = fits && InRing(parts[i], centre + corner);
            }
            if (fits)
            {
                labels.Place(ToScreen(panel.view, centre + shift), text, TextStyle::Label, palette::kInk, 0.0f, 0.0f,
                             0.0f, LabelRank::Name);
                labels.Centre();
            }
            else
            {
                const Vec2 out = side * left;
                double reach = 0.0;
                for (const Vec2& v : parts[i])
                {
                    reach = std::max(reach, Dot(v - centre, out));
                }
                labels.Place(ToScreen(panel.view, centre + shift + reach * out), text, TextStyle::Label, palette::kInk,
                             static_cast<float>(out.x), static_cast<float>(-out.y), 6.0f, LabelRank::Name);
            }
        }
    }
    labels.Flush(palette::kBackground);
}

} // namespace satviz
