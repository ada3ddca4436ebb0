// File menu: New, Open, Open Recent, Import, Save, Save As, the Export submenu's place, drag and drop, the
// unsaved-changes prompt, autosave to a recovery file and the offer to restore it after a crash.
#pragma once

#include <QObject>
#include <QStringList>

#include <functional>
#include <memory>

class QAction;
class QMenu;
class QTimer;

namespace rl {

class MainWindow;
class RecoveryStore;

class FileController : public QObject {
    Q_OBJECT
public:
    // Minutes between autosaves when the scene has unsaved changes; 0 turns autosave off. Default 2.
    static constexpr const char* kAutosaveMinutesKey = "files/autosaveMinutes";
    static constexpr int kDefaultAutosaveMinutes = 2;
    // Folder of the last file opened or saved, where the file dialogs start.
    static constexpr const char* kLastFolderKey = "files/lastFolder";

    explicit FileController(MainWindow* window);
    // A window that goes away normally removes its recovery file.
    ~FileController() override;

    // Why the unsaved-changes prompt is shown; it words its question after it.
    enum class Reason { Close, New, Open };

    // File > New: an empty untitled scene with the default world and the preset materials.
    bool newScene();
    // File > Open, Open Recent and drops: asks about unsaved changes, then opens whatever MainWindow::openFile
    // takes (.bake included) and puts it at the top of the recent list.
    bool open(const QString& path);
    // Opens a scene file into the document; asks about unsaved changes first unless open() already asked. Errors
    // (file, object, problem) go to a message box and leave the current scene as it was.
    bool openScene(const QString& path);
    // File > Import: adds the bodies of scene files to the document as one undo step; clashing names get .001.
    bool importScenes(const QStringList& paths);
    // File > Save: writes the document's .rlscene. An untitled scene, or one opened from .obj, glTF, ..., goes
    // through Save As, so that a mesh file is never overwritten with JSON.
    bool save();
    // File > Save As: asks for a path (see setSavePathProvider), then saves there.
    bool saveAs();
    // Saves to `path`, adding .rlscene when it has no extension. On failure the document stays modified, the old
    // file stays intact and a message box says why.
    bool saveAs(const QString& path);
    // File > Revert to Saved: after a confirmation, goes back to the saved state. Through the undo stack when the
    // saved state is in its history (so Redo brings the changes back), else by reading the file again.
    bool revert();
    // Files dropped on the window: the first scene file opens, the other scene files are imported into it (one
    // undo step, so Ctrl+Z takes them out again); with no scene file, the first .bake opens.
    void openDroppedFiles(const QStringList& paths);
    // Save / Discard / Cancel when there are unsaved changes. False when the user cancels (or a save fails).
    bool maybeSave(Reason reason = Reason::Close);

    // Autosave: every interval, a scene with unsaved changes is written to recoveryFilePath(). For tests, the
    // interval may be set in milliseconds; it otherwise comes from kAutosaveMinutesKey.
    void setAutosaveInterval(int msec);
    int autosaveInterval() const;
    // Writes the recovery file now when there are changes it does not hold yet, removes it when the scene has no
    // unsaved changes. False when writing failed (the status bar says why).
    bool autosave();
    QString recoveryFilePath() const;
    // Looks for a recovery file left by an editor that crashed and offers to restore it (Restore / Discard /
    // Not Now). Runs once by itself right after the window is created. True when a copy was restored.
    bool offerRecovery();

    // Where Save As asks for a path; the default is a file dialog. Tests give a function that returns a path.
    using PathProvider = std::function<QString(const QString& suggestedPath)>;
    void setSavePathProvider(PathProvider provider);

    static bool isSceneFile(const QString& path);
    static bool isBakeFile(const QString& path);

private:
    void createActions();
    void rebuildRecentMenu();
    void openRecent(const QString& path);
    bool saveTo(const QString& path);
    QStringList askOpenPaths(const QString& title, bool many);
    void showError(const QString& text, const QString& details);
    void showStatus(const QString& message);
    QString startFolder() const;
    void rememberFolder(const QString& path);

    MainWindow* m_window;
    QMenu* m_recentMenu = nullptr;
    QTimer* m_autosaveTimer = nullptr;
    std::unique_ptr<RecoveryStore> m_recovery;
    PathProvider m_savePathProvider;
    bool m_changedSinceAutosave = false;
    bool m_askedBeforeOpen = false;
};

} // namespace rl
