#include "document/commands/TransformBodiesCommand.h"

#include "document/SceneDocument.h"

#include <QCoreApplication>

namespace rl {

namespace {
QString transformText(const SceneDocument* document, const QList<int>& indices, const RigidDelta& delta) {
    const bool turn = delta.rotation != glm::dquat(1.0, 0.0, 0.0, 0.0);
    if (indices.size() == 1) {
        const QString name = QString::fromStdString(document->body(indices.first()).name);
        return turn ? QCoreApplication::translate("rl::Commands", "Rotate %1").arg(name)
                    : QCoreApplication::translate("rl::Commands", "Move %1").arg(name);
    }
    const int n = static_cast<int>(indices.size());
    return turn ? QCoreApplication::translate("rl::Commands", "Rotate %n bodies", "", n)
                : QCoreApplication::translate("rl::Commands", "Move %n bodies", "", n);
}
} // namespace

std::vector<BodyDef> TransformBodiesCommand::moved(const SceneDocument* document, const QList<int>& indices,
                                                   const RigidDelta& delta) {
    std::vector<BodyDef> after;
    after.reserve(static_cast<size_t>(indices.size()));
    for (int index : indices) {
        BodyDef body = document->body(index);
        delta.applyToPose(body.position, body.orientation);
        after.push_back(std::move(body));
    }
    return after;
}

TransformBodiesCommand::TransformBodiesCommand(SceneDocument* document, QList<int> indices, const RigidDelta& delta,
                                               int mergeId, QUndoCommand* parent)
    : SetBodiesCommand(document, indices, moved(document, indices, delta), transformText(document, indices, delta),
                       mergeId, parent) {}

} // namespace rl
