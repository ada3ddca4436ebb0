// Symmetric matrix of the contact values every pair of materials in use gets: for the materials the scene's bodies
// use (anchors included), the combined friction and restitution under the world's combine rules (rl::combine).
// Per-body overrides are not part of a material, so bodies that override friction or restitution are counted apart.
#pragma once

#include <QAbstractTableModel>
#include <QStringList>

#include <vector>

namespace rl {

class SceneDocument;
struct MaterialDef;

class MaterialPairModel : public QAbstractTableModel {
    Q_OBJECT
public:
    enum Role { FrictionRole = Qt::UserRole + 1, RestitutionRole };

    explicit MaterialPairModel(SceneDocument* document, QObject* parent = nullptr);

    QStringList materials() const { return m_names; }
    // Bodies whose own friction or restitution override their material's.
    int overridingBodies() const { return m_overriding; }

    int rowCount(const QModelIndex& parent = {}) const override;
    int columnCount(const QModelIndex& parent = {}) const override;
    QVariant data(const QModelIndex& index, int role = Qt::DisplayRole) const override;
    QVariant headerData(int section, Qt::Orientation orientation, int role = Qt::DisplayRole) const override;

signals:
    void updated();

private:
    void reload();

    SceneDocument* m_document;
    QStringList m_names;
    std::vector<MaterialDef> m_materials; // same order as m_names
    int m_overriding = 0;
};

} // namespace rl
