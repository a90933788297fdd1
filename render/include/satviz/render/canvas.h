// SPDX-License-Identifier: MIT
// satviz render: the drawing interface the painter talks to. Screen pixels, y down; thickness in pixels.
#pragma once

#include <satviz/render/palette.h>
#include <satviz/render/view.h>

#include <string_view>

namespace satviz
{

/// The three text styles of a figure.
enum class TextStyle
{
    Label,   ///< small labels: vertex and edge numbers, values on the number line (13 px)
    Body,    ///< captions and panel text (15 px)
    Heading, ///< body names and the first words of a caption (15 px, bold)
};

/// Pixel height of a text style.
float TextSize(TextStyle style);

/// Width and height of one line of text in the figures' fonts (DejaVu Sans, bold for headings) from their advance
/// widths, as the ImGui canvas measures it: for canvases that have no font of their own (recordings, SVG).
ScreenPoint FontTextSize(std::string_view text, TextStyle style);

/// A surface the painter draws on: an ImGui draw list (the app and satviz-render), or a recording (tests).
/// Implementations must accept polygons in either winding.
class Canvas
{
  public:
    virtual ~Canvas() = default;
    /// A straight line.
    virtual void Segment(ScreenPoint a, ScreenPoint b, Color color, float thickness) = 0;
    /// A chain of segments, closed back to the first point when `closed`.
    virtual void Polyline(const ScreenPoint* points, int count, bool closed, Color color, float thickness) = 0;
    /// A filled convex polygon.
    virtual void FillConvex(const ScreenPoint* points, int count, Color color) = 0;
    /// A filled convex polygon with its outline on top: FillConvex, then a closed Polyline of the same points. A
    /// canvas may leave the fill's edges unsmoothed, since the outline covers them.
    virtual void FillOutlined(const ScreenPoint* points, int count, Color fill, Color outline, float thickness)
    {
        FillConvex(points, count, fill);
        Polyline(points, count, true, outline, thickness);
    }
    /// A circle outline.
    virtual void Circle(ScreenPoint center, float radius, Color color, float thickness) = 0;
    /// A filled disc.
    virtual void FillCircle(ScreenPoint center, float radius, Color color) = 0;
    /// A filled axis-aligned rectangle.
    virtual void FillRect(ScreenPoint min, ScreenPoint max, Color color) = 0;
    /// One line of text with its top-left corner at `topLeft`.
    virtual void Text(ScreenPoint topLeft, std::string_view text, TextStyle style, Color color) = 0;
    /// Width and height in pixels that Text would cover.
    virtual ScreenPoint MeasureText(std::string_view text, TextStyle style) = 0;
    /// Names what the following calls draw (for recordings; the default ignores it).
    virtual void BeginGroup(std::string_view name) { (void)name; }
};

} // namespace satviz
