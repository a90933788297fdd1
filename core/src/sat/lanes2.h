// SPDX-License-Identifier: MIT
// satviz (private): two lanes of a scalar, the unit in which the clipping decides: the two ends of an incident edge
// side by side, so that each step of the clip is one operation for both ends and each choice a mask, not a branch
// or a truth value moved between registers. Also the face scan's lanes of double in the baseline instructions
// (face_scan.h). Lanes2<S> is portable (plain arrays); on x86-64 one SSE register (for float, the two low lanes of
// four), written once over the instructions of each scalar (Sse2Of). Every operation is the same IEEE operation lane
// by lane in both, so they give the same bits.
#pragma once

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace satviz::detail
{

#if defined(__SSE2__)
/// The SSE instructions of two lanes of S in their register V: the one difference between the lanes of double and
/// those of float, over which Lanes2 is written once.
template <typename S>
struct Sse2Of;

/// Two doubles: one SSE2 register.
template <>
struct Sse2Of<double>
{
    using V = __m128d; ///< the register

    static V Set(double a, double b) { return _mm_setr_pd(a, b); }                    ///< lanes a, b
    static V Fill(double x) { return _mm_set1_pd(x); }                                ///< both lanes x
    static V Load(const double* p) { return _mm_load_pd(p); }                         ///< p 16-byte aligned
    static void Store(double* p, V v) { _mm_store_pd(p, v); }                         ///< p 16-byte aligned
    static double First(V v) { return _mm_cvtsd_f64(v); }                             ///< lane 0
    static V Second(V v) { return _mm_unpackhi_pd(v, v); }                            ///< lane 1, in lane 0
    static V Swap(V v) { return _mm_shuffle_pd(v, v, 1); }                            ///< the lanes exchanged
    static V MinFirst(V a, V b) { return _mm_min_sd(a, b); }                          ///< lane 0: a < b ? a : b
    static int Bits(V m) { return _mm_movemask_pd(m); }                               ///< a mask's lanes as bits
    static V And(V a, V b) { return _mm_and_pd(a, b); }                               ///< a & b
    static V Or(V a, V b) { return _mm_or_pd(a, b); }                                 ///< a | b
    static V AndNot(V a, V b) { return _mm_andnot_pd(a, b); }                         ///< ~a & b
    static V Not(V a) { return _mm_xor_pd(a, _mm_castsi128_pd(_mm_set1_epi32(-1))); } ///< ~a
    static V Add(V a, V b) { return _mm_add_pd(a, b); }                               ///< a + b
    static V Sub(V a, V b) { return _mm_sub_pd(a, b); }                               ///< a - b
    static V Mul(V a, V b) { return _mm_mul_pd(a, b); }                               ///< a * b
    static V Div(V a, V b) { return _mm_div_pd(a, b); }                               ///< a / b
    static V Less(V a, V b) { return _mm_cmplt_pd(a, b); }                            ///< a < b, as a mask
    static V Greater(V a, V b) { return _mm_cmpgt_pd(a, b); }                         ///< a > b, as a mask
    static V LessEqual(V a, V b) { return _mm_cmple_pd(a, b); }                       ///< a <= b, as a mask
    static V Min(V a, V b) { return _mm_min_pd(a, b); }                               ///< a < b ? a : b
    static V Max(V a, V b) { return _mm_max_pd(a, b); }                               ///< a > b ? a : b
};

/// Two floats: the two low lanes of one SSE register, the high lanes repeating them (they take no part).
template <>
struct Sse2Of<float>
{
    using V = __m128; ///< the register

    static V Set(float a, float b) { return _mm_setr_ps(a, b, a, b); } ///< lanes a, b
    static V Fill(float x) { return _mm_set1_ps(x); }                  ///< both lanes x
    static V Load(const float* p) { return Set(p[0], p[1]); }          ///< p 8-byte aligned
    static void Store(float* p, V v)                                   ///< p[0] and p[1]
    {
        p[0] = First(v);
        p[1] = First(Second(v));
    }
    static float First(V v) { return _mm_cvtss_f32(v); }                              ///< lane 0
    static V Second(V v) { return _mm_shuffle_ps(v, v, 1); }                          ///< lane 1, in lane 0
    static V Swap(V v) { return _mm_shuffle_ps(v, v, _MM_SHUFFLE(2, 3, 0, 1)); }      ///< the lanes exchanged
    static V MinFirst(V a, V b) { return _mm_min_ss(a, b); }                          ///< lane 0: a < b ? a : b
    static int Bits(V m) { return _mm_movemask_ps(m) & 3; }                           ///< the low lanes as bits
    static V And(V a, V b) { return _mm_and_ps(a, b); }                               ///< a & b
    static V Or(V a, V b) { return _mm_or_ps(a, b); }                                 ///< a | b
    static V AndNot(V a, V b) { return _mm_andnot_ps(a, b); }                         ///< ~a & b
    static V Not(V a) { return _mm_xor_ps(a, _mm_castsi128_ps(_mm_set1_epi32(-1))); } ///< ~a
    static V Add(V a, V b) { return _mm_add_ps(a, b); }                               ///< a + b
    static V Sub(V a, V b) { return _mm_sub_ps(a, b); }                               ///< a - b
    static V Mul(V a, V b) { return _mm_mul_ps(a, b); }                               ///< a * b
    static V Div(V a, V b) { return _mm_div_ps(a, b); }                               ///< a / b
    static V Less(V a, V b) { return _mm_cmplt_ps(a, b); }                            ///< a < b, as a mask
    static V Greater(V a, V b) { return _mm_cmpgt_ps(a, b); }                         ///< a > b, as a mask
    static V LessEqual(V a, V b) { return _mm_cmple_ps(a, b); }                       ///< a <= b, as a mask
    static V Min(V a, V b) { return _mm_min_ps(a, b); }                               ///< a < b ? a : b
    static V Max(V a, V b) { return _mm_max_ps(a, b); }                               ///< a > b ? a : b
};

/// Two lanes of double or float in one SSE register, written once over the instructions of each (Sse2Of).
template <typename S>
struct Lanes2
{
    using I = Sse2Of<S>;             ///< the instructions
    static constexpr int kCount = 2; ///< lanes
    typename I::V v;                 ///< the lanes

    /// Lanes a, b.
    static Lanes2 Set(S a, S b) { return {I::Set(a, b)}; }
    /// Both lanes x.
    static Lanes2 Fill(S x) { return {I::Fill(x)}; }
    /// Lanes p[0] and p[1] (p aligned as I::Load needs).
    static Lanes2 Load(const S* p) { return {I::Load(p)}; }
    /// Stores the lanes at p[0] and p[1] (p aligned as I::Store needs).
    void Store(S* p) const { I::Store(p, v); }
    /// Lane i (0 or 1).
    S Get(int i) const { return I::First(i == 0 ? v : I::Second(v)); }
    /// The lanes exchanged.
    Lanes2 Swap() const { return {I::Swap(v)}; }
    /// The smaller lane, lane 0 unless lane 1 is smaller (as the face scans take it: any order would give the same
    /// number but for the sign of a zero and which NaN).
    S MinLaneAnyOrder() const { return I::First(I::MinFirst(v, I::Second(v))); }

    /// A per-lane truth value: all ones or all zeros.
    struct Mask
    {
        typename I::V m; ///< the lanes
        /// The lanes as two bits.
        int Bits() const { return I::Bits(m); }
        /// The lanes exchanged.
        Mask Swap() const { return {I::Swap(m)}; }
        friend Mask operator&(Mask a, Mask b) { return {I::And(a.m, b.m)}; }
        friend Mask operator|(Mask a, Mask b) { return {I::Or(a.m, b.m)}; }
        friend Mask operator~(Mask a) { return {I::Not(a.m)}; }
    };

    friend Lanes2 operator+(Lanes2 a, Lanes2 b) { return {I::Add(a.v, b.v)}; }
    friend Lanes2 operator-(Lanes2 a, Lanes2 b) { return {I::Sub(a.v, b.v)}; }
    friend Lanes2 operator*(Lanes2 a, Lanes2 b) { return {I::Mul(a.v, b.v)}; }
    friend Lanes2 operator/(Lanes2 a, Lanes2 b) { return {I::Div(a.v, b.v)}; }
    friend Mask operator<(Lanes2 a, Lanes2 b) { return {I::Less(a.v, b.v)}; }
    friend Mask operator>(Lanes2 a, Lanes2 b) { return {I::Greater(a.v, b.v)}; }
    friend Mask operator<=(Lanes2 a, Lanes2 b) { return {I::LessEqual(a.v, b.v)}; }
    /// Per lane: a where c holds, else b.
    friend Lanes2 Select(Mask c, Lanes2 a, Lanes2 b) { return {I::Or(I::And(c.m, a.v), I::AndNot(c.m, b.v))}; }
    /// Per lane: a < b ? a : b (the second operand when either is NaN).
    friend Lanes2 Min(Lanes2 a, Lanes2 b) { return {I::Min(a.v, b.v)}; }
    /// Per lane: a > b ? a : b (the second operand when either is NaN).
    friend Lanes2 Max(Lanes2 a, Lanes2 b) { return {I::Max(a.v, b.v)}; }
};
#else
/// Two lanes of S, where there is no SSE2: plain arrays.
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
#endif

} // namespace satviz::detail
