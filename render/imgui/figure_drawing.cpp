// SPDX-License-Identifier: MIT
#include <satviz/render/figure_drawing.h>

namespace satviz
{

FigureDrawing::FigureDrawing(const Scene& scene, const PairStudy& study, const Figure& figure, const FigureFonts& fonts)
    : m_width(static_cast<float>(figure.view.width)), m_height(static_cast<float>(figure.view.height))
{
    ImDrawListCanvas canvas(NewList(), fonts, ImVec2(0.0f, 0.0f), [this]() { return NewList(); });
    PaintFigure(canvas, scene, study, figure);
    m_pointers.clear();
    m_data.Valid = true;
    m_data.TotalVtxCount = 0;
    m_data.TotalIdxCount = 0;
    for (const auto& list : m_lists)
    {
        m_pointers.push_back(list.get());
        m_data.TotalVtxCount += list->VtxBuffer.Size;
        m_data.TotalIdxCount += list->IdxBuffer.Size;
    }
    m_data.CmdLists = m_pointers.data();
    m_data.CmdListsCount = static_cast<int>(m_pointers.size());
    m_data.DisplayPos = ImVec2(0.0f, 0.0f);
    m_data.DisplaySize = ImVec2(m_width, m_height);
    m_data.FramebufferScale = ImVec2(1.0f, 1.0f);
}

ImDrawList* FigureDrawing::NewList()
{
    m_lists.push_back(std::make_unique<ImDrawList>(ImGui::GetDrawListSharedData()));
    ImDrawList* list = m_lists.back().get();
    list->_ResetForNewFrame();
    list->PushTextureID(ImGui::GetIO().Fonts->TexID);
    list->PushClipRect(ImVec2(0.0f, 0.0f), ImVec2(m_width, m_height));
    return list;
}

} // namespace satviz
