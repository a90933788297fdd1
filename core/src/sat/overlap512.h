// SPDX-License-Identifier: MIT
// satviz (private), machinery: Overlap of two polygons of up to 8 vertices on 512-bit vectors (AVX-512F): all the
// faces of a polygon in one register of eight lanes (Lanes8), the other polygon's vertices mapped into its frame and
// held in registers. Used only in code compiled for AVX-512 (entry.h: RunWide512), where the processor has it
// (cpu_dispatch.h). The same separations to the bit as SmallFacesSeparate (face_blocks.h).
#pragma once

#include "cpu_dispatch.h"
#include "face_kernel.h"
#include "face_query.h"
#include "lanes8.h"

#include <satviz/polygon.h>

#include <cstdint>

namespace satviz::detail
{

#if SATVIZ_WIDE
/// The vertices of a polygon of at most 8 vertices mapped by `xf` (as IncidentPolygon maps them, the same bits), one
/// per lane, held in registers: lanes past the last vertex hold vertex 0 again.
[[gnu::target("avx512f")]] inline void MapVertices512(const PolygonT<double>& polygon, const TransformT<double>& xf,
                                                      Lanes8& x, Lanes8& y)
{
    Lanes8 vx;
    Lanes8 vy;
    Lanes8::LoadPoints(&polygon.InlineBlock()[0].x, vx, vy);
    const Lanes8 c = Lanes8::Fill(xf.q.c);
    const Lanes8 s = Lanes8::Fill(xf.q.s);
    const int past = 0xFF & ~((1 << polygon.Count()) - 1);
    x = ((c * vx - s * vy) + Lanes8::Fill(xf.p.x)).FillFromFirst(past);
    y = ((s * vx + c * vy) + Lanes8::Fill(xf.p.y)).FillFromFirst(past);
}

/// Two polygons of at most 8 vertices, each mapped into the other's frame and held in registers (MapVertices512).
struct MappedPair512
{
    Lanes8 bx; ///< B's vertices in A's frame: x
    Lanes8 by; ///< and y
    Lanes8 ax; ///< A's vertices in B's frame: x
    Lanes8 ay; ///< and y
};

/// B mapped by `bInA` (its frame in A's) and A by `aInB`.
[[gnu::target("avx512f")]] inline MappedPair512 MapPair512(const PolygonT<double>& a, const PolygonT<double>& b,
                                                           const TransformT<double>& bInA,
                                                           const TransformT<double>& aInB)
{
    MappedPair512 out;
    MapVertices512(b, bInA, out.bx, out.by);
    MapVertices512(a, aInB, out.ax, out.ay);
    return out;
}

/// Whether a face of `ref` (at most 8 faces, raw edge normals, all in one register of eight lanes) separates it from
/// the N vertices of the other polygon, mapped into ref's frame and held in registers (MapVertices512), less the
/// `skip`ped faces. The face-separation kernel in eight lanes (face_kernel.h), where SmallFacesSeparate runs it in
/// four, so the same separations to the bit; the vertices come from registers, not from an array on the stack.
template <int N>
[[gnu::target("avx512f")]] bool FacesSeparate512(const PolygonT<double>& ref, const Lanes8& x, const Lanes8& y,
                                                 uint64_t skip)
{
    Lanes8 vx;
    Lanes8 vy;
    Lanes8 wx;
    Lanes8 wy;
    Lanes8::LoadPoints(&ref.InlineBlock()[0].x, vx, vy);
    Lanes8::LoadPoints(&ref.InlineBlock()[1].x, wx, wy);
    const Lanes8 nx = wy - vy;
    const Lanes8 ny = vx - wx;
    const Lanes8 separation =
        SeparationsOf(LowestProjection<N, SpreadVertices8>(RegisterVertices8{x, y}, nx, ny), nx * vx + ny * vy);
    const int live = static_cast<int>(((uint64_t(1) << ref.Count()) - 1) & ~skip);
    return (separation.GreaterBits(Lanes8::Fill(0.0)) & live) != 0;
}

/// Overlap of two polygons of at most 8 vertices on AVX-512 (OverlapPolygons, step 0): each polygon's faces in one
/// register against the other polygon's vertices mapped into its frame, held in registers, both decided at once.
[[gnu::target("avx512f")]] inline bool SmallPolygonsOverlap512(const PolygonT<double>& a, const TransformT<double>& xfA,
                                                               const PolygonT<double>& b, const TransformT<double>& xfB,
                                                               bool skipParallel)
{
    const TransformT<double> bInA = InvMulTransforms(xfA, xfB);
    const TransformT<double> aInB = InvMulTransforms(xfB, xfA);
    const MappedPair512 m = MapPair512(a, b, bInA, aInB);
    const uint64_t skip = skipParallel ? AntiParallelFaces(a, b, InvMulRot(aInB.q, RotT<double>{})) : uint64_t(0);
    const bool separatedA =
        b.Count() <= 4 ? FacesSeparate512<4>(a, m.bx, m.by, 0) : FacesSeparate512<8>(a, m.bx, m.by, 0);
    const bool separatedB =
        a.Count() <= 4 ? FacesSeparate512<4>(b, m.ax, m.ay, skip) : FacesSeparate512<8>(b, m.ax, m.ay, skip);
    return !(separatedA | separatedB);
}
#endif

} // namespace satviz::detail
