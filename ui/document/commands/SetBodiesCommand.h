// Undo command that replaces several body definitions at once: one undo step for an edit of a multi-selection.
// Consecutive edits of the same bodies with the same merge id merge; changes go through SceneDocument::setBody.
#pragma once

#include "scene/BodyDef.h"

#include <QList>
#include <QUndoCommand>

#include <vector>

namespace rl {

class SceneDocument;

class SetBodiesCommand : public QUndoCommand {
public:
    // indices and after have the same length; after[i] replaces body indices[i].
    SetBodiesCommand(SceneDocument* document, QList<int> indices, std::vector<BodyDef> after, const QString& text,
                     int mergeId = -1, QUndoCommand* parent = nullptr);

    void undo() override;
    void redo() override;
    int id() const override { return m_mergeId; }
    bool mergeWith(const QUndoCommand* other) override;

    const QList<int>& indices() const { return m_indices; }
    const std::vector<BodyDef>& after() const { return m_after; }

private:
    SceneDocument* m_document;
    QList<int> m_indices;
    std::vector<BodyDef> m_before;
    std::vector<BodyDef> m_after;
    int m_mergeId;
    int m_gesture; // the document's edit gesture at construction: merges stay within one
};

} // namespace rl
