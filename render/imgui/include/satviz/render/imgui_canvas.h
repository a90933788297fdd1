// SPDX-License-Identifier: MIT
// satviz render: the Canvas on Dear ImGui draw lists, shared by the app and satviz-render, and the fonts of the
// figures. The only render header that includes imgui.h.
#pragma once

#include <satviz/render/canvas.h>

#include <imgui.h>

#include <cstdint>
#include <functional>
#include <string>

namespace satviz
{

/// The regular and bold DejaVu Sans files of Debian's fonts-dejavu-core.
constexpr const char* kFigureFontPath = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";
/// The bold face.
constexpr const char* kFigureBoldFontPath = "/usr/share/fonts/truetype/dejavu/DejaVuSans-Bold.ttf";

/// The fonts a figure is drawn with, one per TextStyle.
struct FigureFonts
{
    ImFont* label = nullptr;   ///< TextStyle::Label
    ImFont* body = nullptr;    ///< TextStyle::Body
    ImFont* heading = nullptr; ///< TextStyle::Heading
};

/// Adds the figure fonts to an atlas (before it is built). Returns false, with a one-line error naming the file,
/// when a font file is missing.
bool AddFigureFonts(ImFontAtlas& atlas, FigureFonts& fonts, std::string& error);

/// Draws on an ImGui draw list. With 16-bit indices a draw list holds at most 65 536 vertices, so when a list
/// fills up the canvas asks `more` for the next one (drawn above it); without one, what does not fit is dropped
/// and counted.
class ImDrawListCanvas : public Canvas
{
  public:
    /// A canvas whose screen origin (0, 0) is at `origin` on the draw list.
    ImDrawListCanvas(ImDrawList* list, const FigureFonts& fonts, ImVec2 origin = {0, 0},
                     std::function<ImDrawList*()> more = {});

    void Segment(ScreenPoint a, ScreenPoint b, Color color, float thickness) override;
    void Polyline(const ScreenPoint* points, int count, bool closed, Color color, float thickness) override;
    void FillConvex(const ScreenPoint* points, int count, Color color) override;
    void FillOutlined(const ScreenPoint* points, int count, Color fill, Color outline, float thickness) override;
    void Circle(ScreenPoint center, float radius, Color color, float thickness) override;
    void FillCircle(ScreenPoint center, float radius, Color color) override;
    void FillRect(ScreenPoint min, ScreenPoint max, Color color) override;
    void Text(ScreenPoint topLeft, std::string_view text, TextStyle style, Color color) override;
    ScreenPoint MeasureText(std::string_view text, TextStyle style) override;

    /// Number of calls dropped because both draw lists were full.
    int Dropped() const { return m_dropped; }
    /// Has `clear` fill the opaque rectangles of at least kClearArea pixels (the figure's ground, its panels): the
    /// renderer calls it in the list's order with the command's ClipRect the rectangle and its UserCallbackData
    /// the colour (RGBA, as a Color), and it fills them without shading each pixel (a scissored glClear), which a
    /// software rasterizer does many times faster than two blended, textured triangles. Null: triangles.
    void ClearLargeRects(ImDrawCallback clear) { m_clear = clear; }
    /// Fills FillOutlined's polygons without ImGui's anti-aliased fringe, under their anti-aliased outline: two
    /// triangles fewer per edge, each a thin sliver a software rasterizer pays for, and no visible change. Off by
    /// default, so that satviz-render's figures keep the fringe they were drawn with.
    void PlainFillsUnderOutlines(bool plain) { m_plainUnderOutlines = plain; }
    /// Least area, in pixels, of a rectangle that ClearLargeRects fills by clearing.
    static constexpr float kClearArea = 4096.0f;

  private:
    ImDrawList* Target(int vertices);
    ImVec2 P(ScreenPoint p) const { return {p.x + m_origin.x, p.y + m_origin.y}; }
    ImFont* FontOf(TextStyle style) const;

    ImDrawList* m_list;
    std::function<ImDrawList*()> m_more;
    FigureFonts m_fonts;
    ImVec2 m_origin;
    ImVector<ImVec2> m_scratch;
    int m_dropped = 0;
    ImDrawCallback m_clear = nullptr;
    bool m_plainUnderOutlines = false;
};

/// The colour a ClearLargeRects callback receives in ImDrawCmd::UserCallbackData.
inline Color ClearColorOf(const ImDrawCmd& command)
{
    return static_cast<Color>(reinterpret_cast<uintptr_t>(command.UserCallbackData));
}

} // namespace satviz
