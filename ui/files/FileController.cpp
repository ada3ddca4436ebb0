#include "files/FileController.h"

#include "MainWindow.h"
#include "document/SceneDocument.h"
#include "document/commands/ImportBodiesCommand.h"
#include "files/RecentFiles.h"
#include "files/RecoveryStore.h"
#include "io/AssimpImporter.h"
#include "io/SceneImport.h"
#include "viewport/Viewport.h"

#include <QAction>
#include <QApplication>
#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QLocale>
#include <QMenu>
#include <QMessageBox>
#include <QPushButton>
#include <QScopeGuard>
#include <QSettings>
#include <QStandardPaths>
#include <QStatusBar>
#include <QStyle>
#include <QTime>
#include <QTimer>
#include <QToolBar>
#include <QUndoStack>

namespace rl {

namespace {

// Loading or writing a large scene blocks for a moment; the cursor says so.
struct WaitCursor {
    WaitCursor() { QApplication::setOverrideCursor(Qt::WaitCursor); }
    ~WaitCursor() { QApplication::restoreOverrideCursor(); }
    WaitCursor(const WaitCursor&) = delete;
    WaitCursor& operator=(const WaitCursor&) = delete;
};

QString fileName(const QString& path) {
    return QFileInfo(path).fileName();
}

// "~/scenes" rather than "/home/me/scenes": recent entries stay short.
QString shortFolder(const QString& path) {
    const QString folder = QFileInfo(path).absolutePath();
    const QString home = QDir::homePath();
    if (home != QLatin1String("/") && (folder == home || folder.startsWith(home + QLatin1Char('/'))))
        return QDir::toNativeSeparators(QLatin1Char('~') + folder.mid(home.size()));
    return QDir::toNativeSeparators(folder);
}

QString lowerSuffix(const QString& path) {
    return QFileInfo(path).suffix().toLower();
}

} // namespace

FileController::FileController(MainWindow* window)
    : QObject(window), m_window(window), m_recovery(std::make_unique<RecoveryStore>()) {
    createActions();

    m_autosaveTimer = new QTimer(this);
    m_autosaveTimer->setObjectName("AutosaveTimer");
    connect(m_autosaveTimer, &QTimer::timeout, this, [this] { autosave(); });
    const int minutes = QSettings().value(QLatin1String(kAutosaveMinutesKey), kDefaultAutosaveMinutes).toInt();
    setAutosaveInterval(minutes > 0 ? minutes * 60 * 1000 : 0);

    SceneDocument* document = window->document();
    const auto changed = [this] { m_changedSinceAutosave = true; };
    connect(document, &SceneDocument::sceneReset, this, changed);
    connect(document, &SceneDocument::bodyChanged, this, changed);
    connect(document, &SceneDocument::bodyInserted, this, changed);
    connect(document, &SceneDocument::bodyRemoved, this, changed);
    connect(document, &SceneDocument::worldSettingsChanged, this, changed);
    connect(document, &SceneDocument::materialsChanged, this, changed);

    // After the window is up (and main has opened the file named on its command line), not inside the constructor.
    QTimer::singleShot(0, this, [this] {
        // A scene named on the command line is what the user asked for: a modal offer of some other scene's copy in
        // front of it would take the first key (Enter restores) and replace it. Say so and keep the copy for a
        // start without a file; a copy of this very scene is still offered.
        const QString opened = m_window->document()->filePath();
        if (!opened.isEmpty()) {
            std::optional<RecoveryStore::Orphan> orphan = m_recovery->findOrphan();
            if (!orphan)
                return;
            if (QFileInfo(orphan->sourcePath) != QFileInfo(opened)) {
                const QString name = orphan->sourcePath.isEmpty() ? tr("Untitled") : fileName(orphan->sourcePath);
                m_window->statusBar()->showMessage(
                    tr("Unsaved changes to “%1” from a session that did not close normally were kept; start "
                       "RigidLab without a file to restore them.")
                        .arg(name),
                    30000);
                return;
            }
        }
        offerRecovery();
    });
}

FileController::~FileController() = default;

void FileController::createActions() {
    QMenu* fileMenu = m_window->menu(MainWindow::Menu::File);
    QToolBar* toolBar = m_window->addToolBar(tr("File"));
    toolBar->setObjectName("FileToolBar");
    QStyle* style = m_window->style();
    auto makeAction = [&](const char* name, const char* themeIcon, QStyle::StandardPixmap fallback, const QString& text,
                          const QString& statusTip) {
        auto* action =
            new QAction(QIcon::fromTheme(QLatin1String(themeIcon), style->standardIcon(fallback)), text, this);
        action->setObjectName(QLatin1String(name));
        action->setStatusTip(statusTip);
        return action;
    };

    QAction* newAction = makeAction("NewAction", "document-new", QStyle::SP_FileIcon, tr("&New"),
                                    tr("Start an empty scene with the default world and materials"));
    newAction->setShortcut(QKeySequence::New);
    connect(newAction, &QAction::triggered, this, [this] { newScene(); });

    QAction* openAction = makeAction("OpenAction", "document-open", QStyle::SP_DialogOpenButton, tr("&Open..."),
                                     tr("Open a scene (.rlscene, OBJ, glTF, FBX, ...) or a .bake"));
    openAction->setShortcut(QKeySequence::Open);
    connect(openAction, &QAction::triggered, this, [this] {
        const QStringList paths = askOpenPaths(tr("Open"), false);
        if (!paths.isEmpty())
            open(paths.first());
    });

    m_recentMenu = new QMenu(tr("Open &Recent"), m_window);
    m_recentMenu->setObjectName("RecentMenu");
    m_recentMenu->setIcon(QIcon::fromTheme(QStringLiteral("document-open-recent")));
    connect(m_recentMenu, &QMenu::aboutToShow, this, &FileController::rebuildRecentMenu);

    QAction* importAction = makeAction("ImportAction", "document-import", QStyle::SP_FileDialogNewFolder,
                                       tr("&Import..."), tr("Add the bodies of other scene files to this scene"));
    connect(importAction, &QAction::triggered, this, [this] {
        const QStringList paths = askOpenPaths(tr("Import"), true);
        if (!paths.isEmpty())
            importScenes(paths);
    });

    QAction* saveAction = makeAction("SaveAction", "document-save", QStyle::SP_DialogSaveButton, tr("&Save"),
                                     tr("Save the scene as .rlscene"));
    saveAction->setShortcut(QKeySequence::Save);
    connect(saveAction, &QAction::triggered, this, [this] { save(); });

    QAction* saveAsAction = makeAction("SaveAsAction", "document-save-as", QStyle::SP_DialogSaveButton,
                                       tr("Save &As..."), tr("Save the scene under a new name"));
    saveAsAction->setShortcut(QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_S));
    connect(saveAsAction, &QAction::triggered, this, [this] { saveAs(); });

