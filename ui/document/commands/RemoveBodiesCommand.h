// Undo command that removes several bodies; undo puts each back at its old index with its exact definition.
// The document changes only through SceneDocument::removeBody and insertBody.
#pragma once

#include "scene/BodyDef.h"

#include <QList>
#include <QUndoCommand>

#include <vector>

namespace rl {

class SceneDocument;

class RemoveBodiesCommand : public QUndoCommand {
public:
    RemoveBodiesCommand(SceneDocument* document, QList<int> indices, QUndoCommand* parent = nullptr);

    void undo() override;
    void redo() override;

private:
    SceneDocument* m_document;
    QList<int> m_indices; // ascending, unique
    std::vector<BodyDef> m_bodies;
};

} // namespace rl
