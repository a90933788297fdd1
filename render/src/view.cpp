// SPDX-License-Identifier: MIT
#include <satviz/render/view.h>
#include <satviz/scene.h>

#include <algorithm>

namespace satviz
{

ScreenPoint ToScreen(const View& view, Vec2 world)
{
    const double x = (world.x - view.center.x) * view.zoom + 0.5 * view.width;
    const double y = 0.5 * view.height - (world.y - view.center.y) * view.zoom;
    return {static_cast<float>(x), static_cast<float>(y)};
}

Vec2 ToWorld(const View& view, ScreenPoint screen)
{
    return {view.center.x + (screen.x - 0.5 * view.width) / view.zoom,
            view.center.y - (screen.y - 0.5 * view.height) / view.zoom};
}

View ZoomAbout(const View& view, ScreenPoint fixed, double factor)
{
    const Vec2 before = ToWorld(view, fixed);
    View zoomed = view;
    zoomed.zoom = std::clamp(view.zoom * factor, kMinViewZoom, kMaxViewZoom);
    const Vec2 after = ToWorld(zoomed, fixed);
    zoomed.center = zoomed.center + (before - after);
    return zoomed;
}

View Pan(const View& view, float dx, float dy)
{
    View moved = view;
    moved.center = {view.center.x - dx / view.zoom, view.center.y + dy / view.zoom};
    return moved;
}

View FitDisc(Vec2 center, double radius, int width, int height, float left, float top, float right, float bottom,
             float marginPixels)
{
    View view;
    view.width = width;
    view.height = height;
    const double side = std::max(1.0, std::min<double>(right - left, bottom - top) - 2.0 * marginPixels);
    view.zoom = 0.5 * side / std::max(radius, 1e-12);
    // The disc centre goes to the centre of the rectangle, not of the image.
    const double offsetX = 0.5 * (left + right) - 0.5 * width;
    const double offsetY = 0.5 * (top + bottom) - 0.5 * height;
    view.center = {center.x - offsetX / view.zoom, center.y + offsetY / view.zoom};
    return view;
}

} // namespace satviz
