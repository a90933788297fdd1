// SPDX-License-Identifier: MIT
// satviz (private): four lanes of a scalar, the unit in which the face loops decide: four faces at a time, without
// a branch per face. Lanes<S, false> is portable (plain arrays; two SSE2 registers for double on x86-64);
// Lanes<double, true> holds one AVX2 register and is used only in code compiled for AVX2 (RunWide). Every operation is
// the same IEEE operation lane by lane in both, so they give the same bits.
// The portable templates take the wide lanes only inside the functions compiled for AVX2 or AVX-512, into which
// they are flattened: one left out of line would be compiled for the baseline and pass vector registers in a
// convention the AVX code does not share. tests/wide_inlined.sh fails the build's tests when the library holds one.
#pragma once

#include <algorithm>
#include <limits>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif
#if defined(__x86_64__) && defined(__SSE2__) && (defined(__GNUC__) || defined(__clang__))
#include <immintrin.h>
#define SATVIZ_LANES_AVX2 1
#else
#define SATVIZ_LANES_AVX2 0
#endif

namespace satviz::detail
{

/// Four lanes of S; kWide selects the AVX2 register (double only).
template <typename S, bool kWide>
struct Lanes
{
    static constexpr int kCount = 4; ///< lanes
    S v[4];                          ///< the lanes

    /// Lanes a, b, c, d.
    static Lanes Set(S a, S b, S c, S d) { return {{a, b, c, d}}; }
    /// Every lane x.
    static Lanes Fill(S x) { return {{x, x, x, x}}; }
    /// Lanes p[0] to p[3] (p aligned as the widest lanes need: 32 bytes).
    static Lanes Load(const S* p) { return {{p[0], p[1], p[2], p[3]}}; }
    /// Four points stored as x, y pairs from p (any alignment): their x in xs, their y in ys.
    static void LoadPoints(const S* p, Lanes& xs, Lanes& ys)
    {
        xs = {{p[0], p[2], p[4], p[6]}};
        ys = {{p[1], p[3], p[5], p[7]}};
    }
    /// Stores the lanes at p[0] to p[3] (p aligned as Load needs).
    void Store(S* p) const { std::copy(v, v + 4, p); }
    /// Every lane the value of lane k.
    template <int k>
    Lanes Spread() const
    {
        return Fill(v[k]);
    }
    /// Lane i.
    S Get(int i) const { return v[i]; }

    /// A per-lane truth value.
    struct Mask
    {
        bool m[4]; ///< the lanes
        /// Every lane c.
        static Mask Fill(bool c) { return {{c, c, c, c}}; }
        /// The lanes as four bits.
        int Bits() const { return int(m[0]) | int(m[1]) << 1 | int(m[2]) << 2 | int(m[3]) << 3; }
        /// Lane i.
        bool Get(int i) const { return m[i]; }
        /// Any lane set.
        bool Any() const { return m[0] || m[1] || m[2] || m[3]; }
        /// Every lane set.
        bool All() const { return m[0] && m[1] && m[2] && m[3]; }
        friend Mask operator&(Mask a, Mask b)
        {
            return Map(a, b, [](bool x, bool y) { return x && y; });
        }
        friend Mask operator|(Mask a, Mask b)
        {
            return Map(a, b, [](bool x, bool y) { return x || y; });
        }
        friend Mask operator~(Mask a)
        {
            return Map(a, a, [](bool x, bool) { return !x; });
        }
        template <typename F>
        static Mask Map(Mask a, Mask b, F f)
        {
            return {{f(a.m[0], b.m[0]), f(a.m[1], b.m[1]), f(a.m[2], b.m[2]), f(a.m[3], b.m[3])}};
        }
    };

    template <typename F>
    static Lanes Map(Lanes a, Lanes b, F f)
    {
        return {{f(a.v[0], b.v[0]), f(a.v[1], b.v[1]), f(a.v[2], b.v[2]), f(a.v[3], b.v[3])}};
    }
    template <typename F>
    static Mask Compare(Lanes a, Lanes b, F f)
    {
        return {{f(a.v[0], b.v[0]), f(a.v[1], b.v[1]), f(a.v[2], b.v[2]), f(a.v[3], b.v[3])}};
    }

