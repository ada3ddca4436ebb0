// Undo command that replaces the scene's world settings (gravity, stepping, integrator, damping, combine rules,
// effects). Consecutive edits with the same merge id merge, so a spin-box drag of one field is one undo step.
// The document changes only through SceneDocument::setWorldSettings.
#pragma once

#include "scene/WorldSettings.h"

#include <QUndoCommand>

namespace rl {

class SceneDocument;

// Merge ids of the world settings edits. They belong in ui/document/UndoIds.h (owned elsewhere); until they move
// there they sit far above that enum's values. Gravity is a row X, Y, Z: id + axis names one axis.
enum WorldUndoId {
    SetWorldGravityId = 1100,
    SetWorldFpsId = SetWorldGravityId + 3,
    SetWorldSubstepsId,
    SetWorldIterationsId,
    SetWorldLinearDampingId,
    SetWorldAngularDampingId,
};

class SetWorldSettingsCommand : public QUndoCommand {
public:
    SetWorldSettingsCommand(SceneDocument* document, WorldSettings after, const QString& text, int mergeId = -1,
                            QUndoCommand* parent = nullptr);

    void undo() override;
    void redo() override;
    int id() const override { return m_mergeId; }
    bool mergeWith(const QUndoCommand* other) override;

private:
    SceneDocument* m_document;
    WorldSettings m_before;
    WorldSettings m_after;
    int m_mergeId;
    int m_gesture; // the document's edit gesture at construction: merges stay within one
};

} // namespace rl
