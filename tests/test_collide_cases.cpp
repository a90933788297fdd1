// SPDX-License-Identifier: MIT
// Hand-made collision cases whose answers follow from the geometry by hand.

#include "support/builders.h"

#include <satviz/sat.h>

#include <catch2/catch.hpp>

#include <cmath>

using namespace satviz;
using Catch::Matchers::WithinAbs;
using satviz::testing::At;

namespace
{

constexpr double kPi = 3.14159265358979323846;

Polygon Box(double hx, double hy)
{
    PolygonResult result = MakeBox(hx, hy);
    REQUIRE(result.Ok());
    return result.polygon;
}

Polygon Poly(std::vector<Vec2> points)
{
    PolygonResult result = MakePolygon(points);
    REQUIRE(result.Ok());
    return result.polygon;
}

Circle Disc(double radius)
{
    Circle circle;
    circle.radius = radius;
    return circle;
}

int TestedAxes(const Trace& trace)
{
    int tested = 0;
    for (const AxisTest& test : trace.axes)
    {
        tested += test.skipped ? 0 : 1;
    }
    return tested;
}

} // namespace

TEST_CASE("Overlapping boxes: depth, normal from A to B, two contacts", "[cases]")
{
    const Polygon a = Box(1.0, 1.0);
    const Polygon b = Box(0.5, 0.5);
    const Manifold m = Collide(a, At(0, 0), b, At(1.3, 0.2));
    REQUIRE(m.overlap);
    CHECK_THAT(m.depth, WithinAbs(0.2, 1e-15));
    CHECK(m.normal == Vec2{1.0, 0.0});
    REQUIRE(m.contactCount == 2);
    // B's left face x = 0.8 pushed into A's right face x = 1: contacts halfway, at x = 0.9, y = -0.3 and 0.7.
    for (int i = 0; i < 2; ++i)
    {
        CHECK_THAT(m.contacts[i].point.x, WithinAbs(0.9, 1e-15));
        CHECK_THAT(m.contacts[i].separation, WithinAbs(-0.2, 1e-15));
    }
    CHECK_THAT(std::min(m.contacts[0].point.y, m.contacts[1].point.y), WithinAbs(-0.3, 1e-15));
    CHECK_THAT(std::max(m.contacts[0].point.y, m.contacts[1].point.y), WithinAbs(0.7, 1e-15));
    CHECK(m.axis.kind == AxisKind::FaceNormal);
    CHECK(m.axis.shape == 0);
    CHECK(m.axis.index == 1); // A's right face: edge from (1, -1) to (1, 1)
    CHECK(Overlap(a, At(0, 0), b, At(1.3, 0.2)));

    // Swapped, the normal points from the new A (the small box) to the new B.
    const Manifold swapped = Collide(b, At(1.3, 0.2), a, At(0, 0));
    CHECK_THAT(swapped.depth, WithinAbs(0.2, 1e-15));
    CHECK(swapped.normal == Vec2{-1.0, 0.0});
}

TEST_CASE("Touching shapes overlap with depth zero, a hair apart they do not", "[cases]")
{
    const Polygon a = Box(1.0, 1.0);
    const Polygon b = Box(1.0, 0.5);
    const Manifold touching = Collide(a, At(0, 0), b, At(2.0, 0.3));
    CHECK(touching.overlap);
    CHECK(touching.depth == 0.0);
    CHECK(touching.contactCount == 2);
    CHECK(Overlap(a, At(0, 0), b, At(2.0, 0.3)));

    const double apart = std::nextafter(2.0, 3.0);
    const Manifold separated = Collide(a, At(0, 0), b, At(apart, 0.3));
    CHECK_FALSE(separated.overlap);
    CHECK(separated.gap == apart - 2.0);
    CHECK(separated.normal == Vec2{1.0, 0.0});
    CHECK(separated.contactCount == 0);
    CHECK_FALSE(Overlap(a, At(0, 0), b, At(apart, 0.3)));

    // Corner to corner.
    CHECK(Overlap(a, At(0, 0), b, At(2.0, 1.5)));
    CHECK_FALSE(Overlap(a, At(0, 0), b, At(2.0, std::nextafter(1.5, 2.0))));
}

TEST_CASE("Separated shapes report the separating axis and its gap", "[cases]")
{
    const Polygon a = Box(1.0, 1.0);
    const Polygon b = Box(0.5, 0.5);
    const Manifold m = Collide(a, At(0, 0), b, At(0.0, -3.0));
    REQUIRE_FALSE(m.overlap);
    CHECK_THAT(m.gap, WithinAbs(1.5, 1e-15));
    CHECK(m.normal == Vec2{0.0, -1.0});
    CHECK(m.axis.shape == 0);
    CHECK(m.axis.index == 0); // A's bottom face
}

