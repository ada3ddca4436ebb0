// Undo command that merges another scene's bodies (and the materials they need) into the document as one step.
// Clashing names get Blender-style suffixes (Cube -> Cube.001), which keep the anchor rule (Anchor.001 is an anchor).
#pragma once

#include "scene/Scene.h"

#include <QString>
#include <QUndoCommand>

#include <functional>
#include <string>
#include <vector>

namespace rl {

class SceneDocument;

// `name` itself when it is free, else its base (without a trailing .NNN) with the lowest free .001, .002, ...
std::string uniqueName(const std::string& name, const std::function<bool(const std::string&)>& taken);

// What an import adds to a scene: the bodies with unique names and materials remapped, and the scene's material
// list afterwards. A material the imported scene defines differently from the current scene (or from a preset the
// current scene overrides) is added under a new name, so that no body's physics change by the merge.
struct ImportPlan {
    std::vector<BodyDef> bodies;
    std::vector<MaterialDef> materials; // the current scene's materials followed by the added ones
    int renamedBodies = 0;
    int renamedMaterials = 0;
    int addedMaterials = 0;
};
ImportPlan planImport(const Scene& current, const std::vector<Scene>& imported);

class ImportBodiesCommand : public QUndoCommand {
public:
    // `sourceName` is shown in the undo text ("Import stack.obj"), for one file or "%n files".
    ImportBodiesCommand(SceneDocument* document, ImportPlan plan, const QString& sourceName,
                        QUndoCommand* parent = nullptr);

    void undo() override;
    void redo() override;

    // Index of the first imported body; the imported bodies follow in order.
    int firstIndex() const { return m_first; }
    int count() const { return static_cast<int>(m_plan.bodies.size()); }

private:
    SceneDocument* m_document;
    ImportPlan m_plan;
    std::vector<MaterialDef> m_oldMaterials;
    int m_first;
};

} // namespace rl
