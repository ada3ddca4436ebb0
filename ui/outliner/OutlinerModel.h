// Item model over the scene document's bodies for the outliner: name (with anchor/dynamic icon), an anchor column
// and the material. Names are editable in place (F2, double-click): a rename is one undo step, and an empty name or
// one another body has is refused with renameRefused. A flat list; it follows the document's signals.
#pragma once

#include <QAbstractItemModel>
#include <QIcon>

namespace rl {

class SceneDocument;

class OutlinerModel : public QAbstractItemModel {
    Q_OBJECT
public:
    enum Column { NameColumn, AnchorColumn, MaterialColumn, ColumnCount };
    enum Role { AnchorRole = Qt::UserRole + 1, BodyIndexRole };

    explicit OutlinerModel(SceneDocument* document, QObject* parent = nullptr);

    QModelIndex index(int row, int column, const QModelIndex& parent = {}) const override;
    QModelIndex parent(const QModelIndex& child) const override;
    int rowCount(const QModelIndex& parent = {}) const override;
    int columnCount(const QModelIndex& parent = {}) const override;
    QVariant data(const QModelIndex& index, int role = Qt::DisplayRole) const override;
    QVariant headerData(int section, Qt::Orientation orientation, int role = Qt::DisplayRole) const override;
    Qt::ItemFlags flags(const QModelIndex& index) const override;
    bool setData(const QModelIndex& index, const QVariant& value, int role = Qt::EditRole) override;

    // Why a rename would be refused (empty, or taken by another body); empty when it is fine.
    QString renameProblem(int row, const QString& name) const;

signals:
    void renameRefused(const QString& message);

private:
    SceneDocument* m_document;
    QIcon m_anchorIcon;
    QIcon m_dynamicIcon;
    QIcon m_pinIcon;    // anchor column: anchored
    QIcon m_pinOffIcon; // anchor column: dynamic (faint, so the column reads as a toggle)
};

} // namespace rl
