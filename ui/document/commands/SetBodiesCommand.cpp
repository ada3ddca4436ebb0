#include "document/commands/SetBodiesCommand.h"

#include "document/SceneDocument.h"

namespace rl {

SetBodiesCommand::SetBodiesCommand(SceneDocument* document, QList<int> indices, std::vector<BodyDef> after,
                                   const QString& text, int mergeId, QUndoCommand* parent)
    : QUndoCommand(text, parent), m_document(document), m_indices(std::move(indices)), m_after(std::move(after)),
      m_mergeId(mergeId), m_gesture(document->editGesture()) {
    Q_ASSERT(static_cast<size_t>(m_indices.size()) == m_after.size());
    for (int index : m_indices)
        m_before.push_back(document->body(index));
}

void SetBodiesCommand::undo() {
    for (qsizetype i = 0; i < m_indices.size(); ++i)
        m_document->setBody(m_indices[i], m_before[static_cast<size_t>(i)]);
}

void SetBodiesCommand::redo() {
    for (qsizetype i = 0; i < m_indices.size(); ++i)
        m_document->setBody(m_indices[i], m_after[static_cast<size_t>(i)]);
}

bool SetBodiesCommand::mergeWith(const QUndoCommand* other) {
    const auto* next = dynamic_cast<const SetBodiesCommand*>(other);
    if (!next || next->m_document != m_document || next->m_indices != m_indices || next->m_gesture != m_gesture)
        return false;
    m_after = next->m_after;
    if (m_after == m_before)
        setObsolete(true);
    return true;
}

} // namespace rl
