#include "world/CoreRoundTrip.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdint>
#include <thread>
#include <vector>

#if defined(__linux__)
#include <pthread.h>
#include <sched.h>
#endif

namespace rl {

#if defined(__linux__)

namespace {

using Clock = std::chrono::steady_clock;

// The counter the two threads pass back and forth, on a cache line of its own. The first thread writes odd values,
// the second answers with the next even one; kStop sends the second thread home.
struct alignas(64) Ball {
    std::atomic<uint32_t> value{0};
};
constexpr uint32_t kStop = UINT32_MAX;

bool pin(std::thread& thread, int cpu) {
    cpu_set_t set;
    CPU_ZERO(&set);
    CPU_SET(cpu, &set);
    return pthread_setaffinity_np(thread.native_handle(), sizeof(set), &set) == 0;
}

} // namespace

std::optional<double> measureCoreRoundTripNs(int rounds, int tripsPerRound) {
    if (rounds <= 0 || tripsPerRound <= 0)
        return std::nullopt;
    cpu_set_t allowed;
    CPU_ZERO(&allowed);
    if (sched_getaffinity(0, sizeof(allowed), &allowed) != 0)
        return std::nullopt;
    std::vector<int> cpus;
    for (int cpu = 0; cpu < CPU_SETSIZE && cpus.size() < 2; ++cpu)
        if (CPU_ISSET(cpu, &allowed))
            cpus.push_back(cpu);
    if (cpus.size() < 2)
        return std::nullopt;

    Ball ball;
    std::atomic<bool> pinned{false}, failed{false};
    const Clock::time_point deadline = Clock::now() + std::chrono::seconds(1);
    // Spins until `value` holds `want` (or kStop); false when the deadline passes or the other side gave up.
    const auto await = [&](uint32_t want) {
        for (uint32_t spins = 1;; ++spins) {
            const uint32_t v = ball.value.load(std::memory_order_acquire);
            if (v == want || v == kStop)
                return v == want;
            if (spins % 1024 == 0 && (failed.load(std::memory_order_relaxed) || Clock::now() > deadline)) {
                failed.store(true, std::memory_order_relaxed);
                return false;
            }
        }
    };
    std::vector<double> perTrip;
    const int total = rounds * tripsPerRound;
    std::thread answerer([&] {
        while (!pinned.load(std::memory_order_acquire))
            if (failed.load(std::memory_order_relaxed))
                return;
        for (int i = 0; i < total; ++i) {
            if (!await(2 * static_cast<uint32_t>(i) + 1))
                return;
            ball.value.store(2 * static_cast<uint32_t>(i) + 2, std::memory_order_release);
        }
    });
    std::thread asker([&] {
        while (!pinned.load(std::memory_order_acquire))
            if (failed.load(std::memory_order_relaxed))
                return;
        uint32_t next = 1;
        for (int r = 0; r < rounds; ++r) {
            const Clock::time_point start = Clock::now();
            for (int i = 0; i < tripsPerRound; ++i, next += 2) {
                ball.value.store(next, std::memory_order_release);
                if (!await(next + 1))
                    return;
            }
            perTrip.push_back(std::chrono::duration<double, std::nano>(Clock::now() - start).count() / tripsPerRound);
        }
    });
    if (!pin(asker, cpus[0]) || !pin(answerer, cpus[1]))
        failed.store(true, std::memory_order_relaxed);
    pinned.store(true, std::memory_order_release);
    asker.join();
    if (failed.load(std::memory_order_relaxed))
        ball.value.store(kStop, std::memory_order_release);
    answerer.join();
    if (failed.load(std::memory_order_relaxed) || perTrip.size() != static_cast<size_t>(rounds))
        return std::nullopt;
    std::sort(perTrip.begin(), perTrip.end());
    return perTrip[perTrip.size() / 2];
}

#else

std::optional<double> measureCoreRoundTripNs(int, int) {
    return std::nullopt;
}

#endif

} // namespace rl
