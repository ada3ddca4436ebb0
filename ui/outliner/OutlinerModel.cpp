#include "outliner/OutlinerModel.h"

#include "document/SceneDocument.h"
#include "document/UndoIds.h"
#include "document/commands/SetBodyCommand.h"

#include <QPainter>
#include <QPixmap>

namespace rl {

namespace {

// Small generated icons, so the outliner needs no image files: a grey square for anchors, an orange cube for
// dynamic bodies (the colours the viewport uses).
QIcon makeIcon(const QColor& fill, bool anchor) {
    QPixmap pixmap(16, 16);
    pixmap.fill(Qt::transparent);
    QPainter p(&pixmap);
    p.setRenderHint(QPainter::Antialiasing);
    p.setPen(QPen(fill.darker(160), 1));
    p.setBrush(fill);
    if (anchor) {
        p.drawRect(QRectF(1.5, 9.5, 13, 4));
        p.drawLine(QPointF(8, 2), QPointF(8, 9));
        p.drawEllipse(QPointF(8, 3.5), 2, 2);
    } else {
        const QPointF front[] = {{2.5, 5.5}, {10.5, 5.5}, {10.5, 13.5}, {2.5, 13.5}};
        const QPointF top[] = {{2.5, 5.5}, {5.5, 2.5}, {13.5, 2.5}, {10.5, 5.5}};
        const QPointF side[] = {{10.5, 5.5}, {13.5, 2.5}, {13.5, 10.5}, {10.5, 13.5}};
        p.drawPolygon(front, 4);
        p.setBrush(fill.lighter(130));
        p.drawPolygon(top, 4);
        p.setBrush(fill.darker(120));
        p.drawPolygon(side, 4);
    }
    return QIcon(pixmap);
}

// The anchor column's toggle: a pin, solid when the body is anchored, a faint outline when it is not.
QIcon makePinIcon(bool on) {
    QPixmap pixmap(16, 16);
    pixmap.fill(Qt::transparent);
    QPainter p(&pixmap);
    p.setRenderHint(QPainter::Antialiasing);
    // A mid blue reads on light and dark palettes alike; the dynamic state is a faint grey outline.
    const QColor colour = on ? QColor(52, 120, 200) : QColor(128, 128, 128, 110);
    p.setPen(QPen(colour, 1.4, Qt::SolidLine, Qt::RoundCap));
    p.setBrush(on ? colour : Qt::transparent);
    p.drawEllipse(QPointF(8, 5), 3.2, 3.2);
    p.drawLine(QPointF(8, 8.5), QPointF(8, 14.5));
    p.drawLine(QPointF(4.5, 10), QPointF(11.5, 10));
    return QIcon(pixmap);
}

} // namespace

OutlinerModel::OutlinerModel(SceneDocument* document, QObject* parent)
    : QAbstractItemModel(parent), m_document(document), m_anchorIcon(makeIcon(QColor(150, 150, 150), true)),
      m_dynamicIcon(makeIcon(QColor(232, 140, 60), false)), m_pinIcon(makePinIcon(true)),
      m_pinOffIcon(makePinIcon(false)) {
    connect(document, &SceneDocument::sceneReset, this, [this] {
        beginResetModel();
        endResetModel();
    });
    connect(document, &SceneDocument::bodyChanged, this,
            [this](int row) { emit dataChanged(index(row, 0), index(row, ColumnCount - 1)); });
    // Documents emit after they changed; a reset is the simple correct answer for inserts and removals.
    connect(document, &SceneDocument::bodyInserted, this, [this] {
        beginResetModel();
        endResetModel();
    });
    connect(document, &SceneDocument::bodyRemoved, this, [this] {
        beginResetModel();
        endResetModel();
    });
}

QModelIndex OutlinerModel::index(int row, int column, const QModelIndex& parent) const {
    if (!hasIndex(row, column, parent))
        return {};
    return createIndex(row, column);
}

QModelIndex OutlinerModel::parent(const QModelIndex&) const {
    return {};
}

int OutlinerModel::rowCount(const QModelIndex& parent) const {
    return parent.isValid() ? 0 : m_document->bodyCount();
}

int OutlinerModel::columnCount(const QModelIndex& parent) const {
    return parent.isValid() ? 0 : ColumnCount;
}

QVariant OutlinerModel::data(const QModelIndex& index, int role) const {
    if (!index.isValid() || index.row() >= m_document->bodyCount())
        return {};
    const BodyDef& body = m_document->body(index.row());
    if (role == AnchorRole)
        return body.anchor;
    if (role == BodyIndexRole)
        return index.row();
    switch (index.column()) {
    case NameColumn:
        if (role == Qt::DisplayRole || role == Qt::EditRole)
            return QString::fromStdString(body.name);
        if (role == Qt::DecorationRole)
            return body.anchor ? m_anchorIcon : m_dynamicIcon;
        if (role == Qt::ToolTipRole)
            return body.anchor ? tr("%1 (anchor: static)").arg(QString::fromStdString(body.name))
                               : tr("%1 (dynamic)").arg(QString::fromStdString(body.name));
        break;
    case AnchorColumn:
        if (role == Qt::DecorationRole)
            return body.anchor ? m_pinIcon : m_pinOffIcon;
        if (role == Qt::ToolTipRole)
            return body.anchor ? tr("Anchored (static): click to make it dynamic") : tr("Dynamic: click to anchor it");
        if (role == Qt::AccessibleTextRole)
            return body.anchor ? tr("anchored") : tr("dynamic");
        break;
    case MaterialColumn:
        if (role == Qt::DisplayRole)
            return QString::fromStdString(body.material);
        break;
    default:
        break;
    }
    return {};
}

QVariant OutlinerModel::headerData(int section, Qt::Orientation orientation, int role) const {
    if (orientation != Qt::Horizontal)
        return {};
    if (section == AnchorColumn) {
        if (role == Qt::DecorationRole)
            return m_pinIcon;
        if (role == Qt::ToolTipRole)
            return tr("Anchor: click a row's pin to make that body static or dynamic");
        return {};
    }
    if (role != Qt::DisplayRole)
        return {};
    return section == NameColumn ? tr("Name") : tr("Material");
}

Qt::ItemFlags OutlinerModel::flags(const QModelIndex& index) const {
    if (!index.isValid())
        return Qt::NoItemFlags;
    Qt::ItemFlags f = Qt::ItemIsSelectable | Qt::ItemIsEnabled;
    if (index.column() == NameColumn)
        f |= Qt::ItemIsEditable;
    return f;
}

QString OutlinerModel::renameProblem(int row, const QString& name) const {
    const QString trimmed = name.trimmed();
    if (trimmed.isEmpty())
        return tr("A body needs a name.");
    const std::string wanted = trimmed.toStdString();
    for (int i = 0; i < m_document->bodyCount(); ++i)
        if (i != row && m_document->body(i).name == wanted)
            return tr("Another body is already called \"%1\". Names must be unique.").arg(trimmed);
    return {};
}

bool OutlinerModel::setData(const QModelIndex& index, const QVariant& value, int role) {
    if (!index.isValid() || index.column() != NameColumn || role != Qt::EditRole ||
        index.row() >= m_document->bodyCount())
        return false;
    const QString name = value.toString().trimmed();
    if (name.toStdString() == m_document->body(index.row()).name)
        return true; // unchanged: nothing to undo
    const QString problem = renameProblem(index.row(), name);
    if (!problem.isEmpty()) {
        emit renameRefused(problem);
        return false;
    }
    // A rename from the outliner is a step of its own (NoMergeId), unlike the inspector's typing. It is pushed on
    // the next turn of the event loop: an editor open while the window is destroyed commits on its way out, and
    // the queued push then dies with this model instead of reaching a half-destroyed window.
    const int row = index.row();
    const std::string oldName = m_document->body(row).name;
    QMetaObject::invokeMethod(
        this,
        [this, row, oldName, name] {
            if (row >= m_document->bodyCount() || m_document->body(row).name != oldName ||
                !renameProblem(row, name).isEmpty())
                return; // the scene changed meanwhile
            BodyDef renamed = m_document->body(row);
            renamed.name = name.toStdString();
            m_document->undoStack()->push(new SetBodyCommand(
                m_document, row, renamed, tr("Rename %1 to %2").arg(QString::fromStdString(oldName), name), NoMergeId));
        },
        Qt::QueuedConnection);
    return true;
}

} // namespace rl
