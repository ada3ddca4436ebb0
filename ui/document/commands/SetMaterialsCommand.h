// Undo command that replaces the scene's material library (Scene::materials) as a whole.
// Consecutive edits with the same merge id and merge key (the material and field edited) merge, so a spin-box or
// slider drag becomes one undo step. The document changes only through SceneDocument::setMaterials.
#pragma once

#include "scene/MaterialDef.h"

#include <QString>
#include <QUndoCommand>

#include <vector>

namespace rl {

class SceneDocument;

// Merge ids of the library edits. They belong in ui/document/UndoIds.h (owned elsewhere); until they move there they
// sit far above that enum's values so that no id is shared by accident.
enum MaterialUndoId {
    SetMaterialNameId = 1000,
    SetMaterialDensityId,
    SetMaterialFrictionId,
    SetMaterialRestitutionId,
};

class SetMaterialsCommand : public QUndoCommand {
public:
    // mergeKey names what is edited (for example the material's name), so that editing the friction of Steel and
    // then of Wood stays two steps even though the merge id is the same.
    SetMaterialsCommand(SceneDocument* document, std::vector<MaterialDef> after, const QString& text, int mergeId = -1,
                        const QString& mergeKey = {}, QUndoCommand* parent = nullptr);

    void undo() override;
    void redo() override;
    int id() const override { return m_mergeId; }
    bool mergeWith(const QUndoCommand* other) override;

private:
    SceneDocument* m_document;
    std::vector<MaterialDef> m_before;
    std::vector<MaterialDef> m_after;
    int m_mergeId;
    int m_gesture; // the document's edit gesture at construction: merges stay within one
    QString m_mergeKey;
};

} // namespace rl
