// SPDX-License-Identifier: MIT
// Short builders for hand-made test cases.
#pragma once

#include <satviz/sat.h>

#include <catch2/catch.hpp>

namespace satviz::testing
{

/// A validated box shape with half-widths hx, hy.
inline Shape BoxShape(double hx, double hy)
{
    PolygonResult result = MakeBox(hx, hy);
    REQUIRE(result.Ok());
    return MakeShape(result.polygon);
}

/// A circle shape centred on the body origin.
inline Shape DiscShape(double radius)
{
    Circle circle;
    circle.radius = radius;
    return MakeShape(circle);
}

/// A transform from a position and an angle.
inline Transform At(double x, double y, double angle = 0.0)
{
    return MakeTransform(Vec2{x, y}, angle);
}

} // namespace satviz::testing
