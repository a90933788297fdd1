// SPDX-License-Identifier: MIT
// satviz render: one figure in standalone ImGui draw lists, ready for a renderer backend. satviz-render and the
// app's PNG export both draw figures this way, so the same scene gives the same triangles and the same pixels.
#pragma once

#include <satviz/render/figure.h>
#include <satviz/render/imgui_canvas.h>

#include <memory>
#include <vector>

namespace satviz
{

/// A painted figure: as many draw lists as its vertices need (16-bit indices), and the ImDrawData over them with
/// the display at (0, 0) and the figure's size.
class FigureDrawing
{
  public:
    /// Paints the figure. Needs a current ImGui context between NewFrame and Render, whose font atlas holds the
    /// figure fonts.
    FigureDrawing(const Scene& scene, const PairStudy& study, const Figure& figure, const FigureFonts& fonts);
    FigureDrawing(const FigureDrawing&) = delete;
    FigureDrawing& operator=(const FigureDrawing&) = delete;
    /// The draw data to hand to a renderer backend.
    ImDrawData* DrawData() { return &m_data; }

  private:
    ImDrawList* NewList();

    float m_width;
    float m_height;
    std::vector<std::unique_ptr<ImDrawList>> m_lists;
    std::vector<ImDrawList*> m_pointers;
    ImDrawData m_data;
};

} // namespace satviz
