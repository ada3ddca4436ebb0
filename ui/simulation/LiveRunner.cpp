#include "simulation/LiveRunner.h"

#include <chrono>
#include <deque>

namespace rl {

using Clock = std::chrono::steady_clock;

LiveRunner::LiveRunner(World world, std::function<void()> published)
    : m_world(std::move(world)), m_published(std::move(published)) {
    m_fps = m_world.fps();
    m_initialCentres.resize(m_world.bodyCount());
    for (size_t i = 0; i < m_world.bodyCount(); ++i)
        m_initialCentres[i] = m_world.centerOfMass(i);
    m_thread = std::thread([this] { run(); });
}

LiveRunner::~LiveRunner() {
    {
        std::lock_guard lock(m_mutex);
        m_quit = true;
    }
    m_wake.notify_all();
    m_thread.join();
}

void LiveRunner::setPlaying(bool playing) {
    {
        std::lock_guard lock(m_mutex);
        m_playing.store(playing);
    }
    m_wake.notify_all();
}

void LiveRunner::requestStep() {
    {
        std::lock_guard lock(m_mutex);
        if (m_playing.load())
            return;
        ++m_pendingSteps;
    }
    m_wake.notify_all();
}

bool LiveRunner::takeSnapshot(LiveSnapshot& out) {
    std::lock_guard lock(m_snapshotMutex);
    m_notified.store(false);
    if (!m_fresh)
        return false;
    std::swap(out, m_ready);
    m_fresh = false;
    return true;
}

void LiveRunner::run() {
    const auto dt = std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(1.0 / m_fps));
    // Real-time pacing: frame k of a play stretch is due at start + k dt. A simulation that falls more than a
    // quarter second behind restarts the schedule instead of rushing to catch up.
    Clock::time_point due = Clock::now();
    bool wasPlaying = false;
    std::deque<Clock::time_point> recentSteps; // for steps per second
    for (;;) {
        bool playing = false;
        {
            std::unique_lock lock(m_mutex);
            m_wake.wait(lock, [this] { return m_quit || m_playing.load() || m_pendingSteps > 0; });
            if (m_quit)
                return;
            playing = m_playing.load();
            if (!playing)
                --m_pendingSteps;
            if (playing && !wasPlaying)
                due = Clock::now();
            wasPlaying = playing;
            if (playing) {
                // Wait for this frame's time; a pause or quit ends the wait early.
                if (m_wake.wait_until(lock, due, [this] { return m_quit || !m_playing.load(); }))
                    continue;
            }
        }
        m_world.step();
        const Clock::time_point now = Clock::now();
        if (playing) {
            due += dt;
            if (now - due > std::chrono::milliseconds(250))
                due = now;
        }
        recentSteps.push_back(now);
        while (!recentSteps.empty() && now - recentSteps.front() > std::chrono::seconds(1))
            recentSteps.pop_front();
        publish(playing ? static_cast<double>(recentSteps.size()) : 0.0);
    }
}

void LiveRunner::publish(double stepsPerSecond) {
    const size_t n = m_world.bodyCount();
    LiveSnapshot& s = m_back;
    s.frame = m_world.frame();
    s.time = m_world.time();
    s.stepsPerSecond = stepsPerSecond;
    s.centres.resize(n);
    s.rotations.resize(n);
    s.sleeping.resize(n);
    for (size_t i = 0; i < n; ++i) {
        s.centres[i] = m_world.centerOfMass(i);
        s.rotations[i] = m_world.rotationSinceStart(i);
        s.sleeping[i] = !m_world.isAnchor(i) && !m_world.isAwake(i);
    }
    const uint32_t extras = m_extras.load();
    s.linearVelocities.clear();
    if (extras & Velocities) {
        s.linearVelocities.resize(n);
        for (size_t i = 0; i < n; ++i)
            s.linearVelocities[i] = glm::vec3(m_world.linearVelocity(i));
    }
    s.contacts.clear();
    if (extras & Contacts) {
        for (const Manifold& m : m_world.manifolds())
            for (int p = 0; p < m.pointCount; ++p) {
                OverlayContact c;
                c.point = glm::vec3(m.points[p].position);
                c.normal = glm::vec3(m.normal);
                c.depth = static_cast<float>(std::max(Real(0), -m.points[p].separation));
                s.contacts.push_back(c);
            }
    }
    {
        std::lock_guard lock(m_snapshotMutex);
        std::swap(m_back, m_ready);
        m_fresh = true;
    }
    if (!m_notified.exchange(true) && m_published)
        m_published();
}

} // namespace rl
