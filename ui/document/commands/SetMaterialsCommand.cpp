#include "document/commands/SetMaterialsCommand.h"

#include "document/SceneDocument.h"

namespace rl {

SetMaterialsCommand::SetMaterialsCommand(SceneDocument* document, std::vector<MaterialDef> after, const QString& text,
                                         int mergeId, const QString& mergeKey, QUndoCommand* parent)
    : QUndoCommand(text, parent), m_document(document), m_before(document->scene().materials),
      m_after(std::move(after)), m_mergeId(mergeId), m_gesture(document->editGesture()), m_mergeKey(mergeKey) {}

void SetMaterialsCommand::undo() {
    m_document->setMaterials(m_before);
}

void SetMaterialsCommand::redo() {
    m_document->setMaterials(m_after);
}

bool SetMaterialsCommand::mergeWith(const QUndoCommand* other) {
    const auto* next = dynamic_cast<const SetMaterialsCommand*>(other);
    if (!next || next->m_document != m_document || next->m_mergeKey != m_mergeKey || next->m_gesture != m_gesture)
        return false;
    m_after = next->m_after;
    if (m_after == m_before)
        setObsolete(true); // a drag that ends where it started leaves nothing to undo
    return true;
}

} // namespace rl