    friend Lanes operator-(Lanes a)
    {
        return Map(a, a, [](S x, S) { return -x; });
    }
    friend Lanes operator+(Lanes a, Lanes b)
    {
        return Map(a, b, [](S x, S y) { return x + y; });
    }
    friend Lanes operator-(Lanes a, Lanes b)
    {
        return Map(a, b, [](S x, S y) { return x - y; });
    }
    friend Lanes operator*(Lanes a, Lanes b)
    {
        return Map(a, b, [](S x, S y) { return x * y; });
    }
    friend Lanes operator/(Lanes a, Lanes b)
    {
        return Map(a, b, [](S x, S y) { return x / y; });
    }
    friend Mask operator>(Lanes a, Lanes b)
    {
        return Compare(a, b, [](S x, S y) { return x > y; });
    }
    friend Mask operator>=(Lanes a, Lanes b)
    {
        return Compare(a, b, [](S x, S y) { return x >= y; });
    }
    friend Mask operator==(Lanes a, Lanes b)
    {
        return Compare(a, b, [](S x, S y) { return x == y; });
    }
    /// Per lane: a where c holds, else b.
    friend Lanes Select(Mask c, Lanes a, Lanes b)
    {
        return {
            {c.m[0] ? a.v[0] : b.v[0], c.m[1] ? a.v[1] : b.v[1], c.m[2] ? a.v[2] : b.v[2], c.m[3] ? a.v[3] : b.v[3]}};
    }
    /// Per lane: a < b ? a : b (the second operand when either is NaN).
    friend Lanes Min(Lanes a, Lanes b)
    {
        return Map(a, b, [](S x, S y) { return x < y ? x : y; });
    }
    /// Per lane: a > b ? a : b (the second operand when either is NaN).
    friend Lanes Max(Lanes a, Lanes b)
    {
        return Map(a, b, [](S x, S y) { return x > y ? x : y; });
    }
    /// The largest lane (NaN lanes skipped when another is a number).
    S MaxLane() const { return std::max(std::max(v[0], v[1]), std::max(v[2], v[3])); }
    /// The smallest lane.
    S MinLane() const { return std::min(std::min(v[0], v[1]), std::min(v[2], v[3])); }
    /// The smallest lane, the lanes combined in the order cheapest for the registers: the number MinLane gives, but
    /// for the sign of a zero and which NaN (the face scans add +0 and take any NaN).
    S MinLaneAnyOrder() const { return MinLane(); }
};

#if defined(__SSE2__)
/// Four doubles in two SSE2 registers: what every x86-64 processor runs.
template <>
struct Lanes<double, false>
{
    static constexpr int kCount = 4; ///< lanes
    __m128d lo;                      ///< lanes 0 and 1
    __m128d hi;                      ///< lanes 2 and 3

    /// Lanes a, b, c, d.
    static Lanes Set(double a, double b, double c, double d) { return {_mm_setr_pd(a, b), _mm_setr_pd(c, d)}; }
    /// Every lane x.
    static Lanes Fill(double x) { return {_mm_set1_pd(x), _mm_set1_pd(x)}; }
    /// Lanes p[0] to p[3] (p 16-byte aligned).
    static Lanes Load(const double* p) { return {_mm_load_pd(p), _mm_load_pd(p + 2)}; }
    /// Four points stored as x, y pairs from p (any alignment): their x in xs, their y in ys.
    static void LoadPoints(const double* p, Lanes& xs, Lanes& ys)
    {
        const __m128d a = _mm_loadu_pd(p);
        const __m128d b = _mm_loadu_pd(p + 2);
        const __m128d c = _mm_loadu_pd(p + 4);
        const __m128d d = _mm_loadu_pd(p + 6);
        xs = {_mm_unpacklo_pd(a, b), _mm_unpacklo_pd(c, d)};
        ys = {_mm_unpackhi_pd(a, b), _mm_unpackhi_pd(c, d)};
    }
    /// Stores the lanes at p[0] to p[3] (p 16-byte aligned).
    void Store(double* p) const
    {
        _mm_store_pd(p, lo);
        _mm_store_pd(p + 2, hi);
    }
    /// Every lane the value of lane k.
    template <int k>
    Lanes Spread() const
    {
        const __m128d half = k < 2 ? lo : hi;
        const __m128d x = k % 2 == 0 ? _mm_unpacklo_pd(half, half) : _mm_unpackhi_pd(half, half);
        return {x, x};
    }
    /// Lane i.
    double Get(int i) const
    {
        alignas(16) double out[4];
        _mm_store_pd(out, lo);
        _mm_store_pd(out + 2, hi);
        return out[i];
    }

