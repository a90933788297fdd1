// SPDX-License-Identifier: MIT
// satviz render, private: drawing helpers the painter builds on (dashes, arrows, outlines, label placement).
#pragma once

#include <satviz/render/canvas.h>
#include <satviz/shape.h>

#include <string>
#include <string_view>
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

/// A dashed line, clipped to `bounds` first so that no off-screen dash is generated.
void DashedSegment(Canvas& canvas, ScreenPoint a, ScreenPoint b, Color color, float thickness, const ScreenRect& bounds,
                   float dash = 7.0f, float gap = 5.0f);

/// A line from a to b with a filled triangular head at b.
void Arrow(Canvas& canvas, ScreenPoint a, ScreenPoint b, Color color, float thickness, float head = 10.0f);

/// The outline of a shape placed by xf, in screen points. Polygon vertices closer than half a pixel to the last
/// kept one are merged (a 4096-gon a few hundred pixels wide needs far fewer points); circles get a number of
/// points that keeps the chord error below a quarter pixel.
std::vector<ScreenPoint> ShapeOutline(const View& view, const Shape& shape, const Transform& xf);

/// A closed dashed outline.
void DashedOutline(Canvas& canvas, const std::vector<ScreenPoint>& outline, Color color, float thickness,
                   const ScreenRect& bounds);

/// Places labels so that they do not cover each other: each label tries eight positions around its anchor, and
/// labels placed earlier win. Labels are drawn by Flush, above everything else, on a faint halo of the background.
class LabelPlacer
{
  public:
    /// A placer for an image of the given size.
    LabelPlacer(Canvas& canvas, float width, float height);
    /// Marks a region as taken (panels, the caption).
    void Reserve(const ScreenRect& rect);
    /// Places `text` near `anchor`, `distance` pixels away, preferring the direction (dx, dy) (any length); takes
    /// the first free of eight positions around the anchor, at three distances. When none is free, an optional
    /// label is left out and any other takes the preferred position.
    void Place(ScreenPoint anchor, std::string_view text, TextStyle style, Color color, float dx, float dy,
               float distance = 6.0f, bool optional = false);
    /// Draws the placed labels, in the group "labels".
    void Flush(Color halo);

  private:
    struct Label
    {
        ScreenRect rect;
        std::string text;
        TextStyle style;
        Color color;
    };
    Canvas& canvas_;
    float width_;
    float height_;
    std::vector<ScreenRect> taken_;
    std::vector<Label> labels_;
};

} // namespace satviz
