// SPDX-License-Identifier: MIT
// satviz: the soft step's passes over several contacts at a time, side by side in lanes of double (internal).
//
// Outline (after Box2D v3's contact solver, which solves eight contacts at a time in float lanes over a graph
// colouring; Catto, "Solver2D", 2024):
//  1. The contacts are coloured (SolveSoft) so that no two of a colour share a body the passes move; a colour's
//     contacts can then be visited in any order, and side by side.
//  2. A colour's contacts are packed eight to a SoftBatch, those of one kind together (one point, two points, two
//     points solved as a block in the relax), each field eight lanes wide.
//  3. A pass over a batch (WarmStartLanes, SolveLanes) reads the pairs of bodies into lanes (eight with AVX-512,
//     four at a time with AVX2), does for each lane exactly the operations SolveSoftContact and WarmStart do for one
//     contact, in the same order (a branch becomes both sides and a choice per lane), and writes the bodies back.
//     So the lanes give the same bits as the scalar visit, on every instruction set.
// The lanes write a body only if the passes move it: the velocities of a static or sleeping body, which contacts of
// one colour may share, go to a sink that nothing reads.
#pragma once

#include "sat/lanes.h"
#include "sat/lanes8.h"
#include "soft_solver.h"

#include <cstddef>
#include <cstdint>
#include <cstring>

