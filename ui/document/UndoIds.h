// Merge ids of the editor's undo commands, in one place so that no two commands share an id by accident.
// Commands with the same id (and the same target) merge, so a spin-box drag becomes one undo step.
#pragma once

namespace rl {

enum UndoId {
    NoMergeId = -1,
    SetBodyNameId = 1,
    SetBodyAnchorId,
    SetBodyMaterialId,
    SetBodyDensityId,
    SetBodyMassId,
    SetBodyFrictionId,
    SetBodyRestitutionId,
    // Vector rows: X, Y, Z in a row, so that id + axis names one axis (editing X then Y stays two steps).
    SetBodyPositionId,
    SetBodyRotationId = SetBodyPositionId + 3,
    SetBodyVelocityId = SetBodyRotationId + 3,
    SetBodyAngularVelocityId = SetBodyVelocityId + 3,
};

} // namespace rl
