#include "world/ThreadTeam.h"

#include <algorithm>
#include <chrono>

#if defined(__x86_64__) || defined(__i386__)
#include <immintrin.h>
#endif

namespace rl {

namespace {

inline void cpuRelax() {
#if defined(__x86_64__) || defined(__i386__)
    _mm_pause();
#else
    std::this_thread::yield();
#endif
}

// A member spins this long (300-500 us on this project's machines) before it sleeps on a futex. On those virtual
// machines run() took a median 68 us to get a sleeping worker going after a pause of 300 us or more, 8 us after
// 100-200 us, and under 1 us while it still spun (2026-11-27). A step has serial stretches of 100-300 us (the pair
// lists) between its team jobs, and with 4,000 spins (60-100 us) the worker slept through them: ramps' step on two
// threads took 1.54-1.68 ms, with 20,000 spins 1.50-1.52 ms (boxes1000 3.52-3.59 and 3.41-3.44 ms; three
// interleaved runs of 120 frames). Between steps the workers still go to sleep after it.
constexpr int kSpins = 20000;

// The team whose member 0 runs on this thread, while it runs a job: its waits are counted (takeLeaderWait()).
thread_local const ThreadTeam* t_leading = nullptr;

uint64_t nowNs() {
    return static_cast<uint64_t>(
        std::chrono::duration_cast<std::chrono::nanoseconds>(std::chrono::steady_clock::now().time_since_epoch())
            .count());
}

} // namespace

ThreadTeam::ThreadTeam(int size) : m_size(std::max(1, size)) {
    m_workers.reserve(static_cast<size_t>(m_size - 1));
    for (int member = 1; member < m_size; ++member)
        m_workers.emplace_back([this, member] { work(member); });
}

ThreadTeam::~ThreadTeam() {
    m_stop.store(true, std::memory_order_relaxed);
    m_jobGeneration.fetch_add(1, std::memory_order_release);
    m_jobGeneration.notify_all();
    for (std::thread& worker : m_workers)
        worker.join();
}

void ThreadTeam::awaitChange(const std::atomic<uint32_t>& counter, uint32_t seen) {
    for (int i = 0; i < kSpins; ++i) {
        if (counter.load(std::memory_order_acquire) != seen)
            return;
        cpuRelax();
    }
    while (counter.load(std::memory_order_acquire) == seen)
        counter.wait(seen, std::memory_order_acquire);
}

void ThreadTeam::work(int member) {
    uint32_t seen = 0;
    for (;;) {
        awaitChange(m_jobGeneration, seen);
        seen = m_jobGeneration.load(std::memory_order_acquire);
        if (m_stop.load(std::memory_order_relaxed))
            return;
        (*m_job)(member);
        if (m_unfinished.fetch_sub(1, std::memory_order_acq_rel) == 1)
            m_unfinished.notify_all();
    }
}

void ThreadTeam::run(const std::function<void(int)>& job) {
    if (m_size == 1) {
        job(0);
        return;
    }
    ++m_teamJobs;
    m_job = &job;
    m_unfinished.store(static_cast<uint32_t>(m_size - 1), std::memory_order_relaxed);
    m_jobGeneration.fetch_add(1, std::memory_order_release);
    m_jobGeneration.notify_all();
    const ThreadTeam* const outer = std::exchange(t_leading, this);
    job(0);
    t_leading = outer;
    if (m_unfinished.load(std::memory_order_acquire) != 0) {
        const uint64_t start = nowNs();
        for (int i = 0; i < kSpins && m_unfinished.load(std::memory_order_acquire) != 0; ++i)
            cpuRelax();
        for (uint32_t left = m_unfinished.load(std::memory_order_acquire); left != 0;
             left = m_unfinished.load(std::memory_order_acquire))
            m_unfinished.wait(left, std::memory_order_acquire);
        m_leaderWaitNs += nowNs() - start;
    }
    m_job = nullptr;
}

void ThreadTeam::barrier() {
    if (m_size == 1)
        return;
    const uint32_t generation = m_barrierGeneration.load(std::memory_order_acquire);
    if (m_arrived.fetch_add(1, std::memory_order_acq_rel) == static_cast<uint32_t>(m_size - 1)) {
        m_arrived.store(0, std::memory_order_relaxed);
        m_barrierGeneration.fetch_add(1, std::memory_order_release);
        m_barrierGeneration.notify_all();
        return;
    }
    if (t_leading != this) {
        awaitChange(m_barrierGeneration, generation);
        return;
    }
    const uint64_t start = nowNs();
    awaitChange(m_barrierGeneration, generation);
    m_leaderWaitNs += nowNs() - start;
}

} // namespace rl
