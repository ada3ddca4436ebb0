#include "document/commands/DuplicateBodiesCommand.h"

#include "document/SceneDocument.h"
#include "document/commands/SetBodiesCommand.h"

#include <QCoreApplication>

namespace rl {

DuplicateBodiesCommand::DuplicateBodiesCommand(SceneDocument* document, std::vector<BodyDef> copies,
                                               QUndoCommand* parent)
    : QUndoCommand(parent), m_document(document), m_first(document->bodyCount()), m_copies(std::move(copies)) {
    if (m_copies.size() == 1)
        setText(QCoreApplication::translate("rl::Commands", "Duplicate as %1")
                    .arg(QString::fromStdString(m_copies.front().name)));
    else
        setText(
            QCoreApplication::translate("rl::Commands", "Duplicate %n bodies", "", static_cast<int>(m_copies.size())));
}

// One change signal for all copies: the views rebuild once, not once per copy.
void DuplicateBodiesCommand::redo() {
    m_document->insertBodies(m_first, m_copies);
}

void DuplicateBodiesCommand::undo() {
    m_document->removeBodies(m_first, static_cast<int>(m_copies.size()));
}

bool DuplicateBodiesCommand::mergeWith(const QUndoCommand* other) {
    const auto* move = dynamic_cast<const SetBodiesCommand*>(other);
    if (!move || move->indices() != copyIndices() || move->after().size() != m_copies.size())
        return false;
    // The copies are now where the move left them: redo inserts them there, undo removes them.
    m_copies = move->after();
    return true;
}

QList<int> DuplicateBodiesCommand::copyIndices() const {
    QList<int> indices;
    for (size_t i = 0; i < m_copies.size(); ++i)
        indices.append(m_first + static_cast<int>(i));
    return indices;
}

} // namespace rl
