// SPDX-License-Identifier: MIT
// satviz (private): eight lanes of a scalar in one register: of double on AVX-512, for the face loops of polygons of
// up to 8 faces (all faces side by side, one operation where four lanes need two), used only in code compiled for
// AVX-512 (RunWide512); of float on AVX2, for the face scans of float polygons, used only in code compiled for AVX2
// (RunWide). Every operation is the same IEEE operation lane by lane as in Lanes, so they give the same bits.
#pragma once

#if defined(__x86_64__) && defined(__SSE2__) && (defined(__GNUC__) || defined(__clang__))
#include <immintrin.h>
#define SATVIZ_LANES8 1
#else
#define SATVIZ_LANES8 0
#endif

namespace satviz::detail
{

#if SATVIZ_LANES8
/// Eight doubles in one AVX-512 register.
struct Lanes8
{
    static constexpr int kCount = 8; ///< lanes
    __m512d v;                       ///< the lanes

    /// Every lane x.
    [[gnu::target("avx512f")]] static Lanes8 Fill(double x) { return {_mm512_set1_pd(x)}; }
    /// Lanes p[0] to p[7] (p 64-byte aligned).
    [[gnu::target("avx512f")]] static Lanes8 Load(const double* p) { return {_mm512_load_pd(p)}; }
    /// Eight points stored as x, y pairs from p (any alignment): their x in xs, their y in ys.
    [[gnu::target("avx512f")]] static void LoadPoints(const double* p, Lanes8& xs, Lanes8& ys)
    {
        const __m512d a = _mm512_loadu_pd(p);     // x0 y0 x1 y1 x2 y2 x3 y3
        const __m512d b = _mm512_loadu_pd(p + 8); // x4 y4 x5 y5 x6 y6 x7 y7
        xs = {_mm512_permutex2var_pd(a, _mm512_setr_epi64(0, 2, 4, 6, 8, 10, 12, 14), b)};
        ys = {_mm512_permutex2var_pd(a, _mm512_setr_epi64(1, 3, 5, 7, 9, 11, 13, 15), b)};
    }
    /// Every lane the value of lane k. (The masked permutation with every lane set: GCC 12 warns that the plain
    /// one's undefined pass-through may be used uninitialized.)
    [[gnu::target("avx512f")]] Lanes8 Spread(int k) const
    {
        return {_mm512_mask_permutexvar_pd(v, static_cast<__mmask8>(0xFF), _mm512_set1_epi64(k), v)};
    }
    /// These lanes, with lane 0's value in the lanes whose bit is set in `bits`.
    [[gnu::target("avx512f")]] Lanes8 FillFromFirst(int bits) const
    {
        return {_mm512_mask_permutexvar_pd(v, static_cast<__mmask8>(bits), _mm512_set1_epi64(0), v)};
    }
    /// The lanes greater than b's, one bit each.
    [[gnu::target("avx512f")]] int GreaterBits(const Lanes8& b) const
    {
        return static_cast<int>(_mm512_cmp_pd_mask(v, b.v, _CMP_GT_OQ));
    }
    /// The lanes equal to b's, one bit each.
    [[gnu::target("avx512f")]] int EqualBits(const Lanes8& b) const
    {
        return static_cast<int>(_mm512_cmp_pd_mask(v, b.v, _CMP_EQ_OQ));
    }
    /// A per-lane truth value, one bit a lane.
    struct Mask
    {
        __mmask8 m; ///< the lanes
        /// Every lane c.
        [[gnu::target("avx512f")]] static Mask Fill(bool c) { return {static_cast<__mmask8>(c ? 0xFF : 0)}; }
        /// The lanes as eight bits.
        [[gnu::target("avx512f")]] int Bits() const { return static_cast<int>(m); }
        /// Every lane set.
        [[gnu::target("avx512f")]] bool All() const { return m == 0xFF; }
        /// The lanes set in both.
        [[gnu::target("avx512f")]] friend Mask operator&(Mask a, Mask b) { return {static_cast<__mmask8>(a.m & b.m)}; }
        /// The lanes set in either.
        [[gnu::target("avx512f")]] friend Mask operator|(Mask a, Mask b) { return {static_cast<__mmask8>(a.m | b.m)}; }
        /// The lanes not set.
        [[gnu::target("avx512f")]] friend Mask operator~(Mask a) { return {static_cast<__mmask8>(~a.m)}; }
    };
    /// The lanes greater than b's.
    [[gnu::target("avx512f")]] friend Mask operator>(const Lanes8& a, const Lanes8& b)
    {
        return {_mm512_cmp_pd_mask(a.v, b.v, _CMP_GT_OQ)};
    }
    /// The lanes greater than or equal to b's.
    [[gnu::target("avx512f")]] friend Mask operator>=(const Lanes8& a, const Lanes8& b)
    {
        return {_mm512_cmp_pd_mask(a.v, b.v, _CMP_GE_OQ)};
    }
    /// The lanes equal to b's.
    [[gnu::target("avx512f")]] friend Mask operator==(const Lanes8& a, const Lanes8& b)
    {
        return {_mm512_cmp_pd_mask(a.v, b.v, _CMP_EQ_OQ)};
    }
    /// a in the lanes of `mask`, b in the others.
    [[gnu::target("avx512f")]] friend Lanes8 Select(Mask mask, const Lanes8& a, const Lanes8& b)
    {
        return {_mm512_mask_blend_pd(mask.m, b.v, a.v)};
    }
    /// These lanes, with x in the lanes whose bit is set in `bits` (Blend with x in every lane).
    [[gnu::target("avx512f")]] Lanes8 Replace(int bits, double x) const { return Blend(bits, Fill(x)); }
    /// The largest lane (no lane NaN: then the order of the comparisons cannot change the answer). Halves, then
    /// quarters, then pairs folded onto each other by permutations within the register (masked forms with every
    /// lane set: GCC 12 warns that the 256-bit casts and the plain forms leave pass-through lanes undefined).
    [[gnu::target("avx512f")]] double MaxLane() const
    {
        __m512d m = v;
        for (int fold = 0; fold < 3; ++fold)
        {
            m = _mm512_mask_max_pd(m, static_cast<__mmask8>(0xFF), m, Folded(m, fold));
        }
        return _mm512_cvtsd_f64(m);
    }
    /// The smallest lane (no lane NaN), folded as MaxLane.
    [[gnu::target("avx512f")]] double MinLane() const
    {
        __m512d m = v;
        for (int fold = 0; fold < 3; ++fold)
        {
            m = _mm512_mask_min_pd(m, static_cast<__mmask8>(0xFF), m, Folded(m, fold));
        }
        return _mm512_cvtsd_f64(m);
    }
    /// The lanes greater than or equal to b's, one bit each.
    [[gnu::target("avx512f")]] int GreaterEqualBits(const Lanes8& b) const
    {
        return static_cast<int>(_mm512_cmp_pd_mask(v, b.v, _CMP_GE_OQ));
    }
    /// These lanes, with b's in the lanes whose bit is set in `bits`.
    [[gnu::target("avx512f")]] Lanes8 Blend(int bits, const Lanes8& b) const
    {
        return {_mm512_mask_blend_pd(static_cast<__mmask8>(bits), v, b.v)};
    }
    /// Stores the lanes at p[0] to p[7] (any alignment).
    [[gnu::target("avx512f")]] void Store(double* p) const { _mm512_storeu_pd(p, v); }
    /// Stores lane 0 at p[0] to p[3] (any alignment; a masked store of four lanes).
    [[gnu::target("avx512f")]] void StoreFirst4(double* p) const
    {
        _mm512_mask_storeu_pd(p, static_cast<__mmask8>(0x0F), Spread(0).v);
    }
    /// Lane k (0 to 7).
    [[gnu::target("avx512f")]] double Get(int k) const { return _mm512_cvtsd_f64(Spread(k).v); }