    QAction* revertAction = makeAction("RevertAction", "document-revert", QStyle::SP_BrowserReload,
                                       tr("Re&vert to Saved"), tr("Drop the changes made since the last save"));
    connect(revertAction, &QAction::triggered, this, [this] { revert(); });
    const auto updateRevert = [this, revertAction] {
        SceneDocument* document = m_window->document();
        revertAction->setEnabled(document->isModified() && !document->filePath().isEmpty());
    };
    connect(m_window->document()->undoStack(), &QUndoStack::cleanChanged, this, updateRevert);
    connect(m_window->document(), &SceneDocument::filePathChanged, this, updateRevert);
    updateRevert();

    QAction* quitAction =
        makeAction("QuitAction", "application-exit", QStyle::SP_DialogCloseButton, tr("&Quit"), tr("Quit RigidLab"));
    quitAction->setShortcut(QKeySequence::Quit);
    quitAction->setMenuRole(QAction::QuitRole);
    connect(quitAction, &QAction::triggered, m_window, &QWidget::close);

    fileMenu->addAction(newAction);
    fileMenu->addAction(openAction);
    fileMenu->addMenu(m_recentMenu);
    fileMenu->addAction(importAction);
    fileMenu->addSeparator();
    fileMenu->addAction(saveAction);
    fileMenu->addAction(saveAsAction);
    fileMenu->addAction(revertAction);
    fileMenu->addSeparator();
    fileMenu->addMenu(m_window->menu(MainWindow::Menu::Export));
    fileMenu->addSeparator();
    fileMenu->addAction(quitAction);

    toolBar->addAction(newAction);
    toolBar->addAction(openAction);
    toolBar->addAction(saveAction);
    rebuildRecentMenu();
}

