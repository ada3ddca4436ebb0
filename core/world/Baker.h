// Records a run: steps a World frame by frame into a Bake (frame 0 is the initial state), with diagnostics,
// progress reports and cancellation. The CLI's bake command and the editor's background bake both use it.
#pragma once

#include "bake/Bake.h"
#include "world/World.h"

#include <functional>

namespace rl {

struct BakeRequest {
    size_t frames = 600; // frames after frame 0; the bake holds frames + 1
    // The simulation starts at this frame, as Blender's rigid-body cache starts at its start frame: frames
    // 1 .. startFrame repeat the initial state (the world is not stepped), and the run covers the frames after it.
    // At or beyond `frames`, every frame holds the initial state.
    size_t startFrame = 0;
    bool diagnostics = true; // record the per-frame diagnostic tracks
    // Called after each frame with (frames done, frames requested); returning false cancels and keeps what is done.
    std::function<bool(size_t, size_t)> progress;
};

// Body info and frame 0 of a bake for the world's current state.
Bake startBake(const World& world, bool diagnostics = true);
// Appends the world's current state as the next frame; parallelFor (World::betweenStepsParallelFor()), if given,
// shares the bodies out. The frame is the same either way.
void recordFrame(const World& world, Bake& bake, const ContactSolver::ParallelFor& parallelFor = {});
// Steps the world `frames` times, recording each frame. Returns false when cancelled (the bake keeps its frames).
bool bakeRun(World& world, Bake& bake, const BakeRequest& request);

} // namespace rl
