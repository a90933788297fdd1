// SPDX-License-Identifier: MIT
#include "draw_kit.h"

#include <satviz/render/palette.h>
#include <satviz/render/wrap.h>

#include <algorithm>
#include <cmath>

namespace satviz
{

bool ClipSegment(ScreenPoint& a, ScreenPoint& b, const ScreenRect& rect)
{
    const double dx = static_cast<double>(b.x) - a.x;
    const double dy = static_cast<double>(b.y) - a.y;
    double t0 = 0.0;
    double t1 = 1.0;
    const double p[4] = {-dx, dx, -dy, dy};
    const double q[4] = {a.x - static_cast<double>(rect.minX), rect.maxX - static_cast<double>(a.x),
                         a.y - static_cast<double>(rect.minY), rect.maxY - static_cast<double>(a.y)};
    for (int i = 0; i < 4; ++i)
    {
        if (p[i] == 0.0)
        {
            if (q[i] < 0.0)
            {
                return false;
            }
            continue;
        }
        const double r = q[i] / p[i];
        if (p[i] < 0.0)
        {
            t0 = std::max(t0, r);
        }
        else
        {
            t1 = std::min(t1, r);
        }
        if (t0 > t1)
        {
            return false;
        }
    }
    const ScreenPoint start = a;
    a = {static_cast<float>(start.x + t0 * dx), static_cast<float>(start.y + t0 * dy)};
    b = {static_cast<float>(start.x + t1 * dx), static_cast<float>(start.y + t1 * dy)};
    return true;
}

float DistanceToSegment(ScreenPoint p, ScreenPoint a, ScreenPoint b)
{
    const float dx = b.x - a.x;
    const float dy = b.y - a.y;
    const float squared = dx * dx + dy * dy;
    const float t = squared > 0.0f ? std::clamp(((p.x - a.x) * dx + (p.y - a.y) * dy) / squared, 0.0f, 1.0f) : 0.0f;
    return std::hypot(p.x - (a.x + t * dx), p.y - (a.y + t * dy));
}

void DashedSegment(Canvas& canvas, ScreenPoint a, ScreenPoint b, Color color, float thickness, const ScreenRect& bounds,
                   float dash, float gap)
{
    if (!ClipSegment(a, b, bounds))
    {
        return;
    }
    const float dx = b.x - a.x;
    const float dy = b.y - a.y;
    const float length = std::sqrt(dx * dx + dy * dy);
    if (length < 0.5f)
    {
        return;
    }
    const float ux = dx / length;
    const float uy = dy / length;
    for (float s = 0.0f; s < length; s += dash + gap)
    {
        const float e = std::min(length, s + dash);
        canvas.Segment({a.x + ux * s, a.y + uy * s}, {a.x + ux * e, a.y + uy * e}, color, thickness);
    }
}

ScreenRect Arrow(Canvas& canvas, ScreenPoint a, ScreenPoint b, Color color, float thickness, float head)
{
    const float dx = b.x - a.x;
    const float dy = b.y - a.y;
    const float length = std::sqrt(dx * dx + dy * dy);
    if (length < 1e-3f)
    {
        return {b.x, b.y, b.x, b.y};
    }
    const float ux = dx / length;
    const float uy = dy / length;
    const float h = std::min(head, 0.6f * length + 4.0f);
    const ScreenPoint base{b.x - ux * h, b.y - uy * h};
    canvas.Segment(a, {b.x - ux * h * 0.6f, b.y - uy * h * 0.6f}, color, thickness);
    const ScreenPoint tip[3] = {
        b, {base.x - uy * h * 0.45f, base.y + ux * h * 0.45f}, {base.x + uy * h * 0.45f, base.y - ux * h * 0.45f}};
    canvas.FillConvex(tip, 3, color);
    ScreenRect rect{tip[0].x, tip[0].y, tip[0].x, tip[0].y};
    for (const ScreenPoint& p : tip)
    {
        rect = {std::min(rect.minX, p.x), std::min(rect.minY, p.y), std::max(rect.maxX, p.x), std::max(rect.maxY, p.y)};
    }
    return rect;
}

std::vector<ScreenPoint> ShapeOutline(const View& view, const Shape& shape, const Transform& xf)
{
    std::vector<ScreenPoint> points;
    if (shape.type == ShapeType::Polygon)
    {
        const auto& vertices = shape.polygon.Vertices();
        points.reserve(vertices.size());
        for (const Vec2& v : vertices)
        {
            const ScreenPoint p = ToScreen(view, TransformPoint(xf, v));
            if (!points.empty())
            {
                const float dx = p.x - points.back().x;
                const float dy = p.y - points.back().y;
                if (dx * dx + dy * dy < 0.25f)
                {
                    continue;
                }
            }
            points.push_back(p);
        }
        return points;
    }
    const ScreenPoint center = ToScreen(view, TransformPoint(xf, shape.circle.center));
    const double radius = shape.circle.radius * view.zoom;
    // Chord error r (1 - cos(pi / n)) <= 0.25 px.
    const int count = std::clamp(static_cast<int>(std::ceil(3.1416 * std::sqrt(std::max(radius, 1.0) / 0.5))), 16, 256);
    points.reserve(static_cast<size_t>(count));
    for (int i = 0; i < count; ++i)
    {
        const double angle = 2.0 * 3.14159265358979323846 * i / count;
        points.push_back({static_cast<float>(center.x + radius * std::cos(angle)),
                          static_cast<float>(center.y - radius * std::sin(angle))});
    }
    return points;
}

void DashedOutline(Canvas& canvas, const std::vector<ScreenPoint>& outline, Color color, float thickness,
                   const ScreenRect& bounds)
{
    constexpr float kDash = 6.0f;
    constexpr float kGap = 4.0f;
    constexpr float kPeriod = kDash + kGap;
    const size_t count = outline.size();
    // The pattern starts afresh at each corner, so that a polygon's corners show, and runs on across the bends of
    // a curve: a circle's chords are shorter than one dash, and a dash begun on every chord would draw it solid.
    const auto corner = [&](size_t i) {
        const ScreenPoint& before = outline[(i + count - 1) % count];
        const ScreenPoint& at = outline[i];
        const ScreenPoint& after = outline[(i + 1) % count];
        const float ax = at.x - before.x;
        const float ay = at.y - before.y;
        const float bx = after.x - at.x;
        const float by = after.y - at.y;
        const float la = std::sqrt(ax * ax + ay * ay);
        const float lb = std::sqrt(bx * bx + by * by);
        // A turn of more than 30 degrees: sharper than any chord of the outlines ShapeOutline makes for a circle.
        return la > 0.0f && lb > 0.0f && (ax * bx + ay * by) < 0.866f * la * lb;
    };
    float phase = 0.0f;
    for (size_t i = 0; i < count; ++i)
    {
        if (corner(i))
        {
            phase = 0.0f;
        }
        const ScreenPoint from = outline[i];
        const ScreenPoint to = outline[(i + 1) % count];
        const float dx = to.x - from.x;
        const float dy = to.y - from.y;
        const float length = std::sqrt(dx * dx + dy * dy);
        if (length <= 0.0f)
        {
            continue;
        }
        const float ux = dx / length;
        const float uy = dy / length;
        ScreenPoint a = from;
        ScreenPoint b = to;
        if (ClipSegment(a, b, bounds))
        {
            const float s0 = (a.x - from.x) * ux + (a.y - from.y) * uy;
            const float s1 = (b.x - from.x) * ux + (b.y - from.y) * uy;
            // Dashes of the pattern that began at `from` with this phase, cut to the part in bounds.
            for (float s = -phase; s < s1; s += kPeriod)
            {
                const float start = std::max(s, s0);
                const float end = std::min(s + kDash, s1);
                if (end > start)
                {
                    canvas.Segment({from.x + ux * start, from.y + uy * start}, {from.x + ux * end, from.y + uy * end},
                                   color, thickness);
                }
            }
        }
        phase = std::fmod(phase + length, kPeriod);
    }
}

namespace
{

constexpr float kSubtitleTop = 23.0f;    // from the band's bottom to the subtitle's first line
constexpr float kOneLineHeader = 40.0f;  // a title and one line of subtitle

float SubtitleLineHeight()
{
    return FontTextSize("Ag", TextStyle::Label).y + 2.0f;
}

} // namespace

PanelHeader LayOutPanelHeader(const std::string& subtitle, float panelWidth)
{
    PanelHeader header;
    // 12 pixels in from the panel's left side, 6 clear of its right.
    header.lines = WrapLines(subtitle, std::max(1.0f, panelWidth - 18.0f),
                             [](const std::string& s) { return FontTextSize(s, TextStyle::Label).x; });
    const size_t lines = std::max<size_t>(1, header.lines.size());
    header.height = kOneLineHeader + static_cast<float>(lines - 1) * SubtitleLineHeight();
    return header;
}

void DrawPanelHeader(Canvas& canvas, float x, float top, const std::string& title, const PanelHeader& header)
{
    canvas.Text({x, top + 6.0f}, title, TextStyle::Heading, palette::kInk);
    for (size_t i = 0; i < header.lines.size(); ++i)
    {
        canvas.Text({x, top + kSubtitleTop + static_cast<float>(i) * SubtitleLineHeight()}, header.lines[i],
                    TextStyle::Label, palette::kMuted);
    }
}

} // namespace satviz
