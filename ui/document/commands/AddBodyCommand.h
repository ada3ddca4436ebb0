// Undo command that inserts one body definition at an index (append with index == bodyCount()).
// The document changes only through SceneDocument::insertBody and removeBody.
#pragma once

#include "scene/BodyDef.h"

#include <QUndoCommand>

namespace rl {

class SceneDocument;

class AddBodyCommand : public QUndoCommand {
public:
    AddBodyCommand(SceneDocument* document, int index, BodyDef body, QUndoCommand* parent = nullptr);

    void undo() override;
    void redo() override;

private:
    SceneDocument* m_document;
    int m_index;
    BodyDef m_body;
};

} // namespace rl
