// A fixed team of threads that run one job together and meet at barriers inside it. The caller of run() is member 0,
// so a team of one runs the job on the calling thread with no synchronisation at all. The world uses it for the
// narrowphase and for the level-by-level contact solve (ContactSolver), whose results do not depend on the team size.
#pragma once

#include <algorithm>
#include <atomic>
#include <cstdint>
#include <functional>
#include <thread>
#include <utility>
#include <vector>

namespace rl {

class ThreadTeam {
public:
    explicit ThreadTeam(int size);
    ~ThreadTeam();
    ThreadTeam(const ThreadTeam&) = delete;
    ThreadTeam& operator=(const ThreadTeam&) = delete;

    int size() const { return m_size; }
    // Runs job(member) on every member, member 0 on the calling thread, and returns when all have returned. A job
    // must not throw, and must not call run() itself.
    void run(const std::function<void(int member)>& job);
    // Inside a job: returns once every member has called it; what each member wrote before is then visible to all.
    void barrier();

    // Inside a job: returns once `counter` is at least `atLeast`. For a one-way wait on other members' progress:
    // whoever advances the counter does so with release order and then notifies it (notify_all()).
    static void awaitAtLeast(const std::atomic<uint32_t>& counter, uint32_t atLeast) {
        for (uint32_t seen = counter.load(std::memory_order_acquire); seen < atLeast;
             seen = counter.load(std::memory_order_acquire))
            awaitChange(counter, seen);
    }

    // Nanoseconds member 0 spent waiting for the others, at barriers and at the end of run(), since the last call;
    // zero for a team of one. The world reads it to see whether the team pays (TeamPacer).
    uint64_t takeLeaderWait() { return std::exchange(m_leaderWaitNs, 0); }
    // Jobs run() has started on the whole team (a team of one counts none: it runs the job alone). Member 0's count.
    uint64_t teamJobs() const { return m_teamJobs; }

    // [begin, end) split evenly over the members: member k's part.
    static std::pair<size_t, size_t> share(size_t begin, size_t end, int member, int members) {
        const size_t n = end - begin;
        return {begin + n * static_cast<size_t>(member) / static_cast<size_t>(members),
                begin + n * static_cast<size_t>(member + 1) / static_cast<size_t>(members)};
    }

    // The chunk a member takes with one claim, when the members claim chunks of a list with one shared counter:
    // `claim` is the counter's value before this claim (the claim stands if it is below `chunks`) and `k` counts the
    // member's own claims before it. A team of two takes the list from its two ends, member 0 chunk k and member 1
    // chunk chunks - 1 - k, so that each keeps to one end of the list; as every claim that stands counts once, the two
    // never take the same chunk, and between them they take all. Any other team takes chunk `claim`.
    static size_t chunkOfClaim(size_t claim, size_t k, int member, int members, size_t chunks) {
        return members != 2 ? claim : member == 0 ? k : chunks - 1 - k;
    }
    // Inside a job (or alone, members 1): claims chunks of `chunk` items of [0, count) from `claimed`, a counter the
    // members share that starts at 0, until none is left, and calls range(begin, end) for each, the chunks placed by
    // chunkOfClaim().
    template <class Range>
    static void forEachClaimedChunk(std::atomic<size_t>& claimed, size_t count, size_t chunk, int member, int members,
                                    Range&& range) {
        const size_t chunks = (count + chunk - 1) / chunk;
        for (size_t k = 0;; ++k) {
            const size_t claim = claimed.fetch_add(1, std::memory_order_relaxed);
            if (claim >= chunks)
                break;
            const size_t at = chunkOfClaim(claim, k, member, members, chunks);
            range(at * chunk, std::min(count, (at + 1) * chunk));
        }
    }

private:
    void work(int member);
    // Spins briefly on a changing counter, then sleeps on it (a futex) until it differs from `seen`.
    static void awaitChange(const std::atomic<uint32_t>& counter, uint32_t seen);

    int m_size = 1;
    std::vector<std::thread> m_workers;
    const std::function<void(int)>* m_job = nullptr;
    int m_leaderCpu = -1; // the CPU member 0 ran on when it started the current job, or -1 (written with m_job)
    std::atomic<uint32_t> m_jobGeneration{0}; // advanced to start a job (or to stop)
    std::atomic<uint32_t> m_unfinished{0};    // workers still in the current job
    std::atomic<uint32_t> m_arrived{0};       // members at the current barrier
    std::atomic<uint32_t> m_barrierGeneration{0};
    std::atomic<bool> m_stop{false};
    // Written by member 0 only, on a cache line of its own, away from the counters the other members spin on.
    alignas(64) uint64_t m_leaderWaitNs = 0;
    uint64_t m_teamJobs = 0;
};

} // namespace rl