void FileController::rebuildRecentMenu() {
    m_recentMenu->clear();
    const QStringList paths = RecentFiles::list();
    for (int i = 0; i < paths.size(); ++i) {
        const QString& path = paths[i];
        // 1..9 and 0 as keyboard mnemonics; an '&' in a file name must not become one.
        const QString number = i < 9 ? QStringLiteral("&%1").arg(i + 1) : QStringLiteral("1&0");
        QString label = fileName(path);
        label.replace(QLatin1Char('&'), QLatin1String("&&"));
        QString folder = shortFolder(path);
        folder.replace(QLatin1Char('&'), QLatin1String("&&"));
        QAction* action = m_recentMenu->addAction(QStringLiteral("%1  %2    %3").arg(number, label, folder));
        action->setObjectName("RecentFileAction");
        action->setData(path);
        action->setStatusTip(QDir::toNativeSeparators(path));
        action->setToolTip(QDir::toNativeSeparators(path));
        connect(action, &QAction::triggered, this, [this, path] { openRecent(path); });
    }
    if (paths.isEmpty()) {
        QAction* none = m_recentMenu->addAction(tr("No Recent Files"));
        none->setEnabled(false);
    }
    m_recentMenu->addSeparator();
    QAction* clear = m_recentMenu->addAction(tr("&Clear Recent Files"));
    clear->setObjectName("ClearRecentAction");
    clear->setEnabled(!paths.isEmpty());
    connect(clear, &QAction::triggered, this, [this] {
        RecentFiles::clear();
        rebuildRecentMenu();
    });
}

void FileController::openRecent(const QString& path) {
    if (!QFileInfo::exists(path)) {
        RecentFiles::remove(path);
        rebuildRecentMenu();
        QMessageBox box(QMessageBox::Warning, tr("Open Recent"), tr("“%1” no longer exists.").arg(fileName(path)),
                        QMessageBox::Ok, m_window);
        box.setObjectName("MissingRecentBox");
        box.setInformativeText(tr("It was moved, renamed or deleted, so it was removed from the recent files.\n\n%1")
                                   .arg(QDir::toNativeSeparators(path)));
        box.exec();
        return;
    }
    open(path);
}

bool FileController::newScene() {
    if (!maybeSave(Reason::New))
        return false;
    m_window->document()->reset(Scene{}, QString());
    m_recovery->remove();
    m_changedSinceAutosave = false;
    m_window->viewport()->frameAll();
    showStatus(tr("New scene"));
    return true;
}

bool FileController::open(const QString& path) {
    if (!maybeSave(Reason::Open))
        return false;
    m_askedBeforeOpen = true;
    const auto reset = qScopeGuard([this] { m_askedBeforeOpen = false; });
    const bool opened = m_window->openFile(path);
    if (opened) {
        RecentFiles::add(path);
        rememberFolder(path);
    }
    return opened;
}

bool FileController::openScene(const QString& path) {
    if (!m_askedBeforeOpen && !maybeSave(Reason::Open))
        return false;
    SceneDocument* document = m_window->document();
    QString error;
    bool loaded = false;
    {
        WaitCursor wait;
        loaded = document->load(path, &error);
    }
    if (!loaded) {
        showError(tr("Could not open “%1”.").arg(fileName(path)), error);
        return false;
    }
    RecentFiles::add(path);
    rememberFolder(path);
    // The autosaved copy held changes the user has just chosen to leave.
    m_recovery->remove();
    m_changedSinceAutosave = false;
    m_window->viewport()->frameContents();
    showStatus(tr("Opened %1: %n bodies", "", document->bodyCount()).arg(fileName(path)));
    return true;
}

bool FileController::importScenes(const QStringList& paths) {
    SceneDocument* document = m_window->document();
    std::vector<Scene> scenes;
    QStringList names;
    QStringList errors;
    {
        WaitCursor wait;
        for (const QString& path : paths) {
            Result<Scene> loaded = importScene(path.toStdString());
            if (!loaded) {
                errors << QString::fromStdString(loaded.error().toString());
                continue;
            }
            Scene scene = std::move(loaded).value();
            if (scene.bodies.empty()) {
                errors << tr("%1: the file holds no bodies").arg(QDir::toNativeSeparators(path));
                continue;
            }
            SceneDocument::makeObjPathsAbsolute(scene, path);
            scenes.push_back(std::move(scene));
            names << fileName(path);
        }
    }
    if (!errors.isEmpty())
        showError(paths.size() == 1
                      ? tr("Could not import “%1”.").arg(fileName(paths.first()))
                      : tr("%n of %1 files could not be imported.", "", int(errors.size())).arg(paths.size()),
                  errors.join(QLatin1Char('\n')));
    if (scenes.empty())
        return false;

    ImportPlan plan = planImport(document->scene(), scenes);
    const int first = document->bodyCount();
    const int count = static_cast<int>(plan.bodies.size());
    const int renamed = plan.renamedBodies;
    const QString source = names.size() == 1 ? names.first() : tr("%n files", "", int(names.size()));
    document->undoStack()->push(new ImportBodiesCommand(document, std::move(plan), source));

    QList<int> imported;
    for (int i = 0; i < count; ++i)
        imported.append(first + i);
    m_window->setSelectedBodies(imported);
    QString message = tr("Imported %n bodies from %1", "", count).arg(source);
    if (renamed > 0)
        message += tr("; %n renamed to keep names unique", "", renamed);
    showStatus(message);
    return errors.isEmpty();
}