    /// A per-lane truth value: all ones or all zeros.
    struct Mask
    {
        __m128d lo; ///< lanes 0 and 1
        __m128d hi; ///< lanes 2 and 3
        /// Every lane c.
        static Mask Fill(bool c)
        {
            const __m128d m = _mm_castsi128_pd(_mm_set1_epi32(c ? -1 : 0));
            return {m, m};
        }
        /// The lanes as four bits.
        int Bits() const { return _mm_movemask_pd(lo) | (_mm_movemask_pd(hi) << 2); }
        /// Lane i.
        bool Get(int i) const { return ((Bits() >> i) & 1) != 0; }
        /// Any lane set.
        bool Any() const { return Bits() != 0; }
        /// Every lane set.
        bool All() const { return Bits() == 0xF; }
        friend Mask operator&(const Mask& a, const Mask& b) { return {_mm_and_pd(a.lo, b.lo), _mm_and_pd(a.hi, b.hi)}; }
        friend Mask operator|(const Mask& a, const Mask& b) { return {_mm_or_pd(a.lo, b.lo), _mm_or_pd(a.hi, b.hi)}; }
        friend Mask operator~(const Mask& a)
        {
            const __m128d ones = _mm_castsi128_pd(_mm_set1_epi32(-1));
            return {_mm_xor_pd(a.lo, ones), _mm_xor_pd(a.hi, ones)};
        }
    };

