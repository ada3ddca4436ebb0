// Baked frames held compactly in memory: per frame and body the centre of mass, the rotation since frame 0 and the
// velocities as floats, with O(1) access to any frame, plus per-body info, per-frame diagnostics and the scene OBJ
// text.
#pragma once

#include "math/Types.h"

#include <glm/gtc/quaternion.hpp>

#include <array>
#include <cstddef>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace rl {

struct BakeBodyInfo {
    std::string name;
    bool anchor = false;
    // From the centre of mass to the body's vertex mean, in the body frame at frame 0 (so also in world axes at
    // frame 0). .bake files store the vertex mean (DESIGN.md §4); CSV and playback use the centre of mass.
    Vec3 vertexMeanOffset{0.0};

    bool operator==(const BakeBodyInfo&) const = default;
};

// The state of one body in one frame, as stored. Velocities are in world space, SI units.
struct BakeBodyState {
    glm::vec3 position{0.0f};                   // centre of mass, world
    glm::quat rotation{1.0f, 0.0f, 0.0f, 0.0f}; // since frame 0 (w, x, y, z); identity at frame 0
    glm::vec3 linearVelocity{0.0f};
    glm::vec3 angularVelocity{0.0f};
};

// Optional per-frame figures recorded by the baker for the timeline's diagnostic tracks.
enum class BakeDiagnostic { KineticEnergy, PotentialEnergy, MaxPenetration, ContactCount, AwakeBodies };
inline constexpr int kBakeDiagnosticCount = 5;
std::string_view bakeDiagnosticName(BakeDiagnostic d); // "kinetic_energy", "potential_energy", ...

class Bake {
public:
    Bake() = default;
    Bake(std::vector<BakeBodyInfo> bodies, double fps);

    double fps() const { return m_fps; }
    size_t bodyCount() const { return m_bodies.size(); }
    size_t frameCount() const { return m_frameCount; }
    double frameTime(size_t frame) const { return static_cast<double>(frame) / m_fps; }

    const std::vector<BakeBodyInfo>& bodies() const { return m_bodies; }
    // The frame at which the simulation started (BakeRequest::startFrame): the frames before it hold the initial
    // state. Our .bake carries it as start= in the header; CSV and the original project's format do not.
    size_t simulationStart() const { return m_simulationStart; }
    void setSimulationStart(size_t frame) { m_simulationStart = frame; }

    const BakeBodyInfo& body(size_t index) const { return m_bodies[index]; }
    BakeBodyInfo& body(size_t index) { return m_bodies[index]; }

    // The source scene as OBJ text; it travels into .bake files so that a bake can be replayed on its own.
    const std::string& sceneObjText() const { return m_sceneObjText; }
    void setSceneObjText(std::string text) { m_sceneObjText = std::move(text); }

    // Frames are appended in order. A new frame starts with every body at the origin with identity rotation and
    // zero velocity, and diagnostics at 0. reserveFrames avoids regrowing the arrays during a long bake.
    void reserveFrames(size_t frames);
    size_t addFrame();

    void setState(size_t frame, size_t body, const BakeBodyState& state);
    BakeBodyState state(size_t frame, size_t body) const;
    const glm::vec3& position(size_t frame, size_t body) const { return m_positions[index(frame, body)]; }
    const glm::quat& rotation(size_t frame, size_t body) const { return m_rotations[index(frame, body)]; }
    const glm::vec3& linearVelocity(size_t frame, size_t body) const { return m_linearVelocities[index(frame, body)]; }
    const glm::vec3& angularVelocity(size_t frame, size_t body) const {
        return m_angularVelocities[index(frame, body)];
    }

    // All bodies of one frame, contiguous: what playback uploads to the renderer.
    std::span<const glm::vec3> positions(size_t frame) const;
    std::span<const glm::quat> rotations(size_t frame) const;

    // World position of the body's vertex mean: centre of mass + R * offset (DESIGN.md §4), computed in double.
    Vec3 vertexMean(size_t frame, size_t body) const;

    // Sets a body's offset while keeping its vertex means where they are, moving the stored centre of mass instead.
    // A .bake file only knows vertex means; a caller that knows the geometry re-centres the bodies with this.
    void rebaseVertexMeanOffset(size_t body, const Vec3& offset);

    // .bake files carry no velocities; their readers clear this so that exporters can tell.
    bool hasVelocities() const { return m_hasVelocities; }
    void setHasVelocities(bool has) { m_hasVelocities = has; }

    // Diagnostics are off until enabled; enabling keeps any frames already added (at 0).
    bool hasDiagnostics() const { return m_hasDiagnostics; }
    void enableDiagnostics();
    void setDiagnostic(size_t frame, BakeDiagnostic d, float value) {
        m_diagnostics[static_cast<int>(d)][frame] = value;
    }
    float diagnostic(size_t frame, BakeDiagnostic d) const { return m_diagnostics[static_cast<int>(d)][frame]; }
    std::span<const float> diagnosticTrack(BakeDiagnostic d) const { return m_diagnostics[static_cast<int>(d)]; }

    // Bytes held by the frame arrays, for the UI's memory read-out and the budget checks of long bakes.
    size_t memoryBytes() const;

    bool operator==(const Bake&) const = default;

private:
    size_t index(size_t frame, size_t body) const { return frame * m_bodies.size() + body; }

    size_t m_simulationStart = 0;
    double m_fps = 60.0;
    std::vector<BakeBodyInfo> m_bodies;
    size_t m_frameCount = 0;
    // One contiguous array per quantity, indexed [frame * bodyCount + body].
    std::vector<glm::vec3> m_positions;
    std::vector<glm::quat> m_rotations;
    std::vector<glm::vec3> m_linearVelocities;
    std::vector<glm::vec3> m_angularVelocities;
    bool m_hasVelocities = true;
    bool m_hasDiagnostics = false;
    std::array<std::vector<float>, kBakeDiagnosticCount> m_diagnostics; // [frame] each, empty when disabled
    std::string m_sceneObjText;
};

} // namespace rl
