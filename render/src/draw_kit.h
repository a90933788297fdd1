// SPDX-License-Identifier: MIT
// satviz render, private: drawing helpers the painter builds on (dashes, arrows, outlines).
#pragma once

#include <satviz/render/canvas.h>
#include <satviz/shape.h>

#include <string>
#include <vector>

namespace satviz
{

/// An axis-aligned screen rectangle.
struct ScreenRect
{
    float minX = 0.0f, minY = 0.0f, maxX = 0.0f, maxY = 0.0f;
    /// True when the two rectangles share interior.
    bool Overlaps(const ScreenRect& other) const
    {
        return minX < other.maxX && other.minX < maxX && minY < other.maxY && other.minY < maxY;
    }
};

/// Clips the segment ab to the rectangle (Liang-Barsky); false when nothing is left.
bool ClipSegment(ScreenPoint& a, ScreenPoint& b, const ScreenRect& rect);

/// The distance from p to the segment ab, in pixels.
float DistanceToSegment(ScreenPoint p, ScreenPoint a, ScreenPoint b);

/// A dashed line, clipped to `bounds` first so that no off-screen dash is generated.
void DashedSegment(Canvas& canvas, ScreenPoint a, ScreenPoint b, Color color, float thickness, const ScreenRect& bounds,
                   float dash = 7.0f, float gap = 5.0f);

/// A line from a to b with a filled triangular head at b; returns the rectangle around the head (labels keep off
/// it).
ScreenRect Arrow(Canvas& canvas, ScreenPoint a, ScreenPoint b, Color color, float thickness, float head = 10.0f);

/// The outline of a shape placed by xf, in screen points. Polygon vertices closer than half a pixel to the last
/// kept one are merged (a 4096-gon a few hundred pixels wide needs far fewer points); circles get a number of
/// points that keeps the chord error below a quarter pixel.
std::vector<ScreenPoint> ShapeOutline(const View& view, const Shape& shape, const Transform& xf);

/// A closed dashed outline: the dash pattern restarts at each corner and runs on around a curve.
void DashedOutline(Canvas& canvas, const std::vector<ScreenPoint>& outline, Color color, float thickness,
                   const ScreenRect& bounds);

/// The header of one of a two-panel figure's panels (a slice's, a decomposition's): a title and a subtitle under it,
/// the subtitle broken between words into lines that fit the panel (`panelWidth` wide, its text 12 pixels in) as
/// the figures' fonts measure them, so that on a narrow canvas none runs past the panel's edge.
struct PanelHeader
{
    std::vector<std::string> lines; ///< the subtitle's lines
    float height = 0.0f;            ///< from the band's bottom to the panel's top: 40 pixels for one line
};

/// The header of a panel `panelWidth` wide whose subtitle is `subtitle`.
PanelHeader LayOutPanelHeader(const std::string& subtitle, float panelWidth);

/// Draws a panel's title at (x, top + 6) and the subtitle's lines under it.
void DrawPanelHeader(Canvas& canvas, float x, float top, const std::string& title, const PanelHeader& header);

} // namespace satviz