TEST_CASE("Containment: the shortest way out, both ways round", "[cases]")
{
    const Polygon big = Box(2.0, 1.5);
    const Polygon small = Poly({{-0.3, -0.2}, {0.3, -0.2}, {0.0, 0.3}});
    // The triangle spans x in [0.9, 1.5] and y in [0.2, 0.7]: out through the right face (x = 2) is shortest,
    // 2 - 0.9 = 1.1; through the top (y = 1.5) would take 1.3.
    const Manifold inside = Collide(big, At(0, 0), small, At(1.2, 0.4));
    REQUIRE(inside.overlap);
    CHECK_THAT(inside.depth, WithinAbs(1.1, 1e-15));
    CHECK(inside.normal == Vec2{1.0, 0.0});

    // The big box around the triangle: moving the box by 1.1 to the left frees it.
    const Manifold around = Collide(small, At(1.2, 0.4), big, At(0, 0));
    REQUIRE(around.overlap);
    CHECK_THAT(around.depth, WithinAbs(1.1, 1e-15));
    CHECK(around.normal == Vec2{-1.0, 0.0});
}

TEST_CASE("Rotated boxes: vertex into face", "[cases]")
{
    const Polygon a = Box(1.0, 1.0);
    const Polygon b = Box(0.5, 0.5);
    // B turned by 45 degrees: its lowest corner is 0.5 * sqrt(2) below its centre.
    const double corner = 0.5 * std::sqrt(2.0);
    const Manifold m = Collide(a, At(0, 0), b, At(0.2, 1.0 + corner - 0.1, kPi / 4));
    REQUIRE(m.overlap);
    CHECK_THAT(m.depth, WithinAbs(0.1, 1e-14));
    CHECK_THAT(m.normal.x, WithinAbs(0.0, 1e-15));
    CHECK_THAT(m.normal.y, WithinAbs(1.0, 1e-15));
    // One contact: the corner, halfway between its depth and the top face.
    REQUIRE(m.contactCount == 1);
    CHECK_THAT(m.contacts[0].point.x, WithinAbs(0.2, 1e-14));
    CHECK_THAT(m.contacts[0].point.y, WithinAbs(0.95, 1e-14));
}

TEST_CASE("Parallel edges: aligned boxes test 2 axes, rotated boxes 4", "[cases][trace]")
{
    const Polygon a = Box(1.0, 1.0);
    const Polygon b = Box(0.5, 0.5);
    Trace trace;
    // Collide: Overlap would stop after A's faces, as a corner of B lies inside A.
    CHECK(Collide(a, At(0, 0), b, At(1.2, 0.3), &trace).overlap);
    // Four faces of A (two axes, each tested from both sides), all four faces of B skipped as duplicates.
    CHECK(trace.axes.size() == 8);
    CHECK(TestedAxes(trace) == 4);
    for (size_t i = 4; i < 8; ++i)
    {
        CHECK(trace.axes[i].skipped);
        CHECK(trace.axes[i].duplicateOf >= 0);
        CHECK(trace.axes[trace.axes[i].duplicateOf].direction == -trace.axes[i].direction);
    }

    CHECK(Collide(a, At(0, 0), b, At(1.2, 0.3, 0.25), &trace).overlap);
    CHECK(TestedAxes(trace) == 8); // four axes, each from both sides
    CHECK(trace.axes.size() == 8);

    // A triangle on top of a box face: B's bottom face is anti-parallel to A's top face and is skipped;
    // its other faces are not parallel to anything.
    const Polygon triangle = Poly({{-0.5, 0.0}, {0.5, 0.0}, {0.0, 0.5}});
    const Manifold m = Collide(a, At(0, 0), triangle, At(0.3, 0.9), &trace);
    REQUIRE(m.overlap);
    CHECK_THAT(m.depth, WithinAbs(0.1, 1e-15));
    CHECK(m.normal == Vec2{0.0, 1.0});
    CHECK(m.contactCount == 2);
    CHECK(TestedAxes(trace) == 6);
}

