#include "world/Baker.h"

namespace rl {

Bake startBake(const World& world, bool diagnostics) {
    std::vector<BakeBodyInfo> infos(world.bodyCount());
    for (size_t i = 0; i < world.bodyCount(); ++i) {
        infos[i].name = world.name(i);
        infos[i].anchor = world.isAnchor(i);
        infos[i].vertexMeanOffset = world.vertexMeanOffset(i);
    }
    Bake bake(std::move(infos), world.fps());
    if (diagnostics)
        bake.enableDiagnostics();
    recordFrame(world, bake);
    return bake;
}

void recordFrame(const World& world, Bake& bake, const ContactSolver::ParallelFor& parallelFor) {
    const size_t frame = bake.addFrame();
    // Each body's entry alone, so the frame is the same on any number of threads.
    shareOut(parallelFor, world.bodyCount(), [&](size_t begin, size_t end) {
        for (size_t i = begin; i < end; ++i) {
            BakeBodyState s;
            s.position = glm::vec3(world.centerOfMass(i));
            s.rotation = glm::quat(world.rotationSinceStart(i));
            s.linearVelocity = glm::vec3(world.linearVelocity(i));
            s.angularVelocity = glm::vec3(world.angularVelocity(i));
            bake.setState(frame, i, s);
        }
    });
    if (bake.hasDiagnostics()) {
        const FrameDiagnostics d = world.diagnostics();
        bake.setDiagnostic(frame, BakeDiagnostic::KineticEnergy, static_cast<float>(d.kineticEnergy));
        bake.setDiagnostic(frame, BakeDiagnostic::PotentialEnergy, static_cast<float>(d.potentialEnergy));
        bake.setDiagnostic(frame, BakeDiagnostic::MaxPenetration, static_cast<float>(d.maxPenetration));
        bake.setDiagnostic(frame, BakeDiagnostic::ContactCount, static_cast<float>(d.contactPoints));
        bake.setDiagnostic(frame, BakeDiagnostic::AwakeBodies, static_cast<float>(d.awakeBodies));
    }
}

bool bakeRun(World& world, Bake& bake, const BakeRequest& request) {
    bake.reserveFrames(bake.frameCount() + request.frames);
    if (bake.frameCount() == 1)
        bake.setSimulationStart(request.startFrame);
    for (size_t f = 0; f < request.frames; ++f) {
        if (bake.frameCount() > request.startFrame)
            world.step();
        {
            StageTimer t(world.mutableProfile(), Stage::StoreFrame);
            recordFrame(world, bake, world.betweenStepsParallelFor(world.bodyCount()));
        }
        if (request.progress && !request.progress(f + 1, request.frames))
            return false;
    }
    return true;
}

} // namespace rl
