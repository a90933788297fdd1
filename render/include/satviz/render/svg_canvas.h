// SPDX-License-Identifier: MIT
// satviz render: a canvas that writes the figure as SVG, for slides and print. The painter draws on it exactly as on
// the ImGui canvas, so the figure has the same layers, colours and layout; text stays text (DejaVu Sans, the font of
// the PNG figures), so it can be selected and searched. The bytes depend only on the drawing calls: every number is
// printed with two decimals (a hundredth of a pixel), in the C locale, whatever the environment's.
#pragma once

#include <satviz/render/canvas.h>

#include <functional>
#include <string>

namespace satviz
{

/// Measures text as the canvas that lays out the figure would (the ImGui fonts in satviz-render and the app): the
/// painter places labels by these sizes, so the SVG's layout matches the PNG's only when they agree.
using TextMeasure = std::function<ScreenPoint(std::string_view text, TextStyle style)>;

/// Records drawing calls as SVG elements. Each BeginGroup opens a <g class="NAME">, so a figure's layers can be
/// picked out (and hidden) in an editor.
class SvgCanvas : public Canvas
{
  public:
    /// A width x height canvas whose text is measured by `measure` (FontTextSize when empty).
    SvgCanvas(int width, int height, TextMeasure measure = {});

    void Segment(ScreenPoint a, ScreenPoint b, Color color, float thickness) override;
    void Polyline(const ScreenPoint* points, int count, bool closed, Color color, float thickness) override;
    void FillConvex(const ScreenPoint* points, int count, Color color) override;
    void Circle(ScreenPoint center, float radius, Color color, float thickness) override;
    void FillCircle(ScreenPoint center, float radius, Color color) override;
    void FillRect(ScreenPoint min, ScreenPoint max, Color color) override;
    void Text(ScreenPoint topLeft, std::string_view text, TextStyle style, Color color) override;
    ScreenPoint MeasureText(std::string_view text, TextStyle style) override;
    void BeginGroup(std::string_view name) override;

    /// The whole document: the XML declaration, the <svg> element with the figure's size, and every element drawn.
    std::string Document() const;

  private:
    void Number(float value);
    void Point(ScreenPoint p);
    void Attribute(const char* name, float value);
    void Points(const ScreenPoint* points, int count);
    void Paint(const char* name, Color color);
    void Stroke(Color color, float thickness);

    int m_width;
    int m_height;
    TextMeasure m_measure;
    std::string m_body;
    bool m_groupOpen = false;
};

/// The font size in an SVG file for a text style. The figure fonts are loaded by pixel height, ascent to descent
/// (stb_truetype's rule, which ImGui uses): DejaVu Sans is 2384 units from ascent to descent and 2048 to the em,
/// so a 13 px label is an 11.17 px em.
float SvgFontSize(TextStyle style);

/// Pixels from the top of a line of text to its baseline: ImGui puts the baseline at the font's ascent (1901 of
/// 2384 units) floored after adding one pixel.
float SvgBaseline(TextStyle style);

} // namespace satviz
