// SPDX-License-Identifier: MIT
// The response layer: the solver's impulses on the chosen contact, as arrows at its points and as a panel of its
// steps (DescribeResponse) with the passes' normal impulses before and after the clamp.
#include "world_views.h"

#include <satviz/render/describe.h>
#include <satviz/render/response_steps.h>
#include <satviz/render/wrap.h>

#include <algorithm>
#include <cmath>

namespace satviz
{

namespace
{

constexpr float kLongestArrow = 70.0f; // pixels of the largest impulse drawn
constexpr float kTitleColumn = 150.0f; // width of the steps' titles
constexpr float kLine = 16.0f;         // line spacing of the sentences
constexpr float kTable = 46.0f;        // height of the passes' table

const WorldContact* ChosenContact(const SimRecord& sim)
{
    const int lo = std::min(sim.contact.bodyA, sim.contact.bodyB);
    const int hi = std::max(sim.contact.bodyA, sim.contact.bodyB);
    for (const WorldContact& c : sim.world.contacts)
    {
        if (c.a == lo && c.b == hi)
        {
            return &c;
        }
    }
    return nullptr;
}

} // namespace

void PaintResponseScene(Canvas& canvas, LabelPlacer& labels, const View& view, const Scene& scene, const SimRecord& sim)
{
    (void)scene;
    const ContactSolveTrace& trace = sim.contact;
    const WorldContact* contact = ChosenContact(sim);
    if (!trace.found || contact == nullptr)
    {
        return;
    }
    canvas.BeginGroup("response");
    const Vec2 n = trace.normal;
    const Vec2 t{n.y, -n.x};
    double largest = 0.0;
    double normal[2] = {0.0, 0.0};
    double tangent[2] = {0.0, 0.0};
    for (int p = 0; p < trace.pointCount; ++p)
    {
        if (const ContactPointSolve* last = LastPass(trace, p))
        {
            normal[p] = last->normalImpulse + trace.restitutionImpulse[p];
            tangent[p] = last->tangentImpulse;
        }
        largest = std::max({largest, std::fabs(normal[p]), std::fabs(tangent[p])});
    }
    if (!(largest > 0.0))
    {
        return;
    }
    const double scale = kLongestArrow / largest; // pixels per N s
    // The impulses on the second body of the pair (the first gets the same, reversed), from each point.
    for (int p = 0; p < trace.pointCount; ++p)
    {
        const ScreenPoint at = ToScreen(view, contact->points[p].point);
        canvas.FillCircle(at, 4.0f, palette::kResult);
        const auto arrow = [&](Vec2 direction, double impulse, Color color, const std::string& name) {
            const float length = static_cast<float>(std::fabs(impulse) * scale);
            if (length < 4.0f)
            {
                return;
            }
            const Vec2 d = impulse >= 0.0 ? direction : -1.0 * direction;
            const ScreenPoint tip{at.x + static_cast<float>(d.x) * length, at.y - static_cast<float>(d.y) * length};
            labels.Reserve(Arrow(canvas, at, tip, color, 2.5f, 11.0f));
            labels.ReserveLine(at, tip, 4.5f);
            labels.Place(tip, name + " = " + FormatNumber(std::fabs(impulse), kResponseDigits) + " N s",
                         TextStyle::Label, color, static_cast<float>(d.x), static_cast<float>(-d.y), 6.0f,
                         LabelRank::Verdict);
        };
        const std::string suffix = trace.pointCount == 2 ? std::to_string(p + 1) : "";
        arrow(n, normal[p], palette::kResult, "j" + suffix);
        arrow(t, tangent[p], palette::kInk, "jt" + suffix);
    }
}

void PaintResponsePanel(Canvas& canvas, const Scene& scene, const SimRecord& sim, float width, float top)
{
    canvas.BeginGroup("response panel");
    const std::vector<ResponseStep> steps = DescribeResponse(scene, sim);
    const float left = 12.0f;
    // The titles' column as wide as the widest title (and the table's row names), at least kTitleColumn.
    float titles = kTitleColumn;
    for (const ResponseStep& step : steps)
    {
        titles = std::max(titles, canvas.MeasureText(step.title, TextStyle::Heading).x + 14.0f);
    }
    titles = std::max(titles, canvas.MeasureText("kept, >= 0 (N s)", TextStyle::Label).x + 14.0f);
    const float textLeft = left + titles;
    const float textWidth = std::max(80.0f, width - textLeft - 12.0f);
    const float tableTop = top + kResponsePanel - kTable - 6.0f;
    float y = top + 8.0f;
    for (const ResponseStep& step : steps)
    {
        const std::vector<std::string> lines = WrapLines(step.sentence, textWidth, [&](const std::string& text) {
            return canvas.MeasureText(text, TextStyle::Label).x;
        });
        if (y + kLine * static_cast<float>(lines.size()) > tableTop)
        {
            break; // the table keeps its room; a figure this narrow shows fewer steps
        }
        const Color titleColor = step.title == "Friction: sticks"   ? palette::kGap
                                 : step.title == "Friction: slides" ? palette::kResult
                                                                    : palette::kInk;
        canvas.Text({left, y}, step.title, TextStyle::Heading, titleColor);
        for (const std::string& line : lines)
        {
            canvas.Text({textLeft, y + 1.0f}, line, TextStyle::Label, palette::kInk);
            y += kLine;
        }
        y += 3.0f;
    }
    // The passes over point 1: the running normal impulse each asked for, and what it kept after the clamp.
    const ResponsePasses passes = ResponsePassesOf(sim, 0);
    if (passes.kept.empty())
    {
        return;
    }
    // Three rows in the steps' columns: the pass, what it asked for, what it kept.
    const float rows[3] = {tableTop, tableTop + 15.0f, tableTop + 30.0f};
    canvas.Text({left, rows[0]}, "pass, point 1", TextStyle::Label, palette::kMuted);
    canvas.Text({left, rows[1]}, "asked for (N s)", TextStyle::Label, palette::kMuted);
    canvas.Text({left, rows[2]}, "kept, >= 0 (N s)", TextStyle::Label, palette::kMuted);
    const size_t count = passes.kept.size();
    const float column = std::min(78.0f, (width - textLeft - 12.0f) / static_cast<float>(count));
    for (size_t k = 0; k < count; ++k)
    {
        const float x = textLeft + column * static_cast<float>(k);
        const bool clamped = passes.wanted[k] != passes.kept[k];
        canvas.Text({x, rows[0]}, std::to_string(k + 1), TextStyle::Label, palette::kMuted);
        canvas.Text({x, rows[1]}, FormatNumber(passes.wanted[k], kResponseDigits), TextStyle::Label,
                    clamped ? palette::kResult : palette::kInk);
        canvas.Text({x, rows[2]}, FormatNumber(passes.kept[k], kResponseDigits), TextStyle::Label, palette::kInk);
    }
}

} // namespace satviz
