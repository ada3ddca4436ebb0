// Item model over the scene document's bodies for the outliner: name (with anchor/dynamic icon) and material.
// A flat list for now; it follows the document's signals so it never goes stale.
#pragma once

#include <QAbstractItemModel>
#include <QIcon>

namespace rl {

class SceneDocument;

class OutlinerModel : public QAbstractItemModel {
    Q_OBJECT
public:
    enum Column { NameColumn, MaterialColumn, ColumnCount };
    enum Role { AnchorRole = Qt::UserRole + 1, BodyIndexRole };

    explicit OutlinerModel(SceneDocument* document, QObject* parent = nullptr);

    QModelIndex index(int row, int column, const QModelIndex& parent = {}) const override;
    QModelIndex parent(const QModelIndex& child) const override;
    int rowCount(const QModelIndex& parent = {}) const override;
    int columnCount(const QModelIndex& parent = {}) const override;
    QVariant data(const QModelIndex& index, int role = Qt::DisplayRole) const override;
    QVariant headerData(int section, Qt::Orientation orientation, int role = Qt::DisplayRole) const override;
    Qt::ItemFlags flags(const QModelIndex& index) const override;

private:
    SceneDocument* m_document;
    QIcon m_anchorIcon;
    QIcon m_dynamicIcon;
};

} // namespace rl