namespace satviz::detail
{

/// Contacts in a SoftBatch: the lanes of AVX-512, two runs of the four of AVX2.
constexpr int kSoftLanes = 8;

/// What sets a batch's passes apart: its contacts' points and, in the relax, whether the two are solved together.
enum class SoftKind : uint8_t
{
    OnePoint,  ///< one point
    TwoPoints, ///< two points, solved one after the other
    Block,     ///< two points whose normal impulses the relax solves together (SoftContact::block)
};

/// One point of the contacts of a SoftBatch, each field a lane per contact (see SoftPoint).
struct alignas(64) SoftLanePoints
{
    double rnA[kSoftLanes];              ///< Cross(rA, normal)
    double rnB[kSoftLanes];              ///< Cross(rB, normal)
    double rtA[kSoftLanes];              ///< Cross(rA, tangent)
    double rtB[kSoftLanes];              ///< Cross(rB, tangent)
    double separation[kSoftLanes];       ///< separation at the start of the step
    double normalMass[kSoftLanes];       ///< effective mass along the normal
    double tangentMass[kSoftLanes];      ///< effective mass along the tangent
    double normalImpulse[kSoftLanes];    ///< accumulated normal impulse
    double tangentImpulse[kSoftLanes];   ///< accumulated friction impulse
    double maxNormalImpulse[kSoftLanes]; ///< the largest accumulated normal impulse over the sub-steps
    double normalTotal[kSoftLanes];      ///< the accumulated normal impulses of the sub-steps done, summed
    double tangentTotal[kSoftLanes];     ///< the accumulated friction impulses of the sub-steps done, summed
};

/// Up to kSoftLanes contacts of one colour and one kind, each field a lane per contact (see SoftContact). Lanes
/// beyond `lanes` are padding: they read a body at rest with no mass and write nowhere that is read.
struct alignas(64) SoftBatch
{
    double normalX[kSoftLanes];         ///< normal, x
    double normalY[kSoftLanes];         ///< normal, y
    double friction[kSoftLanes];        ///< sliding friction
    double staticFriction[kSoftLanes];  ///< static friction
    double invMassA[kSoftLanes];        ///< A's inverse mass
    double invInertiaA[kSoftLanes];     ///< A's inverse inertia
    double invMassB[kSoftLanes];        ///< B's inverse mass
    double invInertiaB[kSoftLanes];     ///< B's inverse inertia
    double k11[kSoftLanes];             ///< K, the 2x2 normal mass matrix
    double k12[kSoftLanes];             ///< K's off-diagonal
    double k22[kSoftLanes];             ///< K
    double stiff[kSoftLanes];           ///< 1 where the stiffer spring holds (SoftContact::stiff), else 0
    SoftLanePoints points[2];           ///< the points (the second filled for contacts of two points only)
    int readA[kSoftLanes];              ///< A's record in the body states
    int readB[kSoftLanes];              ///< B's record
    int writeA[kSoftLanes];             ///< where A's velocities go: its record if the passes move it, else a sink
    int writeB[kSoftLanes];             ///< B's
    bool stuck[2][kSoftLanes];          ///< static friction held in the last pass, per point
    int contact[kSoftLanes];            ///< each lane's contact (its SoftContact record), -1 for the padding
    int lanes = 0;                      ///< contacts, 1 to kSoftLanes
    SoftKind kind = SoftKind::OnePoint; ///< what its passes do
};

/// A colour's contacts: batches [batchBegin, batchEnd) and the contacts visited one at a time (those the step trace
/// records; all of them without wide vectors) at [singleBegin, singleEnd) of their list.
struct SoftColour
{
    int batchBegin = 0;  ///< first batch
    int batchEnd = 0;    ///< one past the last batch
    int singleBegin = 0; ///< first contact visited alone
    int singleEnd = 0;   ///< one past the last
};

/// Puts contact s in lane `lane` of batch b, with the records it reads and writes its bodies' velocities in.
void PackSoftLane(SoftBatch& b, int lane, const SoftContact& s, int readA, int readB, int writeA, int writeB);

/// Gives contact s the impulses and static friction's flags of lane `lane` of batch b.
void UnpackSoftLane(const SoftBatch& b, int lane, SoftContact& s);

/// The constants of a pass: the two springs (SoftContact::stiff picks), 1 / h and the push's speed limit.
struct SoftPassConstants
{
    Softness soft;       ///< the spring between two bodies that give way
    Softness stiff;      ///< the spring against a body that cannot give way
    double invH;         ///< 1 / sub-step
    double maxPushSpeed; ///< the soft push's speed limit
};

/// Which of a sub-step's passes.
enum class SoftPass
{
    WarmStart, ///< WarmStart
    Solve,     ///< SolveSoftContact with the soft push
    Relax,     ///< SolveSoftContact without it
};

/// One pass over batches [begin, end) of one colour (in any order: they share no body the passes move), on the
/// widest lanes the processor has: AVX-512 (HasWide512), eight lanes, else AVX2, four. Only with wide vectors
/// (HasWideVectors): without, SolveSoft makes no batches and visits the contacts one at a time.
void SoftPassOverBatches(SoftPass pass, SoftBatch* begin, SoftBatch* end, SoftBody* states, const SoftPassConstants& k);

/// L::kCount rows of four doubles (32-byte aligned) turned into four lanes of L, and back, by shuffles: row k is
/// lane k. A SoftBody is two such rows (velocity, spin and angle; move and turn), so that its fields are read in two
/// loads, not one per field.
template <typename L>
struct Rows;

#if SATVIZ_LANES_AVX2
/// Rows for the AVX2 lanes: a 4x4 transpose, pairs unpacked then halves exchanged.
template <>
struct Rows<Lanes<double, true>>
{
    /// The transpose of rows a, b, c, d, in place.
    [[gnu::target("avx2")]] static void Transpose(__m256d& a, __m256d& b, __m256d& c, __m256d& d)
    {
        const __m256d t0 = _mm256_unpacklo_pd(a, b); // a0 b0 a2 b2
        const __m256d t1 = _mm256_unpackhi_pd(a, b); // a1 b1 a3 b3
        const __m256d t2 = _mm256_unpacklo_pd(c, d); // c0 d0 c2 d2
        const __m256d t3 = _mm256_unpackhi_pd(c, d); // c1 d1 c3 d3
        a = _mm256_permute2f128_pd(t0, t2, 0x20);
        b = _mm256_permute2f128_pd(t1, t3, 0x20);
        c = _mm256_permute2f128_pd(t0, t2, 0x31);
        d = _mm256_permute2f128_pd(t1, t3, 0x31);
    }
    /// Lanes out[j] = (r[0][j], r[1][j], r[2][j], r[3][j]).
    [[gnu::target("avx2")]] static void Load(const double* const* r, Lanes<double, true> out[4])
    {
        __m256d a = _mm256_load_pd(r[0]), b = _mm256_load_pd(r[1]), c = _mm256_load_pd(r[2]), d = _mm256_load_pd(r[3]);
        Transpose(a, b, c, d);
        out[0] = {a};
        out[1] = {b};
        out[2] = {c};
        out[3] = {d};
    }
    /// r[k][j] = lane k of in[j].
    [[gnu::target("avx2")]] static void Store(const Lanes<double, true> in[4], double* const* r)
    {
        __m256d a = in[0].v, b = in[1].v, c = in[2].v, d = in[3].v;
        Transpose(a, b, c, d);
        _mm256_store_pd(r[0], a);
        _mm256_store_pd(r[1], b);
        _mm256_store_pd(r[2], c);
        _mm256_store_pd(r[3], d);
    }
};
#endif

static_assert(offsetof(SoftBody, v) == 0 && offsetof(SoftBody, w) == 16 && offsetof(SoftBody, angle) == 24 &&
                  offsetof(SoftBody, position) == 32 && offsetof(SoftBody, rotation) == 48 && sizeof(SoftBody) == 64,
              "a SoftBody is two rows of four doubles: v, w, angle; position, rotation");

#if SATVIZ_LANES8
/// Rows for the AVX-512 lanes: rows k and k + 4 side by side in one register, unpacked in pairs, then the pairs of
/// each half gathered by a permutation across the two registers.
template <>
struct Rows<Lanes8>
{
    /// Lanes out[j] = (r[0][j], ..., r[7][j]). (Masked forms with every lane set throughout: GCC 12 warns that the
    /// plain forms' undefined pass-through may be used uninitialized.)
    [[gnu::target("avx512f")]] static void Load(const double* const* r, Lanes8 out[4])
    {
        constexpr __mmask8 kAll = 0xFF;
        __m512d row[4];
        for (int k = 0; k < 4; ++k)
        {
            const __m256d low = _mm256_load_pd(r[k]);
            const __m512d both = _mm512_mask_broadcast_f64x4(_mm512_set1_pd(0.0), kAll, low);
            row[k] = _mm512_mask_insertf64x4(both, kAll, both, _mm256_load_pd(r[k + 4]), 1);
        }
        // t0: r0.0 r1.0 r0.2 r1.2 | r4.0 r5.0 r4.2 r5.2, t1 the same of .1 and .3; t2, t3 of rows 2, 3, 6, 7.
        const __m512d t0 = _mm512_mask_unpacklo_pd(row[0], kAll, row[0], row[1]);
        const __m512d t1 = _mm512_mask_unpackhi_pd(row[0], kAll, row[0], row[1]);
        const __m512d t2 = _mm512_mask_unpacklo_pd(row[2], kAll, row[2], row[3]);
        const __m512d t3 = _mm512_mask_unpackhi_pd(row[2], kAll, row[2], row[3]);
        const __m512i even = _mm512_setr_epi64(0, 1, 8, 9, 4, 5, 12, 13);
        const __m512i odd = _mm512_setr_epi64(2, 3, 10, 11, 6, 7, 14, 15);
        out[0] = {_mm512_permutex2var_pd(t0, even, t2)};
        out[1] = {_mm512_permutex2var_pd(t1, even, t3)};
        out[2] = {_mm512_permutex2var_pd(t0, odd, t2)};
        out[3] = {_mm512_permutex2var_pd(t1, odd, t3)};
    }
    /// r[k][j] = lane k of in[j].
    [[gnu::target("avx512f")]] static void Store(const Lanes8 in[4], double* const* r)
    {
        constexpr __mmask8 kAll = 0xFF;
        // a: f0.0 f1.0 | f0.2 f1.2 | f0.4 f1.4 | f0.6 f1.6 (128-bit blocks), b the same of the odd lanes; c, d of
        // fields 2 and 3. Row k is block k / 2 of a (or b) then the same block of c (or d).
        const __m512d a = _mm512_mask_unpacklo_pd(in[0].v, kAll, in[0].v, in[1].v);
        const __m512d b = _mm512_mask_unpackhi_pd(in[0].v, kAll, in[0].v, in[1].v);
        const __m512d c = _mm512_mask_unpacklo_pd(in[2].v, kAll, in[2].v, in[3].v);
        const __m512d d = _mm512_mask_unpackhi_pd(in[2].v, kAll, in[2].v, in[3].v);
        const __m512i lowBlocks = _mm512_setr_epi64(0, 1, 8, 9, 2, 3, 10, 11);
        const __m512i highBlocks = _mm512_setr_epi64(4, 5, 12, 13, 6, 7, 14, 15);
        const __m512d rows[4] = {
            _mm512_permutex2var_pd(a, lowBlocks, c),  // rows 0, 2
            _mm512_permutex2var_pd(b, lowBlocks, d),  // rows 1, 3
            _mm512_permutex2var_pd(a, highBlocks, c), // rows 4, 6
            _mm512_permutex2var_pd(b, highBlocks, d), // rows 5, 7
        };
        // Each half extracted and stored plainly: no permutation to move the upper half down, and no masked store,
        // which a later load of the same row (the next colour's, of a body they share) may have to wait for.
        // (Masked extracts with every lane set: GCC 12 warns that the plain one's pass-through may be used
        // uninitialized.)
        constexpr __mmask8 kHalf = 0x0F;
        for (int k = 0; k < 4; ++k)
        {
            const int first = k % 2 + 4 * (k / 2);
            _mm256_store_pd(r[first], _mm512_mask_extractf64x4_pd(_mm256_setzero_pd(), kHalf, rows[k], 0));
            _mm256_store_pd(r[first + 2], _mm512_mask_extractf64x4_pd(_mm256_setzero_pd(), kHalf, rows[k], 1));
        }
    }
};
#endif

/// One end of L::kCount contacts, lane by lane, while a pass works on them: the fields of SoftBody in its order.
template <typename L>
struct LaneBody
{
    L vx, vy, w, angle; ///< velocity, spin and angle (which the passes do not change)
    L px, py, qc, qs;   ///< move and turn (read by the solve and the relax only)
};

/// The first row of bodies index[0] to index[L::kCount - 1] (velocity, spin, angle), and with kMoves the second
/// (move, turn).
template <typename L, bool kMoves>
inline LaneBody<L> LoadBodies(const SoftBody* states, const int* index)
{
    constexpr int kWidth = L::kCount;
    LaneBody<L> out;
    L first[4];
    const double* rows[kWidth];
    for (int k = 0; k < kWidth; ++k)
    {
        rows[k] = &states[index[k]].v.x;
    }
    Rows<L>::Load(rows, first);
    out.vx = first[0];
    out.vy = first[1];
    out.w = first[2];
    out.angle = first[3];
    if constexpr (kMoves)
    {
        L second[4];
        for (int k = 0; k < kWidth; ++k)
        {
            rows[k] = &states[index[k]].position.x;
        }
        Rows<L>::Load(rows, second);
        out.px = second[0];
        out.py = second[1];
        out.qc = second[2];
        out.qs = second[3];
    }
    return out;
}

/// Writes the first row (velocity, spin and the angle as it was read) to bodies index[0] to index[L::kCount - 1]:
/// every lane, the padding's to the sink.
template <typename L>
inline void StoreBodies(const LaneBody<L>& b, SoftBody* states, const int* index)
{
    constexpr int kWidth = L::kCount;
    const L first[4] = {b.vx, b.vy, b.w, b.angle};
    double* rows[kWidth];
    for (int k = 0; k < kWidth; ++k)
    {
        rows[k] = &states[index[k]].v.x;
    }
    Rows<L>::Store(first, rows);
}

/// WarmStart on lanes at to at + L::kCount - 1 of batch c.
template <typename L, int kPoints>
inline void WarmStartLanes(const SoftBatch& c, int at, SoftBody* states)
{
    LaneBody<L> a = LoadBodies<L, false>(states, c.readA + at);
    LaneBody<L> b = LoadBodies<L, false>(states, c.readB + at);
    const L nx = L::Load(c.normalX + at), ny = L::Load(c.normalY + at);
    const L tx = ny, ty = -nx;
    const L mA = L::Load(c.invMassA + at), iA = L::Load(c.invInertiaA + at);
    const L mB = L::Load(c.invMassB + at), iB = L::Load(c.invInertiaB + at);
    for (int i = 0; i < kPoints; ++i)
    {
        const SoftLanePoints& p = c.points[i];
        const L ni = L::Load(p.normalImpulse + at), ti = L::Load(p.tangentImpulse + at);
        const L ix = ni * nx + ti * tx;
        const L iy = ni * ny + ti * ty;
        a.vx = a.vx - mA * ix;
        a.vy = a.vy - mA * iy;
        a.w = a.w - iA * (ni * L::Load(p.rnA + at) + ti * L::Load(p.rtA + at));
        b.vx = b.vx + mB * ix;
        b.vy = b.vy + mB * iy;
        b.w = b.w + iB * (ni * L::Load(p.rnB + at) + ti * L::Load(p.rtB + at));
    }
    StoreBodies(a, states, c.writeA + at);
    StoreBodies(b, states, c.writeB + at);
}

/// The speed of B's point against A's along (dx, dy) (SpeedAlong), lever arms' cross products rA, rB.
template <typename L>
inline L LaneSpeed(const LaneBody<L>& a, const LaneBody<L>& b, L dx, L dy, L rA, L rB)
{
    return ((b.vx - a.vx) * dx + (b.vy - a.vy) * dy) + b.w * rB - a.w * rA;
}

/// ApplyImpulse on lanes: -impulse along (dx, dy) on A, +impulse on B.
template <typename L>
inline void LaneImpulse(LaneBody<L>& a, LaneBody<L>& b, L mA, L iA, L mB, L iB, L dx, L dy, L rA, L rB, L impulse)
{
    a.vx = a.vx - (mA * impulse) * dx;
    a.vy = a.vy - (mA * impulse) * dy;
    a.w = a.w - iA * impulse * rA;
    b.vx = b.vx + (mB * impulse) * dx;
    b.vy = b.vy + (mB * impulse) * dy;
    b.w = b.w + iB * impulse * rB;
}

/// std::max(x, y) on lanes: x < y ? y : x (Max(y, x) is y > x ? y : x, the same for every input, NaN included).
template <typename L>
inline L StdMax(L x, L y)
{
    return Max(y, x);
}

/// std::min(x, y) on lanes: y < x ? y : x.
template <typename L>
inline L StdMin(L x, L y)
{
    return Min(y, x);
}

/// Stores lane k's bit of `bits` (a Mask's Bits) as flags[k], for k below L::kCount: each bit spread to a byte of
/// its own by a multiplication and written in one store, not a shift and a store a lane (a visit's time goes with its
/// instructions). The lanes are x86's, little-endian: byte k of the word is flags[k].
template <typename L>
inline void StoreFlags(int bits, bool* flags)
{
    static_assert(L::kCount <= 8, "a flag a byte, up to eight bytes");
    // Byte k keeps bit k of the copy of the bits in each byte; adding 0x7F sets its top bit where that bit was set.
    const uint64_t copies = static_cast<uint64_t>(bits & ((1 << L::kCount) - 1)) * 0x0101010101010101ULL;
    const uint64_t kept = copies & 0x8040201008040201ULL;
    const uint64_t spread = ((kept + 0x7F7F7F7F7F7F7F7FULL) >> 7) & 0x0101010101010101ULL;
    std::memcpy(flags, &spread, L::kCount);
}

/// SolveSoftContact (untraced) on lanes at to at + L::kCount - 1 of batch c: the solve of a sub-step with `kUseBias`,
/// else the relax. kPoints: 1 or 2; kBlock: the relax solves the two normal impulses together (SolveNormalBlock,
/// BlockImpulses).
template <typename L, bool kUseBias, int kPoints, bool kBlock>
inline void SolveLanes(SoftBatch& c, int at, SoftBody* states, const SoftPassConstants& k)
{
    using Mask = typename L::Mask;
    LaneBody<L> a = LoadBodies<L, true>(states, c.readA + at);
    LaneBody<L> b = LoadBodies<L, true>(states, c.readB + at);
    const L nx = L::Load(c.normalX + at), ny = L::Load(c.normalY + at);
    const L tx = ny, ty = -nx;
    const L zero = L::Fill(0.0), one = L::Fill(1.0), invH = L::Fill(k.invH);
    const L pxA = a.px, pyA = a.py, qcA = a.qc, qsA = a.qs;
    const L pxB = b.px, pyB = b.py, qcB = b.qc, qsB = b.qs;
    const L moved = (pxB - pxA) * nx + (pyB - pyA) * ny;
    L ni[kPoints], ti[kPoints], maxNi[kPoints], s[kPoints], rnA[kPoints], rnB[kPoints], rtA[kPoints], rtB[kPoints];
    Mask idle = Mask::Fill(true);
    for (int i = 0; i < kPoints; ++i)
    {
        const SoftLanePoints& p = c.points[i];
        ni[i] = L::Load(p.normalImpulse + at);
        ti[i] = L::Load(p.tangentImpulse + at);
        maxNi[i] = L::Load(p.maxNormalImpulse + at);
        rnA[i] = L::Load(p.rnA + at);
        rnB[i] = L::Load(p.rnB + at);
        rtA[i] = L::Load(p.rtA + at);
        rtB[i] = L::Load(p.rtB + at);
        const L turnB = qsB * rnB[i] - (qcB - one) * rtB[i];
        const L turnA = qsA * rnA[i] - (qcA - one) * rtA[i];
        s[i] = ((L::Load(p.separation + at) + moved) + turnB) - turnA;
        idle = idle & (ni[i] == zero) & (ti[i] == zero);
    }
    // The idle contacts whose gaps stay open are skipped (SolveSoftContact): here every lane is worked and the
    // skipped lanes keep what they had, but for static friction's flag, which the skip sets from the slip.
    Mask open = Mask::Fill(true);
    Mask skipStuck[kPoints];
    const L tm[2] = {L::Load(c.points[0].tangentMass + at), L::Load(c.points[kPoints - 1].tangentMass + at)};
    for (int i = 0; i < kPoints; ++i)
    {
        open = open & (s[i] > zero) & ((LaneSpeed(a, b, nx, ny, rnA[i], rnB[i]) + s[i] * invH) > zero);
        skipStuck[i] = (tm[i] * LaneSpeed(a, b, tx, ty, rtA[i], rtB[i])) == zero;
    }
    const Mask skip = idle & open;
    if (skip.All())
    {
        for (int i = 0; i < kPoints; ++i)
        {
            StoreFlags<L>(skipStuck[i].Bits(), c.stuck[i] + at);
        }
        return;
    }
    const LaneBody<L> a0 = a, b0 = b;
    const L mA = L::Load(c.invMassA + at), iA = L::Load(c.invInertiaA + at);
    const L mB = L::Load(c.invMassB + at), iB = L::Load(c.invInertiaB + at);
    L nextNi[kPoints];
    if constexpr (!kUseBias && kBlock)
    {
        // SolveNormalBlock: both normal impulses at once, the four cases of BlockImpulses tried on every lane and
        // the first that holds taken.
        L target[2], vn[2];
        for (int i = 0; i < 2; ++i)
        {
            target[i] = Select(s[i] > zero, (-s[i]) * invH, zero);
            vn[i] = LaneSpeed(a, b, nx, ny, rnA[i], rnB[i]);
        }
        const L k11 = L::Load(c.k11 + at), k12 = L::Load(c.k12 + at), k22 = L::Load(c.k22 + at);
        const L a1 = ni[0], a2 = ni[1];
        const L b1 = (vn[0] - target[0]) - (k11 * a1 + k12 * a2);
        const L b2 = (vn[1] - target[1]) - (k12 * a1 + k22 * a2);
        const L inv = one / (k11 * k22 - k12 * k12);
        const L m11 = inv * k22, m12 = (-inv) * k12, m22 = inv * k11;
        const L nm1 = L::Load(c.points[0].normalMass + at), nm2 = L::Load(c.points[1].normalMass + at);
        const L both1 = -(m11 * b1 + m12 * b2);
        const L both2 = -(m12 * b1 + m22 * b2);
        const Mask both = (both1 >= zero) & (both2 >= zero);
        const L first1 = (-nm1) * b1;
        const Mask first = (first1 >= zero) & ((k12 * first1 + b2) >= zero);
        const L second2 = (-nm2) * b2;
        const Mask second = (second2 >= zero) & ((k12 * second2 + b1) >= zero);
        const Mask neither = (b1 >= zero) & (b2 >= zero);
        const L x1 = Select(both, both1, Select(first, first1, Select(second | neither, zero, a1)));
        const L x2 = Select(both, both2, Select(first, zero, Select(second, second2, Select(neither, zero, a2))));
        LaneImpulse(a, b, mA, iA, mB, iB, nx, ny, rnA[0], rnB[0], x1 - a1);
        LaneImpulse(a, b, mA, iA, mB, iB, nx, ny, rnA[1], rnB[1], x2 - a2);
        nextNi[0] = x1;
        nextNi[1] = x2;
        maxNi[0] = StdMax(maxNi[0], x1);
        maxNi[1] = StdMax(maxNi[1], x2);
    }
    else
    {
        const Mask stiff = L::Load(c.stiff + at) == one;
        const L biasRate = Select(stiff, L::Fill(k.stiff.biasRate), L::Fill(k.soft.biasRate));
        const L massScale = Select(stiff, L::Fill(k.stiff.massScale), L::Fill(k.soft.massScale));
        const L impulseScale = Select(stiff, L::Fill(k.stiff.impulseScale), L::Fill(k.soft.impulseScale));
        for (int i = 0; i < kPoints; ++i)
        {
            const Mask gap = s[i] > zero;
            L bias = Select(gap, s[i] * invH, zero);
            L ms = one;
            L is = zero;
            if constexpr (kUseBias)
            {
                bias = Select(gap, bias, StdMax(biasRate * s[i], L::Fill(-k.maxPushSpeed)));
                ms = Select(gap, one, massScale);
                is = Select(gap, zero, impulseScale);
            }
            const L vn = LaneSpeed(a, b, nx, ny, rnA[i], rnB[i]);
            const L nm = L::Load(c.points[i].normalMass + at);
            const L wanted = (ni[i] - nm * ms * (vn + bias)) - is * ni[i];
            const L next = StdMax(wanted, zero);
            LaneImpulse(a, b, mA, iA, mB, iB, nx, ny, rnA[i], rnB[i], next - ni[i]);
            nextNi[i] = next;
            maxNi[i] = StdMax(maxNi[i], next);
        }
    }
    const L f = L::Load(c.friction + at), sf = L::Load(c.staticFriction + at);
    Mask stuck[kPoints];
    L nextTi[kPoints];
    for (int i = 0; i < kPoints; ++i)
    {
        const L vt = LaneSpeed(a, b, tx, ty, rtA[i], rtB[i]);
        const L wanted = ti[i] - tm[i] * vt;
        const L staticLimit = sf * nextNi[i];
        const L slidingLimit = f * nextNi[i];
        // std::fabs(wanted) <= staticLimit, without the absolute value: the same truth for every input.
        stuck[i] = (staticLimit >= wanted) & (staticLimit >= -wanted);
        const L next = Select(stuck[i], wanted, StdMax(-slidingLimit, StdMin(slidingLimit, wanted)));
        LaneImpulse(a, b, mA, iA, mB, iB, tx, ty, rtA[i], rtB[i], next - ti[i]);
        nextTi[i] = next;
    }
    a.vx = Select(skip, a0.vx, a.vx);
    a.vy = Select(skip, a0.vy, a.vy);
    a.w = Select(skip, a0.w, a.w);
    b.vx = Select(skip, b0.vx, b.vx);
    b.vy = Select(skip, b0.vy, b.vy);
    b.w = Select(skip, b0.w, b.w);
    for (int i = 0; i < kPoints; ++i)
    {
        SoftLanePoints& p = c.points[i];
        const L keptNi = Select(skip, ni[i], nextNi[i]);
        const L keptTi = Select(skip, ti[i], nextTi[i]);
        keptNi.Store(p.normalImpulse + at);
        keptTi.Store(p.tangentImpulse + at);
        if constexpr (!kUseBias)
        {
            // As SolveSoftContact's relax: the sub-step's impulses added to the step's (a skipped lane's are 0).
            (L::Load(p.normalTotal + at) + keptNi).Store(p.normalTotal + at);
            (L::Load(p.tangentTotal + at) + keptTi).Store(p.tangentTotal + at);
        }
        Select(skip, L::Load(p.maxNormalImpulse + at), maxNi[i]).Store(p.maxNormalImpulse + at);
        StoreFlags<L>((skip & skipStuck[i]).Bits() | ((~skip) & stuck[i]).Bits(), c.stuck[i] + at);
    }
    StoreBodies(a, states, c.writeA + at);
    StoreBodies(b, states, c.writeB + at);
}

} // namespace satviz::detail
