// SPDX-License-Identifier: MIT
// An independent reference for segment casts against polygons, in quadruple precision: Cyrus-Beck clipping of the
// segment against the world-space outline (tests/support/reference.h maps the vertices), sharing no code with the
// library.
#pragma once

#include "reference.h"

#include <algorithm>

namespace satviz::testing
{

/// The reference answer for a segment cast.
struct ReferenceRay
{
    bool inside = false; ///< p1 inside or on the shape
    bool hit = false;    ///< the segment meets the shape
    Quad enter = 0;      ///< entry fraction when hit and not inside
    Quad margin = 0;     ///< how far from a change of answer (grazing, ending at the surface, starting on it)
    QVec normal;         ///< unit outward normal of the face entered (when hit and not inside)
};

/// The segment from p1 to p2 (world) against the polygon placed by xf: the latest entry over the faces the
/// segment heads into, against the earliest exit over those it heads out of.
inline ReferenceRay ReferencePolygonRay(const Polygon& polygon, const Transform& xf, Vec2 p1, Vec2 p2)
{
    const std::vector<QVec> w = QWorld(polygon, xf);
    const QVec q{Quad(p1.x), Quad(p1.y)};
    const QVec d{Quad(p2.x) - Quad(p1.x), Quad(p2.y) - Quad(p1.y)};
    Quad enter = -1e300;
    Quad leave = 1e300;
    bool inside = true;
    Quad nearest = 1e300; // smallest |s| / |n| over faces: how close p1 is to a face line
    ReferenceRay out;
    for (size_t i = 0; i < w.size(); ++i)
    {
        const QVec e = w[(i + 1) % w.size()] - w[i];
        const QVec n{e.y, -e.x};
        const Quad length = sqrtq(QDot(n, n));
        const Quad s = QDot(n, q - w[i]) / length;
        const Quad rate = QDot(n, d) / length;
        inside = inside && s <= 0;
        nearest = std::min(nearest, fabsq(s));
        if (rate == 0)
        {
            if (s > 0)
            {
                enter = 1e300; // never enters
            }
            continue;
        }
        const Quad t = -s / rate;
        if (rate < 0)
        {
            if (t > enter)
            {
                enter = t;
                out.normal = {n.x / length, n.y / length};
            }
        }
        else
        {
            leave = std::min(leave, t);
        }
    }
    out.inside = inside;
    out.hit = inside || (enter <= leave && enter <= 1 && enter >= 0);
    out.enter = enter;
    const Quad span = sqrtq(QDot(d, d));
    out.margin = std::min({nearest, fabsq(leave - enter) * span, fabsq(1 - enter) * span});
    return out;
}

} // namespace satviz::testing