    friend Lanes operator-(const Lanes& a)
    {
        const __m128d sign = _mm_set1_pd(-0.0);
        return {_mm_xor_pd(a.lo, sign), _mm_xor_pd(a.hi, sign)};
    }
    friend Lanes operator+(const Lanes& a, const Lanes& b) { return {_mm_add_pd(a.lo, b.lo), _mm_add_pd(a.hi, b.hi)}; }
    friend Lanes operator-(const Lanes& a, const Lanes& b) { return {_mm_sub_pd(a.lo, b.lo), _mm_sub_pd(a.hi, b.hi)}; }
    friend Lanes operator*(const Lanes& a, const Lanes& b) { return {_mm_mul_pd(a.lo, b.lo), _mm_mul_pd(a.hi, b.hi)}; }
    friend Lanes operator/(const Lanes& a, const Lanes& b) { return {_mm_div_pd(a.lo, b.lo), _mm_div_pd(a.hi, b.hi)}; }
    friend Mask operator>(const Lanes& a, const Lanes& b)
    {
        return {_mm_cmpgt_pd(a.lo, b.lo), _mm_cmpgt_pd(a.hi, b.hi)};
    }
    friend Mask operator>=(const Lanes& a, const Lanes& b)
    {
        return {_mm_cmpge_pd(a.lo, b.lo), _mm_cmpge_pd(a.hi, b.hi)};
    }
    friend Mask operator==(const Lanes& a, const Lanes& b)
    {
        return {_mm_cmpeq_pd(a.lo, b.lo), _mm_cmpeq_pd(a.hi, b.hi)};
    }
    /// Per lane: a where c holds, else b.
    friend Lanes Select(const Mask& c, const Lanes& a, const Lanes& b)
    {
        return {_mm_or_pd(_mm_and_pd(c.lo, a.lo), _mm_andnot_pd(c.lo, b.lo)),
                _mm_or_pd(_mm_and_pd(c.hi, a.hi), _mm_andnot_pd(c.hi, b.hi))};
    }
    /// Per lane: a < b ? a : b (the second operand when either is NaN).
    friend Lanes Min(const Lanes& a, const Lanes& b) { return {_mm_min_pd(a.lo, b.lo), _mm_min_pd(a.hi, b.hi)}; }
    /// Per lane: a > b ? a : b (the second operand when either is NaN).
    friend Lanes Max(const Lanes& a, const Lanes& b) { return {_mm_max_pd(a.lo, b.lo), _mm_max_pd(a.hi, b.hi)}; }
    /// The largest lane, as std::max(std::max(v0, v1), std::max(v2, v3)) gives it, in registers: std::max(a, b) is
    /// _mm_max_pd(b, a) (a unless a < b), so the same value for every input, NaN included.
    double MaxLane() const
    {
        const __m128d firsts = _mm_unpacklo_pd(lo, hi);  // v0 v2
        const __m128d seconds = _mm_unpackhi_pd(lo, hi); // v1 v3
        const __m128d pairs = _mm_max_pd(seconds, firsts);
        return _mm_cvtsd_f64(_mm_max_sd(_mm_unpackhi_pd(pairs, pairs), pairs));
    }
    /// The smallest lane, as std::min(std::min(v0, v1), std::min(v2, v3)) gives it, in registers: std::min(a, b)
    /// is _mm_min_pd(b, a) (a unless b < a).
    double MinLane() const
    {
        const __m128d firsts = _mm_unpacklo_pd(lo, hi);
        const __m128d seconds = _mm_unpackhi_pd(lo, hi);
        const __m128d pairs = _mm_min_pd(seconds, firsts);
        return _mm_cvtsd_f64(_mm_min_sd(_mm_unpackhi_pd(pairs, pairs), pairs));
    }
    /// The smallest lane, the lanes combined in the order cheapest for the registers (lanes 0 and 2, 1 and 3, then
    /// the two): the number MinLane gives, but for the sign of a zero and which NaN.
    double MinLaneAnyOrder() const
    {
        const __m128d half = _mm_min_pd(lo, hi);
        return _mm_cvtsd_f64(_mm_min_sd(half, _mm_unpackhi_pd(half, half)));
    }
};
#endif

#if defined(__SSE2__)
/// Four floats in one SSE register: what every x86-64 processor runs.
template <>
struct Lanes<float, false>
{
    static constexpr int kCount = 4; ///< lanes
    __m128 v;                        ///< the lanes

    /// Lanes a, b, c, d.
    static Lanes Set(float a, float b, float c, float d) { return {_mm_setr_ps(a, b, c, d)}; }
    /// Every lane x.
    static Lanes Fill(float x) { return {_mm_set1_ps(x)}; }
    /// Lanes p[0] to p[3] (p 16-byte aligned).
    static Lanes Load(const float* p) { return {_mm_load_ps(p)}; }
    /// Four points stored as x, y pairs from p (any alignment): their x in xs, their y in ys.
    static void LoadPoints(const float* p, Lanes& xs, Lanes& ys)
    {
        const __m128 a = _mm_loadu_ps(p);
        const __m128 b = _mm_loadu_ps(p + 4);
        xs = {_mm_shuffle_ps(a, b, _MM_SHUFFLE(2, 0, 2, 0))};
        ys = {_mm_shuffle_ps(a, b, _MM_SHUFFLE(3, 1, 3, 1))};
    }
    /// Stores the lanes at p[0] to p[3] (p 16-byte aligned).
    void Store(float* p) const { _mm_store_ps(p, v); }
    /// Every lane the value of lane k.
    template <int k>
    Lanes Spread() const
    {
        return {_mm_shuffle_ps(v, v, k * 0x55)};
    }
    /// Lane i.
    float Get(int i) const
    {
        alignas(16) float out[4];
        _mm_store_ps(out, v);
        return out[i];
    }

