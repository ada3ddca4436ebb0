#include "bake/Bake.h"

namespace rl {

std::string_view bakeDiagnosticName(BakeDiagnostic d) {
    static constexpr std::string_view kNames[kBakeDiagnosticCount] = {
        "kinetic_energy", "potential_energy", "max_penetration", "contact_count", "awake_bodies"};
    return kNames[static_cast<int>(d)];
}

Bake::Bake(std::vector<BakeBodyInfo> bodies, double fps) : m_fps(fps), m_bodies(std::move(bodies)) {}

void Bake::reserveFrames(size_t frames) {
    const size_t n = frames * m_bodies.size();
    m_positions.reserve(n);
    m_rotations.reserve(n);
    m_linearVelocities.reserve(n);
    m_angularVelocities.reserve(n);
    if (m_hasDiagnostics)
        for (std::vector<float>& track : m_diagnostics)
            track.reserve(frames);
}

size_t Bake::addFrame() {
    const size_t n = (m_frameCount + 1) * m_bodies.size();
    m_positions.resize(n, glm::vec3(0.0f));
    m_rotations.resize(n, glm::quat(1.0f, 0.0f, 0.0f, 0.0f));
    m_linearVelocities.resize(n, glm::vec3(0.0f));
    m_angularVelocities.resize(n, glm::vec3(0.0f));
    if (m_hasDiagnostics)
        for (std::vector<float>& track : m_diagnostics)
            track.push_back(0.0f);
    return m_frameCount++;
}

void Bake::setState(size_t frame, size_t body, const BakeBodyState& state) {
    const size_t i = index(frame, body);
    m_positions[i] = state.position;
    m_rotations[i] = state.rotation;
    m_linearVelocities[i] = state.linearVelocity;
    m_angularVelocities[i] = state.angularVelocity;
}

BakeBodyState Bake::state(size_t frame, size_t body) const {
    const size_t i = index(frame, body);
    return {m_positions[i], m_rotations[i], m_linearVelocities[i], m_angularVelocities[i]};
}

std::span<const glm::vec3> Bake::positions(size_t frame) const {
    return std::span<const glm::vec3>(m_positions).subspan(frame * m_bodies.size(), m_bodies.size());
}

std::span<const glm::quat> Bake::rotations(size_t frame) const {
    return std::span<const glm::quat>(m_rotations).subspan(frame * m_bodies.size(), m_bodies.size());
}

Vec3 Bake::vertexMean(size_t frame, size_t body) const {
    const size_t i = index(frame, body);
    return Vec3(m_positions[i]) + Quat(m_rotations[i]) * m_bodies[body].vertexMeanOffset;
}

void Bake::rebaseVertexMeanOffset(size_t body, const Vec3& offset) {
    for (size_t f = 0; f < m_frameCount; ++f) {
        const size_t i = index(f, body);
        const Vec3 mean = vertexMean(f, body);
        m_positions[i] = glm::vec3(mean - Quat(m_rotations[i]) * offset);
    }
    m_bodies[body].vertexMeanOffset = offset;
}

void Bake::enableDiagnostics() {
    if (m_hasDiagnostics)
        return;
    m_hasDiagnostics = true;
    for (std::vector<float>& track : m_diagnostics)
        track.assign(m_frameCount, 0.0f);
}

size_t Bake::memoryBytes() const {
    size_t bytes = m_positions.capacity() * sizeof(glm::vec3) + m_rotations.capacity() * sizeof(glm::quat) +
                   m_linearVelocities.capacity() * sizeof(glm::vec3) +
                   m_angularVelocities.capacity() * sizeof(glm::vec3);
    for (const std::vector<float>& track : m_diagnostics)
        bytes += track.capacity() * sizeof(float);
    return bytes + m_sceneObjText.capacity();
}

} // namespace rl
