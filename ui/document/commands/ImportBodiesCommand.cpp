#include "document/commands/ImportBodiesCommand.h"

#include "document/SceneDocument.h"

#include <QCoreApplication>

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <map>
#include <set>

namespace rl {

namespace {

std::string lower(std::string s) {
    std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    return s;
}

// The name without a trailing ".<digits>", as Blender numbers duplicates.
std::string baseName(const std::string& name) {
    const size_t dot = name.rfind('.');
    if (dot == std::string::npos || dot + 1 == name.size())
        return name;
    for (size_t i = dot + 1; i < name.size(); ++i)
        if (!std::isdigit(static_cast<unsigned char>(name[i])))
            return name;
    return name.substr(0, dot);
}

} // namespace

std::string uniqueName(const std::string& name, const std::function<bool(const std::string&)>& taken) {
    if (!taken(name))
        return name;
    const std::string base = baseName(name);
    for (int n = 1;; ++n) {
        char suffix[16];
        std::snprintf(suffix, sizeof suffix, ".%03d", n);
        std::string candidate = base + suffix;
        if (!taken(candidate))
            return candidate;
    }
}

ImportPlan planImport(const Scene& current, const std::vector<Scene>& imported) {
    ImportPlan plan;
    plan.materials = current.materials;
    Scene merged; // the current scene's material lookup, growing as materials are added
    merged.materials = current.materials;

    std::set<std::string> bodyNames;
    for (const BodyDef& body : current.bodies)
        bodyNames.insert(body.name);
    const auto bodyTaken = [&](const std::string& n) { return bodyNames.count(n) > 0; };
    const auto materialTaken = [&](const std::string& n) { return merged.findMaterial(n).has_value(); };

    for (const Scene& source : imported) {
        // Material name in the source scene (lower case) -> name in the merged scene.
        std::map<std::string, std::string> renamed;
        const auto mapMaterial = [&](const std::string& name) -> std::string {
            const std::string key = lower(name);
            if (auto it = renamed.find(key); it != renamed.end())
                return it->second;
            std::string target = name;
            const std::optional<MaterialDef> wanted = source.findMaterial(name);
            if (wanted) {
                std::optional<MaterialDef> existing = merged.findMaterial(name);
                const auto sameValues = [&](const MaterialDef& m) {
                    return m.density == wanted->density && m.friction == wanted->friction &&
                           m.restitution == wanted->restitution;
                };
                if (existing && !sameValues(*existing)) {
                    // Imported before and renamed then ("Bouncy.001" with these values): share that one.
                    for (const MaterialDef& m : merged.materials)
                        if (lower(baseName(m.name)) == lower(baseName(wanted->name)) && sameValues(m)) {
                            existing = m;
                            break;
                        }
                }
                if (!existing || !sameValues(*existing)) {
                    MaterialDef added = *wanted;
                    if (existing) {
                        added.name = uniqueName(wanted->name, materialTaken);
                        ++plan.renamedMaterials;
                    }
                    merged.materials.push_back(added);
                    plan.materials.push_back(added);
                    ++plan.addedMaterials;
                    target = added.name;
                } else {
                    target = existing->name;
                }
            }
            renamed.emplace(key, target);
            return target;
        };
        for (const MaterialDef& m : source.materials)
            mapMaterial(m.name);
        for (BodyDef body : source.bodies) {
            body.material = mapMaterial(body.material);
            const std::string name = uniqueName(body.name, bodyTaken);
            if (name != body.name)
                ++plan.renamedBodies;
            body.name = name;
            bodyNames.insert(name);
            plan.bodies.push_back(std::move(body));
        }
    }
    return plan;
}

ImportBodiesCommand::ImportBodiesCommand(SceneDocument* document, ImportPlan plan, const QString& sourceName,
                                         QUndoCommand* parent)
    : QUndoCommand(parent), m_document(document), m_plan(std::move(plan)), m_oldMaterials(document->scene().materials),
      m_first(document->bodyCount()) {
    setText(QCoreApplication::translate("rl::Commands", "Import %1").arg(sourceName));
}

void ImportBodiesCommand::redo() {
    if (m_plan.materials != m_oldMaterials)
        m_document->setMaterials(m_plan.materials);
    m_document->insertBodies(m_first, m_plan.bodies);
}

void ImportBodiesCommand::undo() {
    m_document->removeBodies(m_first, count());
    if (m_plan.materials != m_oldMaterials)
        m_document->setMaterials(m_oldMaterials);
}

} // namespace rl
