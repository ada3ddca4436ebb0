#include "document/commands/SetBodyCommand.h"

#include "document/SceneDocument.h"

namespace rl {

SetBodyCommand::SetBodyCommand(SceneDocument* document, int index, BodyDef after, const QString& text, int mergeId,
                               QUndoCommand* parent)
    : QUndoCommand(text, parent), m_document(document), m_index(index), m_before(document->body(index)),
      m_after(std::move(after)), m_mergeId(mergeId), m_gesture(document->editGesture()) {}

void SetBodyCommand::undo() {
    m_document->setBody(m_index, m_before);
}

void SetBodyCommand::redo() {
    m_document->setBody(m_index, m_after);
}

bool SetBodyCommand::mergeWith(const QUndoCommand* other) {
    const auto* next = dynamic_cast<const SetBodyCommand*>(other);
    if (!next || next->m_document != m_document || next->m_index != m_index || next->m_gesture != m_gesture)
        return false;
    m_after = next->m_after;
    // An edit that ends where it started leaves nothing to undo.
    if (m_after == m_before)
        setObsolete(true);
    return true;
}

} // namespace rl
