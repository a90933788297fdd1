// SPDX-License-Identifier: MIT
#include <satviz/render/recording_canvas.h>

namespace satviz
{

void RecordingCanvas::Segment(ScreenPoint a, ScreenPoint b, Color color, float thickness)
{
    DrawCommand command;
    command.kind = DrawCommand::Kind::Segment;
    command.group = group_;
    command.points = {a, b};
    command.color = color;
    command.thickness = thickness;
    commands.push_back(std::move(command));
}

void RecordingCanvas::Polyline(const ScreenPoint* points, int count, bool closed, Color color, float thickness)
{
    DrawCommand command;
    command.kind = DrawCommand::Kind::Polyline;
    command.group = group_;
    command.points.assign(points, points + count);
    command.closed = closed;
    command.color = color;
    command.thickness = thickness;
    commands.push_back(std::move(command));
}

void RecordingCanvas::FillConvex(const ScreenPoint* points, int count, Color color)
{
    DrawCommand command;
    command.kind = DrawCommand::Kind::FillConvex;
    command.group = group_;
    command.points.assign(points, points + count);
    command.color = color;
    commands.push_back(std::move(command));
}

void RecordingCanvas::Circle(ScreenPoint center, float radius, Color color, float thickness)
{
    DrawCommand command;
    command.kind = DrawCommand::Kind::Circle;
    command.group = group_;
    command.points = {center};
    command.radius = radius;
    command.color = color;
    command.thickness = thickness;
    commands.push_back(std::move(command));
}

void RecordingCanvas::FillCircle(ScreenPoint center, float radius, Color color)
{
    DrawCommand command;
    command.kind = DrawCommand::Kind::FillCircle;
    command.group = group_;
    command.points = {center};
    command.radius = radius;
    command.color = color;
    commands.push_back(std::move(command));
}

void RecordingCanvas::FillRect(ScreenPoint min, ScreenPoint max, Color color)
{
    DrawCommand command;
    command.kind = DrawCommand::Kind::FillRect;
    command.group = group_;
    command.points = {min, max};
    command.color = color;
    commands.push_back(std::move(command));
}

void RecordingCanvas::Text(ScreenPoint topLeft, std::string_view text, TextStyle style, Color color)
{
    DrawCommand command;
    command.kind = DrawCommand::Kind::Text;
    command.group = group_;
    command.points = {topLeft};
    command.text = std::string(text);
    command.style = style;
    command.color = color;
    commands.push_back(std::move(command));
}

ScreenPoint RecordingCanvas::MeasureText(std::string_view text, TextStyle style)
{
    const float size = TextSize(style);
    return {0.6f * size * static_cast<float>(text.size()), size};
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
