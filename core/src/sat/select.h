// SPDX-License-Identifier: MIT
// satviz (private), machinery: branchless selection. A choice that follows the geometry (which face is better,
// which polygon holds the reference face) is as unpredictable as the data, and a branch on it is mispredicted about
// half of the time; these choose with a mask instead, which the compiler cannot turn back into a branch.
#pragma once

#include <satviz/math.h>

#include <cstdint>
#include <cstring>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace satviz::detail
{

/// a when c holds, else b, computed with a mask: the compiler cannot turn it back into a branch, and a branch
/// on geometric data is mispredicted about half of the time.
inline int Select(bool c, int a, int b)
{
    const int mask = -static_cast<int>(c);
    return (a & mask) | (b & ~mask);
}

/// Select over the bits of a scalar, through the unsigned integer U of its size (the portable form).
template <typename U, typename S>
S SelectBits(bool c, S a, S b)
{
    static_assert(sizeof(U) == sizeof(S), "an integer of the scalar's size");
    U bitsA;
    U bitsB;
    std::memcpy(&bitsA, &a, sizeof a);
    std::memcpy(&bitsB, &b, sizeof b);
    const U mask = U(0) - U(c);
    const U bits = (bitsA & mask) | (bitsB & ~mask);
    S out;
    std::memcpy(&out, &bits, sizeof out);
    return out;
}

/// Select for a double: a mask over the bits.
inline double Select(bool c, double a, double b)
{
#if defined(__x86_64__) && defined(__SSE2__)
    const __m128d mask = _mm_castsi128_pd(_mm_cvtsi64_si128(-static_cast<long long>(c)));
    return _mm_cvtsd_f64(_mm_or_pd(_mm_and_pd(mask, _mm_set_sd(a)), _mm_andnot_pd(mask, _mm_set_sd(b))));
#else
    return SelectBits<uint64_t>(c, a, b);
#endif
}

/// Select for a float: a mask over the bits.
inline float Select(bool c, float a, float b)
{
#if defined(__SSE2__)
    const __m128 mask = _mm_castsi128_ps(_mm_cvtsi32_si128(-static_cast<int>(c)));
    return _mm_cvtss_f32(_mm_or_ps(_mm_and_ps(mask, _mm_set_ss(a)), _mm_andnot_ps(mask, _mm_set_ss(b))));
#else
    return SelectBits<uint32_t>(c, a, b);
#endif
}

/// Select for a point, coordinate by coordinate.
template <typename S>
Vec2T<S> Select(bool c, Vec2T<S> a, Vec2T<S> b)
{
    return {Select(c, a.x, b.x), Select(c, a.y, b.y)};
}

/// Select for a rotation, member by member.
template <typename S>
RotT<S> Select(bool c, RotT<S> a, RotT<S> b)
{
    return {Select(c, a.c, b.c), Select(c, a.s, b.s)};
}

/// Select for a transform, member by member.
template <typename S>
TransformT<S> Select(bool c, const TransformT<S>& a, const TransformT<S>& b)
{
    return {Select(c, a.p, b.p), Select(c, a.q, b.q)};
}

/// Select between two objects by address, with a mask: a reference chosen by geometric data (which polygon holds
/// the reference face) is as unpredictable as the data, and a branch the compiler makes of `c ? a : b` is then
/// mispredicted about half of the time.
template <typename T>
const T& SelectRef(bool c, const T& a, const T& b)
{
    const uintptr_t mask = uintptr_t(0) - uintptr_t(c);
    const uintptr_t address = (reinterpret_cast<uintptr_t>(&a) & mask) | (reinterpret_cast<uintptr_t>(&b) & ~mask);
    return *reinterpret_cast<const T*>(address);
}

} // namespace satviz::detail
