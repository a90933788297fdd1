// SPDX-License-Identifier: MIT
// The broadphase layer: what the world's step compared and what it skipped.
#include "world_views.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace satviz
{

namespace
{

// Clips the segment ab to the convex polygon `poly` (either winding; Cyrus-Beck); false when nothing is left.
bool ClipToConvex(ScreenPoint& a, ScreenPoint& b, const std::vector<ScreenPoint>& poly)
{
    const size_t n = poly.size();
    if (n < 3)
    {
        return false;
    }
    double area = 0.0;
    for (size_t i = 0; i < n; ++i)
    {
        const ScreenPoint& p = poly[i];
        const ScreenPoint& q = poly[(i + 1) % n];
        area += static_cast<double>(p.x) * q.y - static_cast<double>(q.x) * p.y;
    }
    const double sign = area >= 0.0 ? 1.0 : -1.0;
    double t0 = 0.0, t1 = 1.0;
    const double dx = b.x - a.x, dy = b.y - a.y;
    for (size_t i = 0; i < n; ++i)
    {
        const ScreenPoint& p = poly[i];
        const ScreenPoint& q = poly[(i + 1) % n];
        // Inside is where the cross product of the edge and the point has the polygon's sign.
        const double ex = q.x - p.x, ey = q.y - p.y;
        const double f0 = sign * (ex * (a.y - p.y) - ey * (a.x - p.x));
        const double df = sign * (ex * dy - ey * dx);
        if (df == 0.0)
        {
            if (f0 < 0.0)
            {
                return false;
            }
            continue;
        }
        const double t = -f0 / df;
        if (df > 0.0)
        {
            t0 = std::max(t0, t);
        }
        else
        {
            t1 = std::min(t1, t);
        }
        if (t0 >= t1)
        {
            return false;
        }
    }
    const ScreenPoint start{static_cast<float>(a.x + t0 * dx), static_cast<float>(a.y + t0 * dy)};
    const ScreenPoint end{static_cast<float>(a.x + t1 * dx), static_cast<float>(a.y + t1 * dy)};
    a = start;
    b = end;
    return true;
}

// Diagonal hatching across a body's outline, 7 pixels apart: the mark of a sleeping body.
void Hatch(Canvas& canvas, const std::vector<ScreenPoint>& outline, Color color)
{
    float minX = INFINITY, minY = INFINITY, maxX = -INFINITY, maxY = -INFINITY;
    for (const ScreenPoint& p : outline)
    {
        minX = std::min(minX, p.x);
        minY = std::min(minY, p.y);
        maxX = std::max(maxX, p.x);
        maxY = std::max(maxY, p.y);
    }
    const float span = (maxX - minX) + (maxY - minY);
    for (float c = 0.0f; c <= span; c += 7.0f)
    {
        ScreenPoint a{minX + c, minY};
        ScreenPoint b{minX + c - (maxY - minY), maxY};
        if (ClipToConvex(a, b, outline))
        {
            canvas.Segment(a, b, color, 1.0f);
        }
    }
}

} // namespace

void PaintBroadphaseScene(Canvas& canvas, const View& view, const Scene& scene, const SimRecord& sim,
                          const ScreenRect& bounds)
{
    canvas.BeginGroup("sleeping");
    const std::vector<RigidBody>& bodies = sim.world.bodies;
    // Sleeping bodies, hatched over their fill.
    for (size_t i = 0; i < bodies.size() && i < scene.bodies.size(); ++i)
    {
        if (bodies[i].type == BodyType::Dynamic && !bodies[i].awake)
        {
            Hatch(canvas, ShapeOutline(view, scene.bodies[i].shape, scene.bodies[i].Xf()),
                  WithAlpha(palette::kMuted, 0.8f));
        }
    }
    canvas.BeginGroup("broadphase");
    const std::vector<Aabb>& boxes = sim.lastStep.bounds;
    // The boxes the broadphase compared, at the start of the last step: dashed, in the body's colour.
    for (size_t i = 0; i < boxes.size(); ++i)
    {
        const ScreenPoint lo = ToScreen(view, boxes[i].min);
        const ScreenPoint hi = ToScreen(view, boxes[i].max);
        const std::vector<ScreenPoint> box = {{lo.x, lo.y}, {hi.x, lo.y}, {hi.x, hi.y}, {lo.x, hi.y}};
        DashedOutline(canvas, box, WithAlpha(PairInk(sim, static_cast<int>(i)), 0.75f), 1.0f, bounds);
    }
    // The pairs passed to the narrowphase: a thin line between the boxes' centres.
    for (const auto& [i, j] : sim.lastStep.candidates)
    {
        const Aabb& a = boxes[static_cast<size_t>(i)];
        const Aabb& b = boxes[static_cast<size_t>(j)];
        ScreenPoint p = ToScreen(view, 0.5 * (a.min + a.max));
        ScreenPoint q = ToScreen(view, 0.5 * (b.min + b.max));
        if (ClipSegment(p, q, bounds))
        {
            canvas.Segment(p, q, WithAlpha(palette::kGap, 0.85f), 1.2f);
            canvas.FillCircle(p, 2.5f, palette::kGap);
            canvas.FillCircle(q, 2.5f, palette::kGap);
        }
    }
}

void PaintCountsPanel(Canvas& canvas, const SimRecord& sim, float width, float top)
{
    canvas.BeginGroup("counts");
    const StepCounts& c = sim.world.counts;
    auto n = [](int64_t v) { return std::to_string(v); };
    const std::string line = sim.steps == 0 ? "No step taken yet: the broadphase has not run."
                                            : "Step " + std::to_string(sim.steps) + ": " + n(c.pairs) + (c.pairs == 1 ? " pair, " : " pairs, ") +
                                                  n(c.staticPairs) + " static, " + n(c.sleepingPairs) + " sleeping, " +
                                                  n(c.boundsApart) + " bounds apart, " + n(c.tested) + " tested, " +
                                                  n(c.touching) + " touching, " + n(c.speculative) + " speculative, " +
                                                  n(c.swept) + " swept, " + n(c.hits) + " hits";
    canvas.Text({12.0f, top + 7.0f}, line, TextStyle::Label, palette::kInk);
    // The key on the right, when it fits: dashed boxes, green pairs, hatched sleepers.
    const std::string key = "dashed: boxes grown by reach   green: pairs tested   hatched: asleep";
    const ScreenPoint size = canvas.MeasureText(key, TextStyle::Label);
    const ScreenPoint lineSize = canvas.MeasureText(line, TextStyle::Label);
    if (12.0f + lineSize.x + 24.0f + size.x <= width - 12.0f)
    {
        canvas.Text({width - 12.0f - size.x, top + 7.0f}, key, TextStyle::Label, palette::kMuted);
    }
}

} // namespace satviz
