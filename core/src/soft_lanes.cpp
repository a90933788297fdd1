// SPDX-License-Identifier: MIT
// satviz: the soft step's passes over batches of contacts in lanes, and the choice of the lanes' instruction set.

#include "soft_lanes.h"

#include "sat/cpu_dispatch.h"
#include "sat/lanes.h"
#include "sat/lanes8.h"

#include <cassert>

namespace satviz::detail
{

void PackSoftLane(SoftBatch& b, int lane, const SoftContact& s, int readA, int readB, int writeA, int writeB)
{
    b.normalX[lane] = s.normal.x;
    b.normalY[lane] = s.normal.y;
    b.friction[lane] = s.friction;
    b.staticFriction[lane] = s.staticFriction;
    b.invMassA[lane] = s.invMassA;
    b.invInertiaA[lane] = s.invInertiaA;
    b.invMassB[lane] = s.invMassB;
    b.invInertiaB[lane] = s.invInertiaB;
    b.k11[lane] = s.k11;
    b.k12[lane] = s.k12;
    b.k22[lane] = s.k22;
    b.stiff[lane] = s.stiff ? 1.0 : 0.0;
    // A one-point contact's second point is never read (it is in a batch of one point, whose passes read the first
    // alone): not copied.
    for (int i = 0; i < s.count; ++i)
    {
        const SoftPoint& p = s.points[i];
        SoftLanePoints& q = b.points[i];
        q.rnA[lane] = p.rnA;
        q.rnB[lane] = p.rnB;
        q.rtA[lane] = p.rtA;
        q.rtB[lane] = p.rtB;
        q.separation[lane] = p.separation;
        q.normalMass[lane] = p.normalMass;
        q.tangentMass[lane] = p.tangentMass;
        q.normalImpulse[lane] = p.normalImpulse;
        q.tangentImpulse[lane] = p.tangentImpulse;
        q.maxNormalImpulse[lane] = p.maxNormalImpulse;
        q.normalTotal[lane] = p.normalTotal;
        q.tangentTotal[lane] = p.tangentTotal;
        b.stuck[i][lane] = s.stuck[i];
    }
    b.readA[lane] = readA;
    b.readB[lane] = readB;
    b.writeA[lane] = writeA;
    b.writeB[lane] = writeB;
}

void UnpackSoftLane(const SoftBatch& b, int lane, SoftContact& s)
{
    for (int i = 0; i < s.count; ++i)
    {
        SoftPoint& p = s.points[i];
        const SoftLanePoints& q = b.points[i];
        p.normalImpulse = q.normalImpulse[lane];
        p.tangentImpulse = q.tangentImpulse[lane];
        p.maxNormalImpulse = q.maxNormalImpulse[lane];
        p.normalTotal = q.normalTotal[lane];
        p.tangentTotal = q.tangentTotal[lane];
        s.stuck[i] = b.stuck[i][lane];
    }
}

namespace
{

// One pass over a colour's batches, each by the passes of its kind, L::kCount lanes at a time (a run of lanes that
// holds only padding is left out).
template <typename L>
void PassOverBatches(SoftPass pass, SoftBatch* begin, SoftBatch* end, SoftBody* states, const SoftPassConstants& k)
{
    for (SoftBatch* c = begin; c != end; ++c)
    {
        const bool one = c->kind == SoftKind::OnePoint;
        for (int at = 0; at < c->lanes; at += L::kCount)
        {
            switch (pass)
            {
            case SoftPass::WarmStart:
                one ? WarmStartLanes<L, 1>(*c, at, states) : WarmStartLanes<L, 2>(*c, at, states);
                break;
            case SoftPass::Solve:
                one ? SolveLanes<L, true, 1, false>(*c, at, states, k)
                    : SolveLanes<L, true, 2, false>(*c, at, states, k);
                break;
            case SoftPass::Relax:
                if (one)
                {
                    SolveLanes<L, false, 1, false>(*c, at, states, k);
                }
                else if (c->kind == SoftKind::Block)
                {
                    SolveLanes<L, false, 2, true>(*c, at, states, k);
                }
                else
                {
                    SolveLanes<L, false, 2, false>(*c, at, states, k);
                }
                break;
            }
        }
    }
}

#if SATVIZ_WIDE && SATVIZ_LANES_AVX2
[[gnu::target("avx2"), gnu::flatten]] void PassOverBatchesWide(SoftPass pass, SoftBatch* begin, SoftBatch* end,
                                                               SoftBody* states, const SoftPassConstants& k)
{
    PassOverBatches<Lanes<double, true>>(pass, begin, end, states, k);
}
#endif

#if SATVIZ_WIDE && SATVIZ_LANES8
[[gnu::target("avx2,avx512f"), gnu::flatten]] void PassOverBatches512(SoftPass pass, SoftBatch* begin, SoftBatch* end,
                                                                      SoftBody* states, const SoftPassConstants& k)
{
    PassOverBatches<Lanes8>(pass, begin, end, states, k);
}
#endif

} // namespace

void SoftPassOverBatches(SoftPass pass, SoftBatch* begin, SoftBatch* end, SoftBody* states, const SoftPassConstants& k)
{
    assert(HasWideVectors());
#if SATVIZ_WIDE && SATVIZ_LANES8
    if (HasWide512())
    {
        PassOverBatches512(pass, begin, end, states, k);
        return;
    }
#endif
#if SATVIZ_WIDE && SATVIZ_LANES_AVX2
    PassOverBatchesWide(pass, begin, end, states, k);
#else
    (void)pass, (void)begin, (void)end, (void)states, (void)k;
#endif
}

} // namespace satviz::detail
