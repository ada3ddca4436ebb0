// A background bake: steps a World into a Bake with core/world/Baker on its own std::thread, with a progress count
// the UI polls and a cancel flag. A cancelled bake keeps the frames it finished.
#pragma once

#include "bake/Bake.h"
#include "world/World.h"

#include <atomic>
#include <chrono>
#include <functional>
#include <thread>

namespace rl {

class BakeJob {
public:
    // `bake` already holds frame 0 (startBake); the simulation starts at `startFrame` (BakeRequest::startFrame).
    // `finished` is called on the worker thread at the end.
    BakeJob(World world, Bake bake, size_t frames, size_t startFrame, std::function<void()> finished);
    ~BakeJob(); // cancels and joins

    void cancel() { m_cancel.store(true); }
    bool isCancelRequested() const { return m_cancel.load(); }
    bool isFinished() const { return m_finished.load(); }
    size_t framesRequested() const { return m_frames; }
    size_t framesDone() const { return m_done.load(); }
    double elapsedSeconds() const;
    // Seconds left at the rate so far; negative before the first frame.
    double secondsLeft() const;

    // After isFinished(): joins the thread and hands over the bake (frame 0 + every frame done).
    Bake takeBake();
    bool wasCancelled() const { return m_cancelled; }

private:
    World m_world;
    Bake m_bake;
    size_t m_frames = 0;
    size_t m_startFrame = 0;
    std::function<void()> m_finishedCallback;
    std::chrono::steady_clock::time_point m_start;
    std::atomic<size_t> m_done{0};
    std::atomic<bool> m_cancel{false};
    std::atomic<bool> m_finished{false};
    bool m_cancelled = false;
    std::thread m_thread; // last: starts after every member above exists
};

} // namespace rl
