// SPDX-License-Identifier: MIT
// Exact arithmetic on floating-point expansions, after J. R. Shewchuk, "Adaptive Precision Floating-Point
// Arithmetic and Fast Robust Geometric Predicates" (Discrete & Computational Geometry 18, 1997). An expansion is an
// unevaluated sum of doubles, nonoverlapping and sorted by increasing magnitude, without zero components: it
// represents a rational number exactly, and its sign is the sign of its largest component. Sums and products of
// doubles are formed without rounding, so the predicates below decide the sign of a polynomial in the double inputs
// exactly, as long as no intermediate result overflows or underflows: for the predicates of the tests (up to degree
// 8 in the inputs, c x counting as 2), inputs of 0 or of magnitude between about 1e-30 and 1e30. The algorithms
// need IEEE double arithmetic rounding to nearest, without extended intermediate precision.
//
// On top of it, the exact geometry of the tests: the world point of a body-frame vertex under a Transform,
// (c x - s y + px, s x + c y + py), as the rational numbers the double inputs denote, and the sign of the orientation
// of three such points.
#pragma once

#include <satviz/math.h>

#include <cmath>
#include <vector>

namespace satviz::testing
{

/// A double-double: the exact value of an operation on two doubles as x + y, x the rounded result, y its error.
struct TwoTerm
{
    double x = 0; ///< the rounded result
    double y = 0; ///< the rounding error: x + y is exact
};

/// Dekker's Fast-Two-Sum: a + b exactly, valid when |a| >= |b| (or a == 0).
inline TwoTerm FastTwoSum(double a, double b)
{
    const double x = a + b;
    const double bVirtual = x - a;
    return {x, b - bVirtual};
}

/// Knuth's Two-Sum: a + b exactly, for any order of magnitude.
inline TwoTerm TwoSum(double a, double b)
{
    const double x = a + b;
    const double bVirtual = x - a;
    const double aVirtual = x - bVirtual;
    const double bRoundoff = b - bVirtual;
    const double aRoundoff = a - aVirtual;
    return {x, aRoundoff + bRoundoff};
}

/// Two-Product: a * b exactly, the error of the rounded product recovered by a fused multiply-add.
inline TwoTerm TwoProduct(double a, double b)
{
    const double x = a * b;
    return {x, std::fma(a, b, -x)};
}

/// A nonoverlapping expansion: components in order of increasing magnitude, no zeros; the empty expansion is 0.
using Expansion = std::vector<double>;

/// The expansion of one double.
inline Expansion MakeExpansion(double a)
{
    return a == 0.0 ? Expansion{} : Expansion{a};
}

/// The expansion of a double-double.
inline Expansion MakeExpansion(TwoTerm t)
{
    Expansion out;
    if (t.y != 0.0)
    {
        out.push_back(t.y);
    }
    if (t.x != 0.0)
    {
        out.push_back(t.x);
    }
    return out;
}

/// Grow-Expansion with zero elimination: e + b. The running sum carries up through the components of e, each
/// Two-Sum leaving its roundoff behind as an output component.
inline Expansion GrowExpansion(const Expansion& e, double b)
{
    Expansion h;
    h.reserve(e.size() + 1);
    double q = b;
    for (const double component : e)
    {
        const TwoTerm sum = TwoSum(q, component);
        if (sum.y != 0.0)
        {
            h.push_back(sum.y);
        }
        q = sum.x;
    }
    if (q != 0.0)
    {
        h.push_back(q);
    }
    return h;
}

/// Expansion-Sum: e + f, by growing e with each component of f in turn.
inline Expansion ExpansionSum(const Expansion& e, const Expansion& f)
{
    Expansion h = e;
    for (const double component : f)
    {
        h = GrowExpansion(h, component);
    }
    return h;
}

/// -e, exactly.
inline Expansion Negate(const Expansion& e)
{
    Expansion h = e;
    for (double& component : h)
    {
        component = -component;
    }
    return h;
}

/// e - f.
inline Expansion ExpansionDifference(const Expansion& e, const Expansion& f)
{
    return ExpansionSum(e, Negate(f));
}

/// Scale-Expansion with zero elimination: e * b. Each component's exact product is folded into the running sum
/// with a Two-Sum (low part) and a Fast-Two-Sum (high part).
inline Expansion ScaleExpansion(const Expansion& e, double b)
{
    Expansion h;
    if (e.empty() || b == 0.0)
    {
        return h;
    }
    h.reserve(2 * e.size());
    auto keep = [&h](double component) {
        if (component != 0.0)
        {
            h.push_back(component);
        }
    };
    const TwoTerm first = TwoProduct(e[0], b);
    keep(first.y);
    double q = first.x;
    for (size_t i = 1; i < e.size(); ++i)
    {
        const TwoTerm product = TwoProduct(e[i], b);
        const TwoTerm low = TwoSum(q, product.y);
        keep(low.y);
        const TwoTerm high = FastTwoSum(product.x, low.x);
        keep(high.y);
        q = high.x;
    }
    keep(q);
    return h;
}

/// Compress: the same value with as few components as the carries allow (the largest component then approximates
/// the whole to within one of its ulps). A bottom-up pass gathers the carries, a top-down pass sheds the roundoffs.
inline Expansion Compress(const Expansion& e)
{
    if (e.empty())
    {
        return e;
    }
    const size_t m = e.size();
    std::vector<double> g(m);
    size_t bottom = m - 1;
    double q = e[m - 1];
    for (size_t i = m - 1; i-- > 0;)
    {
        const TwoTerm sum = FastTwoSum(q, e[i]);
        if (sum.y != 0.0)
        {
            g[bottom--] = sum.x;
            q = sum.y;
        }
        else
        {
            q = sum.x;
        }
    }
    g[bottom] = q;
    Expansion h;
    for (size_t i = bottom + 1; i < m; ++i)
    {
        const TwoTerm sum = FastTwoSum(g[i], q);
        if (sum.y != 0.0)
        {
            h.push_back(sum.y);
        }
        q = sum.x;
    }
    if (q != 0.0)
    {
        h.push_back(q);
    }
    return h;
}

/// e * f: the sum of e scaled by each component of f, compressed.
inline Expansion ExpansionProduct(const Expansion& e, const Expansion& f)
{
    Expansion h;
    for (const double component : f)
    {
        h = ExpansionSum(h, ScaleExpansion(e, component));
    }
    return Compress(h);
}

/// The sign of an expansion (-1, 0 or +1): that of its largest component.
inline int ExpansionSign(const Expansion& e)
{
    for (size_t i = e.size(); i-- > 0;)
    {
        if (e[i] != 0.0)
        {
            return e[i] > 0.0 ? 1 : -1;
        }
    }
    return 0;
}

/// An approximation of the value: the components summed from the smallest up.
inline double Estimate(const Expansion& e)
{
    double sum = 0.0;
    for (const double component : e)
    {
        sum += component;
    }
    return sum;
}

/// A point (or vector) with exact rational coordinates.
struct ExactPoint
{
    Expansion x; ///< x coordinate
    Expansion y; ///< y coordinate
};

/// A double point, exactly.
inline ExactPoint MakeExactPoint(Vec2 v)
{
    return {MakeExpansion(v.x), MakeExpansion(v.y)};
}

/// The exact world point of the body-frame point v: (c vx - s vy + px, s vx + c vy + py) with c = xf.q.c and
/// s = xf.q.s, no operation rounded (TransformPoint rounds each of them).
inline ExactPoint ExactTransform(const Transform& xf, Vec2 v)
{
    const Expansion cx = MakeExpansion(TwoProduct(xf.q.c, v.x));
    const Expansion sy = MakeExpansion(TwoProduct(xf.q.s, v.y));
    const Expansion sx = MakeExpansion(TwoProduct(xf.q.s, v.x));
    const Expansion cy = MakeExpansion(TwoProduct(xf.q.c, v.y));
    return {Compress(GrowExpansion(ExpansionDifference(cx, sy), xf.p.x)),
            Compress(GrowExpansion(ExpansionSum(sx, cy), xf.p.y))};
}

/// a - b, exactly.
inline ExactPoint ExactDifference(const ExactPoint& a, const ExactPoint& b)
{
    return {Compress(ExpansionDifference(a.x, b.x)), Compress(ExpansionDifference(a.y, b.y))};
}

/// The cross product u.x v.y - u.y v.x, exactly.
inline Expansion ExactCross(const ExactPoint& u, const ExactPoint& v)
{
    return Compress(ExpansionDifference(ExpansionProduct(u.x, v.y), ExpansionProduct(u.y, v.x)));
}

/// The dot product u.x v.x + u.y v.y, exactly.
inline Expansion ExactDot(const ExactPoint& u, const ExactPoint& v)
{
    return Compress(ExpansionSum(ExpansionProduct(u.x, v.x), ExpansionProduct(u.y, v.y)));
}

/// Shewchuk's orient2d, exactly: the sign of Cross(b - a, c - a), +1 when a, b, c turn counter-clockwise, -1
/// clockwise, 0 when they are collinear.
inline int ExactOrient2d(const ExactPoint& a, const ExactPoint& b, const ExactPoint& c)
{
    return ExpansionSign(ExactCross(ExactDifference(b, a), ExactDifference(c, a)));
}

} // namespace satviz::testing
