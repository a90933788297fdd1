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
    : m_width(width), m_height(height), m_measure(measure ? std::move(measure) : TextMeasure(FontTextSize))
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
    m_body.append(text, end);
}

void SvgCanvas::Point(ScreenPoint p)
{
    Number(p.x);
    m_body += ',';
    Number(p.y);
}

void SvgCanvas::Attribute(const char* name, float value)
{
    m_body += ' ';
    m_body += name;
    m_body += "=\"";
    Number(value);
    m_body += '"';
}

void SvgCanvas::Points(const ScreenPoint* points, int count)
{
    m_body += " points=\"";
    for (int i = 0; i < count; ++i)
    {
        if (i > 0)
        {
            m_body += ' ';
        }
        Point(points[i]);
    }
    m_body += '"';
}

// `name` is "stroke" or "fill": the colour, and its alpha as a separate opacity where it is not opaque (SVG 1.1
// colours have no alpha).
void SvgCanvas::Paint(const char* name, Color color)
{
    m_body += ' ';
    m_body += name;
    m_body += "=\"";
    m_body += Hex(color);
    m_body += '"';
    if ((color & 0xFF) != 0xFF)
    {
        m_body += ' ';
        m_body += name;
        m_body += "-opacity=\"";
        Number(Opacity(color));
        m_body += '"';
    }
}

void SvgCanvas::Stroke(Color color, float thickness)
{
    Paint("stroke", color);
    Attribute("stroke-width", thickness);
}

void SvgCanvas::Segment(ScreenPoint a, ScreenPoint b, Color color, float thickness)
{
    m_body += "<line";
    Attribute("x1", a.x);
    Attribute("y1", a.y);
    Attribute("x2", b.x);
    Attribute("y2", b.y);
    Stroke(color, thickness);
    m_body += "/>\n";
}

void SvgCanvas::Polyline(const ScreenPoint* points, int count, bool closed, Color color, float thickness)
{
    if (count < 2)
    {
        return;
    }
    m_body += closed ? "<polygon" : "<polyline";
    Points(points, count);
    m_body += " fill=\"none\"";
    Stroke(color, thickness);
    m_body += " stroke-linejoin=\"round\"/>\n";
}

void SvgCanvas::FillConvex(const ScreenPoint* points, int count, Color color)
{
    if (count < 3)
    {
        return;
    }
    m_body += "<polygon";
    Points(points, count);
    Paint("fill", color);
    m_body += "/>\n";
}

void SvgCanvas::Circle(ScreenPoint center, float radius, Color color, float thickness)
{
    m_body += "<circle";
    Attribute("cx", center.x);
    Attribute("cy", center.y);
    Attribute("r", radius);
    m_body += " fill=\"none\"";
    Stroke(color, thickness);
    m_body += "/>\n";
}

void SvgCanvas::FillCircle(ScreenPoint center, float radius, Color color)
{
    m_body += "<circle";
    Attribute("cx", center.x);
    Attribute("cy", center.y);
    Attribute("r", radius);
    Paint("fill", color);
    m_body += "/>\n";
}

void SvgCanvas::FillRect(ScreenPoint min, ScreenPoint max, Color color)
{
    m_body += "<rect";
    Attribute("x", min.x);
    Attribute("y", min.y);
    Attribute("width", max.x - min.x);
    Attribute("height", max.y - min.y);
    Paint("fill", color);
    m_body += "/>\n";
}

void SvgCanvas::Text(ScreenPoint topLeft, std::string_view text, TextStyle style, Color color)
{
    m_body += "<text";
    Attribute("x", topLeft.x);
    Attribute("y", topLeft.y + SvgBaseline(style));
    Attribute("font-size", SvgFontSize(style));
    if (style == TextStyle::Heading)
    {
        m_body += " font-weight=\"bold\"";
    }
    Paint("fill", color);
    m_body += '>';
    for (const char c : text)
    {
        switch (c)
        {
        case '&':
            m_body += "&amp;";
            break;
        case '<':
            m_body += "&lt;";
            break;
        case '>':
            m_body += "&gt;";
            break;
        default:
            // Control characters are not allowed in XML 1.0; the painter never draws them.
            if (static_cast<unsigned char>(c) >= 0x20 || c == '\t')
            {
                m_body += c;
            }
        }
    }
    m_body += "</text>\n";
}

ScreenPoint SvgCanvas::MeasureText(std::string_view text, TextStyle style)
{
    return m_measure(text, style);
}

void SvgCanvas::BeginGroup(std::string_view name)
{
    if (m_groupOpen)
    {
        m_body += "</g>\n";
    }
    m_body += "<g class=\"";
    for (const char c : name)
    {
        // Group names are the painter's identifiers; anything else becomes '-' so the attribute stays valid.
        const bool plain =
            (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '-' || c == '_';
        m_body += plain ? c : '-';
    }
    m_body += "\">\n";
    m_groupOpen = true;
}

std::string SvgCanvas::Document() const
{
    std::string document = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<svg xmlns=\"http://www.w3.org/2000/svg\" "
                           "version=\"1.1\" width=\"" +
                           std::to_string(m_width) + "\" height=\"" + std::to_string(m_height) + "\" viewBox=\"0 0 " +
                           std::to_string(m_width) + " " + std::to_string(m_height) +
                           "\" font-family=\"DejaVu Sans, sans-serif\" xml:space=\"preserve\">\n";
    document += m_body;
    if (m_groupOpen)
    {
        document += "</g>\n";
    }
    document += "</svg>\n";
    return document;
}

} // namespace satviz
