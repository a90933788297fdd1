// SPDX-License-Identifier: MIT
// CollideWithin (speculative contacts) against independent oracles: the largest separation over every face of both
// polygons by a plain loop, the distance of a circle's centre to a polygon by its edges, and Collide itself for the
// pairs that overlap.

#include "support/random_shapes.h"
#include "support/same_bits.h"

#include <satviz/collide.h>

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

using namespace satviz;
using namespace satviz::testing;

namespace
{

std::vector<Vec2> WorldVertices(const Polygon& p, const Transform& xf)
{
    std::vector<Vec2> out;
    for (const Vec2& v : p.Vertices())
    {
        out.push_back(TransformPoint(xf, v));
    }
    return out;
}

// The largest separation of a face of `ref` from the other polygon's vertices (the textbook loop).
double LargestFaceSeparation(const std::vector<Vec2>& ref, const std::vector<Vec2>& other)
{
    double largest = -1e300;
    const size_t n = ref.size();
    for (size_t i = 0; i < n; ++i)
    {
        const Vec2 edge = ref[(i + 1) % n] - ref[i];
        const Vec2 normal = (1.0 / Length(edge)) * Vec2{edge.y, -edge.x};
        double lowest = 1e300;
        for (const Vec2& v : other)
        {
            lowest = std::min(lowest, Dot(normal, v - ref[i]));
        }
        largest = std::max(largest, lowest);
    }
    return largest;
}

// How far a point lies outside a convex counter-clockwise outline (<= 0: inside or on it).
double Outside(const std::vector<Vec2>& outline, Vec2 point)
{
    double largest = -1e300;
    const size_t n = outline.size();
    for (size_t i = 0; i < n; ++i)
    {
        const Vec2 edge = outline[(i + 1) % n] - outline[i];
        const Vec2 normal = (1.0 / Length(edge)) * Vec2{edge.y, -edge.x};
        largest = std::max(largest, Dot(normal, point - outline[i]));
    }
    return largest;
}

// The distance from a point outside a convex outline to it.
double DistanceTo(const std::vector<Vec2>& outline, Vec2 point)
{
    double nearest = 1e300;
    const size_t n = outline.size();
    for (size_t i = 0; i < n; ++i)
    {
        const Vec2 a = outline[i];
        const Vec2 ab = outline[(i + 1) % n] - a;
        const double t = std::clamp(Dot(point - a, ab) / Dot(ab, ab), 0.0, 1.0);
        nearest = std::min(nearest, Length(point - (a + t * ab)));
    }
    return nearest;
}

} // namespace

TEST_CASE("CollideWithin gives polygons within the margin the contacts of their face of largest separation",
          "[collide][speculative][property]")
{
    Rng rng(90210);
    int within = 0, beyond = 0;
    for (int k = 0; k < 20000; ++k)
    {
        const int n = k % 10 == 9 ? rng.Int(17, 64) : rng.Int(3, 12);
        RandomPair pair = ContactPair(rng, n, PairCategory::Separated);
        const Polygon& a = pair.a.polygon;
        const Polygon& b = pair.b.polygon;
        const std::vector<Vec2> wa = WorldVertices(a, pair.xfA);
        const std::vector<Vec2> wb = WorldVertices(b, pair.xfB);
        const double separation = std::max(LargestFaceSeparation(wa, wb), LargestFaceSeparation(wb, wa));
        const double margin = rng.Uniform(0.0, 0.5);
        const Manifold m = CollideWithin(pair.a, pair.xfA, pair.b, pair.xfB, margin);
        INFO("pair " << k << ": " << n << " vertices, largest separation " << separation << ", margin " << margin);
        REQUIRE(separation > 0.0);
        CHECK_FALSE(m.overlap);
        const double tolerance = 1e-12 * (1.0 + Length(pair.xfA.p) + Length(pair.xfB.p));
        if (separation > margin + tolerance)
        {
            ++beyond;
            CHECK(m.contactCount == 0);
            continue;
        }
        if (separation < margin - tolerance)
        {
            ++within;
            REQUIRE(m.contactCount >= 1);
        }
        if (m.contactCount == 0)
        {
            continue; // at the margin itself, up to rounding
        }
        CHECK(std::abs(m.gap - separation) <= tolerance);
        // The reference face, A's or B's, as the axis names it; its normal points out of the reference polygon.
        const bool refB = m.axis.shape == 1;
        const std::vector<Vec2>& incident = refB ? wa : wb;
        const Vec2 outward = refB ? -m.normal : m.normal;
        for (int c = 0; c < m.contactCount; ++c)
        {
            const ContactPoint& p = m.contacts[c];
            CHECK(p.separation >= separation - tolerance);
            CHECK(p.separation <= margin + tolerance);
            // The contact point is halfway between the incident outline and the reference face.
            const Vec2 onIncident = p.point + (0.5 * p.separation) * outward;
            CHECK(Outside(incident, onIncident) <= tolerance);
        }
    }
    INFO(within << " pairs within the margin, " << beyond << " beyond it");
    CHECK(within > 2000);
    CHECK(beyond > 2000);
}

