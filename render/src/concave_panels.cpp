// SPDX-License-Identifier: MIT
// What the figures of concave shapes share: panels framed on a world box, the caption band, pieces in colours.
#include "concave_views.h"

#include <satviz/render/wrap.h>

#include <algorithm>
#include <cmath>

namespace satviz
{

namespace
{

constexpr float kPad = 12.0f;        // padding inside the caption band, as the pair's figures
constexpr float kLineHeight = 19.0f; // caption line spacing, as the pair's figures
constexpr float kOutline = 2.0f;     // outline thickness, as the pair's figures

} // namespace

double FitZoom(const ScreenRect& rect, Vec2 low, Vec2 high, float margin)
{
    const double sizeX = std::max(high.x - low.x, 1e-12);
    const double sizeY = std::max(high.y - low.y, 1e-12);
    const double roomX = std::max(1.0, static_cast<double>(rect.maxX - rect.minX) - 2.0 * margin);
    const double roomY = std::max(1.0, static_cast<double>(rect.maxY - rect.minY) - 2.0 * margin);
    return std::max(1e-9, std::min(roomX / sizeX, roomY / sizeY));
}

Panel FramePanel(const ScreenRect& rect, Vec2 low, Vec2 high, int width, int height, float margin, double zoom)
{
    Panel panel;
    panel.rect = rect;
    panel.view.width = width;
    panel.view.height = height;
    panel.view.zoom = zoom > 0.0 ? zoom : FitZoom(rect, low, high, margin);
    // The box's middle at the rectangle's middle: ToScreen puts view.center at the image's middle.
    const Vec2 middle = 0.5 * (low + high);
    const double sx = 0.5 * (rect.minX + rect.maxX);
    const double sy = 0.5 * (rect.minY + rect.maxY);
    panel.view.center = {middle.x - (sx - 0.5 * width) / panel.view.zoom,
                         middle.y + (sy - 0.5 * height) / panel.view.zoom};
    return panel;
}

Color PieceColor(int i)
{
    // Okabe-Ito: sky blue, orange, bluish green, yellow, blue, vermillion, reddish purple.
    static constexpr Color kHues[] = {0x56B4E9FFu, 0xE69F00FFu, 0x009E73FFu, 0xF0E442FFu,
                                      0x0072B2FFu, 0xD55E00FFu, 0xCC79A7FFu};
    return kHues[static_cast<size_t>(i) % (sizeof kHues / sizeof kHues[0])];
}

namespace
{

std::vector<std::pair<std::string, TextStyle>> CaptionRows(Canvas& canvas, const std::string& title,
                                                           const std::string& text, float width)
{
    auto measure = [&](TextStyle style) {
        return [&canvas, style](const std::string& s) { return canvas.MeasureText(s, style).x; };
    };
    std::vector<std::pair<std::string, TextStyle>> rows;
    if (!title.empty())
    {
        for (const std::string& l : WrapLines(title, width - 2.0f * kPad, measure(TextStyle::Heading)))
        {
            rows.push_back({l, TextStyle::Heading});
        }
    }
    for (const std::string& l : WrapLines(text, width - 2.0f * kPad, measure(TextStyle::Body)))
    {
        rows.push_back({l, TextStyle::Body});
    }
    return rows;
}

} // namespace

int CaptionBandLines(Canvas& canvas, const std::string& title, const std::string& text, float width)
{
    return static_cast<int>(CaptionRows(canvas, title, text, width).size());
}

float DrawCaptionBand(Canvas& canvas, const std::string& title, const std::string& text, float width, int lines)
{
    const std::vector<std::pair<std::string, TextStyle>> rows = CaptionRows(canvas, title, text, width);
    const float bottom =
        kPad - 2.0f + kLineHeight * static_cast<float>(std::max(static_cast<int>(rows.size()), lines)) + 6.0f;
    canvas.BeginGroup("caption");
    canvas.FillRect({0.0f, 0.0f}, {width, bottom}, palette::kPanel);
    canvas.Segment({0.0f, bottom}, {width, bottom}, palette::kFaint, 1.0f);
    float y = kPad - 2.0f;
    for (const auto& [line, style] : rows)
    {
        canvas.Text({kPad, y}, line, style, palette::kInk);
        y += kLineHeight;
    }
    return bottom;
}

float DrawBackgroundAndCaption(Canvas& canvas, LabelPlacer& labels, const Figure& figure, const std::string& text,
                               int lines)
{
    const float width = static_cast<float>(figure.view.width);
    const float height = static_cast<float>(figure.view.height);
    canvas.BeginGroup("background");
    canvas.FillRect({0.0f, 0.0f}, {width, height}, palette::kBackground);
    const float top =
        (figure.layers & kLayerCaption) ? DrawCaptionBand(canvas, figure.caption, text, width, lines) : 0.0f;
    labels.ReserveBand({0.0f, 0.0f, width, top});
    return top;
}

void DrawPieces(Canvas& canvas, const View& view, const std::vector<ConvexPiece>& pieces, const Transform& xf,
                const ScreenRect& bounds)
{
    for (size_t i = 0; i < pieces.size(); ++i)
    {
        std::vector<ScreenPoint> points;
        for (const Vec2& v : pieces[i].polygon.Vertices())
        {
            points.push_back(ToScreen(view, TransformPoint(xf, v)));
        }
        canvas.FillConvex(points.data(), static_cast<int>(points.size()),
                          WithAlpha(PieceColor(static_cast<int>(i)), 0.45f));
    }
    for (const ConvexPiece& piece : pieces)
    {
        const Vec2Span<double> v = piece.polygon.Vertices();
        const int n = v.count;
        for (int e = 0; e < n; ++e)
        {
            const ScreenPoint a = ToScreen(view, TransformPoint(xf, v[e]));
            const ScreenPoint b = ToScreen(view, TransformPoint(xf, v[(e + 1) % n]));
            if (!piece.internal[static_cast<size_t>(e)])
            {
                canvas.Segment(a, b, palette::kInk, kOutline);
            }
            else if (piece.source[static_cast<size_t>(e)] < piece.source[static_cast<size_t>((e + 1) % n)])
            {
                DashedSegment(canvas, a, b, palette::kInk, 1.5f, bounds, 6.0f, 4.0f);
            }
        }
    }
}

std::vector<Vec2> BodyOutline(const Body& body)
{
    if (body.IsConcave())
    {
        return body.outline;
    }
    if (body.shape.type == ShapeType::Polygon)
    {
        const Vec2Span<double> v = body.shape.polygon.Vertices();
        return {v.begin(), v.end()};
    }
    return {};
}

} // namespace satviz