bool FileController::save() {
    const QString path = m_window->document()->filePath();
    if (path.isEmpty() || lowerSuffix(path) != QLatin1String("rlscene"))
        return saveAs();
    return saveTo(path);
}

bool FileController::saveAs() {
    const QString current = m_window->document()->filePath();
    QString suggested;
    if (current.isEmpty()) {
        suggested = startFolder() + QLatin1Char('/') + tr("Untitled") + QStringLiteral(".rlscene");
    } else {
        const QFileInfo info(current);
        suggested = info.absolutePath() + QLatin1Char('/') + info.completeBaseName() + QStringLiteral(".rlscene");
    }
    QString path;
    if (m_savePathProvider) {
        path = m_savePathProvider(suggested);
    } else {
        QFileDialog dialog(m_window, tr("Save Scene As"), suggested, tr("RigidLab scenes (*.rlscene)"));
        dialog.setObjectName("SaveAsDialog");
        dialog.setAcceptMode(QFileDialog::AcceptSave);
        dialog.setDefaultSuffix(QStringLiteral("rlscene"));
        if (dialog.exec() == QDialog::Accepted)
            path = dialog.selectedFiles().value(0);
    }
    if (path.isEmpty())
        return false;
    return saveAs(path);
}

bool FileController::saveAs(const QString& path) {
    QString target = path;
    // Only .rlscene is written: "scene" and "scene.obj" become "scene.rlscene" and "scene.obj.rlscene", so that a
    // mesh file is never replaced by JSON.
    if (lowerSuffix(target) != QLatin1String("rlscene"))
        target += QStringLiteral(".rlscene");
    return saveTo(target);
}

bool FileController::saveTo(const QString& path) {
    QString error;
    bool saved = false;
    {
        WaitCursor wait;
        saved = m_window->document()->save(path, &error);
    }
    if (!saved) {
        showError(tr("Could not save “%1”.").arg(fileName(path)),
                  tr("%1\n\nNothing was overwritten and your changes are still open. Try File > Save As with "
                     "another name or folder.")
                      .arg(error));
        return false;
    }
    RecentFiles::add(path);
    rememberFolder(path);
    m_recovery->remove();
    m_changedSinceAutosave = false;
    showStatus(tr("Saved %1").arg(QDir::toNativeSeparators(path)));
    return true;
}

bool FileController::revert() {
    SceneDocument* document = m_window->document();
    const QString path = document->filePath();
    if (!document->isModified() || path.isEmpty())
        return false;
    QMessageBox box(QMessageBox::Warning, tr("Revert to Saved"),
                    tr("Revert “%1” to the saved version?").arg(document->displayName()), QMessageBox::Cancel,
                    m_window);
    box.setObjectName("RevertBox");
    QUndoStack* stack = document->undoStack();
    const bool throughUndo = stack->cleanIndex() >= 0;
    box.setInformativeText(throughUndo ? tr("The changes since the last save are undone; Redo brings them back.")
                                       : tr("The file is read again; the changes since the last save are lost."));
    QPushButton* revertButton = box.addButton(tr("&Revert"), QMessageBox::DestructiveRole);
    revertButton->setObjectName("RevertButton");
    box.setDefaultButton(QMessageBox::Cancel);
    box.setEscapeButton(QMessageBox::Cancel);
    box.exec();
    if (box.clickedButton() != revertButton)
        return false;
    if (throughUndo) {
        stack->setIndex(stack->cleanIndex());
        showStatus(tr("Reverted to the saved %1").arg(document->displayName()));
        return true;
    }
    m_askedBeforeOpen = true;
    const auto reset = qScopeGuard([this] { m_askedBeforeOpen = false; });
    return openScene(path);
}

