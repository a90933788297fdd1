// SPDX-License-Identifier: MIT
#include <satviz/render/figure_drawing.h>

namespace satviz
{

FigureDrawing::FigureDrawing(const Scene& scene, const PairStudy& study, const Figure& figure, const FigureFonts& fonts)
    : width_(static_cast<float>(figure.view.width)), height_(static_cast<float>(figure.view.height))
{
    ImDrawListCanvas canvas(NewList(), fonts, ImVec2(0.0f, 0.0f), [this]() { return NewList(); });
    PaintFigure(canvas, scene, study, figure);
    pointers_.clear();
    data_.Valid = true;
    data_.TotalVtxCount = 0;
    data_.TotalIdxCount = 0;
    for (const auto& list : lists_)
    {
        pointers_.push_back(list.get());
        data_.TotalVtxCount += list->VtxBuffer.Size;
        data_.TotalIdxCount += list->IdxBuffer.Size;
    }
    data_.CmdLists = pointers_.data();
    data_.CmdListsCount = static_cast<int>(pointers_.size());
    data_.DisplayPos = ImVec2(0.0f, 0.0f);
    data_.DisplaySize = ImVec2(width_, height_);
    data_.FramebufferScale = ImVec2(1.0f, 1.0f);
}

ImDrawList* FigureDrawing::NewList()
{
    lists_.push_back(std::make_unique<ImDrawList>(ImGui::GetDrawListSharedData()));
    ImDrawList* list = lists_.back().get();
    list->_ResetForNewFrame();
    list->PushTextureID(ImGui::GetIO().Fonts->TexID);
    list->PushClipRect(ImVec2(0.0f, 0.0f), ImVec2(width_, height_));
    return list;
}

} // namespace satviz
