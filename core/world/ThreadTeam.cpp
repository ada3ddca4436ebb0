#include "world/ThreadTeam.h"

#include <algorithm>
#include <chrono>

#if defined(__x86_64__) || defined(__i386__)
#include <immintrin.h>
#endif
#if defined(__linux__)
#include <pthread.h>
#include <sched.h>
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

// The CPU the calling thread runs on, or -1 where that is not known.
int currentCpu() {
#if defined(__linux__)
    return sched_getcpu();
#else
    return -1;
#endif
}

// A new thread starts on its creator's CPU, and Linux moved a worker off member 0's CPU only 10-20 ms later (on this
// project's two-CPU machines, 2026-12-06): until then every barrier cost a time slice, and the first steps of
// ramps.obj on two threads took up to 4.4 ms each against 0.2. So a worker that starts on `cpu` moves off it at once,
// by an affinity that leaves that CPU out, and then takes back the affinity it had, so that the scheduler places it
// freely from there on (kept to one CPU throughout, a team's jobs took longer: tests/benchmarks/LOG.md, 2026-12-05).
void leaveCpu(int cpu) {
#if defined(__linux__)
    if (cpu < 0 || sched_getcpu() != cpu)
        return;
    cpu_set_t allowed;
    if (pthread_getaffinity_np(pthread_self(), sizeof allowed, &allowed) != 0 || !CPU_ISSET(cpu, &allowed))
        return;
    cpu_set_t others = allowed;
    CPU_CLR(cpu, &others);
    if (CPU_COUNT(&others) == 0)
        return;
    if (pthread_setaffinity_np(pthread_self(), sizeof others, &others) == 0)
        pthread_setaffinity_np(pthread_self(), sizeof allowed, &allowed);
#else
    (void)cpu;
#endif
}

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
    const int leaderCpu = currentCpu();
    for (int member = 1; member < m_size; ++member)
        m_workers.emplace_back([this, member, leaderCpu] {
            leaveCpu(leaderCpu);
            work(member);
        });
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
        // A worker woken from its sleep may be placed on the waker's CPU, member 0's: it moves off again, as when it
        // started. (With the move at the start alone, 3 of 30 runs of ramps.obj on two threads still began with
        // steps of 4.3 ms.)
        leaveCpu(m_leaderCpu);
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
    m_leaderCpu = currentCpu();
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
