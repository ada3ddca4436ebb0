// Undo command that moves and turns several bodies by one rigid motion about a pivot: a gizmo drag or a modal
// grab/rotate, pushed once when the drag ends, so that the whole drag is one undo step.
#pragma once

#include "document/commands/SetBodiesCommand.h"
#include "viewport/Gizmo.h"

namespace rl {

class TransformBodiesCommand : public SetBodiesCommand {
public:
    // The text says Move or Rotate and what. mergeId -1 never merges; DuplicateBodiesCommand::kMergeId folds the
    // move that follows a duplicate into the duplicate's step.
    TransformBodiesCommand(SceneDocument* document, QList<int> indices, const RigidDelta& delta, int mergeId = -1,
                           QUndoCommand* parent = nullptr);

    // Definitions of the bodies after the motion (position and orientation only change).
    static std::vector<BodyDef> moved(const SceneDocument* document, const QList<int>& indices,
                                      const RigidDelta& delta);
};

} // namespace rl
