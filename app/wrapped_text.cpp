// SPDX-License-Identifier: MIT
#include "wrapped_text.h"

#include <satviz/render/wrap.h>

#include <algorithm>
#include <vector>

namespace satviz
{

std::string WrapToWidth(const std::string& text, float width)
{
    std::string joined;
    for (const std::string& line :
         WrapLines(text, width, [](const std::string& s) { return ImGui::CalcTextSize(s.c_str()).x; }))
    {
        joined += (joined.empty() ? "" : "\n") + line;
    }
    return joined;
}

void WrappedText(const std::string& text, ImVec4 color)
{
    const std::string wrapped = WrapToWidth(text, ImGui::GetContentRegionAvail().x);
    if (color.w > 0.0f)
    {
        ImGui::PushStyleColor(ImGuiCol_Text, color);
    }
    ImGui::TextUnformatted(wrapped.c_str());
    if (color.w > 0.0f)
    {
        ImGui::PopStyleColor();
    }
}

void WrappedTextDisabled(const std::string& text)
{
    WrappedText(text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
}

} // namespace satviz
