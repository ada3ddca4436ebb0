// The material library of a scene as the editor shows it: the built-in presets (with the scene's overrides applied)
// followed by the scene's own materials, plus the rules every library edit must pass. No widgets here, so the rules
// are tested directly and shared by every place that edits materials.
#pragma once

#include "scene/Scene.h"

#include <QCoreApplication>
#include <QString>
#include <QStringList>

#include <optional>
#include <vector>

namespace rl {

struct LibraryEntry {
    MaterialDef material;  // the values bodies naming it get
    bool preset = false;   // a built-in name: it cannot be renamed or deleted, only reset
    bool modified = false; // a preset whose values this scene overrides with different ones
    int users = 0;         // bodies (anchors included) that name it
};

class MaterialLibrary {
    Q_DECLARE_TR_FUNCTIONS(rl::MaterialLibrary)
public:
    // Presets first (in their built-in order), then the scene's own materials in the scene's order.
    static std::vector<LibraryEntry> entries(const Scene& scene);

    // Upper limits of the editor's fields. The core only asks for density > 0, friction >= 0 and restitution in
    // [0, 1]; the upper limits catch typing slips: the densest element (osmium) is 22,590 kg/m³, and friction
    // coefficients of real material pairs stay well below 2.
    static constexpr double kMaxDensity = 1e6; // kg/m³
    static constexpr double kMaxFriction = 10.0;

    // Why the material cannot be stored under its name in place of the one called oldName (empty oldName: a new
    // material), or an empty string when it can. Names compare ignoring case, as the core looks them up.
    static QString problem(const Scene& scene, const QString& oldName, const MaterialDef& material);

    // The scene's material list with material stored in place of oldName (a preset not yet overridden, or a new
    // material, is appended).
    static std::vector<MaterialDef> withMaterial(const Scene& scene, const QString& oldName,
                                                 const MaterialDef& material);
    // The scene's material list without the entry called name (a custom material, or a preset's override).
    static std::vector<MaterialDef> without(const Scene& scene, const QString& name);

    // Indices of the bodies whose material is called name (ignoring case).
    static QList<int> users(const Scene& scene, const QString& name);

    // base, or "base 2", "base 3", ...: the first name no library entry uses.
    static QString uniqueName(const Scene& scene, const QString& base);

    // The library name a body's material resolves to: the entry's own spelling, or "Default" when unknown.
    static QString resolvedName(const Scene& scene, const BodyDef& body);

    // How a rule combines two values, for people: "geometric mean", and the formula with a and b filled in.
    static QString ruleLabel(CombineRule rule);
    static QString formula(CombineRule rule, const QString& a, const QString& b);
};

} // namespace rl
