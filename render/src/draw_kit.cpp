// SPDX-License-Identifier: MIT
#include "draw_kit.h"

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
    for (size_t i = 0; i < outline.size(); ++i)
    {
        DashedSegment(canvas, outline[i], outline[(i + 1) % outline.size()], color, thickness, bounds, 6.0f, 4.0f);
    }
}

} // namespace satviz
