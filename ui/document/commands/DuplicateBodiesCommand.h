// Undo command that appends copies of several bodies (new names, optionally moved): Duplicate, one undo step.
// The copies go to the end of the scene, in the order of the originals.
#pragma once

#include "scene/BodyDef.h"

#include <QList>
#include <QUndoCommand>

#include <vector>

namespace rl {

class SceneDocument;

class DuplicateBodiesCommand : public QUndoCommand {
public:
    // copies are complete definitions (the caller names and places them); they are appended at bodyCount().
    DuplicateBodiesCommand(SceneDocument* document, std::vector<BodyDef> copies, QUndoCommand* parent = nullptr);

    void undo() override;
    void redo() override;
    // A SetBodiesCommand with this id over exactly the copies (the move that follows Shift+D) merges into this
    // step. Outside rl::UndoId's range so that no inspector edit can match it.
    static constexpr int kMergeId = 1000;
    int id() const override { return kMergeId; }
    bool mergeWith(const QUndoCommand* other) override;

    // Indices the copies have after redo().
    QList<int> copyIndices() const;

private:
    SceneDocument* m_document;
    int m_first;
    std::vector<BodyDef> m_copies;
};

} // namespace rl
