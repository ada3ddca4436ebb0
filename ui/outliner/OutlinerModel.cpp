#include "outliner/OutlinerModel.h"

#include "document/SceneDocument.h"

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

} // namespace

OutlinerModel::OutlinerModel(SceneDocument* document, QObject* parent)
    : QAbstractItemModel(parent), m_document(document), m_anchorIcon(makeIcon(QColor(150, 150, 150), true)),
      m_dynamicIcon(makeIcon(QColor(232, 140, 60), false)) {
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
    if (orientation != Qt::Horizontal || role != Qt::DisplayRole)
        return {};
    return section == NameColumn ? tr("Name") : tr("Material");
}

Qt::ItemFlags OutlinerModel::flags(const QModelIndex& index) const {
    if (!index.isValid())
        return Qt::NoItemFlags;
    return Qt::ItemIsSelectable | Qt::ItemIsEnabled;
}

} // namespace rl
