// SPDX-License-Identifier: MIT
// satviz (private), machinery: the face-scan kernel, one face of the reference polygon against every vertex of a
// small incident polygon mapped into its frame (IncidentPolygon): the smallest projection of the vertices on the
// face's normal, without a branch. The textbook face query (face_query.h) calls it once per face.
#pragma once

#include "cpu_dispatch.h"

#include <satviz/math.h>

#include <algorithm>
#include <limits>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif
#if SATVIZ_WIDE
#include <immintrin.h>
#endif

namespace satviz::detail
{

/// Smallest of the projections nx * x[j] + ny * y[j] over `count` entries, `count` a multiple of 4 (the caller
/// pads by repeating a vertex).
template <typename S>
S MinProjection(const S* x, const S* y, int count, S nx, S ny)
{
    S low = nx * x[0] + ny * y[0];
    for (int j = 1; j < count; ++j)
    {
        low = std::min(low, nx * x[j] + ny * y[j]);
    }
    return low;
}

/// One face of a scan over N padded entries (N a multiple of 4, known at compile time so the loop unrolls): the
/// separation min_j (nx x[j] + ny y[j]) - offset. With kInside it also keeps, per entry, the largest separation
/// over the faces scanned so far: inside[j] = max(inside[j], nx x[j] + ny y[j] - offset). An entry whose largest
/// separation over all faces is <= 0 lies inside the polygon. Rounding is monotonic, so subtracting the offset
/// before or after taking the minimum gives the same separation to the bit.
template <int N, bool kInside, typename S>
S ScanFace(const S* x, const S* y, S nx, S ny, S offset, S* inside)
{
    S low = std::numeric_limits<S>::infinity();
    for (int j = 0; j < N; ++j)
    {
        const S p = nx * x[j] + ny * y[j];
        if constexpr (kInside)
        {
            inside[j] = std::max(inside[j], p - offset);
        }
        low = std::min(low, p);
    }
    return low - offset;
}

#if defined(__SSE2__)
/// MinProjection with SSE2, two lanes: the same multiplications and additions as the scalar version, without
/// contraction, and a minimum is exact, so the result is the same to the bit.
inline double MinProjection(const double* x, const double* y, int count, double nx, double ny)
{
    const __m128d vx = _mm_set1_pd(nx);
    const __m128d vy = _mm_set1_pd(ny);
    __m128d low = _mm_add_pd(_mm_mul_pd(vx, _mm_load_pd(x)), _mm_mul_pd(vy, _mm_load_pd(y)));
    for (int j = 2; j < count; j += 2)
    {
        low = _mm_min_pd(low, _mm_add_pd(_mm_mul_pd(vx, _mm_load_pd(x + j)), _mm_mul_pd(vy, _mm_load_pd(y + j))));
    }
    return _mm_cvtsd_f64(_mm_min_sd(low, _mm_unpackhi_pd(low, low)));
}

/// MinProjection with SSE2, four lanes.
inline float MinProjection(const float* x, const float* y, int count, float nx, float ny)
{
    const __m128 vx = _mm_set1_ps(nx);
    const __m128 vy = _mm_set1_ps(ny);
    __m128 low = _mm_add_ps(_mm_mul_ps(vx, _mm_load_ps(x)), _mm_mul_ps(vy, _mm_load_ps(y)));
    for (int j = 4; j < count; j += 4)
    {
        low = _mm_min_ps(low, _mm_add_ps(_mm_mul_ps(vx, _mm_load_ps(x + j)), _mm_mul_ps(vy, _mm_load_ps(y + j))));
    }
    low = _mm_min_ps(low, _mm_movehl_ps(low, low));
    return _mm_cvtss_f32(_mm_min_ss(low, _mm_shuffle_ps(low, low, 1)));
}

/// ScanFace with SSE2, two lanes.
template <int N, bool kInside>
double ScanFace(const double* x, const double* y, double nx, double ny, double offset, double* inside)
{
    const __m128d vx = _mm_set1_pd(nx);
    const __m128d vy = _mm_set1_pd(ny);
    const __m128d off = _mm_set1_pd(offset);
    __m128d low = _mm_set1_pd(std::numeric_limits<double>::infinity());
    for (int j = 0; j < N; j += 2)
    {
        const __m128d p = _mm_add_pd(_mm_mul_pd(vx, _mm_load_pd(x + j)), _mm_mul_pd(vy, _mm_load_pd(y + j)));
        if constexpr (kInside)
        {
            _mm_store_pd(inside + j, _mm_max_pd(_mm_load_pd(inside + j), _mm_sub_pd(p, off)));
        }
        low = _mm_min_pd(low, p);
    }
    return _mm_cvtsd_f64(_mm_min_sd(low, _mm_unpackhi_pd(low, low))) - offset;
}

/// ScanFace with SSE2, four lanes.
template <int N, bool kInside>
float ScanFace(const float* x, const float* y, float nx, float ny, float offset, float* inside)
{
    const __m128 vx = _mm_set1_ps(nx);
    const __m128 vy = _mm_set1_ps(ny);
    const __m128 off = _mm_set1_ps(offset);
    __m128 low = _mm_set1_ps(std::numeric_limits<float>::infinity());
    for (int j = 0; j < N; j += 4)
    {
        const __m128 p = _mm_add_ps(_mm_mul_ps(vx, _mm_load_ps(x + j)), _mm_mul_ps(vy, _mm_load_ps(y + j)));
        if constexpr (kInside)
        {
            _mm_store_ps(inside + j, _mm_max_ps(_mm_load_ps(inside + j), _mm_sub_ps(p, off)));
        }
        low = _mm_min_ps(low, p);
    }
    low = _mm_min_ps(low, _mm_movehl_ps(low, low));
    return _mm_cvtss_f32(_mm_min_ss(low, _mm_shuffle_ps(low, low, 1))) - offset;
}
#endif

#if SATVIZ_WIDE
/// MinProjection with AVX2, four lanes of double.
[[gnu::target("avx2")]] inline double MinProjectionWide(const double* x, const double* y, int count, double nx,
                                                        double ny)
{
    const __m256d vx = _mm256_set1_pd(nx);
    const __m256d vy = _mm256_set1_pd(ny);
    __m256d low = _mm256_add_pd(_mm256_mul_pd(vx, _mm256_load_pd(x)), _mm256_mul_pd(vy, _mm256_load_pd(y)));
    for (int j = 4; j < count; j += 4)
    {
        low = _mm256_min_pd(
            low, _mm256_add_pd(_mm256_mul_pd(vx, _mm256_load_pd(x + j)), _mm256_mul_pd(vy, _mm256_load_pd(y + j))));
    }
    __m128d half = _mm_min_pd(_mm256_castpd256_pd128(low), _mm256_extractf128_pd(low, 1));
    return _mm_cvtsd_f64(_mm_min_sd(half, _mm_unpackhi_pd(half, half)));
}

/// MinProjection with AVX2, eight lanes of float, then four.
[[gnu::target("avx2")]] inline float MinProjectionWide(const float* x, const float* y, int count, float nx, float ny)
{
    if (count % 8 != 0)
    {
        return MinProjection(x, y, count, nx, ny);
    }
    const __m256 vx = _mm256_set1_ps(nx);
    const __m256 vy = _mm256_set1_ps(ny);
    __m256 low = _mm256_add_ps(_mm256_mul_ps(vx, _mm256_load_ps(x)), _mm256_mul_ps(vy, _mm256_load_ps(y)));
    for (int j = 8; j < count; j += 8)
    {
        low = _mm256_min_ps(
            low, _mm256_add_ps(_mm256_mul_ps(vx, _mm256_load_ps(x + j)), _mm256_mul_ps(vy, _mm256_load_ps(y + j))));
    }
    __m128 half = _mm_min_ps(_mm256_castps256_ps128(low), _mm256_extractf128_ps(low, 1));
    half = _mm_min_ps(half, _mm_movehl_ps(half, half));
    return _mm_cvtss_f32(_mm_min_ss(half, _mm_shuffle_ps(half, half, 1)));
}

/// ScanFace with AVX2, four lanes of double.
template <int N, bool kInside>
[[gnu::target("avx2")]] double ScanFaceWide(const double* x, const double* y, double nx, double ny, double offset,
                                            double* inside)
{
    const __m256d vx = _mm256_set1_pd(nx);
    const __m256d vy = _mm256_set1_pd(ny);
    const __m256d off = _mm256_set1_pd(offset);
    __m256d low = _mm256_set1_pd(std::numeric_limits<double>::infinity());
    for (int j = 0; j < N; j += 4)
    {
        const __m256d p =
            _mm256_add_pd(_mm256_mul_pd(vx, _mm256_load_pd(x + j)), _mm256_mul_pd(vy, _mm256_load_pd(y + j)));
        if constexpr (kInside)
        {
            _mm256_store_pd(inside + j, _mm256_max_pd(_mm256_load_pd(inside + j), _mm256_sub_pd(p, off)));
        }
        low = _mm256_min_pd(low, p);
    }
    __m128d half = _mm_min_pd(_mm256_castpd256_pd128(low), _mm256_extractf128_pd(low, 1));
    return _mm_cvtsd_f64(_mm_min_sd(half, _mm_unpackhi_pd(half, half))) - offset;
}

/// ScanFace with AVX2, eight lanes of float (and four for a remainder of four).
template <int N, bool kInside>
[[gnu::target("avx2")]] float ScanFaceWide(const float* x, const float* y, float nx, float ny, float offset,
                                           float* inside)
{
    if constexpr (N % 8 != 0)
    {
        return ScanFace<N, kInside>(x, y, nx, ny, offset, inside);
    }
    else
    {
        const __m256 vx = _mm256_set1_ps(nx);
        const __m256 vy = _mm256_set1_ps(ny);
        const __m256 off = _mm256_set1_ps(offset);
        __m256 low = _mm256_set1_ps(std::numeric_limits<float>::infinity());
        for (int j = 0; j < N; j += 8)
        {
            const __m256 p =
                _mm256_add_ps(_mm256_mul_ps(vx, _mm256_load_ps(x + j)), _mm256_mul_ps(vy, _mm256_load_ps(y + j)));
            if constexpr (kInside)
            {
                _mm256_store_ps(inside + j, _mm256_max_ps(_mm256_load_ps(inside + j), _mm256_sub_ps(p, off)));
            }
            low = _mm256_min_ps(low, p);
        }
        __m128 half = _mm_min_ps(_mm256_castps256_ps128(low), _mm256_extractf128_ps(low, 1));
        half = _mm_min_ps(half, _mm_movehl_ps(half, half));
        return _mm_cvtss_f32(_mm_min_ss(half, _mm_shuffle_ps(half, half, 1))) - offset;
    }
}
#endif

/// The separation of one face over a scan of N padded entries (ScanFace), with the wide vectors when kWide. The
/// smallest projection is the same number whatever the order the lanes combine it in, except for the sign of a
/// zero; adding +0 makes a zero separation +0, so both kernels give the same bits.
template <int N, bool kInside, bool kWide, typename S>
S FaceSeparation(const S* x, const S* y, Vec2T<S> normal, S offset, S* inside)
{
#if SATVIZ_WIDE
    if constexpr (kWide)
    {
        return ScanFaceWide<N, kInside>(x, y, normal.x, normal.y, offset, inside) + S(0);
    }
#endif
    return ScanFace<N, kInside>(x, y, normal.x, normal.y, offset, inside) + S(0);
}

} // namespace satviz::detail
