// SPDX-License-Identifier: MIT
// satviz (private), machinery: the CPU dispatch. The library keeps the baseline instruction set; the untraced
// queries also run, compiled for wider vectors with a target attribute (entry.h: RunWide, RunWide512), where the
// processor has them: 256-bit vectors (AVX2) and 512-bit ones (AVX-512F). This file decides, once, whether it has.
#pragma once

// Wide scans: 256-bit vectors (AVX2) in code compiled for them with a target attribute, chosen at run time
// (HasWideVectors), so the library itself keeps the baseline instruction set.
#if defined(__x86_64__) && defined(__SSE2__) && (defined(__GNUC__) || defined(__clang__))
#define SATVIZ_WIDE 1
#else
#define SATVIZ_WIDE 0
#endif

#include <cstdlib>
#include <cstring>

namespace satviz::detail
{

/// The widest vectors the environment allows: SATVIZ_CPU=baseline (none), SATVIZ_CPU=avx2 (256 bits), unset or
/// anything else: what the processor has. It runs the paths of an older processor on a newer one, so that every
/// path a user's machine may take is tested on any machine.
inline int AllowedVectorBits()
{
    const char* cpu = std::getenv("SATVIZ_CPU");
    if (cpu == nullptr)
    {
        return 512;
    }
    return std::strcmp(cpu, "baseline") == 0 ? 0 : std::strcmp(cpu, "avx2") == 0 ? 256 : 512;
}

/// Whether the untraced queries take the wide scans: set once from the processor (AVX2) and AllowedVectorBits.
/// Tests clear it to run the baseline instructions on any machine; both give the same bits.
inline bool& WideVectorsEnabled()
{
#if SATVIZ_WIDE
    static bool enabled = (__builtin_cpu_init(), __builtin_cpu_supports("avx2") != 0) && AllowedVectorBits() >= 256;
#else
    static bool enabled = false;
#endif
    return enabled;
}

/// Whether the queries that take them run the face loops of small polygons on 512-bit vectors (AVX-512F) on top of
/// the wide scans: set once from the processor and AllowedVectorBits. Tests clear it to run the 256-bit loops; all give the same bits.
inline bool& Wide512Enabled()
{
#if SATVIZ_WIDE
    static bool enabled = (__builtin_cpu_init(), __builtin_cpu_supports("avx512f") != 0) && AllowedVectorBits() >= 512;
#else
    static bool enabled = false;
#endif
    return enabled;
}

#if SATVIZ_WIDE
/// Whether the untraced queries take the wide scans now.
inline bool HasWideVectors()
{
    return WideVectorsEnabled();
}

/// Whether the untraced queries that take them run 512-bit face loops now.
inline bool HasWide512()
{
    return WideVectorsEnabled() && Wide512Enabled();
}
#else
/// Whether the untraced queries take the wide scans now: never on this processor family.
inline constexpr bool HasWideVectors()
{
    return false;
}
#endif

} // namespace satviz::detail
