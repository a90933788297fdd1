// SPDX-License-Identifier: MIT
// satviz (private), machinery: the face-separation kernel. The textbook loop (face_query.h) takes a face, finds the
// smallest projection of the other polygon's vertices on its normal, and branches on the separation. The kernel holds
// a block of faces in lanes, one face each (four lanes: two SSE2 registers or one AVX2 register; eight: one AVX-512
// register), projects each vertex of the other polygon on all of them at once and keeps the smallest projection per
// lane, with the products, sums and minimum of the textbook loop in its order: every instantiation gives its bits.
// It is written once, over the lanes and over where the vertices come from (read one at a time from the arrays of a
// scanned incident polygon, read four at a time and spread across the lanes from registers, or held in registers
// already). What a loop decides from the separations is its own: the first separating face (Overlap), the largest
// separation (Collide), the entry and exit times (the sweep).
#pragma once

#include "incident_polygon.h"
#include "lanes8.h"

namespace satviz::detail
{

/// Vertex j0 of a scanned inc, its x (X<0>) and y (Y<0>) in every lane of L, read from inc's arrays by itself (a
/// broadcast load): the form for two blocks of faces taken together, whose normals fill the registers.
template <typename L, typename S>
struct BroadcastVertices
{
    static constexpr int kCount = 1; ///< vertices per group
    const S* x;                      ///< vertex j0's x
    const S* y;                      ///< and y

    /// Vertex j0 of `inc`.
    BroadcastVertices(const IncidentPolygon<S>& inc, int j0) : x(inc.x + j0), y(inc.y + j0) {}
    /// Vertex j0 + k's x in every lane.
    template <int k>
    L X() const
    {
        return L::Fill(x[k]);
    }
    /// Vertex j0 + k's y in every lane.
    template <int k>
    L Y() const
    {
        return L::Fill(y[k]);
    }
};

/// Four vertices of a scanned inc from vertex j0, read together into one group of four lanes and spread across the
/// lanes from registers, which is faster than a broadcast load per vertex where one block of faces is taken alone.
template <typename L, typename S>
struct SpreadVertices
{
    static constexpr int kCount = 4; ///< vertices per group
    L xs;                            ///< the four vertices' x, one per lane
    L ys;                            ///< and y

    /// The four vertices of `inc` from vertex j0 (j0 a multiple of 4: inc's arrays are aligned for whole lanes).
    SpreadVertices(const IncidentPolygon<S>& inc, int j0) : xs(L::Load(inc.x + j0)), ys(L::Load(inc.y + j0)) {}
    /// Vertex j0 + k's x in every lane.
    template <int k>
    L X() const
    {
        return xs.template Spread<k>();
    }
    /// Vertex j0 + k's y in every lane.
    template <int k>
    L Y() const
    {
        return ys.template Spread<k>();
    }
};

/// Takes vertex k of group w into the smallest projections of one or two blocks of normals (kBlocks): its
/// projection on each lane's normal, nx x + ny y, the first (`first`) or the smaller of it and the smallest so far
/// (Min keeps the second operand when either is NaN, as the textbook loop's comparison does).
template <int k, int kBlocks, typename Group, typename L>
void TakeVertex(const Group& w, bool first, const L& nx0, const L& ny0, const L& nx1, const L& ny1, L& low0, L& low1)
{
    const L x = w.template X<k>();
    const L y = w.template Y<k>();
    const L projection0 = nx0 * x + ny0 * y;
    low0 = first ? projection0 : Min(low0, projection0);
    if constexpr (kBlocks == 2)
    {
        const L projection1 = nx1 * x + ny1 * y;
        low1 = first ? projection1 : Min(low1, projection1);
    }
}

/// The kernel: per lane, the smallest projection min_j (nx x_j + ny y_j) of the N vertices of `vertices` (N a
/// multiple of 4) on the lane's normal, for one block of normals (nx0, ny0) or two (kBlocks = 2: each vertex read
/// once for both). The vertices are taken in order, in groups of one or four (Group: how they are read).
template <int N, int kBlocks, typename Group, typename Vertices, typename L>
void LowestProjections(const Vertices& vertices, const L& nx0, const L& ny0, const L& nx1, const L& ny1, L& low0,
                       L& low1)
{
    static_assert(N > 0 && N % 4 == 0 && (kBlocks == 1 || kBlocks == 2), "whole groups, one or two blocks");
    static_assert(Group::kCount == 1 || Group::kCount == 4, "groups of one or four vertices");
    for (int j0 = 0; j0 < N; j0 += Group::kCount)
    {
        const Group w(vertices, j0);
        TakeVertex<0, kBlocks>(w, j0 == 0, nx0, ny0, nx1, ny1, low0, low1);
        if constexpr (Group::kCount == 4)
        {
            TakeVertex<1, kBlocks>(w, false, nx0, ny0, nx1, ny1, low0, low1);
            TakeVertex<2, kBlocks>(w, false, nx0, ny0, nx1, ny1, low0, low1);
            TakeVertex<3, kBlocks>(w, false, nx0, ny0, nx1, ny1, low0, low1);
        }
    }
}

/// The kernel for one block of normals: per lane, the smallest projection of the N vertices on its normal.
template <int N, typename Group, typename Vertices, typename L>
L LowestProjection(const Vertices& vertices, const L& nx, const L& ny)
{
    L low = nx; // every lane replaced by the first vertex's projection
    LowestProjections<N, 1, Group>(vertices, nx, ny, nx, ny, low, low);
    return low;
}

/// The separations of a block of faces from the smallest projections `low` and the faces' offsets Dot(normal, v_i):
/// low - offset. Rounding is monotonic, so subtracting before or after the minimum gives the same number; adding +0
/// makes a zero separation +0 whichever zero the minimum kept, so every loop and width gives the same bits.
template <typename L>
L SeparationsOf(const L& low, const L& offset)
{
    return (low - offset) + L::Fill(0);
}

#if SATVIZ_LANES8
/// The other polygon's vertices held in registers, one per lane of Lanes8 (MapVertices512, overlap512.h).
struct RegisterVertices8
{
    const Lanes8& x; ///< the vertices' x
    const Lanes8& y; ///< and y
};

/// Vertex j0 of them, spread across the lanes from those registers.
struct SpreadVertices8
{
    static constexpr int kCount = 1; ///< vertices per group
    const Lanes8& xs;                ///< the vertices' x
    const Lanes8& ys;                ///< and y
    int j0;                          ///< the vertex

    /// Vertex j0.
    SpreadVertices8(const RegisterVertices8& v, int j) : xs(v.x), ys(v.y), j0(j) {}
    /// Vertex j0 + k's x in every lane.
    template <int k>
    [[gnu::target("avx512f")]] Lanes8 X() const
    {
        return xs.Spread(j0 + k);
    }
    /// Vertex j0 + k's y in every lane.
    template <int k>
    [[gnu::target("avx512f")]] Lanes8 Y() const
    {
        return ys.Spread(j0 + k);
    }
};
#endif

} // namespace satviz::detail
