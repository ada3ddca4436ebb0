#include "materials/MaterialLibraryModel.h"

#include "document/SceneDocument.h"

#include <QFont>
#include <QLocale>

namespace rl {

MaterialLibraryModel::MaterialLibraryModel(SceneDocument* document, QObject* parent)
    : QAbstractTableModel(parent), m_document(document), m_entries(MaterialLibrary::entries(document->scene())) {
    connect(document, &SceneDocument::sceneReset, this, &MaterialLibraryModel::reload);
    connect(document, &SceneDocument::materialsChanged, this, &MaterialLibraryModel::reload);
    // Body edits only change how many bodies use each material.
    connect(document, &SceneDocument::bodyChanged, this, &MaterialLibraryModel::reloadUsers);
    connect(document, &SceneDocument::bodyInserted, this, &MaterialLibraryModel::reloadUsers);
    connect(document, &SceneDocument::bodyRemoved, this, &MaterialLibraryModel::reloadUsers);
}

void MaterialLibraryModel::reload() {
    beginResetModel();
    m_entries = MaterialLibrary::entries(m_document->scene());
    endResetModel();
}

void MaterialLibraryModel::reloadUsers() {
    std::vector<LibraryEntry> next = MaterialLibrary::entries(m_document->scene());
    if (next.size() != m_entries.size()) {
        reload();
        return;
    }
    m_entries = std::move(next);
    if (!m_entries.empty())
        emit dataChanged(index(0, UsersColumn), index(rowCount() - 1, UsersColumn));
}

int MaterialLibraryModel::rowOf(const QString& name) const {
    for (size_t i = 0; i < m_entries.size(); ++i)
        if (QString::fromStdString(m_entries[i].material.name).compare(name, Qt::CaseInsensitive) == 0)
            return static_cast<int>(i);
    return -1;
}

int MaterialLibraryModel::rowCount(const QModelIndex& parent) const {
    return parent.isValid() ? 0 : static_cast<int>(m_entries.size());
}

int MaterialLibraryModel::columnCount(const QModelIndex& parent) const {
    return parent.isValid() ? 0 : ColumnCount;
}

QVariant MaterialLibraryModel::data(const QModelIndex& index, int role) const {
    if (!index.isValid() || index.row() >= rowCount())
        return {};
    const LibraryEntry& entry = m_entries[static_cast<size_t>(index.row())];
    const MaterialDef& m = entry.material;
    switch (role) {
    case Qt::DisplayRole:
    case ValueRole:
        switch (index.column()) {
        case NameColumn:
            return QString::fromStdString(m.name);
        case DensityColumn:
            return role == ValueRole ? QVariant(m.density) : QVariant(QLocale().toString(m.density, 'g', 6));
        case FrictionColumn:
            return role == ValueRole ? QVariant(m.friction) : QVariant(QLocale().toString(m.friction, 'g', 4));
        case RestitutionColumn:
            return role == ValueRole ? QVariant(m.restitution) : QVariant(QLocale().toString(m.restitution, 'g', 4));
        case UsersColumn:
            return entry.users;
        }
        break;
    case PresetRole:
        return entry.preset;
    case ModifiedRole:
        return entry.modified;
    case Qt::TextAlignmentRole:
        return index.column() == NameColumn ? QVariant(Qt::AlignLeft | Qt::AlignVCenter)
                                            : QVariant(Qt::AlignRight | Qt::AlignVCenter);
    case Qt::FontRole:
        if (index.column() == NameColumn && entry.modified) {
            QFont font;
            font.setBold(true);
            return font;
        }
        break;
    case Qt::ToolTipRole:
        if (entry.preset && entry.modified) {
            const MaterialDef preset = *findPreset(m.name);
            return tr("Built-in preset, changed for this scene (built-in: %1 kg/m³, friction %2, restitution %3).")
                .arg(preset.density)
                .arg(preset.friction)
                .arg(preset.restitution);
        }
        return entry.preset ? tr("Built-in preset") : tr("Material of this scene");
    }
    return {};
}

QVariant MaterialLibraryModel::headerData(int section, Qt::Orientation orientation, int role) const {
    if (orientation != Qt::Horizontal)
        return {};
    if (role == Qt::DisplayRole) {
        switch (section) {
        case NameColumn:
            return tr("Material");
        case DensityColumn:
            return tr("kg/m³");
        case FrictionColumn:
            return tr("μ");
        case RestitutionColumn:
            return tr("e");
        case UsersColumn:
            return tr("Bodies");
        }
    }
    if (role == Qt::ToolTipRole) {
        switch (section) {
        case DensityColumn:
            return tr("Density in kg/m³");
        case FrictionColumn:
            return tr("Coulomb friction coefficient");
        case RestitutionColumn:
            return tr("Restitution: 0 = no bounce, 1 = elastic");
        case UsersColumn:
            return tr("Bodies (anchors included) that use the material");
        }
    }
    return {};
}

} // namespace rl
