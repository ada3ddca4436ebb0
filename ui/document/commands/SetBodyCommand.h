// Undo command that replaces one body definition; consecutive edits of the same body with the same merge id merge.
// The document changes only through SceneDocument::setBody, which emits bodyChanged.
#pragma once

#include "scene/BodyDef.h"

#include <QUndoCommand>

namespace rl {

class SceneDocument;

class SetBodyCommand : public QUndoCommand {
public:
    // mergeId is an rl::UndoId, or NoMergeId (-1) for an edit that never merges.
    SetBodyCommand(SceneDocument* document, int index, BodyDef after, const QString& text, int mergeId = -1,
                   QUndoCommand* parent = nullptr);

    void undo() override;
    void redo() override;
    int id() const override { return m_mergeId; }
    bool mergeWith(const QUndoCommand* other) override;

    int bodyIndex() const { return m_index; }

private:
    SceneDocument* m_document;
    int m_index;
    BodyDef m_before;
    BodyDef m_after;
    int m_mergeId;
    int m_gesture; // the document's edit gesture at construction: merges stay within one
};

} // namespace rl
