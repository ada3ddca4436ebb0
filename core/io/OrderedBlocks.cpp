#include "io/OrderedBlocks.h"

#include <algorithm>
#include <condition_variable>
#include <exception>
#include <mutex>
#include <optional>
#include <thread>
#include <vector>

namespace rl {

bool writeBlocksInOrder(size_t count, int threads, const std::function<void(size_t block, std::string& text)>& format,
                        const std::function<bool(const std::string& text)>& write) {
    constexpr int kMaxThreads = 64; // as the world's team (World::create())
    const size_t formatters = std::min(static_cast<size_t>(std::clamp(threads, 1, kMaxThreads)), count);
    if (formatters <= 1) {
        std::string text;
        for (size_t block = 0; block < count; ++block) {
            text.clear();
            format(block, text);
            if (!write(text))
                return false;
        }
        return true;
    }

    // A ring of slots: block k is formatted into slot k % slots, and only once block k - slots has been written out
    // of it. The calling thread writes each block as soon as it is its turn and formats blocks in between; the other
    // threads only format. (With the caller only writing and `threads` others formatting, two threads on two cores
    // wrote ramps.obj's 600-frame CSV 1.4-1.6 times as fast as one, 2026-12-04: the writer's copies into the
    // stream took a core's time from the formatting.) Blocks are large (framesPerBlock()), so one lock per hand-over
    // is nothing to save.
    const size_t slots = 2 * formatters;
    // Each slot's string on a cache line of its own: every append writes the string's size, and two threads
    // appending to neighbouring strings fought over one line (each thread then took 1.5 times as long for a block).
    struct alignas(64) Slot {
        std::string text;
    };
    std::vector<Slot> texts(slots);
    std::vector<char> ready(slots, 0);
    size_t nextBlock = 0; // the next block to format
    size_t written = 0;   // blocks written so far
    bool stop = false;
    bool cancelled = false; // a write() returned false
    // A format() that throws for block k ends the output as on one thread: blocks 0 .. k - 1 are still written, in
    // order, and nothing after. Of several failing blocks the lowest one's exception is the one rethrown.
    size_t failedBlock = count;
    std::exception_ptr failure; // the exception of a format() (block failedBlock) or of write(), rethrown at the end
    std::mutex mutex;
    std::condition_variable changed;

    // Under the lock: the next block to format, if its slot is free, else none.
    const auto claim = [&]() -> std::optional<size_t> {
        if (stop || nextBlock >= failedBlock || nextBlock >= written + slots)
            return std::nullopt;
        return nextBlock++;
    };
    // Outside the lock: formats the claimed block into its slot and marks it ready (or records the failure).
    const auto formatBlock = [&](size_t block) {
        std::string& text = texts[block % slots].text;
        text.clear();
        std::exception_ptr error;
        try {
            format(block, text);
        } catch (...) {
            error = std::current_exception();
        }
        {
            std::lock_guard lock(mutex);
            ready[block % slots] = 1;
            if (error && block < failedBlock) {
                failedBlock = block;
                failure = error;
            }
        }
        changed.notify_all();
    };
    const auto work = [&] {
        for (;;) {
            std::optional<size_t> block;
            {
                std::unique_lock lock(mutex);
                changed.wait(lock, [&] { return stop || nextBlock >= failedBlock || nextBlock < written + slots; });
                block = claim();
                if (!block)
                    return;
            }
            formatBlock(*block);
        }
    };
    std::vector<std::thread> team;
    team.reserve(formatters - 1);
    for (size_t w = 1; w < formatters; ++w)
        team.emplace_back(work);

    for (;;) {
        std::optional<size_t> block;
        {
            std::unique_lock lock(mutex);
            if (stop || written == failedBlock)
                break;
            if (!ready[written % slots]) {
                block = claim();
                if (!block) {
                    changed.wait(lock, [&] { return stop || ready[written % slots] != 0; });
                    continue;
                }
            }
        }
        if (block) {
            formatBlock(*block);
            continue;
        }
        // The slot is this thread's until it is marked free: no worker touches it before.
        const size_t slot = written % slots;
        bool ok = false;
        std::exception_ptr error;
        try {
            ok = write(texts[slot].text);
        } catch (...) {
            error = std::current_exception();
        }
        {
            std::lock_guard lock(mutex);
            ready[slot] = 0;
            ++written;
            if (error)
                failure = error; // a format() failure is of a later block, not yet written: this one comes first
            cancelled = cancelled || !ok;
            stop = stop || !ok; // (ok stays false where write() threw)
        }
        changed.notify_all();
    }
    const bool completed = written == count && !cancelled;
    {
        // Cancelled or failed: the workers stop at their next block.
        std::lock_guard lock(mutex);
        stop = true;
    }
    changed.notify_all();
    for (std::thread& t : team)
        t.join();
    if (failure)
        std::rethrow_exception(failure);
    return completed;
}

size_t framesPerBlock(size_t bodies) {
    constexpr size_t kLinesPerBlock = 8192;
    return std::max<size_t>(1, kLinesPerBlock / std::max<size_t>(bodies, 1));
}

} // namespace rl
