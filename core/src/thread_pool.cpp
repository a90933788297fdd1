// SPDX-License-Identifier: MIT
// satviz: the default parallel-for of the world, on a persistent pool of std::thread.

#include <satviz/tasks.h>

#include <algorithm>
#include <atomic>
#include <condition_variable>
#include <mutex>
#include <thread>
#include <vector>

namespace satviz
{

namespace
{

// How many times a waiting thread looks for work (or for the end of a run) before it sleeps. A step hands the pool
// several short runs in a row: a thread that slept between them would be woken by the system, which costs more
// than the runs it waits for; one that looks for a while finds the next run at once.
constexpr int kSpins = 20000;

// Pieces per thread: a few, so that a thread slowed by another program's work leaves its share to the others.
constexpr int kPiecesPerWorker = 4;

} // namespace

struct ThreadPool::Shared
{
    std::mutex mutex;
    std::condition_variable wake; // a run started, or the pool ends
    std::condition_variable done; // the last piece of a run finished
    std::atomic<unsigned> generation{0};
    std::atomic<int> remaining{0}; // pieces of the present run not yet finished
    std::atomic<int> busy{0};      // pool threads inside the present run
    std::atomic<int> next{0};      // the next piece to take
    // The run, written under the mutex before `generation` changes, read by a thread that joined it under the mutex.
    TaskFunction task = nullptr;
    void* taskContext = nullptr;
    int count = 0;
    int pieceSize = 1;
    int pieces = 0;
    bool stop = false;
    std::vector<std::thread> threads;

    // Takes pieces of the present run until none is left.
    void Work(TaskFunction f, void* context, int n, int size, int total)
    {
        for (int piece = next.fetch_add(1); piece < total; piece = next.fetch_add(1))
        {
            const int begin = piece * size;
            f(context, begin, std::min(n, begin + size));
            if (remaining.fetch_sub(1) == 1)
            {
                std::lock_guard<std::mutex> lock(mutex);
                done.notify_all();
            }
        }
    }

    void Loop()
    {
        unsigned seen = 0;
        for (;;)
        {
            for (int spin = 0; spin < kSpins && generation.load(std::memory_order_acquire) == seen; ++spin)
            {
            }
            std::unique_lock<std::mutex> lock(mutex);
            wake.wait(lock, [&] { return stop || generation.load() != seen; });
            if (stop)
            {
                return;
            }
            seen = generation.load();
            const TaskFunction f = task;
            void* const context = taskContext;
            const int n = count, size = pieceSize, total = pieces;
            busy.fetch_add(1);
            lock.unlock();
            Work(f, context, n, size, total);
            lock.lock();
            if (busy.fetch_sub(1) == 1)
            {
                done.notify_all();
            }
        }
    }
};

ThreadPool::ThreadPool(int workers) : m_workers(std::max(1, workers)), m_shared(std::make_unique<Shared>())
{
    for (int k = 1; k < m_workers; ++k)
    {
        m_shared->threads.emplace_back([shared = m_shared.get()] { shared->Loop(); });
    }
}

ThreadPool::~ThreadPool()
{
    {
        std::lock_guard<std::mutex> lock(m_shared->mutex);
        m_shared->stop = true;
    }
    m_shared->wake.notify_all();
    for (std::thread& thread : m_shared->threads)
    {
        thread.join();
    }
}

void ThreadPool::Run(int count, TaskFunction task, void* taskContext)
{
    if (count <= 0)
    {
        return;
    }
    if (m_workers == 1)
    {
        task(taskContext, 0, count);
        return;
    }
    Shared& s = *m_shared;
    const int wanted = m_workers * kPiecesPerWorker;
    const int size = (count + wanted - 1) / wanted;
    const int total = (count + size - 1) / size;
    {
        // A pool thread that joined the last run after it ended (it found no piece left) may still be in it, about
        // to take a piece: the run is changed only once it is out.
        std::unique_lock<std::mutex> lock(s.mutex);
        s.done.wait(lock, [&] { return s.busy.load() == 0; });
        s.task = task;
        s.taskContext = taskContext;
        s.count = count;
        s.pieceSize = size;
        s.pieces = total;
        s.next.store(0);
        s.remaining.store(total);
        s.generation.fetch_add(1, std::memory_order_release);
    }
    s.wake.notify_all();
    s.Work(task, taskContext, count, size, total);
    // Done when every piece is finished and no pool thread is still inside the run (one that joined late may still
    // be reading it): only then may the next run change it.
    const auto finished = [&] { return s.remaining.load() == 0 && s.busy.load() == 0; };
    for (int spin = 0; spin < kSpins && !finished(); ++spin)
    {
    }
    std::unique_lock<std::mutex> lock(s.mutex);
    s.done.wait(lock, finished);
}

TaskRunner PoolTasks(ThreadPool& pool)
{
    TaskRunner runner;
    runner.run = [](void* context, int count, TaskFunction task, void* taskContext) {
        static_cast<ThreadPool*>(context)->Run(count, task, taskContext);
    };
    runner.context = &pool;
    runner.workers = pool.Workers();
    return runner;
}

} // namespace satviz