    /// The lanes of m with their partner at fold 0 (four lanes away), 1 (two) or 2 (one), for the reductions.
    [[gnu::target("avx512f")]] static __m512d Folded(__m512d m, int fold)
    {
        const __m512i partner = fold == 0   ? _mm512_setr_epi64(4, 5, 6, 7, 0, 1, 2, 3)
                                : fold == 1 ? _mm512_setr_epi64(2, 3, 0, 1, 6, 7, 4, 5)
                                            : _mm512_setr_epi64(1, 0, 3, 2, 5, 4, 7, 6);
        return _mm512_mask_permutexvar_pd(m, static_cast<__mmask8>(0xFF), partner, m);
    }

    [[gnu::target("avx512f")]] friend Lanes8 operator+(const Lanes8& a, const Lanes8& b)
    {
        return {_mm512_add_pd(a.v, b.v)};
    }
    [[gnu::target("avx512f")]] friend Lanes8 operator-(const Lanes8& a, const Lanes8& b)
    {
        return {_mm512_sub_pd(a.v, b.v)};
    }
    [[gnu::target("avx512f")]] friend Lanes8 operator*(const Lanes8& a, const Lanes8& b)
    {
        return {_mm512_mul_pd(a.v, b.v)};
    }
    [[gnu::target("avx512f")]] friend Lanes8 operator/(const Lanes8& a, const Lanes8& b)
    {
        return {_mm512_div_pd(a.v, b.v)};
    }
    /// The sign flipped, as the unary minus of Lanes (a sign bit, so -0 from 0).
    [[gnu::target("avx512f")]] friend Lanes8 operator-(const Lanes8& a)
    {
        return {_mm512_castsi512_pd(_mm512_xor_si512(
            _mm512_castpd_si512(a.v), _mm512_set1_epi64(static_cast<long long>(0x8000000000000000ULL))))};
    }
    /// Per lane: a > b ? a : b (the second operand when either is NaN), as Max of Lanes.
    [[gnu::target("avx512f")]] friend Lanes8 Max(const Lanes8& a, const Lanes8& b)
    {
        return {_mm512_mask_max_pd(a.v, static_cast<__mmask8>(0xFF), a.v, b.v)};
    }
    /// Per lane: a < b ? a : b (the second operand when either is NaN), as Min of Lanes. (The masked form with
    /// every lane set: GCC 12 warns that _mm512_min_pd's undefined pass-through may be used uninitialized.)
    [[gnu::target("avx512f")]] friend Lanes8 Min(const Lanes8& a, const Lanes8& b)
    {
        return {_mm512_mask_min_pd(a.v, static_cast<__mmask8>(0xFF), a.v, b.v)};
    }
};

/// Eight floats in one AVX2 register: what the face scan (face_scan.h) needs of them.
struct Lanes8F
{
    static constexpr int kCount = 8; ///< lanes
    __m256 v;                        ///< the lanes

