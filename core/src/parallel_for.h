// SPDX-License-Identifier: MIT
// satviz: the world's work over a range, on the caller's task runner (internal).
#pragma once

#include <satviz/tasks.h>

namespace satviz::detail
{

/// Calls f(begin, end) on pieces covering [0, count), through `tasks` when it has several workers and the range
/// holds at least two pieces of `grain` indices, else once on the calling thread. f must write only the results of
/// its own indices: then the results are the same bits however the range is split.
template <typename F>
void ParallelFor(const TaskRunner& tasks, int count, int grain, const F& f)
{
    if (count <= 0)
    {
        return;
    }
    if (tasks.run == nullptr || tasks.workers <= 1 || count < 2 * grain)
    {
        f(0, count);
        return;
    }
    tasks.run(
        tasks.context, count,
        [](void* context, int begin, int end) { (*static_cast<const F*>(context))(begin, end); },
        const_cast<F*>(&f));
}

/// How many pieces of at least `grain` indices a range of `count` is cut into for ParallelForPieces: 1 (the whole
/// range, on the calling thread) without several workers, else a few per worker.
inline int PieceCount(const TaskRunner& tasks, int count, int grain)
{
    if (tasks.run == nullptr || tasks.workers <= 1 || count < 2 * grain)
    {
        return 1;
    }
    const int most = (count + grain - 1) / grain;
    const int wanted = 4 * tasks.workers;
    return most < wanted ? most : wanted;
}

/// Calls f(piece, begin, end) for each of `pieces` consecutive pieces of [0, count), through `tasks`: for work that
/// appends its results to a list of its piece's own, the lists then joined in the pieces' order, which gives the
/// order of one pass over the whole range. With a single piece, f runs once on the calling thread and may append
/// straight to the final list.
template <typename F>
void ParallelForPieces(const TaskRunner& tasks, int count, int pieces, const F& f)
{
    const auto run = [&](int first, int last) {
        for (int piece = first; piece < last; ++piece)
        {
            const int begin = static_cast<int>(static_cast<long long>(count) * piece / pieces);
            const int end = static_cast<int>(static_cast<long long>(count) * (piece + 1) / pieces);
            f(piece, begin, end);
        }
    };
    ParallelFor(tasks, pieces, 1, run);
}

} // namespace satviz::detail
