// SPDX-License-Identifier: MIT
// The plots layer: the world's totals over the steps (SimRecord::history), three small plots side by side under
// the scene, the current step marked on each.
#include "world_views.h"

#include <satviz/render/describe.h>
#include <satviz/render/wrap.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <string>

namespace satviz
{

namespace
{

struct Series
{
    std::string name;
    Color color;
    std::function<double(const SimSample&)> value;
};

constexpr float kPlotLine = 15.0f; // a line of the plots' header

// A plot's header between x0 and x1 from y0 down: the title's words (each kept whole: "(kg m/s):") a space apart,
// then the series' names in their colours 6 pixels apart, running on as the words of one line do, onto the next line
// where the plot is too narrow for them. Drawn when `draw`; the y of its last line's top either way.
float PlotHeader(Canvas& canvas, const std::vector<std::string>& title, const std::vector<Series>& series, float x0,
                 float x1, float y0, bool draw)
{
    float tx = x0;
    float ty = y0;
    // The title's words on one line are one text, as a line reads ("Energy (J):").
    std::string line;
    float lineX = x0;
    const auto flush = [&]() {
        if (draw && !line.empty())
        {
            canvas.Text({lineX, ty}, line, TextStyle::Label, palette::kInk);
        }
        line.clear();
    };
    for (const std::string& w : title)
    {
        const std::string joined = line.empty() ? w : line + " " + w;
        const float width = canvas.MeasureText(joined, TextStyle::Label).x;
        if (!line.empty() && lineX + width > x1)
        {
            flush();
            ty += kPlotLine;
            lineX = x0;
            line = w;
        }
        else
        {
            line = joined;
        }
        tx = lineX + canvas.MeasureText(line, TextStyle::Label).x + 6.0f;
    }
    flush();
    for (const Series& s : series)
    {
        const float w = canvas.MeasureText(s.name, TextStyle::Label).x;
        if (tx > x0 && tx + w > x1)
        {
            tx = x0;
            ty += kPlotLine;
        }
        if (draw)
        {
            canvas.Text({tx, ty}, s.name, TextStyle::Label, s.color);
        }
        tx += w + 6.0f;
    }
    return ty;
}

// One plot in the box [x0, x1] x [y0, y1]: its header (PlotHeader), a frame from `frameTop` with the range of the
// values at its left, each series as a line over the steps, and the current (last) step marked.
void Plot(Canvas& canvas, const std::vector<SimSample>& history, const std::vector<std::string>& title,
          const std::vector<Series>& series, float x0, float x1, float y0, float y1, float frameTop)
{
    PlotHeader(canvas, title, series, x0, x1, y0, true);
    double lo = INFINITY, hi = -INFINITY;
    for (const SimSample& sample : history)
    {
        for (const Series& s : series)
        {
            lo = std::min(lo, s.value(sample));
            hi = std::max(hi, s.value(sample));
        }
    }
    lo = std::min(lo, 0.0);
    hi = std::max(hi, 0.0);
    const bool flat = !(hi - lo > 1e-12);
    if (flat)
    {
        hi = lo + 1.0;
    }
    const std::string top = FormatNumber(hi);
    const std::string bottom = FormatNumber(lo);
    const float labels =
        std::max(canvas.MeasureText(top, TextStyle::Label).x, canvas.MeasureText(bottom, TextStyle::Label).x) + 6.0f;
    const float left = x0 + labels;
    const float frameBottom = y1 - 16.0f;
    canvas.FillRect({left, frameTop}, {x1, frameBottom}, palette::kBackground);
    const ScreenPoint frame[4] = {{left, frameTop}, {x1, frameTop}, {x1, frameBottom}, {left, frameBottom}};
    canvas.Polyline(frame, 4, true, palette::kFaint, 1.0f);
    if (flat)
    {
        // Broken between words where the frame is narrow.
        const std::vector<std::string> lines =
            WrapLines(FormatNumber(lo) + " at every step", std::max(1.0f, x1 - left - 12.0f),
                      [&](const std::string& s) { return canvas.MeasureText(s, TextStyle::Label).x; });
        for (size_t i = 0; i < lines.size(); ++i)
        {
            canvas.Text({left + 8.0f, frameTop + 6.0f + static_cast<float>(i) * kPlotLine}, lines[i],
                        TextStyle::Label, palette::kMuted);
        }
    }
    else
    {
        canvas.Text({x0, frameTop - 2.0f}, top, TextStyle::Label, palette::kMuted);
    }
    canvas.Text({x0, frameBottom - 12.0f}, bottom, TextStyle::Label, palette::kMuted);
    const int last = history.back().step;
    const int first = history.front().step;
    const auto X = [&](int step) {
        return last == first ? x1
                             : left + (x1 - left) * static_cast<float>(step - first) / static_cast<float>(last - first);
    };
    const auto Y = [&](double v) {
        return frameBottom - static_cast<float>((v - lo) / (hi - lo)) * (frameBottom - frameTop);
    };
    if (lo < 0.0 && hi > 0.0)
    {
        canvas.Segment({left, Y(0.0)}, {x1, Y(0.0)}, palette::kFaint, 1.0f);
    }
    // At most one point per pixel column: a long run is sampled evenly, the last step always kept.
    const size_t n = history.size();
    const size_t stride = std::max<size_t>(1, n / static_cast<size_t>(std::max(1.0f, x1 - left)));
    // The first series is drawn last, on top (the total hides nothing when it equals the kinetic energy, say).
    for (auto it = series.rbegin(); it != series.rend(); ++it)
    {
        const Series& s = *it;
        std::vector<ScreenPoint> points;
        for (size_t i = 0; i < n; i += stride)
        {
            points.push_back({X(history[i].step), Y(s.value(history[i]))});
        }
        if ((n - 1) % stride != 0)
        {
            points.push_back({X(history.back().step), Y(s.value(history.back()))});
        }
        if (points.size() == 1)
        {
            canvas.FillCircle(points[0], 2.5f, s.color);
        }
        canvas.Polyline(points.data(), static_cast<int>(points.size()), false, s.color, 1.6f);
    }
    // The current step: a line, and the step number under the frame.
    const float now = X(last);
    canvas.Segment({now, frameTop}, {now, frameBottom}, WithAlpha(palette::kResult, 0.7f), 1.0f);
    const std::string step = "step " + std::to_string(last);
    const ScreenPoint size = canvas.MeasureText(step, TextStyle::Label);
    const float stepX = std::clamp(now - size.x, left, std::max(left, x1 - size.x));
    canvas.Text({stepX, frameBottom + 2.0f}, step, TextStyle::Label, palette::kResult);
    // The first step held, at the frame's left end, where it keeps clear of the current one (a narrow frame, or the
    // current step the first).
    const std::string from = "step " + std::to_string(first);
    if (last != first && left + canvas.MeasureText(from, TextStyle::Label).x + 6.0f <= stepX)
    {
        canvas.Text({left, frameBottom + 2.0f}, from, TextStyle::Label, palette::kMuted);
    }
}

} // namespace

void PaintPlotsPanel(Canvas& canvas, const SimRecord& sim, float width, float top)
{
    canvas.BeginGroup("plots");
    if (sim.history.empty())
    {
        return;
    }
    const float gap = 22.0f;
    const float w = (width - 24.0f - 2.0f * gap) / 3.0f;
    const float y0 = top + 8.0f;
    const float y1 = top + kPlotsPanel - 4.0f;
    struct Titled
    {
        std::vector<std::string> title;
        std::vector<Series> series;
    };
    const Titled plots[3] = {
        {{"Energy", "(J):"},
         {{"kinetic", palette::kShapeA, [](const SimSample& s) { return s.kinetic; }},
          {"potential", palette::kShapeBInk, [](const SimSample& s) { return s.potential; }},
          {"total", palette::kInk, [](const SimSample& s) { return s.kinetic + s.potential; }}}},
        {{"Momentum", "(kg m/s):"},
         {{"x", palette::kShapeA, [](const SimSample& s) { return s.momentum.x; }},
          {"y", palette::kShapeBInk, [](const SimSample& s) { return s.momentum.y; }}}},
        {{"Deepest", "overlap", "(m):"},
         {{"depth", palette::kOverlap, [](const SimSample& s) { return s.deepestOverlap; }}}},
    };
    // The three frames start level, below the header of the most lines.
    float lastLine = y0;
    for (int i = 0; i < 3; ++i)
    {
        const float x = 12.0f + static_cast<float>(i) * (w + gap);
        lastLine = std::max(lastLine, PlotHeader(canvas, plots[i].title, plots[i].series, x, x + w, y0, false));
    }
    for (int i = 0; i < 3; ++i)
    {
        const float x = 12.0f + static_cast<float>(i) * (w + gap);
        Plot(canvas, sim.history, plots[i].title, plots[i].series, x, x + w, y0, y1, lastLine + 20.0f);
    }
}

} // namespace satviz
