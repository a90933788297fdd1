// SPDX-License-Identifier: MIT
// satviz: how the world runs its work on several threads: a parallel-for the caller provides, and a default one on
// std::thread.
#pragma once

#include <memory>

namespace satviz
{

/// A piece of work over the indices [begin, end) of a range: each index writes only its own results, so the pieces
/// may run in any order, on any thread.
using TaskFunction = void (*)(void* taskContext, int begin, int end);

/// A parallel-for the world hands its work to (as Box2D v3's task callbacks): `run` must call `task` on pieces that
/// cover [0, count) exactly once each, in any order and on any threads, and return when all are done. The world asks
/// only for work whose results do not depend on the order, so a step gives the same bits for any number of workers.
/// The default (run null) runs everything on the calling thread.
struct TaskRunner
{
    /// Runs `task` over [0, count) and returns when it is done; null: the world runs the range itself.
    void (*run)(void* context, int count, TaskFunction task, void* taskContext) = nullptr;
    void* context = nullptr; ///< passed to `run` as its first argument
    int workers = 1;         ///< threads `run` spreads the work on (the caller's included); 1: no gain from splitting
};

/// A small persistent pool of threads: `workers - 1` threads that wait for work, and the caller's thread, which
/// works too. Not copyable; its threads end when it is destroyed. One Run at a time (one world stepping on it).
class ThreadPool
{
  public:
    /// A pool of `workers` threads, the caller's included (at least 1; 1 starts no thread).
    explicit ThreadPool(int workers);
    ~ThreadPool();
    ThreadPool(const ThreadPool&) = delete;
    ThreadPool& operator=(const ThreadPool&) = delete;

    /// Runs `task` over [0, count) in pieces shared by the pool's threads and the caller's; returns when all are done.
    void Run(int count, TaskFunction task, void* taskContext);
    /// The number of threads that work, the caller's included.
    int Workers() const { return m_workers; }

  private:
    struct Shared;
    int m_workers = 1;
    std::unique_ptr<Shared> m_shared;
};

/// The TaskRunner that runs a world's work on `pool` (which must outlive the world's steps).
TaskRunner PoolTasks(ThreadPool& pool);

} // namespace satviz