    /// Every lane x.
    [[gnu::target("avx2")]] static Lanes8F Fill(float x) { return {_mm256_set1_ps(x)}; }
    /// Lanes p[0] to p[7] (p 32-byte aligned).
    [[gnu::target("avx2")]] static Lanes8F Load(const float* p) { return {_mm256_load_ps(p)}; }
    /// Stores the lanes at p[0] to p[7] (p 32-byte aligned).
    [[gnu::target("avx2")]] void Store(float* p) const { _mm256_store_ps(p, v); }

    [[gnu::target("avx2")]] friend Lanes8F operator+(const Lanes8F& a, const Lanes8F& b)
    {
        return {_mm256_add_ps(a.v, b.v)};
    }
    [[gnu::target("avx2")]] friend Lanes8F operator-(const Lanes8F& a, const Lanes8F& b)
    {
        return {_mm256_sub_ps(a.v, b.v)};
    }
    [[gnu::target("avx2")]] friend Lanes8F operator*(const Lanes8F& a, const Lanes8F& b)
    {
        return {_mm256_mul_ps(a.v, b.v)};
    }
    /// Per lane: a < b ? a : b (the second operand when either is NaN), as Min of Lanes.
    [[gnu::target("avx2")]] friend Lanes8F Min(const Lanes8F& a, const Lanes8F& b) { return {_mm256_min_ps(a.v, b.v)}; }
    /// Per lane: a > b ? a : b (the second operand when either is NaN), as Max of Lanes.
    [[gnu::target("avx2")]] friend Lanes8F Max(const Lanes8F& a, const Lanes8F& b) { return {_mm256_max_ps(a.v, b.v)}; }
    /// The smallest lane, the lanes combined in the order cheapest for the registers: the smallest number, but for
    /// the sign of a zero and which NaN (as MinLaneAnyOrder of Lanes).
    [[gnu::target("avx2")]] float MinLaneAnyOrder() const
    {
        __m128 half = _mm_min_ps(_mm256_castps256_ps128(v), _mm256_extractf128_ps(v, 1));
        half = _mm_min_ps(half, _mm_movehl_ps(half, half));
        return _mm_cvtss_f32(_mm_min_ss(half, _mm_shuffle_ps(half, half, 1)));
    }
};
#endif

} // namespace satviz::detail
