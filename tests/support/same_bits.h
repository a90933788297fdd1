// SPDX-License-Identifier: MIT
// Bit-for-bit comparison of query results: traced against untraced, wide against baseline scans.
#pragma once

#include <satviz/sat.h>

#include <cmath>
#include <cstring>

namespace satviz::testing
{

/// The same bits (a NaN equals only the same NaN; -0 differs from +0). With `anyNaN`, a NaN equals any NaN: the sign
/// and payload of a NaN follow the order of the operands of the operation that made it, which the traced and the
/// untraced queries need not share.
template <typename S>
bool SameBits(S a, S b, bool anyNaN = false)
{
    return std::memcmp(&a, &b, sizeof a) == 0 || (anyNaN && std::isnan(a) && std::isnan(b));
}

/// Both coordinates have the same bits.
template <typename S>
bool SameBits(Vec2T<S> a, Vec2T<S> b, bool anyNaN = false)
{
    return SameBits(a.x, b.x, anyNaN) && SameBits(a.y, b.y, anyNaN);
}

/// Every field of the manifold, and the contacts it holds, have the same bits.
template <typename S>
bool SameBits(const ManifoldT<S>& a, const ManifoldT<S>& b, bool anyNaN = false)
{
    bool same = a.overlap == b.overlap && SameBits(a.depth, b.depth, anyNaN) && SameBits(a.gap, b.gap, anyNaN) &&
                SameBits(a.normal, b.normal, anyNaN) && a.contactCount == b.contactCount &&
                a.axis.kind == b.axis.kind && a.axis.shape == b.axis.shape && a.axis.index == b.axis.index &&
                a.incidentEdge == b.incidentEdge;
    for (int i = 0; same && i < a.contactCount; ++i)
    {
        same = SameBits(a.contacts[i].point, b.contacts[i].point, anyNaN) &&
               SameBits(a.contacts[i].separation, b.contacts[i].separation, anyNaN);
    }
    return same;
}

/// Every field of the sweep result, its contacts and its initial manifold, have the same bits.
template <typename S>
bool SameBits(const SweepResultT<S>& a, const SweepResultT<S>& b, bool anyNaN = false)
{
    bool same = a.status == b.status && SameBits(a.toi, b.toi, anyNaN) && SameBits(a.normal, b.normal, anyNaN) &&
                a.axis.kind == b.axis.kind && a.axis.shape == b.axis.shape && a.axis.index == b.axis.index &&
                a.contactCount == b.contactCount && SameBits(a.initial, b.initial, anyNaN);
    for (int i = 0; same && i < a.contactCount; ++i)
    {
        same = SameBits(a.contacts[i].point, b.contacts[i].point, anyNaN) &&
               SameBits(a.contacts[i].separation, b.contacts[i].separation, anyNaN);
    }
    return same;
}

} // namespace satviz::testing
