// A small baked scene shared by the bake, .bake and CSV tests: three OBJ objects (a flat anchor, a cube, a wedge)
// moving along closed-form paths, so every stored number has a known origin.
#pragma once

#include "bake/Bake.h"

#include <glm/gtc/quaternion.hpp>

#include <sstream>
#include <string>
#include <vector>

namespace rl::test {

inline const char* fixtureObjText() {
    return "# fixture scene\n"
           "mtllib none.mtl\n"
           "o Anchor.001\n"
           "v -2 0 -2\nv 2 0 -2\nv 2 0 2\nv -2 0 2\n"
           "f 1 2 3 4\n"
           "o Cube\n"
           "v 0 1 0\nv 1 1 0\nv 1 2 0\nv 0 2 0\nv 0 1 1\nv 1 1 1\nv 1 2 1\nv 0 2 1\n"
           "f 5 6 7 8\nf 9 10 11 12\nf 5 6 10 9\nf 6 7 11 10\nf 7 8 12 11\nf 8 5 9 12\n"
           "o Wedge Part\n"
           "v 3 1 0\nv 4 1 0\nv 3 2 0\nv 3 1 1.5\n"
           "f 13 14 15\nf 13 14 16\nf 13 15 16\nf 14 15 16\n";
}

// The vertex mean of each `o` block: the reference the original project used as the object position.
inline std::vector<Vec3> objVertexMeans(const std::string& objText) {
    std::vector<Vec3> sums;
    std::vector<int> counts;
    std::istringstream in(objText);
    std::string line;
    while (std::getline(in, line)) {
        if (line.rfind("o ", 0) == 0) {
            sums.emplace_back(0.0);
            counts.push_back(0);
        } else if (line.rfind("v ", 0) == 0 && !sums.empty()) {
            std::istringstream v(line.substr(2));
            Vec3 p;
            v >> p.x >> p.y >> p.z;
            sums.back() += p;
            ++counts.back();
        }
    }
    for (size_t i = 0; i < sums.size(); ++i)
        sums[i] /= static_cast<double>(counts[i]);
    return sums;
}

// Dynamic bodies fall from rest with a spin about a tilted axis; the anchor stays. The centre of mass is placed a
// little away from the vertex mean so that the offset matters.
inline Bake makeFixtureBake(size_t frames, double fps) {
    const std::vector<Vec3> means = objVertexMeans(fixtureObjText());
    const std::vector<std::string> names = {"Anchor.001", "Cube", "Wedge Part"};
    std::vector<BakeBodyInfo> infos(3);
    std::vector<Vec3> com0(3);
    for (size_t b = 0; b < 3; ++b) {
        infos[b].name = names[b];
        infos[b].anchor = b == 0;
        infos[b].vertexMeanOffset = Vec3(0.01 * double(b), -0.02 * double(b), 0.03 * double(b));
        com0[b] = means[b] - infos[b].vertexMeanOffset;
    }
    Bake bake(infos, fps);
    bake.setSceneObjText(fixtureObjText());
    const Vec3 g(0.0, -9.81, 0.0);
    for (size_t f = 0; f < frames; ++f) {
        bake.addFrame();
        const double t = bake.frameTime(f);
        for (size_t b = 0; b < 3; ++b) {
            BakeBodyState s;
            if (b == 0) {
                s.position = glm::vec3(com0[b]);
            } else {
                const Vec3 axis = glm::normalize(Vec3(0.3, 1.0, 0.2 * double(b)));
                const double w = 2.0 * double(b);
                s.position = glm::vec3(com0[b] + 0.5 * g * t * t);
                s.linearVelocity = glm::vec3(g * t);
                s.rotation = glm::quat(glm::angleAxis(w * t, axis));
                s.angularVelocity = glm::vec3(w * axis);
            }
            bake.setState(f, b, s);
        }
    }
    return bake;
}

// A bake of many bodies with no OBJ part, each moving and turning on its own, every number different: for the
// writers that split their output into blocks of frames (framesPerBlock()).
inline Bake makeMovingBake(size_t bodies, size_t frames) {
    std::vector<BakeBodyInfo> infos(bodies);
    for (size_t b = 0; b < bodies; ++b) {
        infos[b].name = "Body " + std::to_string(b) + (b % 5 == 0 ? ", quoted" : "");
        infos[b].anchor = b % 17 == 0;
        infos[b].vertexMeanOffset = Vec3(0.001 * double(b % 7), -0.002 * double(b % 3), 0.0);
    }
    Bake bake(std::move(infos), 60.0);
    bake.reserveFrames(frames);
    for (size_t f = 0; f < frames; ++f) {
        bake.addFrame();
        const double t = bake.frameTime(f);
        for (size_t b = 0; b < bodies; ++b) {
            const double k = 1.0 + 0.013 * double(b);
            BakeBodyState s;
            s.position = glm::vec3(Vec3(0.37 * double(b), 10.0 - 4.905 * t * t * k, std::sin(t * k)));
            s.linearVelocity = glm::vec3(Vec3(0.0, -9.81 * t * k, k * std::cos(t * k)));
            s.rotation = glm::quat(glm::angleAxis(k * t, glm::normalize(Vec3(0.2, 1.0, 0.1 * double(b % 4)))));
            s.angularVelocity = glm::vec3(Vec3(0.0, k, 0.0));
            bake.setState(f, b, s);
        }
    }
    return bake;
}

} // namespace rl::test
