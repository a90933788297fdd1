// SPDX-License-Identifier: MIT
// Fuzz target for the core API: the bytes become two shapes (vertex lists through MakePolygon, ComputeHull or the
// repair option, or circles), transforms and velocities, raw IEEE bit patterns included (NaN, infinities, huge
// and subnormal values). Invalid input must come back as an error value; valid input must give consistent
// answers: Overlap agrees with Collide, traced agrees with untraced, a segment cast stays within its segment, and
// nothing crashes or hangs.
#include <satviz/sat.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <vector>

namespace
{

/// Reads values from the fuzzer's bytes; zeros once they run out.
struct Bytes
{
    const uint8_t* data;
    size_t size;
    size_t at = 0;

    uint8_t Byte() { return at < size ? data[at++] : 0; }
    double Double()
    {
        // Half of the values are small and tame (contacts happen), half raw bit patterns (anything goes).
        if (Byte() & 1)
        {
            return (static_cast<int>(Byte()) - 128) / 32.0;
        }
        uint64_t bits = 0;
        for (int i = 0; i < 8; ++i)
        {
            bits |= static_cast<uint64_t>(Byte()) << (8 * i);
        }
        double value;
        std::memcpy(&value, &bits, sizeof(value));
        return value;
    }
};

bool MakeShapeFrom(Bytes& in, satviz::Shape& shape)
{
    const uint8_t kind = in.Byte() % 4;
    if (kind == 3)
    {
        satviz::Circle circle{{in.Double(), in.Double()}, in.Double()};
        if (!std::isfinite(circle.radius) || !(circle.radius > 0.0) || circle.radius > 1e12 ||
            !satviz::IsFinite(circle.center) || std::abs(circle.center.x) > 1e12 || std::abs(circle.center.y) > 1e12)
        {
            return false;
        }
        shape = satviz::MakeShape(circle);
        return true;
    }
    const int count = 1 + in.Byte() % 40;
    std::vector<satviz::Vec2> points;
    for (int i = 0; i < count; ++i)
    {
        points.push_back({in.Double(), in.Double()});
    }
    satviz::PolygonResult result = kind == 0   ? satviz::MakePolygon(points)
                                   : kind == 1 ? satviz::ComputeHull(points)
                                               : satviz::MakePolygon(points, satviz::PolygonOptions{true});
    if (!result.Ok())
    {
        if (satviz::DescribePolygonError(result.error, result.vertex).empty())
        {
            std::abort(); // every error has a description
        }
        return false;
    }
    shape = satviz::MakeShape(std::move(result.polygon));
    return true;
}

// The same bits, or NaN on both sides: a NaN input gives NaN on every path, but which NaN (its sign) IEEE 754 leaves
// open, and it follows the operand order each instruction sequence happens to use.
bool SameBitsOrBothNaN(double a, double b)
{
    return (std::isnan(a) && std::isnan(b)) || std::memcmp(&a, &b, sizeof a) == 0;
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
    Bytes in{data, size};
    satviz::Shape a;
    satviz::Shape b;
    if (!MakeShapeFrom(in, a) || !MakeShapeFrom(in, b))
    {
        return 0;
    }
    // Each transform's position, then its angle, read in that order whatever the compiler: the order in which a
    // call's arguments are evaluated is unspecified, and a compiler that read the angle first would replay the
    // corpus as other pairs than the fuzzer found.
    const satviz::Vec2 pA{in.Double(), in.Double()};
    const double angleA = in.Double();
    const satviz::Vec2 pB{in.Double(), in.Double()};
    const double angleB = in.Double();
    const satviz::Transform xfA = satviz::MakeTransform(pA, angleA);
    const satviz::Transform xfB = satviz::MakeTransform(pB, angleB);
    const satviz::Vec2 vA{in.Double(), in.Double()};
    const satviz::Vec2 vB{in.Double(), in.Double()};
    const bool overlap = satviz::Overlap(a, xfA, b, xfB);
    const satviz::Manifold m = satviz::Collide(a, xfA, b, xfB);
    satviz::Trace trace;
    const satviz::Manifold traced = satviz::Collide(a, xfA, b, xfB, &trace);
    const bool finite = satviz::IsFinite(xfA.p) && satviz::IsFinite(xfB.p) && std::isfinite(xfA.q.c) &&
                        std::isfinite(xfB.q.c) && std::abs(xfA.p.x) < 1e12 && std::abs(xfA.p.y) < 1e12 &&
                        std::abs(xfB.p.x) < 1e12 && std::abs(xfB.p.y) < 1e12;
    // Overlap decides with raw edge normals, Collide with unit ones: for shapes that touch, their rounding may
    // fall on either side of zero, so they may differ only by a separation within rounding of the shapes' size.
    double extent = std::max({std::abs(xfA.p.x), std::abs(xfA.p.y), std::abs(xfB.p.x), std::abs(xfB.p.y), 1.0});
    for (const satviz::Shape* shape : {&a, &b})
    {
        if (shape->type == satviz::ShapeType::Circle)
        {
            extent = std::max(extent, std::abs(shape->circle.radius) + satviz::Length(shape->circle.center));
        }
        else
        {
            for (const satviz::Vec2& v : shape->polygon.Vertices())
            {
                extent = std::max(extent, satviz::Length(v));
            }
        }
    }
    if (finite && overlap != m.overlap && std::max(m.depth, m.gap) > 1e-12 * extent)
    {
        std::abort();
    }
    if (!SameBitsOrBothNaN(m.depth, traced.depth) || m.overlap != traced.overlap ||
        m.contactCount != traced.contactCount)
    {
        std::abort(); // traced and untraced results are bit-identical
    }
    if (m.contactCount < 0 || m.contactCount > 2)
    {
        std::abort();
    }
    satviz::SweepTrace sweepTrace;
    const satviz::SweepResult sweep = satviz::Sweep(a, xfA, vA, b, xfB, vB, &sweepTrace);
    if (sweep.status == satviz::SweepStatus::Hit && !(sweep.toi >= 0.0 && sweep.toi <= 1.0))
    {
        std::abort();
    }
    const satviz::SweepResult plainSweep = satviz::Sweep(a, xfA, vA, b, xfB, vB);
    if (plainSweep.status != sweep.status || !SameBitsOrBothNaN(plainSweep.toi, sweep.toi))
    {
        std::abort(); // traced and untraced sweeps agree
    }
    const satviz::Obstacle obstacle{&b, xfB};
    const satviz::SlideResult slide = satviz::MoveAndSlide(a, xfA, vA, &obstacle, 1);
    if (slide.contactCount < 0 || slide.contactCount > satviz::kMaxSlideContacts)
    {
        std::abort();
    }
    const satviz::RayHit ray = satviz::RayCast(b, xfB, vA, vB);
    if (ray.hit && !(ray.fraction >= 0.0 && ray.fraction <= 1.0))
    {
        std::abort();
    }
    return 0;
}
