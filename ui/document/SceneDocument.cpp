#include "document/SceneDocument.h"

#include "io/SceneImport.h"

#include <QFileInfo>

namespace rl {

SceneDocument::SceneDocument(QObject* parent) : QObject(parent) {}

QString SceneDocument::displayName() const {
    return m_filePath.isEmpty() ? tr("Untitled") : QFileInfo(m_filePath).fileName();
}

void SceneDocument::reset(Scene scene, const QString& filePath) {
    m_scene = std::move(scene);
    m_undoStack.clear();
    m_undoStack.setClean();
    m_filePath = filePath;
    emit sceneReset();
    emit filePathChanged(m_filePath);
}

bool SceneDocument::load(const QString& path, QString* errorMessage) {
    Result<Scene> loaded = importScene(path.toStdString());
    if (!loaded) {
        if (errorMessage)
            *errorMessage = QString::fromStdString(loaded.error().toString());
        return false;
    }
    reset(std::move(loaded).value(), path);
    return true;
}

void SceneDocument::setBody(int index, const BodyDef& body) {
    m_scene.bodies.at(static_cast<size_t>(index)) = body;
    emit bodyChanged(index);
}

void SceneDocument::insertBody(int index, const BodyDef& body) {
    m_scene.bodies.insert(m_scene.bodies.begin() + index, body);
    emit bodyInserted(index);
}

void SceneDocument::removeBody(int index) {
    m_scene.bodies.erase(m_scene.bodies.begin() + index);
    emit bodyRemoved(index);
}

void SceneDocument::setWorldSettings(const WorldSettings& settings) {
    m_scene.world = settings;
    emit worldSettingsChanged();
}

void SceneDocument::setMaterials(const std::vector<MaterialDef>& materials) {
    m_scene.materials = materials;
    emit materialsChanged();
}

} // namespace rl
