#include "materials/MaterialLibrary.h"

#include <algorithm>
#include <cmath>

namespace rl {

namespace {

bool sameName(const std::string& a, const QString& b) {
    return QString::fromStdString(a).compare(b, Qt::CaseInsensitive) == 0;
}

} // namespace

std::vector<LibraryEntry> MaterialLibrary::entries(const Scene& scene) {
    std::vector<LibraryEntry> out;
    for (const MaterialDef& preset : materialPresets()) {
        LibraryEntry entry;
        entry.material = preset;
        entry.preset = true;
        for (const MaterialDef& m : scene.materials)
            if (sameName(m.name, QString::fromStdString(preset.name))) {
                entry.material = m;
                entry.material.name = preset.name; // the preset's spelling
                entry.modified = !(entry.material == preset);
            }
        out.push_back(entry);
    }
    for (const MaterialDef& m : scene.materials) {
        if (findPreset(m.name))
            continue;
        LibraryEntry entry;
        entry.material = m;
        out.push_back(entry);
    }
    for (LibraryEntry& entry : out)
        for (const BodyDef& body : scene.bodies)
            entry.users += sameName(body.material, QString::fromStdString(entry.material.name)) ? 1 : 0;
    return out;
}

QString MaterialLibrary::problem(const Scene& scene, const QString& oldName, const MaterialDef& material) {
    const QString name = QString::fromStdString(material.name);
    if (name.trimmed().isEmpty())
        return tr("A material needs a name.");
    if (name.trimmed() != name)
        return tr("The name \"%1\" starts or ends with a space.").arg(name);
    const bool renamed = oldName.isEmpty() || name.compare(oldName, Qt::CaseInsensitive) != 0;
    if (renamed && !oldName.isEmpty() && findPreset(oldName.toStdString()))
        return tr("\"%1\" is a built-in preset and keeps its name; duplicate it to make a material of your own.")
            .arg(oldName);
    if (renamed) {
        if (findPreset(material.name))
            return tr("\"%1\" is the name of a built-in preset; choose another name.").arg(name);
        for (const MaterialDef& m : scene.materials)
            if (sameName(m.name, name))
                return tr("The library already has a material called \"%1\".").arg(name);
    }
    if (!std::isfinite(material.density) || !(material.density > 0.0) || material.density > kMaxDensity)
        return tr("Density of \"%1\" must be above 0 and at most %2 kg/m³ (got %3).")
            .arg(name)
            .arg(kMaxDensity, 0, 'g', 6)
            .arg(material.density);
    if (!std::isfinite(material.friction) || material.friction < 0.0 || material.friction > kMaxFriction)
        return tr("Friction of \"%1\" must be between 0 and %2 (got %3).")
            .arg(name)
            .arg(kMaxFriction)
            .arg(material.friction);
    if (!std::isfinite(material.restitution) || material.restitution < 0.0 || material.restitution > 1.0)
        return tr("Restitution of \"%1\" must be between 0 (no bounce) and 1 (elastic) (got %2).")
            .arg(name)
            .arg(material.restitution);
    return {};
}

std::vector<MaterialDef> MaterialLibrary::withMaterial(const Scene& scene, const QString& oldName,
                                                       const MaterialDef& material) {
    std::vector<MaterialDef> out = scene.materials;
    if (!oldName.isEmpty())
        for (MaterialDef& m : out)
            if (sameName(m.name, oldName)) {
                m = material;
                return out;
            }
    out.push_back(material);
    return out;
}

std::vector<MaterialDef> MaterialLibrary::without(const Scene& scene, const QString& name) {
    std::vector<MaterialDef> out;
    for (const MaterialDef& m : scene.materials)
        if (!sameName(m.name, name))
            out.push_back(m);
    return out;
}

QList<int> MaterialLibrary::users(const Scene& scene, const QString& name) {
    QList<int> out;
    for (size_t i = 0; i < scene.bodies.size(); ++i)
        if (sameName(scene.bodies[i].material, name))
            out.append(static_cast<int>(i));
    return out;
}

QString MaterialLibrary::uniqueName(const Scene& scene, const QString& base) {
    auto taken = [&](const QString& name) {
        return findPreset(name.toStdString()).has_value() ||
               std::any_of(scene.materials.begin(), scene.materials.end(),
                           [&](const MaterialDef& m) { return sameName(m.name, name); });
    };
    if (!taken(base))
        return base;
    for (int n = 2;; ++n) {
        const QString candidate = QStringLiteral("%1 %2").arg(base).arg(n);
        if (!taken(candidate))
            return candidate;
    }
}

QString MaterialLibrary::resolvedName(const Scene& scene, const BodyDef& body) {
    if (const std::optional<MaterialDef> preset = findPreset(body.material))
        return QString::fromStdString(preset->name);
    for (const MaterialDef& m : scene.materials)
        if (sameName(m.name, QString::fromStdString(body.material)))
            return QString::fromStdString(m.name);
    return QStringLiteral("Default");
}

QString MaterialLibrary::ruleLabel(CombineRule rule) {
    switch (rule) {
    case CombineRule::GeometricMean:
        return tr("geometric mean");
    case CombineRule::Average:
        return tr("average");
    case CombineRule::Min:
        return tr("minimum");
    case CombineRule::Max:
        return tr("maximum");
    case CombineRule::Multiply:
        return tr("product");
    }
    return {};
}

QString MaterialLibrary::formula(CombineRule rule, const QString& a, const QString& b) {
    switch (rule) {
    case CombineRule::GeometricMean:
        return QStringLiteral("\u221a(%1 \u00b7 %2)").arg(a, b);
    case CombineRule::Average:
        return QStringLiteral("(%1 + %2) / 2").arg(a, b);
    case CombineRule::Min:
        return QStringLiteral("min(%1, %2)").arg(a, b);
    case CombineRule::Max:
        return QStringLiteral("max(%1, %2)").arg(a, b);
    case CombineRule::Multiply:
        return QStringLiteral("%1 \u00b7 %2").arg(a, b);
    }
    return {};
}

} // namespace rl
