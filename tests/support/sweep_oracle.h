// SPDX-License-Identifier: MIT
// The full face loop of a polygon sweep, as the textbook writes it: every face of A against B, then every face of B
// against A, each with its exact separation at t = 0, its rate and its entry and exit times, and the verdict of them
// all (Ericson 5.5.2). An oracle for the sweep's trace, which evaluates only the faces that can decide when a polygon
// has more than 16 vertices.
//
// The numbers are those of the sweep's own arithmetic, so that a face the sweep evaluates can be compared to the bit:
//   - the other polygon is mapped into the face's polygon's frame by InvMulTransforms (p below), n is the face's unit
//     normal and v its first vertex. A polygon of up to 256 faces against one of up to 16 vertices is scanned: the
//     separation is min over p of Dot(n, p), minus Dot(n, v), as the sweep computes it. Otherwise it is the least
//     Dot(n, p - v) over every p, where the sweep finds the support point by walking, climbing or bisecting: the
//     sweep's separation is then one vertex's value of the same expression, never below the oracle's, and equal to
//     it unless two vertices tie on the face's normal up to rounding;
//   - the rate is n.x v.x + n.y v.y with v the relative velocity vB - vA in the face's polygon's frame (negated for
//     a face of B, so that a negative rate closes either way);
//   - a rate within 8 eps max(|v.x|, |v.y|) of 0 counts as 0 (the motion runs along the face as far as its rounding
//     can tell), then: s >= 0 enters at s / -r (r < 0) or never closes (r >= 0); s < 0 overlaps from t = 0 (no
//     entry, -infinity) and exits at -s / r when r > 0.
#pragma once

#include <satviz/sat.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace satviz::testing
{

/// One face of a sweep's full face loop.
struct OracleFace
{
    int side = 0;          ///< 0: a face of A (against B), 1: a face of B (against A)
    int face = 0;          ///< the face's index in its polygon
    double separation = 0; ///< at t = 0, the least over the other polygon's vertices
    double rate = 0;       ///< change of the separation per unit of t, as computed (before it counts as 0)
    double entry = 0;      ///< time the intervals start to overlap; -infinity: they overlap at t = 0
    double exit = 0;       ///< time they stop overlapping; infinity: never
    bool never = false;    ///< the axis never closes: it separates (or touches) and does not approach
    double scale = 0;      ///< the largest coordinate in the face's polygon's frame: the scale of the rounding
    double still = 0;      ///< the rate that counts as 0 on the face's polygon
};

/// The full face loop of a polygon sweep and its verdict.
struct SweepOracle
{
    std::vector<OracleFace> faces;                           ///< every face of A, then every face of B, in order
    double first = -std::numeric_limits<double>::infinity(); ///< the latest entry (-infinity: none)
    int firstFace = -1;                                      ///< index in `faces` of the first face that has it
    double last = std::numeric_limits<double>::infinity();   ///< the earliest exit
    bool anyNever = false;                                   ///< some axis never closes
    bool inside = true;                                      ///< every separation is < 0
    /// A hit: no axis that never closes, the latest entry at most 1 and before the earliest exit, and not every
    /// face overlapping at t = 0 (the sweep then reports the static test's verdict).
    bool Hit() const { return !anyNever && first <= 1.0 && first < last && !inside; }
    /// The face of A (side 0) or B (side 1), `face`.
    const OracleFace& Face(int side, int face, int countA) const
    {
        return faces[static_cast<size_t>(side == 0 ? face : countA + face)];
    }
    /// The verdict of the faces, in order.
    void Decide()
    {
        first = -std::numeric_limits<double>::infinity();
        firstFace = -1;
        last = std::numeric_limits<double>::infinity();
        anyNever = false;
        inside = true;
        for (size_t k = 0; k < faces.size(); ++k)
        {
            const OracleFace& f = faces[k];
            inside = inside && !(f.separation >= 0.0);
            if (f.entry > first)
            {
                first = f.entry;
                firstFace = static_cast<int>(k);
            }
            last = std::min(last, f.exit);
            anyNever = anyNever || f.never;
        }
    }
};

/// Entry, exit and whether the axis never closes, for separation s and rate r, with a rate within `still` of 0
/// counted as 0.
inline void OracleTimes(double s, double r, double still, double& entry, double& exit, bool& never)
{
    const double infinity = std::numeric_limits<double>::infinity();
    const double rate = std::max(r, -r) > still ? r : 0.0;
    const bool apart = s >= 0.0;
    const double q = s / -rate;
    entry = apart ? q : -infinity;
    exit = !apart && rate > 0.0 ? q : infinity;
    never = apart && rate >= 0.0;
}

/// The faces of `ref` (transform xfRef) against `inc` (xfInc); `v` is the motion that closes the faces' separations
/// when against their normals, in ref's frame.
inline void OracleFaces(const Polygon& ref, const Transform& xfRef, const Polygon& inc, const Transform& xfInc, Vec2 v,
                        int side, std::vector<OracleFace>& out)
{
    const Transform xf = InvMulTransforms(xfRef, xfInc);
    std::vector<Vec2> mapped;
    double scale = 0.0;
    for (const Vec2& w : inc.Vertices())
    {
        mapped.push_back(TransformPoint(xf, w));
        scale = std::max({scale, std::abs(mapped.back().x), std::abs(mapped.back().y)});
    }
    for (const Vec2& v : ref.Vertices())
    {
        scale = std::max({scale, std::abs(v.x), std::abs(v.y)});
    }
    const double still = 8.0 * std::numeric_limits<double>::epsilon() * std::max(std::abs(v.x), std::abs(v.y));
    const bool scanned = ref.Count() <= 256 && inc.Count() <= 16;
    for (int i = 0; i < ref.Count(); ++i)
    {
        OracleFace f;
        f.side = side;
        f.face = i;
        f.scale = scale;
        f.still = still;
        const Vec2 n = ref.Normal(i);
        const Vec2 vertex = ref.Vertices()[i];
        f.separation = std::numeric_limits<double>::infinity();
        for (const Vec2& p : mapped)
        {
            f.separation = std::min(f.separation, scanned ? n.x * p.x + n.y * p.y : Dot(n, p - vertex));
        }
        if (scanned)
        {
            f.separation = (f.separation - (n.x * vertex.x + n.y * vertex.y)) + 0.0;
        }
        f.rate = n.x * v.x + n.y * v.y;
        OracleTimes(f.separation, f.rate, still, f.entry, f.exit, f.never);
        out.push_back(f);
    }
}

/// The full face loop of the sweep of polygon a (transform xfA, displacement vA) against b (xfB, vB).
inline SweepOracle OracleSweep(const Polygon& a, const Transform& xfA, Vec2 vA, const Polygon& b, const Transform& xfB,
                               Vec2 vB)
{
    SweepOracle oracle;
    const Vec2 velocity = vB - vA;
    OracleFaces(a, xfA, b, xfB, InvRotate(xfA.q, velocity), 0, oracle.faces);
    OracleFaces(b, xfB, a, xfA, -InvRotate(xfB.q, velocity), 1, oracle.faces);
    oracle.Decide();
    return oracle;
}

} // namespace satviz::testing
