// SPDX-License-Identifier: MIT
// The view's mapping between world and screen: a round trip, a zoom about the pointer and a pan.

#include <satviz/render/view.h>

#include <catch2/catch.hpp>

using namespace satviz;

TEST_CASE("View: world and screen round trip, zoom keeps the point under the pointer", "[view]")
{
    View view;
    view.center = {3.0, -2.0};
    view.zoom = 37.5;
    const Vec2 world{4.25, -1.5};
    const ScreenPoint screen = ToScreen(view, world);
    CHECK(screen.x == Approx(400.0 + 1.25 * 37.5));
    CHECK(screen.y == Approx(300.0 - 0.5 * 37.5));
    const Vec2 back = ToWorld(view, screen);
    CHECK(back.x == Approx(world.x));
    CHECK(back.y == Approx(world.y));
    const View zoomed = ZoomAbout(view, screen, 2.0);
    const ScreenPoint again = ToScreen(zoomed, world);
    CHECK(again.x == Approx(screen.x).margin(1e-3));
    CHECK(again.y == Approx(screen.y).margin(1e-3));
    const View panned = Pan(view, 10.0f, -20.0f);
    const ScreenPoint moved = ToScreen(panned, world);
    CHECK(moved.x == Approx(screen.x + 10.0f));
    CHECK(moved.y == Approx(screen.y - 20.0f));
}
