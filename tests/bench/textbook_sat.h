// SPDX-License-Identifier: MIT
// The textbook separating-axis test, as tutorials teach it: both polygons in world space, every edge normal of
// both as an axis, every vertex projected on every axis (O((n + m)^2)). The baseline satviz-bench measures the
// library against: same inputs, same precision, no cleverness.
#pragma once

#include <satviz/sat.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace satviz::bench
{

/// World-space vertices of a placed polygon, in a reused buffer (no allocation once warm).
inline const std::vector<Vec2>& WorldVertices(const Polygon& p, const Transform& xf, std::vector<Vec2>& out)
{
    out.resize(p.Vertices().size());
    for (int i = 0; i < p.Count(); ++i)
    {
        out[static_cast<size_t>(i)] = TransformPoint(xf, p.Vertices()[i]);
    }
    return out;
}

/// Lowest and highest projection of points on an axis.
inline void Project(const std::vector<Vec2>& points, Vec2 axis, double& lo, double& hi)
{
    lo = std::numeric_limits<double>::infinity();
    hi = -lo;
    for (const Vec2& p : points)
    {
        const double s = Dot(p, axis);
        lo = std::min(lo, s);
        hi = std::max(hi, s);
    }
}

/// The tutorial's boolean test: stop at the first axis whose intervals do not overlap. Touching is overlap.
inline bool TextbookOverlap(const Polygon& a, const Transform& xfA, const Polygon& b, const Transform& xfB)
{
    thread_local std::vector<Vec2> wa;
    thread_local std::vector<Vec2> wb;
    WorldVertices(a, xfA, wa);
    WorldVertices(b, xfB, wb);
    for (const std::vector<Vec2>* shape : {&wa, &wb})
    {
        const std::vector<Vec2>& w = *shape;
        for (size_t i = 0; i < w.size(); ++i)
        {
            const Vec2 axis = RightPerp(w[(i + 1) % w.size()] - w[i]);
            double loA, hiA, loB, hiB;
            Project(wa, axis, loA, hiA);
            Project(wb, axis, loB, hiB);
            if (hiA < loB || hiB < loA)
            {
                return false;
            }
        }
    }
    return true;
}

/// The tutorial's minimum translation vector: unit axes, overlap min(hiA - loB, hiB - loA) on each, the smallest
/// wins, oriented from A to B. Returns the depth (< 0: separated, minus the largest gap found).
inline double TextbookMtv(const Polygon& a, const Transform& xfA, const Polygon& b, const Transform& xfB, Vec2& normal)
{
    thread_local std::vector<Vec2> wa;
    thread_local std::vector<Vec2> wb;
    WorldVertices(a, xfA, wa);
    WorldVertices(b, xfB, wb);
    double best = std::numeric_limits<double>::infinity();
    for (const std::vector<Vec2>* shape : {&wa, &wb})
    {
        const std::vector<Vec2>& w = *shape;
        for (size_t i = 0; i < w.size(); ++i)
        {
            const Vec2 axis = Normalize(RightPerp(w[(i + 1) % w.size()] - w[i]));
            double loA, hiA, loB, hiB;
            Project(wa, axis, loA, hiA);
            Project(wb, axis, loB, hiB);
            const double pushB = hiA - loB; // moving B along +axis
            const double pushA = hiB - loA; // moving B along -axis
            const double overlap = std::min(pushB, pushA);
            if (overlap < 0.0)
            {
                normal = pushB < pushA ? -axis : axis;
                return overlap;
            }
            if (overlap < best)
            {
                best = overlap;
                normal = pushB <= pushA ? axis : -axis;
            }
        }
    }
    return best;
}

/// The tutorial's swept test for B moving by v (A still): on every axis the entry and exit times of the moving
/// interval; the first contact is the latest entry if it comes before the earliest exit. Returns t in [0, 1], or
/// -1 for no hit.
inline double TextbookToi(const Polygon& a, const Transform& xfA, const Polygon& b, const Transform& xfB, Vec2 v)
{
    thread_local std::vector<Vec2> wa;
    thread_local std::vector<Vec2> wb;
    WorldVertices(a, xfA, wa);
    WorldVertices(b, xfB, wb);
    double enter = 0.0;
    double leave = 1.0;
    for (const std::vector<Vec2>* shape : {&wa, &wb})
    {
        const std::vector<Vec2>& w = *shape;
        for (size_t i = 0; i < w.size(); ++i)
        {
            const Vec2 axis = Normalize(RightPerp(w[(i + 1) % w.size()] - w[i]));
            double loA, hiA, loB, hiB;
            Project(wa, axis, loA, hiA);
            Project(wb, axis, loB, hiB);
            const double speed = Dot(v, axis);
            if (speed == 0.0)
            {
                if (hiA < loB || hiB < loA)
                {
                    return -1.0;
                }
                continue;
            }
            double t0 = (loA - hiB) / speed;
            double t1 = (hiA - loB) / speed;
            if (t0 > t1)
            {
                std::swap(t0, t1);
            }
            enter = std::max(enter, t0);
            leave = std::min(leave, t1);
            if (enter > leave)
            {
                return -1.0;
            }
        }
    }
    return enter;
}

} // namespace satviz::bench
