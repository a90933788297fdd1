// SPDX-License-Identifier: MIT
#include <satviz/render/recording_canvas.h>

namespace satviz
{

namespace
{

// Advance widths of the printable ASCII characters (space to '~') in the figures' fonts, DejaVu Sans and DejaVu Sans
// Bold, in font units; a font of pixel size s draws a unit as s / 2384 pixels (2384: the fonts' ascent plus
// descent), as Dear ImGui scales them. Measuring with them, a recording places labels where the PNG figures do.
constexpr int kRegular[95] = {
    651, 821, 942, 1716, 1303, 1946, 1597, 563, 799, 799, 1024, 1716, 651, 739, 651, 690,
    1303, 1303, 1303, 1303, 1303, 1303, 1303, 1303, 1303, 1303, 690, 690, 1716, 1716, 1716, 1087,
    2048, 1401, 1405, 1430, 1577, 1294, 1178, 1587, 1540, 604, 604, 1343, 1141, 1767, 1532, 1612,
    1235, 1612, 1423, 1300, 1251, 1499, 1401, 2025, 1403, 1251, 1403, 799, 690, 799, 1716, 1024,
    1024, 1255, 1300, 1126, 1300, 1260, 721, 1300, 1298, 569, 569, 1186, 569, 1995, 1298, 1253,
    1300, 1300, 842, 1067, 803, 1298, 1212, 1675, 1212, 1212, 1075, 1303, 690, 1303, 1716};
constexpr int kBold[95] = {
    713, 934, 1067, 1716, 1425, 2052, 1786, 627, 936, 936, 1071, 1716, 778, 850, 778, 748,
    1425, 1425, 1425, 1425, 1425, 1425, 1425, 1425, 1425, 1425, 819, 819, 1716, 1716, 1716, 1188,
    2048, 1585, 1561, 1503, 1700, 1399, 1399, 1681, 1714, 762, 762, 1587, 1305, 2038, 1714, 1741,
    1501, 1741, 1577, 1475, 1397, 1663, 1585, 2259, 1579, 1483, 1485, 936, 748, 936, 1716, 1024,
    1024, 1382, 1466, 1214, 1466, 1389, 891, 1466, 1458, 702, 702, 1362, 702, 2134, 1458, 1407,
    1466, 1466, 1010, 1219, 979, 1458, 1335, 1892, 1321, 1335, 1192, 1458, 748, 1458, 1716};
constexpr float kUnitsPerLine = 2384.0f;

} // namespace

DrawCommand& RecordingCanvas::Add(DrawCommand::Kind kind, Color color)
{
    DrawCommand& command = commands.emplace_back();
    command.kind = kind;
    command.group = group_;
    command.color = color;
    return command;
}

void RecordingCanvas::Segment(ScreenPoint a, ScreenPoint b, Color color, float thickness)
{
    DrawCommand& command = Add(DrawCommand::Kind::Segment, color);
    command.points = {a, b};
    command.thickness = thickness;
}

void RecordingCanvas::Polyline(const ScreenPoint* points, int count, bool closed, Color color, float thickness)
{
    DrawCommand& command = Add(DrawCommand::Kind::Polyline, color);
    command.points.assign(points, points + count);
    command.closed = closed;
    command.thickness = thickness;
}

void RecordingCanvas::FillConvex(const ScreenPoint* points, int count, Color color)
{
    Add(DrawCommand::Kind::FillConvex, color).points.assign(points, points + count);
}

void RecordingCanvas::Circle(ScreenPoint center, float radius, Color color, float thickness)
{
    DrawCommand& command = Add(DrawCommand::Kind::Circle, color);
    command.points = {center};
    command.radius = radius;
    command.thickness = thickness;
}

void RecordingCanvas::FillCircle(ScreenPoint center, float radius, Color color)
{
    DrawCommand& command = Add(DrawCommand::Kind::FillCircle, color);
    command.points = {center};
    command.radius = radius;
}

void RecordingCanvas::FillRect(ScreenPoint min, ScreenPoint max, Color color)
{
    Add(DrawCommand::Kind::FillRect, color).points = {min, max};
}

void RecordingCanvas::Text(ScreenPoint topLeft, std::string_view text, TextStyle style, Color color)
{
    DrawCommand& command = Add(DrawCommand::Kind::Text, color);
    command.points = {topLeft};
    command.text = std::string(text);
    command.style = style;
}

ScreenPoint RecordingCanvas::MeasureText(std::string_view text, TextStyle style)
{
    const float size = TextSize(style);
    const int* advances = style == TextStyle::Heading ? kBold : kRegular;
    float units = 0.0f;
    for (size_t i = 0; i < text.size(); ++i)
    {
        const unsigned char c = static_cast<unsigned char>(text[i]);
        if (c >= 32 && c < 127)
        {
            units += static_cast<float>(advances[c - 32]);
        }
        else if ((c & 0xC0) != 0x80)
        {
            // Beyond ASCII: one advance per character (not per UTF-8 byte), as wide as an 'M'.
            units += static_cast<float>(advances['M' - 32]);
        }
    }
    return {units * size / kUnitsPerLine, size};
}

void RecordingCanvas::BeginGroup(std::string_view name)
{
    group_ = std::string(name);
}

std::vector<const DrawCommand*> RecordingCanvas::InGroup(std::string_view name) const
{
    std::vector<const DrawCommand*> found;
    for (const DrawCommand& command : commands)
    {
        if (command.group == name)
        {
            found.push_back(&command);
        }
    }
    return found;
}

std::vector<std::string> RecordingCanvas::Texts() const
{
    std::vector<std::string> texts;
    for (const DrawCommand& command : commands)
    {
        if (command.kind == DrawCommand::Kind::Text)
        {
            texts.push_back(command.text);
        }
    }
    return texts;
}

} // namespace satviz
