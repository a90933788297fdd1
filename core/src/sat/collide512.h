// SPDX-License-Identifier: MIT
// satviz (private), machinery: Collide of two polygons of up to 8 vertices on 512-bit vectors (AVX-512F): the face
// queries of both polygons, each with all its faces in one register of eight lanes against the other polygon's
// vertices held in registers, then one branch for the verdict. Used only in code compiled for AVX-512 (entry.h:
// RunWide512), where the processor has it (cpu_dispatch.h). The same separations to the bit as SmallRefFaceQuery
// (face_blocks.h), so the same manifold as the face loops of polygon_polygon.h.
#pragma once

#include "clip.h"
#include "cpu_dispatch.h"
#include "face_kernel.h"
#include "face_query.h"
#include "incident_polygon.h"
#include "lanes8.h"
#include "overlap512.h"
#include "select.h"

#include <satviz/manifold.h>
#include <satviz/polygon.h>

#include <cstdint>
#include <limits>
#include <type_traits>

namespace satviz::detail
{

#if SATVIZ_WIDE
/// The separations of the faces of `ref` (at most 8, unit normals, one per lane) from the first N of the other
/// polygon's vertices, mapped into ref's frame and held in registers (MapVertices512; N is its padded count, 4 or
/// 8): the face-separation kernel in eight lanes (face_kernel.h), where SmallRefSeparations runs it in four, so the
/// same bits. The lanes past ref's last face and those of the `skip`ped faces hold -infinity, so that they take no
/// part.
template <int N>
[[gnu::target("avx512f")]] Lanes8 FaceSeparations512(const PolygonT<double>& ref, const Lanes8& x, const Lanes8& y,
                                                     uint64_t skip)
{
    const int n = ref.Count();
    Lanes8 vx;
    Lanes8 vy;
    Lanes8 nx;
    Lanes8 ny;
    Lanes8::LoadPoints(&ref.InlineBlock()[0].x, vx, vy);
    Lanes8::LoadPoints(&ref.InlineBlock()[n + 1].x, nx, ny);
    const Lanes8 separation =
        SeparationsOf(LowestProjection<N, SpreadVertices8>(RegisterVertices8{x, y}, nx, ny), nx * vx + ny * vy);
    const int hidden = static_cast<int>((skip | ~((uint64_t(1) << n) - 1)) & 0xFF);
    return separation.Replace(hidden, -std::numeric_limits<double>::infinity());
}

/// The separations of every face of A from B and of every face of B from A (FaceSeparations512), B's `skip`ped faces
/// at -infinity.
[[gnu::target("avx512f")]] inline void PairSeparations512(const PolygonT<double>& a, const PolygonT<double>& b,
                                                          const MappedPair512& m, uint64_t skip, Lanes8& sepA,
                                                          Lanes8& sepB)
{
    sepA = b.Count() <= 4 ? FaceSeparations512<4>(a, m.bx, m.by, 0) : FaceSeparations512<8>(a, m.bx, m.by, 0);
    sepB = a.Count() <= 4 ? FaceSeparations512<4>(b, m.ax, m.ay, skip) : FaceSeparations512<8>(b, m.ax, m.ay, skip);
}

/// The incident polygon `p` of at most 8 vertices, which `xfInc` (its frame relative to the reference polygon)
/// maps, built from its vertices as MapVertices512 mapped them and holds them in `x` and `y` (the same bits as
/// IncidentPolygon maps them): the face loops mapped them already.
[[gnu::target("avx512f")]] inline IncidentPolygon<double>
MappedIncidentPolygon(const PolygonT<double>& p, const TransformT<double>& xfInc, const Lanes8& x, const Lanes8& y)
{
    static_assert(IncidentPolygon<double>::kCapacity >= 12, "8 vertices, then vertex 0 in the 4 entries after them");
    return IncidentPolygon<double>(p, xfInc, [&](double* xs, double* ys) {
        // Lanes past the last vertex hold vertex 0 already (MapVertices512).
        x.Store(xs);
        y.Store(ys);
        x.StoreFirst4(xs + 8);
        y.StoreFirst4(ys + 8);
    });
}

/// The manifold of two polygons of at most 8 vertices of which no face separates, from the separations of their
/// faces (FaceSeparations512: B's skipped faces at -infinity): the reference face is the face of largest separation,
/// A's on a tie; the incident polygon, as the face loops mapped it (`m`), is clipped as in CollidePolygons.
/// Without kContacts, the depth, normal and reference face alone: no contact points, no incident edge.
template <bool kContacts = true>
[[gnu::target("avx2,avx512f")]] ManifoldT<double>
ManifoldFromSeparations512(const PolygonT<double>& a, const TransformT<double>& xfA, const PolygonT<double>& b,
                           const TransformT<double>& xfB, const TransformT<double>& bInA,
                           const TransformT<double>& aInB, const MappedPair512& m, const Lanes8& sepA,
                           const Lanes8& sepB)
{
    int faceA = 0;
    int faceB = 0;
    const double largestA = LargestSeparation(a.Count(), faceA, sepA);
    const double largestB = LargestSeparation(b.Count(), faceB, sepB);
    // Reference face (a skipped duplicate of A's face keeps A's).
    const ReferenceFace<double> ref = ChooseReferenceFace(a, xfA, faceA, largestA, b, xfB, faceB, largestB);
    if constexpr (!kContacts)
    {
        return ReferenceFaceManifold(ref);
    }
    // The incident polygon for the clipping: its vertices as the face queries mapped them, from the registers.
    const int flipBits = Select(ref.flip, 0xFF, 0);
    const IncidentPolygon<double> inc =
        MappedIncidentPolygon(SelectRef(ref.flip, a, b), Select(ref.flip, aInB, bInA), m.bx.Blend(flipBits, m.ax),
                              m.by.Blend(flipBits, m.ay));
    const ClipResult<double> clip = ClipIncidentEdge<true>(ref.polygon, ref.face, inc, -1, 0.0);
    return ReferenceFaceManifold(ref, clip);
}

/// Collide of two polygons of at most 8 vertices on AVX-512 (CollidePolygons, step 0). The face queries of A and B
/// do not wait for each other: both polygons are mapped into the other's frame and every face of both is tested, then
/// one branch decides between a separating face (A's first, else B's first: the face the textbook loop stops at) and
/// the reference face (the largest separation, A's on a tie), where the face loops take a branch per polygon, each
/// mispredicted on about half of the pairs near contact. The contacts are clipped as in CollidePolygons.
[[gnu::target("avx2,avx512f")]] inline ManifoldT<double>
SmallPolygonsCollide512(const PolygonT<double>& a, const TransformT<double>& xfA, const PolygonT<double>& b,
                        const TransformT<double>& xfB, bool skipParallel)
{
    const TransformT<double> bInA = InvMulTransforms(xfA, xfB);
    const TransformT<double> aInB = InvMulTransforms(xfB, xfA);
    const uint64_t skip = skipParallel ? AntiParallelFaces(a, b, InvMulRot(aInB.q, RotT<double>{})) : uint64_t(0);
    Lanes8 sepA;
    Lanes8 sepB;
    const MappedPair512 m = MapPair512(a, b, bInA, aInB);
    PairSeparations512(a, b, m, skip, sepA, sepB);
    const Lanes8 zero = Lanes8::Fill(0.0);
    const int separatingA = sepA.GreaterBits(zero);
    const int separatingB = sepB.GreaterBits(zero);
    if ((separatingA | separatingB) != 0)
    {
        const bool byB = separatingA == 0;
        const int face = __builtin_ctz(static_cast<unsigned>(Select(byB, separatingB, separatingA)));
        const double separation = Select(byB, sepB.Get(face), sepA.Get(face));
        const Vec2T<double> normal = Rotate(Select(byB, xfB.q, xfA.q), SelectRef(byB, b, a).Normal(face));
        return {false,
                0.0,
                separation,
                Select(byB, -normal, normal),
                {},
                0,
                {AxisKind::FaceNormal, Select(byB, 1, 0), face},
                -1};
    }
    return ManifoldFromSeparations512(a, xfA, b, xfB, bInA, aInB, m, sepA, sepB);
}
#endif

} // namespace satviz::detail
