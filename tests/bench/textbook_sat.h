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

/// A placed polygon's world-space vertices, on the stack up to 16 (no allocation, no thread-local buffer: the loops
/// below are timed against the library, so they are given the data layout a hand-written loop would use).
class Outline
{
  public:
    /// The vertices of `polygon` placed by `xf`.
    Outline(const Polygon& polygon, const Transform& xf) : m_count(polygon.Count())
    {
        if (m_count > kLocal)
        {
            m_heap.resize(static_cast<size_t>(m_count));
        }
        Vec2* out = m_count > kLocal ? m_heap.data() : m_local.vertices;
        for (int i = 0; i < m_count; ++i)
        {
            out[i] = TransformPoint(xf, polygon.Vertices()[i]);
        }
        m_data = out;
    }
    Outline(const Outline&) = delete;
    Outline& operator=(const Outline&) = delete;

    /// The vertex count.
    int Count() const { return m_count; }
    /// Vertex i (0 <= i < Count()).
    Vec2 operator[](int i) const { return m_data[i]; }
    /// The edge normal of edge i (vertex i to i + 1), not normalised, pointing out of a counter-clockwise outline.
    Vec2 EdgeNormal(int i) const { return RightPerp(m_data[i + 1 < m_count ? i + 1 : 0] - m_data[i]); }
    /// Lowest and highest projection of the vertices on an axis.
    void Project(Vec2 axis, double& lo, double& hi) const
    {
        lo = Dot(m_data[0], axis);
        hi = lo;
        for (int i = 1; i < m_count; ++i)
        {
            const double s = Dot(m_data[i], axis);
            lo = std::min(lo, s);
            hi = std::max(hi, s);
        }
    }

  private:
    static constexpr int kLocal = 16;
    // Left uninitialised until the constructor writes the vertices it uses.
    union Local
    {
        Local() {}
        Vec2 vertices[kLocal];
    };
    int m_count;
    Local m_local;
    std::vector<Vec2> m_heap;
    const Vec2* m_data = nullptr;
};

/// The tutorial's boolean test: stop at the first axis whose intervals do not overlap. Touching is overlap.
inline bool TextbookOverlap(const Polygon& a, const Transform& xfA, const Polygon& b, const Transform& xfB)
{
    const Outline wa(a, xfA);
    const Outline wb(b, xfB);
    for (const Outline* shape : {&wa, &wb})
    {
        for (int i = 0; i < shape->Count(); ++i)
        {
            const Vec2 axis = shape->EdgeNormal(i);
            double loA, hiA, loB, hiB;
            wa.Project(axis, loA, hiA);
            wb.Project(axis, loB, hiB);
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
    const Outline wa(a, xfA);
    const Outline wb(b, xfB);
    double best = std::numeric_limits<double>::infinity();
    for (const Outline* shape : {&wa, &wb})
    {
        for (int i = 0; i < shape->Count(); ++i)
        {
            const Vec2 axis = Normalize(shape->EdgeNormal(i));
            double loA, hiA, loB, hiB;
            wa.Project(axis, loA, hiA);
            wb.Project(axis, loB, hiB);
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
    const Outline wa(a, xfA);
    const Outline wb(b, xfB);
    double enter = 0.0;
    double leave = 1.0;
    for (const Outline* shape : {&wa, &wb})
    {
        for (int i = 0; i < shape->Count(); ++i)
        {
            const Vec2 axis = Normalize(shape->EdgeNormal(i));
            double loA, hiA, loB, hiB;
            wa.Project(axis, loA, hiA);
            wb.Project(axis, loB, hiB);
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
