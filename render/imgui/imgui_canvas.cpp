// SPDX-License-Identifier: MIT
#include <satviz/render/imgui_canvas.h>

#include <cfloat>
#include <fstream>

namespace satviz
{

namespace
{

ImU32 ToImColor(Color color)
{
    return IM_COL32((color >> 24) & 0xFF, (color >> 16) & 0xFF, (color >> 8) & 0xFF, color & 0xFF);
}

// Vertices an anti-aliased call may add: generous, so that a list never passes the 16-bit index limit.
int Estimate(int points)
{
    return 8 * points + 64;
}

} // namespace

bool AddFigureFonts(ImFontAtlas& atlas, FigureFonts& fonts, std::string& error)
{
    for (const char* path : {kFigureFontPath, kFigureBoldFontPath})
    {
        if (!std::ifstream(path))
        {
            error = std::string(path) + ": font file not found (install the fonts-dejavu-core package)";
            return false;
        }
    }
    ImFontConfig config;
    config.OversampleH = 3;
    config.OversampleV = 2;
    fonts.label = atlas.AddFontFromFileTTF(kFigureFontPath, TextSize(TextStyle::Label), &config);
    fonts.body = atlas.AddFontFromFileTTF(kFigureFontPath, TextSize(TextStyle::Body), &config);
    fonts.heading = atlas.AddFontFromFileTTF(kFigureBoldFontPath, TextSize(TextStyle::Heading), &config);
    if (fonts.label == nullptr || fonts.body == nullptr || fonts.heading == nullptr)
    {
        error = std::string(kFigureFontPath) + ": could not load the font";
        return false;
    }
    return true;
}

ImDrawListCanvas::ImDrawListCanvas(ImDrawList* list, const FigureFonts& fonts, ImVec2 origin,
                                   std::function<ImDrawList*()> more)
    : m_list(list), m_more(std::move(more)), m_fonts(fonts), m_origin(origin)
{
}

ImDrawList* ImDrawListCanvas::Target(int vertices)
{
    constexpr int kLimit = 65535;
    if (m_list->_VtxCurrentIdx + static_cast<unsigned>(vertices) < kLimit)
    {
        return m_list;
    }
    if (m_more && vertices < kLimit)
    {
        if (ImDrawList* next = m_more())
        {
            m_list = next;
            return m_list;
        }
    }
    ++m_dropped;
    return nullptr;
}

ImFont* ImDrawListCanvas::FontOf(TextStyle style) const
{
    switch (style)
    {
    case TextStyle::Label:
        return m_fonts.label;
    case TextStyle::Body:
        return m_fonts.body;
    case TextStyle::Heading:
        return m_fonts.heading;
    }
    return m_fonts.body;
}

void ImDrawListCanvas::Segment(ScreenPoint a, ScreenPoint b, Color color, float thickness)
{
    if (ImDrawList* list = Target(Estimate(2)))
    {
        list->AddLine(P(a), P(b), ToImColor(color), thickness);
    }
}

void ImDrawListCanvas::Polyline(const ScreenPoint* points, int count, bool closed, Color color, float thickness)
{
    if (count < 2)
    {
        return;
    }
    if (ImDrawList* list = Target(Estimate(count)))
    {
        m_scratch.resize(count);
        for (int i = 0; i < count; ++i)
        {
            m_scratch[i] = P(points[i]);
        }
        list->AddPolyline(m_scratch.Data, count, ToImColor(color), closed ? ImDrawFlags_Closed : ImDrawFlags_None,
                          thickness);
    }
}

void ImDrawListCanvas::FillConvex(const ScreenPoint* points, int count, Color color)
{
    if (count < 3)
    {
        return;
    }
    ImDrawList* list = Target(Estimate(count));
    if (list == nullptr)
    {
        return;
    }
    // Anti-aliased fills need clockwise order on screen (positive shoelace sum with y down).
    double area = 0.0;
    for (int i = 0; i < count; ++i)
    {
        const ScreenPoint& p = points[i];
        const ScreenPoint& q = points[(i + 1) % count];
        area += static_cast<double>(p.x) * q.y - static_cast<double>(q.x) * p.y;
    }
    m_scratch.resize(count);
    for (int i = 0; i < count; ++i)
    {
        m_scratch[i] = P(points[area >= 0.0 ? i : count - 1 - i]);
    }
    list->AddConvexPolyFilled(m_scratch.Data, count, ToImColor(color));
}

void ImDrawListCanvas::FillOutlined(const ScreenPoint* points, int count, Color fill, Color outline, float thickness)
{
    if (!m_plainUnderOutlines || count < 3)
    {
        Canvas::FillOutlined(points, count, fill, outline, thickness);
        return;
    }
    if (ImDrawList* list = Target(Estimate(count)))
    {
        const ImDrawListFlags flags = list->Flags;
        list->Flags &= ~ImDrawListFlags_AntiAliasedFill;
        FillConvex(points, count, fill);
        list->Flags = flags;
    }
    Polyline(points, count, true, outline, thickness);
}

void ImDrawListCanvas::Circle(ScreenPoint center, float radius, Color color, float thickness)
{
    if (ImDrawList* list = Target(Estimate(128)))
    {
        list->AddCircle(P(center), radius, ToImColor(color), 0, thickness);
    }
}

void ImDrawListCanvas::FillCircle(ScreenPoint center, float radius, Color color)
{
    if (ImDrawList* list = Target(Estimate(128)))
    {
        list->AddCircleFilled(P(center), radius, ToImColor(color), 0);
    }
}

void ImDrawListCanvas::FillRect(ScreenPoint min, ScreenPoint max, Color color)
{
    if (m_clear != nullptr && (color & 0xFFu) == 0xFFu && (max.x - min.x) * (max.y - min.y) >= kClearArea)
    {
        if (ImDrawList* list = Target(4))
        {
            list->PushClipRect(P(min), P(max), true);
            list->AddCallback(m_clear, reinterpret_cast<void*>(static_cast<uintptr_t>(color)));
            list->PopClipRect();
            return;
        }
    }
    if (ImDrawList* list = Target(Estimate(4)))
    {
        list->AddRectFilled(P(min), P(max), ToImColor(color));
    }
}

void ImDrawListCanvas::Text(ScreenPoint topLeft, std::string_view text, TextStyle style, Color color)
{
    if (ImDrawList* list = Target(Estimate(4 * static_cast<int>(text.size()))))
    {
        ImFont* font = FontOf(style);
        list->AddText(font, font->FontSize, P(topLeft), ToImColor(color), text.data(), text.data() + text.size());
    }
}

ScreenPoint ImDrawListCanvas::MeasureText(std::string_view text, TextStyle style)
{
    ImFont* font = FontOf(style);
    const ImVec2 size = font->CalcTextSizeA(font->FontSize, FLT_MAX, 0.0f, text.data(), text.data() + text.size());
    return {size.x, size.y};
}

} // namespace satviz