void FileController::openDroppedFiles(const QStringList& paths) {
    QStringList scenes;
    QStringList bakes;
    QStringList others;
    for (const QString& path : paths) {
        if (isSceneFile(path))
            scenes << path;
        else if (isBakeFile(path))
            bakes << path;
        else
            others << path;
    }
    m_window->activateWindow();
    QStringList ignored = others;
    if (!scenes.isEmpty()) {
        // The first file becomes the scene and the others are added to it, so dropping a folder's part files
        // builds one scene; the import is one undo step.
        ignored += bakes;
        if (open(scenes.first()) && scenes.size() > 1)
            importScenes(scenes.mid(1));
    } else if (!bakes.isEmpty()) {
        ignored += bakes.mid(1);
        open(bakes.first());
    }
    if (ignored.isEmpty())
        return;
    QStringList names;
    for (const QString& path : ignored)
        names << fileName(path);
    if (scenes.isEmpty() && bakes.isEmpty())
        showError(tr("RigidLab cannot open %1.").arg(names.join(QStringLiteral(", "))),
                  tr("It opens scenes (.rlscene, OBJ, glTF, FBX, COLLADA, PLY, STL, 3DS) and .bake files."));
    else
        m_window->statusBar()->showMessage(
            m_window->statusBar()->currentMessage() + QStringLiteral("  ·  ") +
                tr("Ignored: %1 (only one bake opens, and never together with scenes)").arg(names.join(", ")),
            8000);
}

bool FileController::maybeSave(Reason reason) {
    SceneDocument* document = m_window->document();
    if (!document->isModified())
        return true;
    QString question;
    switch (reason) {
    case Reason::Close:
        question = tr("Do you want to save the changes to “%1” before closing?");
        break;
    case Reason::New:
        question = tr("Do you want to save the changes to “%1” before starting a new scene?");
        break;
    case Reason::Open:
        question = tr("Do you want to save the changes to “%1” before opening another scene?");
        break;
    }
    QMessageBox box(QMessageBox::Warning, tr("Unsaved Changes"), question.arg(document->displayName()),
                    QMessageBox::Save | QMessageBox::Discard | QMessageBox::Cancel, m_window);
    box.setObjectName("UnsavedChangesBox");
    box.setInformativeText(tr("Your changes will be lost if you don't save them."));
    box.setDefaultButton(QMessageBox::Save);
    box.setEscapeButton(QMessageBox::Cancel);
    switch (box.exec()) {
    case QMessageBox::Save:
        return save();
    case QMessageBox::Discard:
        return true;
    default:
        return false;
    }
}

void FileController::setAutosaveInterval(int msec) {
    if (msec <= 0) {
        m_autosaveTimer->stop();
        return;
    }
    m_autosaveTimer->start(msec);
}

int FileController::autosaveInterval() const {
    return m_autosaveTimer->isActive() ? m_autosaveTimer->interval() : 0;
}

bool FileController::autosave() {
    SceneDocument* document = m_window->document();
    if (!document->isModified()) {
        m_recovery->remove(); // the file on disk holds everything
        m_changedSinceAutosave = false;
        return true;
    }
    if (!m_changedSinceAutosave && QFileInfo::exists(m_recovery->path()))
        return true;
    QString error;
    if (!m_recovery->write(*document, &error)) {
        m_window->statusBar()->showMessage(tr("Autosave failed: %1").arg(error), 10000);
        return false;
    }
    m_changedSinceAutosave = false;
    m_window->statusBar()->showMessage(
        tr("Autosaved unsaved changes at %1").arg(QLocale().toString(QTime::currentTime(), QLocale::ShortFormat)),
        3000);
    return true;
}

QString FileController::recoveryFilePath() const {
    return m_recovery->path();
}

