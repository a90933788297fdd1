// SPDX-License-Identifier: MIT
// Vectors, rotations and transforms.

#include <satviz/math.h>

#include <catch2/catch.hpp>

using namespace satviz;
using Catch::Matchers::WithinAbs;

TEST_CASE("Perpendiculars follow the counter-clockwise convention", "[math]")
{
    const Vec2 east{1.0, 0.0};
    CHECK(LeftPerp(east) == Vec2{0.0, 1.0});
    CHECK(RightPerp(east) == Vec2{0.0, -1.0});
    CHECK(Cross(east, LeftPerp(east)) > 0.0);
}

TEST_CASE("Transforms round-trip and compose relative to the first frame", "[math]")
{
    const Transform a = MakeTransform(Vec2{1e6, -2e6}, 0.7);
    const Transform b = MakeTransform(Vec2{1e6 + 3.0, -2e6 + 4.0}, -1.1);
    const Vec2 local{0.25, -0.5};
    const Vec2 world = TransformPoint(b, local);
    const Vec2 back = InvTransformPoint(b, world);
    CHECK_THAT(back.x, WithinAbs(local.x, 1e-9));
    CHECK_THAT(back.y, WithinAbs(local.y, 1e-9));

    // B relative to A is computed from B.p - A.p, exact here, so it keeps full precision despite the offset.
    const Transform bInA = InvMulTransforms(a, b);
    const Vec2 expected = InvRotate(a.q, Vec2{3.0, 4.0});
    CHECK(bInA.p == expected);
    CHECK_THAT(std::atan2(bInA.q.s, bInA.q.c), WithinAbs(-1.8, 1e-15));
}

TEST_CASE("Length neither overflows nor underflows", "[math]")
{
    CHECK_THAT(Length(Vec2{3e200, 4e200}), Catch::Matchers::WithinRel(5e200, 1e-15));
    CHECK_THAT(Length(Vec2{3e-200, 4e-200}), WithinAbs(5e-200, 1e-214));
    CHECK(Normalize(Vec2{0.0, 0.0}) == Vec2{0.0, 0.0});
}
