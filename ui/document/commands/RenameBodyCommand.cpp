#include "document/commands/RenameBodyCommand.h"

#include "document/SceneDocument.h"
#include "document/UndoIds.h"

#include <QCoreApplication>

namespace rl {

namespace {
BodyDef renamed(const SceneDocument* document, int index, const QString& name) {
    BodyDef body = document->body(index);
    body.name = name.toStdString();
    return body;
}
} // namespace

RenameBodyCommand::RenameBodyCommand(SceneDocument* document, int index, const QString& name, QUndoCommand* parent)
    : SetBodyCommand(document, index, renamed(document, index, name),
                     QCoreApplication::translate("rl::Commands", "Rename %1 to %2")
                         .arg(QString::fromStdString(document->body(index).name), name),
                     SetBodyNameId, parent) {}

} // namespace rl