    /// A per-lane truth value: all ones or all zeros.
    struct Mask
    {
        __m128 m; ///< the lanes
        /// Every lane c.
        static Mask Fill(bool c) { return {_mm_castsi128_ps(_mm_set1_epi32(c ? -1 : 0))}; }
        /// The lanes as four bits.
        int Bits() const { return _mm_movemask_ps(m); }
        /// Lane i.
        bool Get(int i) const { return ((Bits() >> i) & 1) != 0; }
        /// Any lane set.
        bool Any() const { return Bits() != 0; }
        /// Every lane set.
        bool All() const { return Bits() == 0xF; }
        friend Mask operator&(const Mask& a, const Mask& b) { return {_mm_and_ps(a.m, b.m)}; }
        friend Mask operator|(const Mask& a, const Mask& b) { return {_mm_or_ps(a.m, b.m)}; }
        friend Mask operator~(const Mask& a) { return {_mm_xor_ps(a.m, _mm_castsi128_ps(_mm_set1_epi32(-1)))}; }
    };

    friend Lanes operator-(const Lanes& a) { return {_mm_xor_ps(a.v, _mm_set1_ps(-0.0f))}; }
    friend Lanes operator+(const Lanes& a, const Lanes& b) { return {_mm_add_ps(a.v, b.v)}; }
    friend Lanes operator-(const Lanes& a, const Lanes& b) { return {_mm_sub_ps(a.v, b.v)}; }
    friend Lanes operator*(const Lanes& a, const Lanes& b) { return {_mm_mul_ps(a.v, b.v)}; }
    friend Lanes operator/(const Lanes& a, const Lanes& b) { return {_mm_div_ps(a.v, b.v)}; }
    friend Mask operator>(const Lanes& a, const Lanes& b) { return {_mm_cmpgt_ps(a.v, b.v)}; }
    friend Mask operator>=(const Lanes& a, const Lanes& b) { return {_mm_cmpge_ps(a.v, b.v)}; }
    friend Mask operator==(const Lanes& a, const Lanes& b) { return {_mm_cmpeq_ps(a.v, b.v)}; }
    /// Per lane: a where c holds, else b.
    friend Lanes Select(const Mask& c, const Lanes& a, const Lanes& b)
    {
        return {_mm_or_ps(_mm_and_ps(c.m, a.v), _mm_andnot_ps(c.m, b.v))};
    }
    /// Per lane: a < b ? a : b (the second operand when either is NaN).
    friend Lanes Min(const Lanes& a, const Lanes& b) { return {_mm_min_ps(a.v, b.v)}; }
    /// Per lane: a > b ? a : b (the second operand when either is NaN).
    friend Lanes Max(const Lanes& a, const Lanes& b) { return {_mm_max_ps(a.v, b.v)}; }
    /// The largest lane, as std::max(std::max(v0, v1), std::max(v2, v3)) gives it, in registers: std::max(a, b) is
    /// _mm_max_ps(b, a) (a unless a < b), so the same value for every input, NaN included.
    float MaxLane() const
    {
        const __m128 firsts = _mm_shuffle_ps(v, v, _MM_SHUFFLE(2, 0, 2, 0));  // v0 v2
        const __m128 seconds = _mm_shuffle_ps(v, v, _MM_SHUFFLE(3, 1, 3, 1)); // v1 v3
        const __m128 pairs = _mm_max_ps(seconds, firsts);
        return _mm_cvtss_f32(_mm_max_ss(_mm_shuffle_ps(pairs, pairs, 1), pairs));
    }
    /// The smallest lane, as std::min(std::min(v0, v1), std::min(v2, v3)) gives it, in registers: std::min(a, b)
    /// is _mm_min_ps(b, a) (a unless b < a).
    float MinLane() const
    {
        const __m128 firsts = _mm_shuffle_ps(v, v, _MM_SHUFFLE(2, 0, 2, 0));
        const __m128 seconds = _mm_shuffle_ps(v, v, _MM_SHUFFLE(3, 1, 3, 1));
        const __m128 pairs = _mm_min_ps(seconds, firsts);
        return _mm_cvtss_f32(_mm_min_ss(_mm_shuffle_ps(pairs, pairs, 1), pairs));
    }
    /// The smallest lane, the lanes combined in the order cheapest for the registers (lanes 0 and 2, 1 and 3, then
    /// the two): the number MinLane gives, but for the sign of a zero and which NaN.
    float MinLaneAnyOrder() const
    {
        const __m128 half = _mm_min_ps(v, _mm_movehl_ps(v, v));
        return _mm_cvtss_f32(_mm_min_ss(half, _mm_shuffle_ps(half, half, 1)));
    }
};
#endif

#if SATVIZ_LANES_AVX2
/// Four doubles in one AVX2 register. Only code compiled for AVX2 may use it.
template <>
struct Lanes<double, true>
{
    static constexpr int kCount = 4; ///< lanes
    __m256d v;                       ///< the lanes

