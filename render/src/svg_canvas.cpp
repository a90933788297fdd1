// SPDX-License-Identifier: MIT
#include <satviz/render/svg_canvas.h>

#include <charconv>
#include <cmath>

namespace satviz
{

namespace
{

// DejaVu Sans's vertical metrics, in font units (regular and bold share them).
constexpr float kAscent = 1901.0f;
constexpr float kDescent = 483.0f;
constexpr float kUnitsPerEm = 2048.0f;

const char* Hex(Color color)
{
    static thread_local char text[8];
    static const char digits[] = "0123456789abcdef";
    text[0] = '#';
    for (int i = 0; i < 6; ++i)
    {
        text[1 + i] = digits[(color >> (28 - 4 * i)) & 0xF];
    }
    text[7] = '\0';
    return text;
}

float Opacity(Color color)
{
    return static_cast<float>(color & 0xFF) / 255.0f;
}

} // namespace

float SvgFontSize(TextStyle style)
{
    return TextSize(style) * kUnitsPerEm / (kAscent + kDescent);
}

float SvgBaseline(TextStyle style)
{
    return std::floor(TextSize(style) * kAscent / (kAscent + kDescent) + 1.0f);
}

SvgCanvas::SvgCanvas(int width, int height, TextMeasure measure)
    : width_(width), height_(height), measure_(measure ? std::move(measure) : TextMeasure(FontTextSize))
{
}

// Two decimals, trailing zeros dropped, "-0" as "0": to_chars is locale-independent and exact for a given float.
void SvgCanvas::Number(float value)
{
    if (!std::isfinite(value))
    {
        value = 0.0f;
    }
    const double rounded = std::round(static_cast<double>(value) * 100.0) / 100.0;
    char text[48];
    auto [end, code] =
        std::to_chars(text, text + sizeof(text), rounded == 0.0 ? 0.0 : rounded, std::chars_format::fixed, 2);
    (void)code;
    while (end > text && end[-1] == '0')
    {
        --end;
    }
    if (end > text && end[-1] == '.')
    {
        --end;
    }
    body_.append(text, end);
}

void SvgCanvas::Point(ScreenPoint p)
{
    Number(p.x);
    body_ += ',';
    Number(p.y);
}

void SvgCanvas::Stroke(Color color, float thickness)
{
    body_ += " stroke=\"";
    body_ += Hex(color);
    body_ += '"';
    if ((color & 0xFF) != 0xFF)
    {
        body_ += " stroke-opacity=\"";
        Number(Opacity(color));
        body_ += '"';
    }
    body_ += " stroke-width=\"";
    Number(thickness);
    body_ += '"';
}

void SvgCanvas::Fill(Color color)
{
    body_ += " fill=\"";
    body_ += Hex(color);
    body_ += '"';
    if ((color & 0xFF) != 0xFF)
    {
        body_ += " fill-opacity=\"";
        Number(Opacity(color));
        body_ += '"';
    }
}

void SvgCanvas::Segment(ScreenPoint a, ScreenPoint b, Color color, float thickness)
{
    body_ += "<line x1=\"";
    Number(a.x);
    body_ += "\" y1=\"";
    Number(a.y);
    body_ += "\" x2=\"";
    Number(b.x);
    body_ += "\" y2=\"";
    Number(b.y);
    body_ += '"';
    Stroke(color, thickness);
    body_ += "/>\n";
}

void SvgCanvas::Polyline(const ScreenPoint* points, int count, bool closed, Color color, float thickness)
{
    if (count < 2)
    {
        return;
    }
    body_ += closed ? "<polygon points=\"" : "<polyline points=\"";
    for (int i = 0; i < count; ++i)
    {
        if (i > 0)
        {
            body_ += ' ';
        }
        Point(points[i]);
    }
    body_ += "\" fill=\"none\"";
    Stroke(color, thickness);
    body_ += " stroke-linejoin=\"round\"/>\n";
}

void SvgCanvas::FillConvex(const ScreenPoint* points, int count, Color color)
{
    if (count < 3)
    {
        return;
    }
    body_ += "<polygon points=\"";
    for (int i = 0; i < count; ++i)
    {
        if (i > 0)
        {
            body_ += ' ';
        }
        Point(points[i]);
    }
    body_ += '"';
    Fill(color);
    body_ += "/>\n";
}

void SvgCanvas::Circle(ScreenPoint center, float radius, Color color, float thickness)
{
    body_ += "<circle cx=\"";
    Number(center.x);
    body_ += "\" cy=\"";
    Number(center.y);
    body_ += "\" r=\"";
    Number(radius);
    body_ += "\" fill=\"none\"";
    Stroke(color, thickness);
    body_ += "/>\n";
}

void SvgCanvas::FillCircle(ScreenPoint center, float radius, Color color)
{
    body_ += "<circle cx=\"";
    Number(center.x);
    body_ += "\" cy=\"";
    Number(center.y);
    body_ += "\" r=\"";
    Number(radius);
    body_ += '"';
    Fill(color);
    body_ += "/>\n";
}

void SvgCanvas::FillRect(ScreenPoint min, ScreenPoint max, Color color)
{
    body_ += "<rect x=\"";
    Number(min.x);
    body_ += "\" y=\"";
    Number(min.y);
    body_ += "\" width=\"";
    Number(max.x - min.x);
    body_ += "\" height=\"";
    Number(max.y - min.y);
    body_ += '"';
    Fill(color);
    body_ += "/>\n";
}

void SvgCanvas::Text(ScreenPoint topLeft, std::string_view text, TextStyle style, Color color)
{
    body_ += "<text x=\"";
    Number(topLeft.x);
    body_ += "\" y=\"";
    Number(topLeft.y + SvgBaseline(style));
    body_ += "\" font-size=\"";
    Number(SvgFontSize(style));
    body_ += '"';
    if (style == TextStyle::Heading)
    {
        body_ += " font-weight=\"bold\"";
    }
    Fill(color);
    body_ += '>';
    for (const char c : text)
    {
        switch (c)
        {
        case '&':
            body_ += "&amp;";
            break;
        case '<':
            body_ += "&lt;";
            break;
        case '>':
            body_ += "&gt;";
            break;
        default:
            // Control characters are not allowed in XML 1.0; the painter never draws them.
            if (static_cast<unsigned char>(c) >= 0x20 || c == '\t')
            {
                body_ += c;
            }
        }
    }
    body_ += "</text>\n";
}

ScreenPoint SvgCanvas::MeasureText(std::string_view text, TextStyle style)
{
    return measure_(text, style);
}

void SvgCanvas::BeginGroup(std::string_view name)
{
    if (groupOpen_)
    {
        body_ += "</g>\n";
    }
    body_ += "<g class=\"";
    for (const char c : name)
    {
        // Group names are the painter's identifiers; anything else becomes '-' so the attribute stays valid.
        const bool plain =
            (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '-' || c == '_';
        body_ += plain ? c : '-';
    }
    body_ += "\">\n";
    groupOpen_ = true;
}

std::string SvgCanvas::Document() const
{
    std::string document = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<svg xmlns=\"http://www.w3.org/2000/svg\" "
                           "version=\"1.1\" width=\"" +
                           std::to_string(width_) + "\" height=\"" + std::to_string(height_) + "\" viewBox=\"0 0 " +
                           std::to_string(width_) + " " + std::to_string(height_) +
                           "\" font-family=\"DejaVu Sans, sans-serif\" xml:space=\"preserve\">\n";
    document += body_;
    if (groupOpen_)
    {
        document += "</g>\n";
    }
    document += "</svg>\n";
    return document;
}

} // namespace satviz
