#include "document/commands/RemoveBodiesCommand.h"

#include "document/SceneDocument.h"

#include <QCoreApplication>

#include <algorithm>

namespace rl {

RemoveBodiesCommand::RemoveBodiesCommand(SceneDocument* document, QList<int> indices, QUndoCommand* parent)
    : QUndoCommand(parent), m_document(document), m_indices(std::move(indices)) {
    std::sort(m_indices.begin(), m_indices.end());
    m_indices.erase(std::unique(m_indices.begin(), m_indices.end()), m_indices.end());
    for (int index : m_indices)
        m_bodies.push_back(document->body(index));
    if (m_indices.size() == 1)
        setText(QCoreApplication::translate("rl::Commands", "Delete %1").arg(QString::fromStdString(m_bodies[0].name)));
    else
        setText(
            QCoreApplication::translate("rl::Commands", "Delete %n bodies", "", static_cast<int>(m_indices.size())));
}

void RemoveBodiesCommand::redo() {
    // Highest index first, so the lower indices stay valid.
    for (qsizetype i = m_indices.size() - 1; i >= 0; --i)
        m_document->removeBody(m_indices[i]);
}

void RemoveBodiesCommand::undo() {
    for (qsizetype i = 0; i < m_indices.size(); ++i)
        m_document->insertBody(m_indices[i], m_bodies[static_cast<size_t>(i)]);
}

} // namespace rl