    /// Lanes a, b, c, d.
    [[gnu::target("avx2")]] static Lanes Set(double a, double b, double c, double d)
    {
        return {_mm256_setr_pd(a, b, c, d)};
    }
    /// Every lane x.
    [[gnu::target("avx2")]] static Lanes Fill(double x) { return {_mm256_set1_pd(x)}; }
    /// Lanes p[0] to p[3] (p 32-byte aligned).
    [[gnu::target("avx2")]] static Lanes Load(const double* p) { return {_mm256_load_pd(p)}; }
    /// Four points stored as x, y pairs from p (any alignment): their x in xs, their y in ys.
    [[gnu::target("avx2")]] static void LoadPoints(const double* p, Lanes& xs, Lanes& ys)
    {
        const __m256d a = _mm256_loadu_pd(p);     // x0 y0 x1 y1
        const __m256d b = _mm256_loadu_pd(p + 4); // x2 y2 x3 y3
        xs = {_mm256_permute4x64_pd(_mm256_unpacklo_pd(a, b), 0xD8)};
        ys = {_mm256_permute4x64_pd(_mm256_unpackhi_pd(a, b), 0xD8)};
    }
    /// Stores the lanes at p[0] to p[3] (p 32-byte aligned).
    [[gnu::target("avx2")]] void Store(double* p) const { _mm256_store_pd(p, v); }
    /// Every lane the value of lane k.
    template <int k>
    [[gnu::target("avx2")]] Lanes Spread() const
    {
        return {_mm256_permute4x64_pd(v, k * 0x55)};
    }
    /// Lane i.
    [[gnu::target("avx2")]] double Get(int i) const
    {
        alignas(32) double out[4];
        _mm256_store_pd(out, v);
        return out[i];
    }

    /// A per-lane truth value: all ones or all zeros.
    struct Mask
    {
        __m256d m; ///< the lanes
        /// Every lane c.
        [[gnu::target("avx2")]] static Mask Fill(bool c)
        {
            return {_mm256_castsi256_pd(_mm256_set1_epi64x(c ? -1 : 0))};
        }
        /// The lanes as four bits.
        [[gnu::target("avx2")]] int Bits() const { return _mm256_movemask_pd(m); }
        /// Lane i.
        [[gnu::target("avx2")]] bool Get(int i) const { return ((_mm256_movemask_pd(m) >> i) & 1) != 0; }
        /// Any lane set.
        [[gnu::target("avx2")]] bool Any() const { return _mm256_movemask_pd(m) != 0; }
        /// Every lane set.
        [[gnu::target("avx2")]] bool All() const { return _mm256_movemask_pd(m) == 0xF; }
        [[gnu::target("avx2")]] friend Mask operator&(const Mask& a, const Mask& b)
        {
            return {_mm256_and_pd(a.m, b.m)};
        }
        [[gnu::target("avx2")]] friend Mask operator|(const Mask& a, const Mask& b) { return {_mm256_or_pd(a.m, b.m)}; }
        [[gnu::target("avx2")]] friend Mask operator~(const Mask& a)
        {
            return {_mm256_xor_pd(a.m, _mm256_castsi256_pd(_mm256_set1_epi64x(-1)))};
        }
    };

