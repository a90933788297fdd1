// SPDX-License-Identifier: MIT
// Bit-for-bit comparison of query results: traced against untraced, wide against baseline scans.
#pragma once

#include <satviz/sat.h>

#include <cstring>

namespace satviz::testing
{

/// The same bits (a NaN equals only the same NaN; -0 differs from +0).
template <typename S>
bool SameBits(S a, S b)
{
    return std::memcmp(&a, &b, sizeof a) == 0;
}

/// Both coordinates have the same bits.
template <typename S>
bool SameBits(Vec2T<S> a, Vec2T<S> b)
{
    return SameBits(a.x, b.x) && SameBits(a.y, b.y);
}

/// Every field of the manifold, and the contacts it holds, have the same bits.
template <typename S>
bool SameBits(const ManifoldT<S>& a, const ManifoldT<S>& b)
{
    bool same = a.overlap == b.overlap && SameBits(a.depth, b.depth) && SameBits(a.gap, b.gap) &&
                SameBits(a.normal, b.normal) && a.contactCount == b.contactCount && a.axis.kind == b.axis.kind &&
                a.axis.shape == b.axis.shape && a.axis.index == b.axis.index && a.incidentEdge == b.incidentEdge;
    for (int i = 0; same && i < a.contactCount; ++i)
    {
        same = SameBits(a.contacts[i].point, b.contacts[i].point) &&
               SameBits(a.contacts[i].separation, b.contacts[i].separation);
    }
    return same;
}

/// Every field of the sweep result, its contacts and its initial manifold, have the same bits.
template <typename S>
bool SameBits(const SweepResultT<S>& a, const SweepResultT<S>& b)
{
    bool same = a.status == b.status && SameBits(a.toi, b.toi) && SameBits(a.normal, b.normal) &&
                a.axis.kind == b.axis.kind && a.axis.shape == b.axis.shape && a.axis.index == b.axis.index &&
                a.contactCount == b.contactCount && SameBits(a.initial, b.initial);
    for (int i = 0; same && i < a.contactCount; ++i)
    {
        same = SameBits(a.contacts[i].point, b.contacts[i].point) &&
               SameBits(a.contacts[i].separation, b.contacts[i].separation);
    }
    return same;
}

} // namespace satviz::testing
