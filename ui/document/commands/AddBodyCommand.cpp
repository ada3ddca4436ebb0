#include "document/commands/AddBodyCommand.h"

#include "document/SceneDocument.h"

#include <QCoreApplication>

namespace rl {

AddBodyCommand::AddBodyCommand(SceneDocument* document, int index, BodyDef body, QUndoCommand* parent)
    : QUndoCommand(parent), m_document(document), m_index(index), m_body(std::move(body)) {
    setText(QCoreApplication::translate("rl::Commands", "Add %1").arg(QString::fromStdString(m_body.name)));
}

void AddBodyCommand::undo() {
    m_document->removeBody(m_index);
}

void AddBodyCommand::redo() {
    m_document->insertBody(m_index, m_body);
}

} // namespace rl