bool FileController::offerRecovery() {
    std::optional<RecoveryStore::Orphan> orphan = m_recovery->findOrphan();
    if (!orphan)
        return false;
    const QString name = orphan->sourcePath.isEmpty() ? tr("Untitled") : fileName(orphan->sourcePath);
    QMessageBox box(QMessageBox::Question, tr("Recover Unsaved Work"),
                    tr("RigidLab did not close normally. Unsaved changes to “%1” were autosaved on %2.")
                        .arg(name, QLocale().toString(orphan->saved, QLocale::ShortFormat)),
                    QMessageBox::NoButton, m_window);
    box.setObjectName("RecoveryBox");
    box.setInformativeText(tr("Restore opens them as an unsaved scene; Discard deletes the autosaved copy; "
                              "Not Now keeps it for the next start."));
    QPushButton* restore = box.addButton(tr("&Restore"), QMessageBox::AcceptRole);
    restore->setObjectName("RestoreButton");
    QPushButton* discard = box.addButton(QMessageBox::Discard);
    box.setEscapeButton(box.addButton(tr("&Not Now"), QMessageBox::RejectRole));
    box.setDefaultButton(restore);
    box.exec();
    if (box.clickedButton() == discard) {
        RecoveryStore::discard(*orphan);
        return false;
    }
    if (box.clickedButton() != restore || !maybeSave(Reason::Open))
        return false;

    Result<Scene> loaded = importScene(orphan->path.toStdString());
    if (!loaded) {
        showError(tr("Could not restore the autosaved copy."),
                  tr("%1\n\nThe copy was kept at %2.")
                      .arg(QString::fromStdString(loaded.error().toString()), QDir::toNativeSeparators(orphan->path)));
        return false;
    }
    Scene scene = std::move(loaded).value();
    scene.sourcePath = orphan->sourcePath.toStdString();
    SceneDocument* document = m_window->document();
    document->reset(std::move(scene), orphan->sourcePath);
    document->markModified();
    // Our own copy first, then the old one goes: a crash in between loses nothing.
    m_changedSinceAutosave = true;
    if (autosave())
        RecoveryStore::discard(*orphan);
    m_window->viewport()->frameContents();
    showStatus(tr("Restored unsaved changes to %1").arg(name));
    return true;
}

void FileController::setSavePathProvider(PathProvider provider) {
    m_savePathProvider = std::move(provider);
}

bool FileController::isSceneFile(const QString& path) {
    const QString suffix = lowerSuffix(path);
    if (suffix.isEmpty())
        return false;
    return suffix == QLatin1String("rlscene") || suffix == QLatin1String("obj") ||
           assimpReadsExtension(suffix.toStdString());
}

bool FileController::isBakeFile(const QString& path) {
    return lowerSuffix(path) == QLatin1String("bake");
}

QStringList FileController::askOpenPaths(const QString& title, bool many) {
    const QString scenes = QStringLiteral("*.rlscene *.obj *.gltf *.glb *.fbx *.dae *.ply *.stl *.3ds");
    QStringList filters;
    if (many) {
        filters << tr("Scenes (%1)").arg(scenes);
    } else {
        filters << tr("Scenes and bakes (%1 *.bake)").arg(scenes);
        filters << tr("Bakes (*.bake)");
    }
    filters << tr("RigidLab scenes (*.rlscene)") << tr("Wavefront OBJ (*.obj)") << tr("All files (*)");
    const QString filter = filters.join(QStringLiteral(";;"));
    if (many)
        return QFileDialog::getOpenFileNames(m_window, title, startFolder(), filter);
    const QString path = QFileDialog::getOpenFileName(m_window, title, startFolder(), filter);
    return path.isEmpty() ? QStringList{} : QStringList{path};
}

void FileController::showError(const QString& text, const QString& details) {
    QMessageBox box(QMessageBox::Critical, tr("RigidLab"), text, QMessageBox::Ok, m_window);
    box.setObjectName("FileErrorBox");
    box.setInformativeText(details);
    box.setTextInteractionFlags(Qt::TextSelectableByMouse);
    // Paths and core messages are long: a wider box than QMessageBox picks keeps them on a line or two.
    box.setStyleSheet(QStringLiteral("QLabel#qt_msgbox_label, QLabel#qt_msgbox_informativelabel { min-width: 32em; }"));
    box.exec();
}

void FileController::showStatus(const QString& message) {
    m_window->statusBar()->showMessage(message, 8000);
}

QString FileController::startFolder() const {
    const QString current = m_window->document()->filePath();
    if (!current.isEmpty())
        return QFileInfo(current).absolutePath();
    const QString last = QSettings().value(QLatin1String(kLastFolderKey)).toString();
    if (!last.isEmpty() && QFileInfo(last).isDir())
        return last;
    return QStandardPaths::writableLocation(QStandardPaths::DocumentsLocation);
}

void FileController::rememberFolder(const QString& path) {
    QSettings().setValue(QLatin1String(kLastFolderKey), QFileInfo(path).absolutePath());
}

} // namespace rl