TEST_CASE("A skipped last face of a polygon above 8 faces takes no part, at every angle", "[cases][trace]")
{
    // A 2 x 2 box, and B a half disc of nine vertices whose last face (vertex 8 to vertex 0) is its flat bottom. B
    // rests on A's top face 0.1 deep, both turned by the same angle: B's bottom is anti-parallel to A's top, so the
    // face query of B skips it as a repeat of A's. Both faces have the same depth by hand, so the reference face is
    // A's top (A's on a tie) at depth 0.1, whichever of the two the rounding makes an ulp shallower. B's faces are
    // tested four at a time, and the last block holds face 8 with three lanes past it.
    const Polygon a = Box(1.0, 1.0);
    std::vector<Vec2> half;
    for (int k = 0; k <= 8; ++k)
    {
        half.push_back({std::cos(kPi * k / 8), std::sin(kPi * k / 8)});
    }
    half.back() = {-1.0, 0.0}; // exactly level with vertex 0: the bottom's normal is exactly (0, -1)
    const Polygon b = Poly(half);
    REQUIRE(b.Count() == 9);
    for (int step = 0; step < 360; ++step)
    {
        const double angle = 2.0 * kPi * step / 360;
        const Vec2 offset{0.3 * std::cos(angle) - 0.9 * std::sin(angle), 0.3 * std::sin(angle) + 0.9 * std::cos(angle)};
        Trace trace;
        const Manifold m = Collide(a, At(0, 0, angle), b, At(offset.x, offset.y, angle));
        const Manifold t = Collide(a, At(0, 0, angle), b, At(offset.x, offset.y, angle), &trace);
        INFO("angle step " << step);
        REQUIRE(m.overlap);
        CHECK(m.axis.shape == 0);
        CHECK(m.axis.index == 2);
        CHECK_THAT(m.depth, WithinAbs(0.1, 1e-14));
        CHECK(t.axis.shape == m.axis.shape);
        CHECK(t.axis.index == m.axis.index);
        CHECK(t.depth == m.depth);
    }
}

TEST_CASE("Vertex against edge and edge against vertex", "[cases]")
{
    const Polygon triangle = Poly({{0.0, 0.0}, {1.0, 0.0}, {0.5, 1.0}});
    const Polygon box = Box(1.0, 0.25);
    // The triangle's apex (0.5, 1) pokes 0.05 into the box's bottom face at y = 0.95.
    const Manifold m = Collide(triangle, At(0, 0), box, At(0.5, 1.2));
    REQUIRE(m.overlap);
    CHECK_THAT(m.depth, WithinAbs(0.05, 1e-15));
    CHECK_THAT(m.normal.y, WithinAbs(1.0, 1e-15));
    REQUIRE(m.contactCount == 1);
    CHECK_THAT(m.contacts[0].point.x, WithinAbs(0.5, 1e-15));
    CHECK_THAT(m.contacts[0].point.y, WithinAbs(0.975, 1e-15));
}

TEST_CASE("Tiny and huge scales give the same relative answers", "[cases]")
{
    for (double scale : {1e-6, 1.0, 1e6})
    {
        INFO("scale " << scale);
        const Polygon a = Box(scale, scale);
        const Polygon b = Box(0.5 * scale, 0.5 * scale);
        const Manifold m = Collide(a, At(0, 0), b, At(1.3 * scale, 0.2 * scale, 0.0));
        REQUIRE(m.overlap);
        CHECK_THAT(m.depth / scale, WithinAbs(0.2, 1e-15));
        const Manifold apart = Collide(a, At(0, 0), b, At(1.6 * scale, 0.0));
        REQUIRE_FALSE(apart.overlap);
        CHECK_THAT(apart.gap / scale, WithinAbs(0.1, 1e-15));
    }
}

TEST_CASE("Far from the origin the pair keeps full relative precision", "[cases]")
{
    const Polygon a = Box(1.0, 1.0);
    const Polygon b = Box(0.5, 0.5);
    for (double far : {1e3, 1e6, 1e8, 1e11})
    {
        // A gap of 64 ulps of the offset: world-space arithmetic rounds every vertex by about one ulp, the pair's
        // own frame decides it exactly.
        const double delta = 64.0 * (std::nextafter(far, 2.0 * far) - far);
        INFO("offset " << far << ", gap " << delta);
        const Transform xfA = At(far, -far);
        const Manifold apart = Collide(a, xfA, b, At(far + 1.5 + delta, -far + 0.25));
        CHECK_FALSE(apart.overlap);
        CHECK(apart.gap == delta);
        const Manifold in = Collide(a, xfA, b, At(far + 1.5 - delta, -far + 0.25));
        CHECK(in.overlap);
        CHECK(in.depth == delta);
        CHECK(Overlap(a, xfA, b, At(far + 1.5 - delta, -far + 0.25)));
        CHECK_FALSE(Overlap(a, xfA, b, At(far + 1.5 + delta, -far + 0.25)));
        // Contacts come back in world coordinates, rounded to the offset's resolution only.
        REQUIRE(in.contactCount == 2);
        CHECK_THAT(in.contacts[0].point.x - far, WithinAbs(1.0, 4.0 * delta));
    }
}

