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
                    int chosen, const ScreenRect& bounds)
{
    const std::vector<StepHit>& hits = sim.lastStep.hits;
    if (hits.empty())
    {
        return;
    }
    const bool one = chosen >= 0 && static_cast<size_t>(chosen) < hits.size();
    canvas.BeginGroup("hits");
    for (size_t h = 0; h < hits.size() && h < kMostHitsDrawn; ++h)
    {
        if (one && h != static_cast<size_t>(chosen))
        {
            continue;
        }
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
            if (one)
            {
                // The hit chosen on the time bar: its bodies solid, where they are at that instant.
                if (outline.size() >= 3)
                {
                    canvas.FillConvex(outline.data(), static_cast<int>(outline.size()),
                                      WithAlpha(palette::kResult, 0.18f));
                }
                canvas.Polyline(outline.data(), static_cast<int>(outline.size()), true, palette::kResult, 2.0f);
            }
            else
            {
                DashedOutline(canvas, outline, WithAlpha(palette::kResult, 0.8f), 1.4f, bounds);
            }
        }
        for (int k = 0; k < hit.pointCount; ++k)
        {
            const ScreenPoint at = ToScreen(view, hit.points[k]);
            canvas.FillCircle(at, 3.5f, palette::kResult);
            if (k == 0)
            {
                labels.Place(at, "hit " + std::to_string(h + 1) + (one ? " at t = " + FormatNumber(hit.time) : ""),
                             TextStyle::Label, palette::kResult, static_cast<float>(-hit.normal.x),
                             static_cast<float>(hit.normal.y), 6.0f, LabelRank::Note);
            }
        }
    }
}

std::vector<HitMark> LayOutHitMarks(Canvas& canvas, const Scene& scene, const SimRecord& sim, float width, float top)
{
    const std::vector<StepHit>& hits = sim.lastStep.hits;
    const float left = 12.0f;
    const float barLeft = left + 14.0f;
    const float barRight = width - 26.0f;
    const float barY = top + 34.0f;
    // Each hit a dot on the bar and its label below; labels of hits at nearly the same time are shifted right so
    // that none covers another.
    std::vector<HitMark> marks;
    std::vector<ScreenRect> taken;
    for (size_t h = 0; h < hits.size() && h < kMostHitsDrawn; ++h)
    {
        const StepHit& hit = hits[h];
        HitMark mark;
        mark.dot = {barLeft + static_cast<float>(std::clamp(hit.time, 0.0, 1.0)) * (barRight - barLeft), barY};
        mark.text = std::to_string(h + 1) + ": " + NameOf(scene, hit.a) + "-" + NameOf(scene, hit.b) + " at " +
                    FormatNumber(hit.time);
        const ScreenPoint size = canvas.MeasureText(mark.text, TextStyle::Label);
        const float tx = std::clamp(mark.dot.x - 0.5f * size.x, left, width - 12.0f - size.x);
        ScreenRect rect{tx, barY + 24.0f, tx + size.x, barY + 24.0f + size.y};
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
        mark.labelMin = {rect.minX, rect.minY};
        mark.labelMax = {rect.maxX, rect.maxY};
        marks.push_back(std::move(mark));
    }
    return marks;
}

void PaintHitsPanel(Canvas& canvas, const Scene& scene, const SimRecord& sim, int chosen, float width, float top)
{
    canvas.BeginGroup("hits panel");
    const std::vector<StepHit>& hits = sim.lastStep.hits;
    const float left = 12.0f;
    std::string title;
    const bool one =
        chosen >= 0 && static_cast<size_t>(chosen) < hits.size() && static_cast<size_t>(chosen) < kMostHitsDrawn;
    if (one)
    {
        // The instant of the hit: the step began at the world's time less dt, and the hit came t of dt later.
        const StepHit& hit = hits[static_cast<size_t>(chosen)];
        title = "Hit " + std::to_string(chosen + 1) + " of step " + std::to_string(sim.steps) + ": " +
                NameOf(scene, hit.a) + " and " + NameOf(scene, hit.b) + " touch at t = " + FormatNumber(hit.time) +
                " of the step (time " + FormatNumber(sim.world.time - (1.0 - hit.time) * sim.dt) +
                "), drawn solid where they are then";
    }
    else
    {
        title = "Hits of step " + std::to_string(sim.steps) +
                " in the order resolved, on the step's time (0 to 1 of dt)" +
                (hits.empty() ? ": none; the step's contacts held every pair."
                              : (hits.size() > kMostHitsDrawn ? ", the first " + std::to_string(kMostHitsDrawn) +
                                                                    " of " + std::to_string(hits.size())
                                                              : ""));
    }
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
    const std::vector<HitMark> marks = LayOutHitMarks(canvas, scene, sim, width, top);
    for (size_t h = 0; h < marks.size(); ++h)
    {
        const HitMark& mark = marks[h];
        const bool faded = one && h != static_cast<size_t>(chosen);
        const Color ink = faded ? WithAlpha(palette::kResult, 0.45f) : palette::kResult;
        if (one && !faded)
        {
            canvas.Circle(mark.dot, 7.0f, palette::kResult, 1.5f);
        }
        canvas.FillCircle(mark.dot, 4.0f, ink);
        canvas.Segment(mark.dot, {mark.labelMin.x + 2.0f, mark.labelMin.y}, WithAlpha(palette::kResult, 0.5f), 1.0f);
        canvas.Text({mark.labelMin.x, mark.labelMin.y + 2.0f}, mark.text, TextStyle::Label, ink);
    }
}

} // namespace satviz