    [[gnu::target("avx2")]] friend Lanes operator-(const Lanes& a)
    {
        return {_mm256_xor_pd(a.v, _mm256_set1_pd(-0.0))};
    }
    [[gnu::target("avx2")]] friend Lanes operator+(const Lanes& a, const Lanes& b) { return {_mm256_add_pd(a.v, b.v)}; }
    [[gnu::target("avx2")]] friend Lanes operator-(const Lanes& a, const Lanes& b) { return {_mm256_sub_pd(a.v, b.v)}; }
    [[gnu::target("avx2")]] friend Lanes operator*(const Lanes& a, const Lanes& b) { return {_mm256_mul_pd(a.v, b.v)}; }
    [[gnu::target("avx2")]] friend Lanes operator/(const Lanes& a, const Lanes& b) { return {_mm256_div_pd(a.v, b.v)}; }
    [[gnu::target("avx2")]] friend Mask operator>(const Lanes& a, const Lanes& b)
    {
        return {_mm256_cmp_pd(a.v, b.v, _CMP_GT_OQ)};
    }
    [[gnu::target("avx2")]] friend Mask operator>=(const Lanes& a, const Lanes& b)
    {
        return {_mm256_cmp_pd(a.v, b.v, _CMP_GE_OQ)};
    }
    [[gnu::target("avx2")]] friend Mask operator==(const Lanes& a, const Lanes& b)
    {
        return {_mm256_cmp_pd(a.v, b.v, _CMP_EQ_OQ)};
    }
    /// Per lane: a where c holds, else b.
    [[gnu::target("avx2")]] friend Lanes Select(const Mask& c, const Lanes& a, const Lanes& b)
    {
        return {_mm256_blendv_pd(b.v, a.v, c.m)};
    }
    /// Per lane: a < b ? a : b (the second operand when either is NaN).
    [[gnu::target("avx2")]] friend Lanes Min(const Lanes& a, const Lanes& b) { return {_mm256_min_pd(a.v, b.v)}; }
    /// Per lane: a > b ? a : b (the second operand when either is NaN).
    [[gnu::target("avx2")]] friend Lanes Max(const Lanes& a, const Lanes& b) { return {_mm256_max_pd(a.v, b.v)}; }
    /// The largest lane, as std::max(std::max(v0, v1), std::max(v2, v3)) gives it, in registers: std::max(a, b) is
    /// _mm_max_pd(b, a) (a unless a < b), so the same value for every input, NaN included.
    [[gnu::target("avx2")]] double MaxLane() const
    {
        const __m128d lo = _mm256_castpd256_pd128(v);    // v0 v1
        const __m128d hi = _mm256_extractf128_pd(v, 1);  // v2 v3
        const __m128d firsts = _mm_unpacklo_pd(lo, hi);  // v0 v2
        const __m128d seconds = _mm_unpackhi_pd(lo, hi); // v1 v3
        const __m128d pairs = _mm_max_pd(seconds, firsts);
        return _mm_cvtsd_f64(_mm_max_sd(_mm_unpackhi_pd(pairs, pairs), pairs));
    }
    /// The smallest lane, as std::min(std::min(v0, v1), std::min(v2, v3)) gives it, in registers: std::min(a, b)
    /// is _mm_min_pd(b, a) (a unless b < a).
    [[gnu::target("avx2")]] double MinLane() const
    {
        const __m128d lo = _mm256_castpd256_pd128(v);
        const __m128d hi = _mm256_extractf128_pd(v, 1);
        const __m128d firsts = _mm_unpacklo_pd(lo, hi);
        const __m128d seconds = _mm_unpackhi_pd(lo, hi);
        const __m128d pairs = _mm_min_pd(seconds, firsts);
        return _mm_cvtsd_f64(_mm_min_sd(_mm_unpackhi_pd(pairs, pairs), pairs));
    }
    /// The smallest lane, the lanes combined in the order cheapest for the registers (lanes 0 and 2, 1 and 3, then
    /// the two): the number MinLane gives, but for the sign of a zero and which NaN.
    [[gnu::target("avx2")]] double MinLaneAnyOrder() const
    {
        const __m128d half = _mm_min_pd(_mm256_castpd256_pd128(v), _mm256_extractf128_pd(v, 1));
        return _mm_cvtsd_f64(_mm_min_sd(half, _mm_unpackhi_pd(half, half)));
    }
};
#endif

} // namespace satviz::detail
