// The live simulation's worker: owns a World on its own std::thread and steps it at its fixed dt in real time (or
// one frame on request), independent of the display. After each step it publishes a snapshot of what the viewport
// and the overlays need; the UI takes the newest one when it gets round to it, so a slow display skips states and a
// slow simulation just runs slower than real time.
#pragma once

#include "overlays/OverlayFrame.h"
#include "world/World.h"

#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

namespace rl {

struct LiveSnapshot {
    int64_t frame = 0;
    double time = 0.0;           // simulated seconds
    double stepsPerSecond = 0.0; // steps in the last wall-clock second
    std::vector<Vec3> centres;   // centre of mass per body
    std::vector<Quat> rotations; // since frame 0
    std::vector<uint8_t> sleeping;
    // Only when asked for (see LiveRunner::setExtras).
    std::vector<glm::vec3> linearVelocities;
    std::vector<OverlayContact> contacts;
};

class LiveRunner {
public:
    enum Extra : uint32_t { Velocities = 1u << 0, Contacts = 1u << 1 };

    // Takes the world (built by the caller, so that errors surface there). `published` is called on the worker
    // thread when a snapshot is ready and the previous one has been taken: queue a call to the UI thread in it.
    LiveRunner(World world, std::function<void()> published);
    ~LiveRunner(); // stops the thread (after its current step)

    void setPlaying(bool playing);
    bool isPlaying() const { return m_playing.load(); }
    // One more frame; ignored while playing.
    void requestStep();
    // What the snapshots should carry besides poses (Extra bits).
    void setExtras(uint32_t extras) { m_extras.store(extras); }

    // Swaps the newest snapshot into `out`; false when none arrived since the last call.
    bool takeSnapshot(LiveSnapshot& out);
    // The reference centres (frame 0), for the pose mapping.
    const std::vector<Vec3>& initialCentres() const { return m_initialCentres; }
    double fps() const { return m_fps; }

private:
    void run();
    void publish(double stepsPerSecond);

    World m_world;
    std::function<void()> m_published;
    std::vector<Vec3> m_initialCentres;
    double m_fps = 60.0;

    std::mutex m_mutex; // guards the control fields below
    std::condition_variable m_wake;
    bool m_quit = false;
    int m_pendingSteps = 0;
    std::atomic<bool> m_playing{false};
    std::atomic<uint32_t> m_extras{0};

    std::mutex m_snapshotMutex;
    LiveSnapshot m_back, m_ready;
    bool m_fresh = false;
    std::atomic<bool> m_notified{false};

    std::thread m_thread; // last: starts after every member above exists
};

} // namespace rl
