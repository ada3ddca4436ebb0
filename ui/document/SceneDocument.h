// The document the editor edits: an rl::Scene, its file and an undo stack, with signals that keep every view in sync.
// Views read through this class; edits go through QUndoCommands (ui/document/commands/) that call its model methods.
#pragma once

#include "scene/Scene.h"

#include <QObject>
#include <QString>
#include <QUndoStack>

class QWidget;

namespace rl {

class SceneDocument : public QObject {
    Q_OBJECT
public:
    explicit SceneDocument(QObject* parent = nullptr);

    const Scene& scene() const { return m_scene; }
    int bodyCount() const { return static_cast<int>(m_scene.bodies.size()); }
    const BodyDef& body(int index) const { return m_scene.bodies.at(static_cast<size_t>(index)); }

    QString filePath() const { return m_filePath; }
    QString displayName() const;
    QUndoStack* undoStack() { return &m_undoStack; }
    bool isModified() const { return !m_undoStack.isClean(); }

    // Replaces the whole scene (New, Open). Clears the undo history. Relative OBJ paths of "obj" shapes become
    // absolute (against the scene's sourcePath), so that a later Save As to another folder still finds the OBJ.
    void reset(Scene scene, const QString& filePath);
    // Loads any scene file the core reads; on failure returns false and sets errorMessage (file, object, problem).
    bool load(const QString& path, QString* errorMessage);

    // Writes the scene as .rlscene to `path` atomically (QSaveFile: the old file stays intact when anything fails),
    // then makes `path` the document's file and marks the undo stack clean. On failure returns false, sets
    // errorMessage (file, body, problem) and leaves the document as it was, modified. OBJ paths of "obj" shapes
    // are written relative to the new file's folder.
    bool save(const QString& path, QString* errorMessage);
    // Writes a copy (autosave, recovery) without touching the document's file or clean state. OBJ paths are
    // written absolute so that the copy opens from any folder.
    bool writeCopy(const QString& path, QString* errorMessage) const;
    // Marks the document modified without an undo step (a scene restored from an autosave is unsaved work).
    void markModified();

    // Edit gestures. Field edits merge into one undo step only within one gesture: a slider drag, a run of
    // spin-box steps, or typing a value up to Enter. Commands take the gesture they were made in; when the
    // gesture ends (Enter, focus leaves the field, the slider is released) the next edit of the same field is a
    // new undo step, so setting friction to 0.3 and later to 0.5 undoes to 0.3 first.
    int editGesture() const { return m_editGesture; }
    void endEditGesture() { ++m_editGesture; }
    // Ends the gesture whenever one of the spin boxes or sliders under root finishes an edit.
    void endEditGestureOnFinish(QWidget* root);

    // Makes every relative "obj" shape path absolute against the folder of `baseFile` (a scene file).
    static void makeObjPathsAbsolute(Scene& scene, const QString& baseFile);

    // Model methods: the only way commands change the scene. Each emits the matching signal.
    void setBody(int index, const BodyDef& body);
    void insertBody(int index, const BodyDef& body);
    void removeBody(int index);
    // Many bodies in one change and one signal (Import, undoing it): views rebuild once, not once per body, which
    // took 11 s to import and 57 s to undo the 646-body ramps scene when done body by body.
    void insertBodies(int index, const std::vector<BodyDef>& bodies);
    void removeBodies(int index, int count);
    void setWorldSettings(const WorldSettings& settings);
    void setMaterials(const std::vector<MaterialDef>& materials);

signals:
    void sceneReset();
    void bodyChanged(int index);
    // `count` bodies were inserted at / removed from `index` on (1 for insertBody and removeBody).
    void bodyInserted(int index, int count = 1);
    void bodyRemoved(int index, int count = 1);
    void worldSettingsChanged();
    void materialsChanged();
    void filePathChanged(const QString& path);

private:
    Scene m_scene;
    QString m_filePath;
    QUndoStack m_undoStack;
    int m_editGesture = 0;
};

} // namespace rl
