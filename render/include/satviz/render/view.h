// SPDX-License-Identifier: MIT
// satviz render: the camera that maps world units (y up) to screen pixels (y down).
#pragma once

#include <satviz/math.h>

namespace satviz
{

/// A point on the screen, in pixels from the top-left corner, y down.
struct ScreenPoint
{
    float x = 0.0f; ///< pixels to the right of the left edge
    float y = 0.0f; ///< pixels below the top edge
};

/// The camera: which world point sits at the centre of the image, and how many pixels one world unit spans.
struct View
{
    Vec2 center{};       ///< world point at the centre of the image
    double zoom = 100.0; ///< pixels per world unit
    int width = 800;     ///< image width in pixels
    int height = 600;    ///< image height in pixels
};

/// World point to screen pixels.
ScreenPoint ToScreen(const View& view, Vec2 world);

/// Screen pixels to world point.
Vec2 ToWorld(const View& view, ScreenPoint screen);

/// A world length in pixels.
inline float ToPixels(const View& view, double length)
{
    return static_cast<float>(length * view.zoom);
}

/// Zooms by `factor` about a fixed screen point (the pointer): the world point under it stays put.
View ZoomAbout(const View& view, ScreenPoint fixed, double factor);

/// Moves the camera so the world follows a drag of (dx, dy) pixels.
View Pan(const View& view, float dx, float dy);

/// The view of a width x height image that shows the world disc (centre, radius) inside the screen rectangle
/// [left, right] x [top, bottom], leaving `marginPixels` around the disc.
View FitDisc(Vec2 center, double radius, int width, int height, float left, float top, float right, float bottom,
             float marginPixels);

} // namespace satviz
