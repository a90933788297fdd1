// SPDX-License-Identifier: MIT
#include <satviz/render/recording_canvas.h>

namespace satviz
{

DrawCommand& RecordingCanvas::Add(DrawCommand::Kind kind, Color color)
{
    DrawCommand& command = commands.emplace_back();
    command.kind = kind;
    command.group = m_group;
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
    return FontTextSize(text, style);
}

void RecordingCanvas::BeginGroup(std::string_view name)
{
    m_group = std::string(name);
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
