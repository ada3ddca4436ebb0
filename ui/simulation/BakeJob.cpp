#include "simulation/BakeJob.h"

#include "world/Baker.h"

namespace rl {

BakeJob::BakeJob(World world, Bake bake, size_t frames, size_t startFrame, std::function<void()> finished)
    : m_world(std::move(world)), m_bake(std::move(bake)), m_frames(frames), m_startFrame(startFrame),
      m_finishedCallback(std::move(finished)), m_start(std::chrono::steady_clock::now()) {
    m_thread = std::thread([this] {
        BakeRequest request;
        request.frames = m_frames;
        request.startFrame = m_startFrame;
        request.diagnostics = true;
        request.progress = [this](size_t done, size_t) {
            m_done.store(done);
            return !m_cancel.load();
        };
        m_cancelled = !bakeRun(m_world, m_bake, request);
        m_finished.store(true);
        if (m_finishedCallback)
            m_finishedCallback();
    });
}

BakeJob::~BakeJob() {
    cancel();
    if (m_thread.joinable())
        m_thread.join();
}

double BakeJob::elapsedSeconds() const {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - m_start).count();
}

double BakeJob::secondsLeft() const {
    const size_t done = m_done.load();
    if (done == 0)
        return -1.0;
    return elapsedSeconds() / static_cast<double>(done) * static_cast<double>(m_frames - done);
}

Bake BakeJob::takeBake() {
    if (m_thread.joinable())
        m_thread.join();
    return std::move(m_bake);
}

} // namespace rl
