#include "document/SceneDocument.h"

#include "io/Json.h"
#include "io/SceneImport.h"
#include "io/SceneJson.h"

#include <QAbstractSpinBox>
#include <QDir>
#include <QFileInfo>
#include <QSaveFile>
#include <QSlider>

#include <cmath>

namespace rl {

namespace {

// JSON has no spelling for NaN or infinity: find the first such number and say where it is (".bodies[3].position[1]").
bool findNonFinite(const JsonValue& v, std::string& where) {
    if (v.isNumber())
        return !std::isfinite(v.asNumber());
    if (v.isArray()) {
        for (size_t i = 0; i < v.asArray().size(); ++i)
            if (findNonFinite(v.asArray()[i], where)) {
                std::string index = "[";
                index += std::to_string(i);
                index += ']';
                where.insert(0, index);
                return true;
            }
    } else if (v.isObject()) {
        for (const JsonMember& m : v.asObject())
            if (findNonFinite(m.value, where)) {
                where = "." + m.key + where;
                return true;
            }
    }
    return false;
}

// The .rlscene text of `scene` for a file at `path`. The document keeps "obj" paths absolute; the file gets them
// relative to its own folder (so that a scene folder can be moved as a whole) unless `absoluteObjPaths`.
bool sceneFileText(Scene scene, const QString& path, bool absoluteObjPaths, std::string* text, QString* error) {
    const QDir folder = QFileInfo(path).absoluteDir();
    for (BodyDef& body : scene.bodies)
        if (!body.shape.objFile.empty() && !absoluteObjPaths)
            body.shape.objFile = folder.relativeFilePath(QString::fromStdString(body.shape.objFile)).toStdString();
    const JsonValue doc = sceneToJson(scene);
    std::string where;
    if (findNonFinite(doc, where)) {
        Error e{path.toStdString(), 0, {}, "not a finite number at " + where.substr(1) + "; JSON cannot hold it"};
        constexpr std::string_view kBodies = ".bodies[";
        if (where.rfind(kBodies, 0) == 0) {
            const size_t index = std::stoul(where.substr(kBodies.size()));
            e.object = scene.bodies[index].name;
        }
        if (error)
            *error = QString::fromStdString(e.toString());
        return false;
    }
    *text = writeJson(doc);
    return true;
}

bool writeSceneText(const std::string& text, const QString& path, QString* error) {
    QSaveFile file(path);
    // Never write in place: when the temporary file cannot be made, the save fails and the old file stays.
    file.setDirectWriteFallback(false);
    const auto fail = [&](const QString& why) {
        if (error)
            *error = QStringLiteral("%1: %2").arg(QDir::toNativeSeparators(path), why);
        return false;
    };
    if (!file.open(QIODevice::WriteOnly))
        return fail(file.errorString());
    if (file.write(text.data(), qint64(text.size())) != qint64(text.size()))
        return fail(file.errorString());
    if (!file.commit())
        return fail(file.errorString());
    return true;
}

} // namespace

SceneDocument::SceneDocument(QObject* parent) : QObject(parent) {}

QString SceneDocument::displayName() const {
    return m_filePath.isEmpty() ? tr("Untitled") : QFileInfo(m_filePath).fileName();
}

void SceneDocument::makeObjPathsAbsolute(Scene& scene, const QString& baseFile) {
    const QDir folder = QFileInfo(baseFile).absoluteDir();
    for (BodyDef& body : scene.bodies) {
        const QString objFile = QString::fromStdString(body.shape.objFile);
        if (!objFile.isEmpty() && QDir::isRelativePath(objFile))
            body.shape.objFile = QDir::cleanPath(folder.absoluteFilePath(objFile)).toStdString();
    }
}

void SceneDocument::reset(Scene scene, const QString& filePath) {
    const QString base = !scene.sourcePath.empty() ? QString::fromStdString(scene.sourcePath) : filePath;
    makeObjPathsAbsolute(scene, base.isEmpty() ? QDir::currentPath() + QStringLiteral("/scene") : base);
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

bool SceneDocument::save(const QString& path, QString* errorMessage) {
    std::string text;
    if (!sceneFileText(m_scene, path, false, &text, errorMessage) || !writeSceneText(text, path, errorMessage))
        return false;
    m_scene.sourcePath = path.toStdString();
    m_undoStack.setClean();
    if (m_filePath != path) {
        m_filePath = path;
        emit filePathChanged(m_filePath);
    }
    return true;
}

bool SceneDocument::writeCopy(const QString& path, QString* errorMessage) const {
    std::string text;
    return sceneFileText(m_scene, path, true, &text, errorMessage) && writeSceneText(text, path, errorMessage);
}

void SceneDocument::markModified() {
    m_undoStack.resetClean();
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

void SceneDocument::insertBodies(int index, const std::vector<BodyDef>& bodies) {
    if (bodies.empty())
        return;
    m_scene.bodies.insert(m_scene.bodies.begin() + index, bodies.begin(), bodies.end());
    emit bodyInserted(index, static_cast<int>(bodies.size()));
}

void SceneDocument::removeBodies(int index, int count) {
    if (count <= 0)
        return;
    m_scene.bodies.erase(m_scene.bodies.begin() + index, m_scene.bodies.begin() + index + count);
    emit bodyRemoved(index, count);
}

void SceneDocument::setWorldSettings(const WorldSettings& settings) {
    m_scene.world = settings;
    emit worldSettingsChanged();
}

void SceneDocument::setMaterials(const std::vector<MaterialDef>& materials) {
    m_scene.materials = materials;
    emit materialsChanged();
}

void SceneDocument::endEditGestureOnFinish(QWidget* root) {
    for (QAbstractSpinBox* box : root->findChildren<QAbstractSpinBox*>())
        connect(box, &QAbstractSpinBox::editingFinished, this, &SceneDocument::endEditGesture);
    for (QSlider* slider : root->findChildren<QSlider*>())
        connect(slider, &QSlider::sliderReleased, this, &SceneDocument::endEditGesture);
}

} // namespace rl