TEST_CASE("CollideWithin of overlapping polygons is Collide's manifold, with the points up to the margin added",
          "[collide][speculative][property]")
{
    Rng rng(4711);
    int added = 0;
    for (int k = 0; k < 20000; ++k)
    {
        const int n = k % 10 == 9 ? rng.Int(17, 64) : rng.Int(3, 12);
        const RandomPair pair = ContactPair(rng, n, k % 2 == 0 ? PairCategory::Overlap : PairCategory::Touch);
        const Manifold still = Collide(pair.a, pair.xfA, pair.b, pair.xfB);
        if (!still.overlap)
        {
            continue; // a touching pair that rounding put apart
        }
        const double margin = rng.Uniform(0.0, 0.5);
        const Manifold m = CollideWithin(pair.a, pair.xfA, pair.b, pair.xfB, margin);
        INFO("pair " << k << ": " << n << " vertices, margin " << margin);
        CHECK(m.overlap);
        CHECK(SameBits(m.depth, still.depth));
        CHECK(SameBits(m.normal.x, still.normal.x));
        CHECK(SameBits(m.normal.y, still.normal.y));
        CHECK(m.axis.shape == still.axis.shape);
        CHECK(m.axis.index == still.axis.index);
        // Every point of Collide is there, to the bit; the others are within the margin, not touching.
        for (int c = 0; c < still.contactCount; ++c)
        {
            bool found = false;
            for (int d = 0; d < m.contactCount; ++d)
            {
                found = found || (SameBits(m.contacts[d].point.x, still.contacts[c].point.x) &&
                                  SameBits(m.contacts[d].point.y, still.contacts[c].point.y) &&
                                  SameBits(m.contacts[d].separation, still.contacts[c].separation));
            }
            CHECK(found);
        }
        for (int d = 0; d < m.contactCount; ++d)
        {
            CHECK(m.contacts[d].separation <= margin);
        }
        CHECK(m.contactCount >= still.contactCount);
        added += m.contactCount - still.contactCount;
    }
    CHECK(added > 100);
}

TEST_CASE("CollideWithin gives a circle within the margin one contact at its distance", "[collide][speculative]")
{
    Rng rng(1234);
    int within = 0;
    for (int k = 0; k < 20000; ++k)
    {
        Circle circle;
        circle.radius = rng.Uniform(0.1, 1.0);
        const Shape disc = MakeShape(circle);
        const bool circles = k % 4 == 0;
        const Shape other = circles ? disc : MakeShape(RandomPolygon(rng, rng.Int(3, 12), 1.0, rng.Uniform(0.35, 1.0)));
        const Transform xfOther =
            MakeTransform(Vec2{rng.Uniform(-2.0, 2.0), rng.Uniform(-2.0, 2.0)}, rng.Uniform(-kPi, kPi));
        const double angle = rng.Uniform(0.0, 2.0 * kPi);
        const double reach = rng.Uniform(1.0, 2.8);
        const Transform xfDisc =
            MakeTransform(xfOther.p + reach * Vec2{std::cos(angle), std::sin(angle)}, rng.Uniform(-kPi, kPi));
        double distance = 0.0;
        if (circles)
        {
            distance = Length(xfDisc.p - xfOther.p) - 2.0 * circle.radius;
        }
        else
        {
            const std::vector<Vec2> outline = WorldVertices(other.polygon, xfOther);
            if (Outside(outline, xfDisc.p) <= 0.0)
            {
                continue;
            }
            distance = DistanceTo(outline, xfDisc.p) - circle.radius;
        }
        if (distance <= 0.0)
        {
            continue;
        }
        const double margin = rng.Uniform(0.0, 1.0);
        const bool discFirst = k % 2 == 1;
        const Manifold m = discFirst ? CollideWithin(disc, xfDisc, other, xfOther, margin)
                                     : CollideWithin(other, xfOther, disc, xfDisc, margin);
        INFO("pair " << k << (circles ? ", two circles" : ", polygon and circle") << ": distance " << distance
                     << ", margin " << margin);
        CHECK_FALSE(m.overlap);
        if (distance > margin + 1e-12)
        {
            CHECK(m.contactCount == 0);
            continue;
        }
        if (distance < margin - 1e-12)
        {
            ++within;
            REQUIRE(m.contactCount == 1);
            CHECK(std::abs(m.gap - distance) <= 1e-12);
            CHECK(std::abs(m.contacts[0].separation - distance) <= 1e-12);
            // Halfway between the surfaces: the disc's surface is half the distance away, towards the disc.
            const Vec2 towardsDisc = discFirst ? -m.normal : m.normal;
            const Vec2 surface = m.contacts[0].point + (0.5 * distance) * towardsDisc;
            CHECK(std::abs(Length(surface - xfDisc.p) - circle.radius) <= 1e-12);
        }
    }
    CHECK(within > 2000);
}