TEST_CASE("Circle against circle", "[cases][circle]")
{
    const Circle a = Disc(1.0);
    const Circle b = Disc(0.5);
    const Manifold m = Collide(a, At(0, 0), b, At(0.0, 1.2));
    REQUIRE(m.overlap);
    CHECK_THAT(m.depth, WithinAbs(0.3, 1e-15));
    CHECK(m.normal == Vec2{0.0, 1.0});
    REQUIRE(m.contactCount == 1);
    CHECK_THAT(m.contacts[0].point.y, WithinAbs(0.85, 1e-15));
    CHECK(m.axis.kind == AxisKind::CenterToCenter);

    const Manifold apart = Collide(a, At(0, 0), b, At(3.0, 4.0));
    CHECK_FALSE(apart.overlap);
    CHECK_THAT(apart.gap, WithinAbs(3.5, 1e-15));
    CHECK_THAT(apart.normal.x, WithinAbs(0.6, 1e-15));

    // Touching counts; concentric circles get the documented normal.
    CHECK(Overlap(a, At(0, 0), b, At(1.5, 0.0)));
    const Manifold concentric = Collide(a, At(2, 2), b, At(2, 2));
    CHECK(concentric.overlap);
    CHECK(concentric.depth == 1.5);
    CHECK(concentric.normal == Vec2{0.0, 1.0});
}

TEST_CASE("Circle against polygon: face region, vertex region, inside", "[cases][circle]")
{
    const Polygon box = Box(1.0, 1.0);
    const Circle ball = Disc(0.5);

    // Face region: above the top face.
    const Manifold face = Collide(box, At(0, 0), ball, At(0.3, 1.4));
    REQUIRE(face.overlap);
    CHECK_THAT(face.depth, WithinAbs(0.1, 1e-15));
    CHECK(face.normal == Vec2{0.0, 1.0});
    CHECK(face.axis.kind == AxisKind::FaceNormal);
    CHECK_THAT(face.contacts[0].point.y, WithinAbs(0.95, 1e-15));

    // Vertex region: near the corner (1, 1) along the diagonal; the face axes alone would call this overlapping.
    const double d = 0.5 / std::sqrt(2.0);
    const Manifold corner = Collide(box, At(0, 0), ball, At(1.0 + d + 0.01, 1.0 + d + 0.01));
    CHECK_FALSE(corner.overlap);
    CHECK(corner.axis.kind == AxisKind::VertexToCenter);
    CHECK(corner.axis.index == 2);
    CHECK_THAT(corner.gap, WithinAbs(0.01 * std::sqrt(2.0), 1e-15));
    CHECK_FALSE(Overlap(box, At(0, 0), ball, At(1.0 + d + 0.01, 1.0 + d + 0.01)));
    const Manifold cornerIn = Collide(box, At(0, 0), ball, At(1.0 + d - 0.01, 1.0 + d - 0.01));
    CHECK(cornerIn.overlap);
    CHECK_THAT(cornerIn.normal.x, WithinAbs(std::sqrt(0.5), 1e-15));

    // Centre inside the box: out through the nearest face, the right one.
    const Manifold inside = Collide(box, At(0, 0), ball, At(0.7, 0.1));
    REQUIRE(inside.overlap);
    CHECK_THAT(inside.depth, WithinAbs(0.8, 1e-15));
    CHECK(inside.normal == Vec2{1.0, 0.0});

    // Circle as A: the normal points from the circle to the polygon.
    const Manifold swapped = Collide(ball, At(0.3, 1.4), box, At(0, 0));
    CHECK_THAT(swapped.depth, WithinAbs(0.1, 1e-15));
    CHECK(swapped.normal == Vec2{0.0, -1.0});
    CHECK(swapped.axis.shape == 1);
}

TEST_CASE("Large polygons: 4096 vertices", "[cases]")
{
    // Phased by pi / n, the 4096-gon has a face (not a vertex) facing +x, at its inscribed radius cos(pi / n).
    PolygonResult big = MakeRegularPolygon(4096, 1.0, kPi / 4096);
    REQUIRE(big.Ok());
    const Polygon box = Box(0.1, 0.1);
    const double inradius = std::cos(kPi / 4096);
    const Manifold m = Collide(big.polygon, At(0, 0), box, At(inradius + 0.05, 0.0, 0.0));
    REQUIRE(m.overlap);
    CHECK_THAT(m.depth, WithinAbs(0.05, 1e-12));
    const Manifold both = Collide(big.polygon, At(0, 0), big.polygon, At(1.9, 0.0, 0.001));
    CHECK(both.overlap);
    CHECK_FALSE(Overlap(big.polygon, At(0, 0), big.polygon, At(2.1, 0.0, 0.001)));
}
