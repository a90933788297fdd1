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

} // namespace satviz::detail
