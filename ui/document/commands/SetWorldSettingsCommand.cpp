#include "document/commands/SetWorldSettingsCommand.h"

#include "document/SceneDocument.h"

namespace rl {

SetWorldSettingsCommand::SetWorldSettingsCommand(SceneDocument* document, WorldSettings after, const QString& text,
                                                 int mergeId, QUndoCommand* parent)
    : QUndoCommand(text, parent), m_document(document), m_before(document->scene().world), m_after(after),
      m_mergeId(mergeId), m_gesture(document->editGesture()) {}

void SetWorldSettingsCommand::undo() {
    m_document->setWorldSettings(m_before);
}

void SetWorldSettingsCommand::redo() {
    m_document->setWorldSettings(m_after);
}

bool SetWorldSettingsCommand::mergeWith(const QUndoCommand* other) {
    const auto* next = dynamic_cast<const SetWorldSettingsCommand*>(other);
    if (!next || next->m_document != m_document || next->m_gesture != m_gesture)
        return false;
    m_after = next->m_after;
    if (m_after == m_before)
        setObsolete(true);
    return true;
}

} // namespace rl
