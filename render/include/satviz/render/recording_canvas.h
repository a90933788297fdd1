// SPDX-License-Identifier: MIT
// satviz render: a canvas that records what is drawn, for tests that check each view without GL.
#pragma once

#include <satviz/render/canvas.h>

#include <string>
#include <vector>

namespace satviz
{

/// One recorded drawing call.
struct DrawCommand
{
    /// The kind of call.
    enum class Kind
    {
        Segment,
        Polyline,
        FillConvex,
        Circle,
        FillCircle,
        FillRect,
        Text,
    };
    Kind kind = Kind::Segment;          ///< which Canvas call
    std::string group;                  ///< the group named by the last BeginGroup
    std::vector<ScreenPoint> points;    ///< the points (circles: the centre; rectangles: min and max)
    Color color = 0;                    ///< colour
    float thickness = 0.0f;             ///< line thickness (circles: the radius is in `radius`)
    float radius = 0.0f;                ///< circle radius
    bool closed = false;                ///< polylines: closed
    std::string text;                   ///< text calls: the text
    TextStyle style = TextStyle::Label; ///< text calls: the style
};

/// Records every call. Text is measured with the advance widths of the figures' fonts (DejaVu Sans, bold for
/// headings), size high, so that labels land where they do in the rendered figures.
class RecordingCanvas : public Canvas
{
  public:
    std::vector<DrawCommand> commands; ///< every call, in order

    void Segment(ScreenPoint a, ScreenPoint b, Color color, float thickness) override;
    void Polyline(const ScreenPoint* points, int count, bool closed, Color color, float thickness) override;
    void FillConvex(const ScreenPoint* points, int count, Color color) override;
    void Circle(ScreenPoint center, float radius, Color color, float thickness) override;
    void FillCircle(ScreenPoint center, float radius, Color color) override;
    void FillRect(ScreenPoint min, ScreenPoint max, Color color) override;
    void Text(ScreenPoint topLeft, std::string_view text, TextStyle style, Color color) override;
    ScreenPoint MeasureText(std::string_view text, TextStyle style) override;
    void BeginGroup(std::string_view name) override;

    /// The commands drawn in a group.
    std::vector<const DrawCommand*> InGroup(std::string_view name) const;
    /// All text drawn, in order, one string per Text call.
    std::vector<std::string> Texts() const;

  private:
    DrawCommand& Add(DrawCommand::Kind kind, Color color);
    std::string m_group;
};

} // namespace satviz
