// SPDX-License-Identifier: MIT
// satviz (private): two lanes of a scalar, the unit in which the clipping decides: the two ends of an incident edge
// side by side, so that each step of the clip is one operation for both ends and each choice a mask, not a branch
// or a truth value moved between registers. Also the face scan's lanes of double in the baseline instructions
// (face_scan.h). Lanes2<S> is portable (plain arrays); on x86-64 one SSE register (for float, the two low lanes of
// four). Every operation is the same IEEE operation lane by lane in both, so they give the same bits.
#pragma once

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace satviz::detail
{

/// Two lanes of S.
template <typename S>
struct Lanes2
{
    static constexpr int kCount = 2; ///< lanes
    S v[2];                          ///< the lanes

    /// Lanes a, b.
    static Lanes2 Set(S a, S b) { return {{a, b}}; }
    /// Both lanes x.
    static Lanes2 Fill(S x) { return {{x, x}}; }
    /// Lanes p[0] and p[1] (p aligned as the SSE2 lanes need: 16 bytes).
    static Lanes2 Load(const S* p) { return {{p[0], p[1]}}; }
    /// Stores the lanes at p[0] and p[1] (p aligned as Load needs).
    void Store(S* p) const
    {
        p[0] = v[0];
        p[1] = v[1];
    }
    /// Lane i (0 or 1).
    S Get(int i) const { return v[i]; }
    /// The lanes exchanged.
    Lanes2 Swap() const { return {{v[1], v[0]}}; }
    /// The smaller lane, lane 0 unless lane 1 is smaller (as the face scans take it: any order would give the same
    /// number but for the sign of a zero and which NaN).
    S MinLaneAnyOrder() const { return v[0] < v[1] ? v[0] : v[1]; }

    /// A per-lane truth value.
    struct Mask
    {
        bool m[2]; ///< the lanes
        /// The lanes as two bits.
        int Bits() const { return int(m[0]) | int(m[1]) << 1; }
        /// The lanes exchanged.
        Mask Swap() const { return {{m[1], m[0]}}; }
        friend Mask operator&(Mask a, Mask b) { return {{a.m[0] && b.m[0], a.m[1] && b.m[1]}}; }
        friend Mask operator|(Mask a, Mask b) { return {{a.m[0] || b.m[0], a.m[1] || b.m[1]}}; }
        friend Mask operator~(Mask a) { return {{!a.m[0], !a.m[1]}}; }
    };

    friend Lanes2 operator+(Lanes2 a, Lanes2 b) { return {{a.v[0] + b.v[0], a.v[1] + b.v[1]}}; }
    friend Lanes2 operator-(Lanes2 a, Lanes2 b) { return {{a.v[0] - b.v[0], a.v[1] - b.v[1]}}; }
    friend Lanes2 operator*(Lanes2 a, Lanes2 b) { return {{a.v[0] * b.v[0], a.v[1] * b.v[1]}}; }
    friend Lanes2 operator/(Lanes2 a, Lanes2 b) { return {{a.v[0] / b.v[0], a.v[1] / b.v[1]}}; }
    friend Mask operator<(Lanes2 a, Lanes2 b) { return {{a.v[0] < b.v[0], a.v[1] < b.v[1]}}; }
    friend Mask operator>(Lanes2 a, Lanes2 b) { return {{a.v[0] > b.v[0], a.v[1] > b.v[1]}}; }
    friend Mask operator<=(Lanes2 a, Lanes2 b) { return {{a.v[0] <= b.v[0], a.v[1] <= b.v[1]}}; }
    /// Per lane: a where c holds, else b.
    friend Lanes2 Select(Mask c, Lanes2 a, Lanes2 b) { return {{c.m[0] ? a.v[0] : b.v[0], c.m[1] ? a.v[1] : b.v[1]}}; }
    /// Per lane: a < b ? a : b (the second operand when either is NaN).
    friend Lanes2 Min(Lanes2 a, Lanes2 b)
    {
        return {{a.v[0] < b.v[0] ? a.v[0] : b.v[0], a.v[1] < b.v[1] ? a.v[1] : b.v[1]}};
    }
    /// Per lane: a > b ? a : b (the second operand when either is NaN).
    friend Lanes2 Max(Lanes2 a, Lanes2 b)
    {
        return {{a.v[0] > b.v[0] ? a.v[0] : b.v[0], a.v[1] > b.v[1] ? a.v[1] : b.v[1]}};
    }
};

#if defined(__SSE2__)
/// Two doubles in one SSE2 register.
template <>
struct Lanes2<double>
{
    static constexpr int kCount = 2; ///< lanes
    __m128d v;                       ///< the lanes

    /// Lanes a, b.
    static Lanes2 Set(double a, double b) { return {_mm_setr_pd(a, b)}; }
    /// Both lanes x.
    static Lanes2 Fill(double x) { return {_mm_set1_pd(x)}; }
    /// Lanes p[0] and p[1] (p 16-byte aligned).
    static Lanes2 Load(const double* p) { return {_mm_load_pd(p)}; }
    /// Stores the lanes at p[0] and p[1] (p 16-byte aligned).
    void Store(double* p) const { _mm_store_pd(p, v); }
    /// Lane i (0 or 1).
    double Get(int i) const { return _mm_cvtsd_f64(i == 0 ? v : _mm_unpackhi_pd(v, v)); }
    /// The lanes exchanged.
    Lanes2 Swap() const { return {_mm_shuffle_pd(v, v, 1)}; }
    /// The smaller lane, lane 0 unless lane 1 is smaller (as the face scans take it: any order would give the same
    /// number but for the sign of a zero and which NaN).
    double MinLaneAnyOrder() const { return _mm_cvtsd_f64(_mm_min_sd(v, _mm_unpackhi_pd(v, v))); }

    /// A per-lane truth value: all ones or all zeros.
    struct Mask
    {
        __m128d m; ///< the lanes
        /// The lanes as two bits.
        int Bits() const { return _mm_movemask_pd(m); }
        /// The lanes exchanged.
        Mask Swap() const { return {_mm_shuffle_pd(m, m, 1)}; }
        friend Mask operator&(Mask a, Mask b) { return {_mm_and_pd(a.m, b.m)}; }
        friend Mask operator|(Mask a, Mask b) { return {_mm_or_pd(a.m, b.m)}; }
        friend Mask operator~(Mask a) { return {_mm_xor_pd(a.m, _mm_castsi128_pd(_mm_set1_epi32(-1)))}; }
    };

    friend Lanes2 operator+(Lanes2 a, Lanes2 b) { return {_mm_add_pd(a.v, b.v)}; }
    friend Lanes2 operator-(Lanes2 a, Lanes2 b) { return {_mm_sub_pd(a.v, b.v)}; }
    friend Lanes2 operator*(Lanes2 a, Lanes2 b) { return {_mm_mul_pd(a.v, b.v)}; }
    friend Lanes2 operator/(Lanes2 a, Lanes2 b) { return {_mm_div_pd(a.v, b.v)}; }
    friend Mask operator<(Lanes2 a, Lanes2 b) { return {_mm_cmplt_pd(a.v, b.v)}; }
    friend Mask operator>(Lanes2 a, Lanes2 b) { return {_mm_cmpgt_pd(a.v, b.v)}; }
    friend Mask operator<=(Lanes2 a, Lanes2 b) { return {_mm_cmple_pd(a.v, b.v)}; }
    /// Per lane: a where c holds, else b.
    friend Lanes2 Select(Mask c, Lanes2 a, Lanes2 b)
    {
        return {_mm_or_pd(_mm_and_pd(c.m, a.v), _mm_andnot_pd(c.m, b.v))};
    }
    /// Per lane: a < b ? a : b (the second operand when either is NaN).
    friend Lanes2 Min(Lanes2 a, Lanes2 b) { return {_mm_min_pd(a.v, b.v)}; }
    /// Per lane: a > b ? a : b (the second operand when either is NaN).
    friend Lanes2 Max(Lanes2 a, Lanes2 b) { return {_mm_max_pd(a.v, b.v)}; }
};

/// Two floats in the low lanes of one SSE register (the high lanes repeat them and take no part).
template <>
struct Lanes2<float>
{
    static constexpr int kCount = 2; ///< lanes
    __m128 v;                        ///< the lanes

    /// Lanes a, b.
    static Lanes2 Set(float a, float b) { return {_mm_setr_ps(a, b, a, b)}; }
    /// Both lanes x.
    static Lanes2 Fill(float x) { return {_mm_set1_ps(x)}; }
    /// Lanes p[0] and p[1] (p 8-byte aligned).
    static Lanes2 Load(const float* p) { return Set(p[0], p[1]); }
    /// Stores the lanes at p[0] and p[1].
    void Store(float* p) const
    {
        p[0] = Get(0);
        p[1] = Get(1);
    }
    /// Lane i (0 or 1).
    float Get(int i) const { return _mm_cvtss_f32(i == 0 ? v : _mm_shuffle_ps(v, v, 1)); }
    /// The lanes exchanged.
    Lanes2 Swap() const { return {_mm_shuffle_ps(v, v, _MM_SHUFFLE(2, 3, 0, 1))}; }
    /// The smaller lane, lane 0 unless lane 1 is smaller (as the face scans take it: any order would give the same
    /// number but for the sign of a zero and which NaN).
    float MinLaneAnyOrder() const { return _mm_cvtss_f32(_mm_min_ss(v, _mm_shuffle_ps(v, v, 1))); }

    /// A per-lane truth value: all ones or all zeros.
    struct Mask
    {
        __m128 m; ///< the lanes
        /// The lanes as two bits.
        int Bits() const { return _mm_movemask_ps(m) & 3; }
        /// The lanes exchanged.
        Mask Swap() const { return {_mm_shuffle_ps(m, m, _MM_SHUFFLE(2, 3, 0, 1))}; }
        friend Mask operator&(Mask a, Mask b) { return {_mm_and_ps(a.m, b.m)}; }
        friend Mask operator|(Mask a, Mask b) { return {_mm_or_ps(a.m, b.m)}; }
        friend Mask operator~(Mask a) { return {_mm_xor_ps(a.m, _mm_castsi128_ps(_mm_set1_epi32(-1)))}; }
    };

    friend Lanes2 operator+(Lanes2 a, Lanes2 b) { return {_mm_add_ps(a.v, b.v)}; }
    friend Lanes2 operator-(Lanes2 a, Lanes2 b) { return {_mm_sub_ps(a.v, b.v)}; }
    friend Lanes2 operator*(Lanes2 a, Lanes2 b) { return {_mm_mul_ps(a.v, b.v)}; }
    friend Lanes2 operator/(Lanes2 a, Lanes2 b) { return {_mm_div_ps(a.v, b.v)}; }
    friend Mask operator<(Lanes2 a, Lanes2 b) { return {_mm_cmplt_ps(a.v, b.v)}; }
    friend Mask operator>(Lanes2 a, Lanes2 b) { return {_mm_cmpgt_ps(a.v, b.v)}; }
    friend Mask operator<=(Lanes2 a, Lanes2 b) { return {_mm_cmple_ps(a.v, b.v)}; }
    /// Per lane: a where c holds, else b.
    friend Lanes2 Select(Mask c, Lanes2 a, Lanes2 b)
    {
        return {_mm_or_ps(_mm_and_ps(c.m, a.v), _mm_andnot_ps(c.m, b.v))};
    }
    /// Per lane: a < b ? a : b (the second operand when either is NaN).
    friend Lanes2 Min(Lanes2 a, Lanes2 b) { return {_mm_min_ps(a.v, b.v)}; }
    /// Per lane: a > b ? a : b (the second operand when either is NaN).
    friend Lanes2 Max(Lanes2 a, Lanes2 b) { return {_mm_max_ps(a.v, b.v)}; }
};
#endif

} // namespace satviz::detail
