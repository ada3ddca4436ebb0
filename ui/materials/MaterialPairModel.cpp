#include "materials/MaterialPairModel.h"

#include "document/SceneDocument.h"
#include "materials/MaterialLibrary.h"

#include <QBrush>
#include <QLocale>
#include <QPalette>

#include <cmath>

namespace rl {

MaterialPairModel::MaterialPairModel(SceneDocument* document, QObject* parent)
    : QAbstractTableModel(parent), m_document(document) {
    for (auto signal :
         {&SceneDocument::sceneReset, &SceneDocument::materialsChanged, &SceneDocument::worldSettingsChanged})
        connect(document, signal, this, &MaterialPairModel::reload);
    connect(document, &SceneDocument::bodyChanged, this, &MaterialPairModel::reload);
    connect(document, &SceneDocument::bodyInserted, this, &MaterialPairModel::reload);
    connect(document, &SceneDocument::bodyRemoved, this, &MaterialPairModel::reload);
    reload();
}

void MaterialPairModel::reload() {
    const Scene& scene = m_document->scene();
    // Used materials in library order, so the matrix reads like the table above it.
    QStringList used;
    m_overriding = 0;
    for (const BodyDef& body : scene.bodies) {
        const QString name = MaterialLibrary::resolvedName(scene, body);
        if (!used.contains(name))
            used.append(name);
        m_overriding += (body.friction || body.restitution) ? 1 : 0;
    }
    QStringList names;
    std::vector<MaterialDef> materials;
    for (const LibraryEntry& entry : MaterialLibrary::entries(scene)) {
        const QString name = QString::fromStdString(entry.material.name);
        if (used.contains(name)) {
            names.append(name);
            materials.push_back(entry.material);
        }
    }
    if (names != m_names) {
        beginResetModel();
        m_names = names;
        m_materials = std::move(materials);
        endResetModel();
    } else {
        m_materials = std::move(materials);
        if (!m_names.isEmpty())
            emit dataChanged(index(0, 0), index(rowCount() - 1, columnCount() - 1));
    }
    emit updated();
}

int MaterialPairModel::rowCount(const QModelIndex& parent) const {
    return parent.isValid() ? 0 : static_cast<int>(m_names.size());
}

int MaterialPairModel::columnCount(const QModelIndex& parent) const {
    return rowCount(parent);
}

QVariant MaterialPairModel::data(const QModelIndex& index, int role) const {
    if (!index.isValid() || index.row() >= rowCount() || index.column() >= columnCount())
        return {};
    const MaterialDef& a = m_materials[static_cast<size_t>(index.row())];
    const MaterialDef& b = m_materials[static_cast<size_t>(index.column())];
    const WorldSettings& world = m_document->scene().world;
    const double friction = combine(world.frictionCombine, a.friction, b.friction);
    const double restitution = combine(world.restitutionCombine, a.restitution, b.restitution);
    auto number = [](double v) { return QLocale().toString(v, 'f', v != 0.0 && std::abs(v) < 0.01 ? 3 : 2); };
    switch (role) {
    case Qt::DisplayRole:
        return QStringLiteral("%1 / %2").arg(number(friction), number(restitution));
    case FrictionRole:
        return friction;
    case RestitutionRole:
        return restitution;
    case Qt::TextAlignmentRole:
        return Qt::AlignCenter;
    case Qt::BackgroundRole:
        if (index.row() == index.column())
            return QPalette().brush(QPalette::AlternateBase);
        break;
    case Qt::ToolTipRole: {
        auto plain = [](double v) { return QLocale().toString(v, 'g', 6); };
        return tr("%1 on %2\nfriction %3 = %4\nrestitution %5 = %6")
            .arg(m_names[index.row()], m_names[index.column()])
            .arg(MaterialLibrary::formula(world.frictionCombine, plain(a.friction), plain(b.friction)))
            .arg(plain(friction))
            .arg(MaterialLibrary::formula(world.restitutionCombine, plain(a.restitution), plain(b.restitution)))
            .arg(plain(restitution));
    }
    }
    return {};
}

QVariant MaterialPairModel::headerData(int section, Qt::Orientation, int role) const {
    if (role == Qt::DisplayRole && section >= 0 && section < m_names.size())
        return m_names[section];
    return {};
}

} // namespace rl
