// SPDX-License-Identifier: MIT
// The hits layer: the step's time-ordered hits, in the order the world resolved them, on a time bar of the step
// (as the swept test's), and the two bodies of each hit where they were at its time.
#include "world_views.h"

#include <satviz/render/describe.h>

#include <algorithm>
#include <string>

namespace satviz
{

namespace
{

constexpr size_t kMostHitsDrawn = 9; // more would crowd the bar; the panel says how many are left out

std::string NameOf(const Scene& scene, int body)
{
    return static_cast<size_t>(body) < scene.bodies.size() ? scene.bodies[static_cast<size_t>(body)].name
                                                           : std::to_string(body);
}

} // namespace

void PaintHitsScene(Canvas& canvas, LabelPlacer& labels, const View& view, const Scene& scene, const SimRecord& sim,
                    const ScreenRect& bounds)
{
    const std::vector<StepHit>& hits = sim.lastStep.hits;
    if (hits.empty())
    {
        return;
    }
    canvas.BeginGroup("hits");
    for (size_t h = 0; h < hits.size() && h < kMostHitsDrawn; ++h)
    {
        const StepHit& hit = hits[h];
        for (int side = 0; side < 2; ++side)
        {
            const int body = side == 0 ? hit.a : hit.b;
            if (static_cast<size_t>(body) >= scene.bodies.size() ||
                sim.world.bodies[static_cast<size_t>(body)].type == BodyType::Static)
            {
                continue; // a wall is where it always is
            }
            const std::vector<ScreenPoint> outline = ShapeOutline(view, scene.bodies[static_cast<size_t>(body)].shape,
                                                                  MakeTransform(hit.position[side], hit.angle[side]));
            DashedOutline(canvas, outline, WithAlpha(palette::kResult, 0.8f), 1.4f, bounds);
        }
        for (int k = 0; k < hit.pointCount; ++k)
        {
            const ScreenPoint at = ToScreen(view, hit.points[k]);
            canvas.FillCircle(at, 3.5f, palette::kResult);
            if (k == 0)
            {
                labels.Place(at, "hit " + std::to_string(h + 1), TextStyle::Label, palette::kResult,
                             static_cast<float>(-hit.normal.x), static_cast<float>(hit.normal.y), 6.0f, LabelRank::Note);
            }
        }
    }
}

void PaintHitsPanel(Canvas& canvas, const Scene& scene, const SimRecord& sim, float width, float top)
{
    canvas.BeginGroup("hits panel");
    const std::vector<StepHit>& hits = sim.lastStep.hits;
    const float left = 12.0f;
    const std::string title =
        "Hits of step " + std::to_string(sim.steps) +
        " in the order resolved, on the step's "
        "time (0 to 1 of dt)" +
        (hits.empty() ? ": none; the step's contacts held every pair."
                      : (hits.size() > kMostHitsDrawn
                             ? ", the first " + std::to_string(kMostHitsDrawn) + " of " + std::to_string(hits.size())
                             : ""));
    canvas.Text({left, top + 6.0f}, title, TextStyle::Label, palette::kInk);
    const float barLeft = left + 14.0f;
    const float barRight = width - 26.0f;
    const float barY = top + 34.0f;
    canvas.Segment({barLeft, barY}, {barRight, barY}, palette::kMuted, 1.5f);
    for (const float u : {0.0f, 0.5f, 1.0f})
    {
        const float x = barLeft + u * (barRight - barLeft);
        canvas.Segment({x, barY - 4.0f}, {x, barY + 4.0f}, palette::kMuted, 1.0f);
        const std::string tick = u == 0.0f ? "0" : (u == 1.0f ? "1" : "0.5");
        const ScreenPoint size = canvas.MeasureText(tick, TextStyle::Label);
        canvas.Text({x - 0.5f * size.x, barY + 7.0f}, tick, TextStyle::Label, palette::kMuted);
    }
    // Each hit a dot on the bar and its number above; numbers of hits at nearly the same time stack upwards so
    // that none covers another.
    std::vector<ScreenRect> taken;
    for (size_t h = 0; h < hits.size() && h < kMostHitsDrawn; ++h)
    {
        const StepHit& hit = hits[h];
        const float x = barLeft + static_cast<float>(std::clamp(hit.time, 0.0, 1.0)) * (barRight - barLeft);
        canvas.FillCircle({x, barY}, 4.0f, palette::kResult);
        const std::string text = std::to_string(h + 1) + ": " + NameOf(scene, hit.a) + "-" + NameOf(scene, hit.b) +
                                 " at " + FormatNumber(hit.time);
        const ScreenPoint size = canvas.MeasureText(text, TextStyle::Label);
        float tx = std::clamp(x - 0.5f * size.x, left, width - 12.0f - size.x);
        ScreenRect rect{tx, barY + 24.0f, tx + size.x, barY + 24.0f + size.y};
        // Below the bar and its ticks; shifted right past any label already placed.
        for (bool moved = true; moved;)
        {
            moved = false;
            for (const ScreenRect& other : taken)
            {
                if (rect.Overlaps(other))
                {
                    rect.minX = other.maxX + 8.0f;
                    rect.maxX = rect.minX + size.x;
                    moved = true;
                }
            }
        }
        taken.push_back(rect);
        canvas.Segment({x, barY}, {rect.minX + 2.0f, rect.minY}, WithAlpha(palette::kResult, 0.5f), 1.0f);
        canvas.Text({rect.minX, rect.minY + 2.0f}, text, TextStyle::Label, palette::kResult);
    }
}

} // namespace satviz
