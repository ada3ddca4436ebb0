// Debian's Bullet (libbullet-dev) stepping the same scene as RigidLab, so that `rigidlab-cli bench` and
// tests/benchmarks/bench_world can print RigidLab's cost as a ratio to Bullet's from one run on one machine.
// Without libbullet-dev at configure time, create() says so and the benchmarks print RigidLab's figures only.
#pragma once

#include "scene/Scene.h"

#include <memory>
#include <string>

namespace rl::bench {

class BulletReference {
public:
    // True when this build links Bullet.
    static bool available();
    // "Bullet 3.24 (float), btDbvtBroadphase + btSequentialImpulseConstraintSolver, 10 iterations", or why not.
    static std::string description();

    // Builds the scene in Bullet: Box -> btBoxShape, Sphere -> btSphereShape, Hull/Mesh -> btConvexHullShape of
    // RigidLab's collision hull about the centre of mass (hull against hull, as in RigidLab); anchors are static;
    // each body's friction and restitution come from its effective material, combined by the scene's rules;
    // Bullet's own defaults otherwise (margins, 10 solver iterations, sleeping). keepAwake disables deactivation.
    // Returns null and sets *error when a body cannot be built or Bullet is not available.
    static std::unique_ptr<BulletReference> create(const Scene& scene, bool keepAwake, std::string* error);
    ~BulletReference();
    BulletReference(const BulletReference&) = delete;
    BulletReference& operator=(const BulletReference&) = delete;

    // One step of 1/fps with exactly one internal step (stepSimulation(dt, 0)).
    void step();
    int awakeBodies() const;
    int contactPoints() const;      // manifold points at or below zero distance
    double highestDynamicY() const; // highest centre of mass of a dynamic body: shows whether a tower stands

private:
    BulletReference();
    struct Impl;
    std::unique_ptr<Impl> m;
};

} // namespace rl::bench
