// Table model of the scene's material library (MaterialLibrary::entries): name, density, friction, restitution and
// how many bodies use each material. Read-only: edits go through MaterialsWidget, which pushes undo commands. It
// follows the document's signals, so it never goes stale.
#pragma once

#include "materials/MaterialLibrary.h"

#include <QAbstractTableModel>

namespace rl {

class SceneDocument;

class MaterialLibraryModel : public QAbstractTableModel {
    Q_OBJECT
public:
    enum Column { NameColumn, DensityColumn, FrictionColumn, RestitutionColumn, UsersColumn, ColumnCount };
    enum Role { ValueRole = Qt::UserRole + 1, PresetRole, ModifiedRole };

    explicit MaterialLibraryModel(SceneDocument* document, QObject* parent = nullptr);

    const std::vector<LibraryEntry>& entries() const { return m_entries; }
    // The row of the material called name (ignoring case), or -1.
    int rowOf(const QString& name) const;

    int rowCount(const QModelIndex& parent = {}) const override;
    int columnCount(const QModelIndex& parent = {}) const override;
    QVariant data(const QModelIndex& index, int role = Qt::DisplayRole) const override;
    QVariant headerData(int section, Qt::Orientation orientation, int role = Qt::DisplayRole) const override;

private:
    void reload();
    void reloadUsers();

    SceneDocument* m_document;
    std::vector<LibraryEntry> m_entries;
};

} // namespace rl
