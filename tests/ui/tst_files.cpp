// File handling in the editor: Save / Save As round trips, failed saves that keep the work, the recent list, Import
// with Blender-style renaming and undo, the unsaved-changes prompt, autosave and crash recovery, drag and drop.
// Settings and the recovery folder live in a private XDG folder, so a user's settings are never touched.
#include "MainWindow.h"
#include "document/SceneDocument.h"
#include "document/commands/ImportBodiesCommand.h"
#include "document/commands/SetBodyCommand.h"
#include "files/FileController.h"
#include "files/RecentFiles.h"
#include "files/RecoveryStore.h"
#include "io/SceneImport.h"
#include "ui/GuiTestSetup.h"
#include "viewport/Viewport.h"

#include <QAbstractButton>
#include <QApplication>
#include <QDir>
#include <QDropEvent>
#include <QFile>
#include <QMenu>
#include <QMessageBox>
#include <QMimeData>
#include <QPointer>
#include <QPushButton>
#include <QSettings>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QStatusBar>
#include <QTemporaryDir>
#include <QTest>
#include <QTimer>
#include <QUrl>
#include <QWindow>

#include <cmath>
#include <functional>
#include <limits>
#include <unistd.h>

namespace {

const QString kScenes = QStringLiteral(RL_SOURCE_DIR "/resources/scenes/");
const QString kData = QStringLiteral(RL_TEST_DATA_DIR "/");

// Answers message boxes as they appear: polls the top-level widgets, so it does not depend on when exec() starts.
// Each box seen is recorded (object name, text and informative text), then answered by `answer` (the default
// presses Escape's button, or OK).
class BoxAnswerer : public QObject {
public:
    using Answer = std::function<QAbstractButton*(QMessageBox*)>;
    explicit BoxAnswerer(Answer answer = {}) : m_answer(std::move(answer)) {
        connect(&m_timer, &QTimer::timeout, this, &BoxAnswerer::poll);
        m_timer.start(20);
    }
    static Answer press(QMessageBox::StandardButton button) {
        return [button](QMessageBox* box) { return box->button(button); };
    }
    static Answer pressNamed(const char* name) {
        return [name](QMessageBox* box) { return box->findChild<QAbstractButton*>(QLatin1String(name)); };
    }

    struct Seen {
        QString name;
        QString text;
    };
    QList<Seen> seen;
    QString names() const {
        QStringList out;
        for (const Seen& s : seen)
            out << s.name + QStringLiteral(": ") + s.text;
        return out.join(QStringLiteral(" | "));
    }

private:
    void poll() {
        for (QWidget* widget : QApplication::topLevelWidgets()) {
            auto* box = qobject_cast<QMessageBox*>(widget);
            if (!box || !box->isVisible() || m_answered.contains(box))
                continue;
            m_answered.append(box);
            seen.append({box->objectName(), box->text() + QLatin1Char('\n') + box->informativeText()});
            QAbstractButton* button = m_answer ? m_answer(box) : nullptr;
            if (!button)
                button = box->escapeButton() ? box->escapeButton() : box->buttons().value(0);
            QMetaObject::invokeMethod(button, &QAbstractButton::click, Qt::QueuedConnection);
        }
    }
    Answer m_answer;
    QTimer m_timer;
    QList<QPointer<QMessageBox>> m_answered;
};

// World, materials and bodies: what a .rlscene holds (the source path and OBJ text say where it came from).
bool sameDefinitions(const rl::Scene& a, const rl::Scene& b, QString* why) {
    if (!(a.world == b.world)) {
        *why = QStringLiteral("world settings differ");
        return false;
    }
    if (a.materials != b.materials) {
        *why = QStringLiteral("materials differ");
        return false;
    }
    if (a.bodies.size() != b.bodies.size()) {
        *why = QStringLiteral("%1 bodies vs %2").arg(a.bodies.size()).arg(b.bodies.size());
        return false;
    }
    for (size_t i = 0; i < a.bodies.size(); ++i)
        if (!(a.bodies[i] == b.bodies[i])) {
            *why = QStringLiteral("body %1 '%2' differs").arg(i).arg(QString::fromStdString(a.bodies[i].name));
            return false;
        }
    return true;
}

void editBody(rl::SceneDocument* document, int index, const std::function<void(rl::BodyDef&)>& edit) {
    rl::BodyDef body = document->body(index);
    edit(body);
    document->undoStack()->push(new rl::SetBodyCommand(document, index, body, QStringLiteral("test edit")));
}

QByteArray readAll(const QString& path) {
    QFile file(path);
    return file.open(QIODevice::ReadOnly) ? file.readAll() : QByteArray();
}

void writeFile(const QString& path, const QByteArray& bytes) {
    QFile file(path);
    QVERIFY(file.open(QIODevice::WriteOnly));
    file.write(bytes);
}

QStringList bodyNames(const rl::SceneDocument* document) {
    QStringList names;
    for (int i = 0; i < document->bodyCount(); ++i)
        names << QString::fromStdString(document->body(i).name);
    return names;
}

} // namespace

class TestFiles : public QObject {
    Q_OBJECT
public:
    static void initMain() {
        rl::test::prepareGuiTest();
        // A private home for QSettings (XDG_CONFIG_HOME) and the recovery folder (XDG_DATA_HOME).
        static QTemporaryDir home(QDir::tempPath() + QStringLiteral("/rigidlab-tst-files-XXXXXX"));
        qputenv("XDG_CONFIG_HOME", (home.path() + QStringLiteral("/config")).toLocal8Bit());
        qputenv("XDG_DATA_HOME", (home.path() + QStringLiteral("/data")).toLocal8Bit());
        s_home = home.path();
    }

private:
    static inline QString s_home;

    static bool showAndOpen(rl::MainWindow& window, const QString& path) {
        window.show();
        return QTest::qWaitForWindowExposed(&window) && window.openFile(path);
    }

private slots:
    void initTestCase() {
        QVERIFY(!s_home.isEmpty());
        QVERIFY2(QStandardPaths::writableLocation(QStandardPaths::AppDataLocation).startsWith(s_home),
                 qPrintable(QStandardPaths::writableLocation(QStandardPaths::AppDataLocation)));
        QVERIFY2(QSettings().fileName().startsWith(s_home), qPrintable(QSettings().fileName()));
    }

    void init() {
        QSettings().clear();
        QDir(rl::RecoveryStore::directory()).removeRecursively();
    }

    // Save -> open again gives the same world, materials and bodies, bit for bit. The .rlscene row has an "obj"
    // shape with a relative path: saved into another folder, the path is rewritten so that the OBJ is still found.
    void saveAndReopenIsExact_data() {
        QTest::addColumn<QString>("source");
        QTest::newRow("obj") << kScenes + "stack.obj";
        QTest::newRow("rlscene with obj shape") << kData + "formats/design_example.rlscene";
        QTest::newRow("many bodies") << kScenes + "mixed.obj";
    }
    void saveAndReopenIsExact() {
        QFETCH(QString, source);
        QTemporaryDir dir;
        BoxAnswerer boxes;
        rl::MainWindow window;
        QVERIFY(showAndOpen(window, source));
        rl::SceneDocument* document = window.document();
        // An edit with digits that only survive a shortest-round-trip writer.
        editBody(document, 1, [](rl::BodyDef& b) {
            b.position.x = 0.1 + 0.2;
            b.velocity = {1.0 / 3.0, -2.5e-7, 1e300};
            b.friction = 0.7;
        });
        QVERIFY(document->isModified());
        QVERIFY(window.isWindowModified());
        const rl::Scene before = document->scene();

        const QString path = dir.filePath("sub/../saved.rlscene");
        QVERIFY(QDir().mkpath(dir.filePath("sub")));
        QVERIFY(window.files()->saveAs(path));
        QVERIFY2(boxes.seen.isEmpty(), qPrintable(boxes.names()));
        QVERIFY(!document->isModified());
        QVERIFY(!window.isWindowModified());
        QCOMPARE(document->filePath(), path);
        QVERIFY(window.windowTitle().startsWith("saved.rlscene"));

        rl::MainWindow reopened;
        QVERIFY(showAndOpen(reopened, path));
        QString why;
        QVERIFY2(sameDefinitions(before, reopened.document()->scene(), &why), qPrintable(why));
        QVERIFY(!reopened.document()->isModified());
        QVERIFY2(boxes.seen.isEmpty(), qPrintable(boxes.names()));
    }

    // Save on a scene opened from OBJ asks for a .rlscene path (never writes JSON into the .obj); afterwards Save
    // writes there without asking; the status bar and the recent list follow.
    void saveAsFromObjToNewPath() {
        QTemporaryDir dir;
        const QString obj = dir.filePath("stack.obj");
        QVERIFY(QFile::copy(kScenes + "stack.obj", obj));
        const QByteArray objBytes = readAll(obj);
        BoxAnswerer boxes;
        rl::MainWindow window;
        QVERIFY(showAndOpen(window, obj));
        rl::FileController* files = window.files();
        QStringList suggestions;
        QString answer = dir.filePath("copy"); // no extension: .rlscene is added
        files->setSavePathProvider([&](const QString& suggested) {
            suggestions << suggested;
            return answer;
        });
        editBody(window.document(), 2, [](rl::BodyDef& b) { b.anchor = true; });
        QVERIFY(files->save());
        QCOMPARE(suggestions, QStringList{dir.filePath("stack.rlscene")});
        QCOMPARE(window.document()->filePath(), dir.filePath("copy.rlscene"));
        QVERIFY(QFile::exists(dir.filePath("copy.rlscene")));
        QCOMPARE(readAll(obj), objBytes);
        QVERIFY(window.windowTitle().startsWith("copy.rlscene"));
        QVERIFY(window.statusBar()->currentMessage().contains("copy.rlscene"));
        QCOMPARE(rl::RecentFiles::list().value(0), dir.filePath("copy.rlscene"));

        // Save now goes to copy.rlscene without asking.
        editBody(window.document(), 3, [](rl::BodyDef& b) { b.anchor = true; });
        QVERIFY(files->save());
        QCOMPARE(suggestions.size(), 1);
        QVERIFY(!window.document()->isModified());
        QVERIFY(rl::importScene(dir.filePath("copy.rlscene").toStdString())->bodies[3].anchor);

        // Save As to an existing name ending in .obj writes name.obj.rlscene, the .obj stays.
        QVERIFY(files->saveAs(obj));
        QCOMPARE(readAll(obj), objBytes);
        QVERIFY(QFile::exists(obj + ".rlscene"));

        // A cancelled Save As dialog saves nothing and keeps the changes.
        editBody(window.document(), 4, [](rl::BodyDef& b) { b.anchor = true; });
        answer.clear();
        QVERIFY(!files->saveAs());
        QVERIFY(window.document()->isModified());
        QVERIFY2(boxes.seen.isEmpty(), qPrintable(boxes.names()));
    }

    // A save that fails shows a message naming the file and the problem, keeps the document modified and leaves the
    // old file as it was.
    void failedSaveKeepsWork_data() {
        QTest::addColumn<QString>("kind");
        QTest::addColumn<QString>("problem");
        QTest::newRow("missing folder") << "missing folder"
                                        << "saved.rlscene";
        QTest::newRow("folder is a file") << "folder is a file"
                                          << "saved.rlscene";
        QTest::newRow("read-only folder") << "read-only folder"
                                          << "saved.rlscene";
        QTest::newRow("NaN position") << "nan"
                                      << "Cube.002";
        // Unwritable even for root, where the read-only folder row is skipped.
        QTest::newRow("proc file system") << "proc"
                                          << "saved.rlscene";
    }
    void failedSaveKeepsWork() {
        QFETCH(QString, kind);
        QFETCH(QString, problem);
        QTemporaryDir dir;
        rl::MainWindow window;
        QVERIFY(showAndOpen(window, kScenes + "stack.obj"));
        rl::SceneDocument* document = window.document();
        QString target = dir.filePath("saved.rlscene");
        if (kind == "missing folder") {
            target = dir.filePath("missing/saved.rlscene");
        } else if (kind == "folder is a file") {
            writeFile(dir.filePath("file"), "x");
            target = dir.filePath("file/saved.rlscene");
        } else if (kind == "proc") {
            target = QStringLiteral("/proc/saved.rlscene");
        } else if (kind == "read-only folder") {
            QVERIFY(window.files()->saveAs(target));
            QFile::setPermissions(dir.path(), QFileDevice::ReadOwner | QFileDevice::ExeOwner);
            if (QFileInfo(dir.path()).isWritable() || ::access(qPrintable(dir.path()), W_OK) == 0) {
                QFile::setPermissions(dir.path(),
                                      QFileDevice::ReadOwner | QFileDevice::WriteOwner | QFileDevice::ExeOwner);
                QSKIP("running as root: a read-only folder is still writable");
            }
        } else {
            QVERIFY(window.files()->saveAs(target));
        }
        const QByteArray oldBytes = readAll(target);
        const QString oldPath = document->filePath();
        editBody(document, 3, [&](rl::BodyDef& b) {
            b.anchor = true;
            if (kind == "nan")
                b.position.y = std::numeric_limits<double>::quiet_NaN();
        });

        BoxAnswerer boxes;
        QVERIFY(!window.files()->saveAs(target));
        QFile::setPermissions(dir.path(), QFileDevice::ReadOwner | QFileDevice::WriteOwner | QFileDevice::ExeOwner);
        QCOMPARE(boxes.seen.size(), 1);
        QCOMPARE(boxes.seen[0].name, QStringLiteral("FileErrorBox"));
        QVERIFY2(boxes.seen[0].text.contains(problem), qPrintable(boxes.seen[0].text));
        QVERIFY2(boxes.seen[0].text.contains("saved.rlscene"), qPrintable(boxes.seen[0].text));
        QVERIFY(document->isModified());
        QVERIFY(window.isWindowModified());
        QCOMPARE(document->filePath(), oldPath);
        QCOMPARE(readAll(target), oldBytes);
        QVERIFY(document->body(3).anchor);
        // No temporary file is left next to the target.
        if (kind != "proc" && QFileInfo(target).absoluteDir().exists())
            QCOMPARE(QFileInfo(target).absoluteDir().entryList(QDir::Files | QDir::Hidden).size(),
                     oldBytes.isEmpty() ? 0 : 1);
    }

    // Bad input on open: the message names the file, the line and the problem; the scene shown stays.
    void openErrorNamesFileAndLine() {
        rl::MainWindow window;
        QVERIFY(showAndOpen(window, kScenes + "stack.obj"));
        BoxAnswerer boxes;
        QVERIFY(!window.openFile(kData + "import/obj/garbled_number.obj"));
        QCOMPARE(boxes.seen.size(), 1);
        QVERIFY2(boxes.seen[0].text.contains("garbled_number.obj:4"), qPrintable(boxes.seen[0].text));
        QCOMPARE(window.document()->bodyCount(), 11);
        QVERIFY(window.windowTitle().startsWith("stack.obj"));
    }

    // Most recent first, no duplicates (also through "..", or a symlink), at most ten, Clear empties it.
    void recentFilesOrderDedupLimit() {
        QTemporaryDir dir;
        QStringList paths;
        for (int i = 0; i < 12; ++i) {
            paths << dir.filePath(QStringLiteral("scene%1.rlscene").arg(i));
            writeFile(paths.last(), "{}");
            rl::RecentFiles::add(paths.last());
        }
        QStringList expected;
        for (int i = 11; i >= 2; --i)
            expected << paths[i];
        QCOMPARE(rl::RecentFiles::list(), expected);
        QCOMPARE(rl::RecentFiles::kMaxCount, 10);

        rl::RecentFiles::add(dir.filePath("x/../scene5.rlscene"));
        expected.removeAll(paths[5]);
        expected.prepend(paths[5]);
        QCOMPARE(rl::RecentFiles::list(), expected);

        QVERIFY(QFile::link(paths[7], dir.filePath("link.rlscene")));
        rl::RecentFiles::add(dir.filePath("link.rlscene"));
        expected.removeAll(paths[7]);
        expected.prepend(paths[7]);
        QCOMPARE(rl::RecentFiles::list(), expected);

        // The list lives in QSettings, so a new window (and a new session) sees it.
        rl::MainWindow window;
        auto* menu = window.findChild<QMenu*>("RecentMenu");
        QVERIFY(menu);
        emit menu->aboutToShow();
        QStringList shown;
        for (QAction* action : menu->actions())
            if (action->objectName() == "RecentFileAction")
                shown << action->data().toString();
        QCOMPARE(shown, expected);
        QVERIFY2(menu->actions().first()->text().startsWith("&1  scene7.rlscene"),
                 qPrintable(menu->actions().first()->text()));

        auto* clear = menu->findChild<QAction*>("ClearRecentAction");
        QVERIFY(clear && clear->isEnabled());
        clear->trigger();
        QVERIFY(rl::RecentFiles::list().isEmpty());
        emit menu->aboutToShow();
        QVERIFY(!menu->findChild<QAction*>("ClearRecentAction")->isEnabled());
    }

    // Choosing a recent file that is gone says so and removes it; one that exists opens and moves to the top.
    void recentFileMissingIsRemoved() {
        QTemporaryDir dir;
        const QString kept = dir.filePath("kept.obj");
        const QString gone = dir.filePath("gone.obj");
        QVERIFY(QFile::copy(kScenes + "stack.obj", kept));
        QVERIFY(QFile::copy(kScenes + "mixed.obj", gone));
        rl::RecentFiles::add(gone);
        rl::RecentFiles::add(kept);
        QVERIFY(QFile::remove(gone));
        rl::MainWindow window;
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        auto* menu = window.findChild<QMenu*>("RecentMenu");
        emit menu->aboutToShow();
        auto actionFor = [&](const QString& path) -> QAction* {
            for (QAction* action : menu->actions())
                if (action->data().toString() == path)
                    return action;
            return nullptr;
        };
        QVERIFY(actionFor(gone));
        BoxAnswerer boxes;
        actionFor(gone)->trigger();
        QCOMPARE(boxes.seen.size(), 1);
        QCOMPARE(boxes.seen[0].name, QStringLiteral("MissingRecentBox"));
        QVERIFY(boxes.seen[0].text.contains("gone.obj"));
        QCOMPARE(rl::RecentFiles::list(), QStringList{kept});
        QVERIFY(!actionFor(gone));

        rl::RecentFiles::add(kScenes + "mixed.obj");
        emit menu->aboutToShow();
        actionFor(kept)->trigger();
        QCOMPARE(window.document()->filePath(), kept);
        QCOMPARE(rl::RecentFiles::list().value(0), kept);
        QCOMPARE(boxes.seen.size(), 1);
    }

    void uniqueNameIsBlenderStyle_data() {
        QTest::addColumn<QString>("name");
        QTest::addColumn<QStringList>("taken");
        QTest::addColumn<QString>("expected");
        QTest::newRow("free") << "Cube" << QStringList{"Sphere"} << "Cube";
        QTest::newRow("taken") << "Cube" << QStringList{"Cube"} << "Cube.001";
        QTest::newRow("next free") << "Cube" << QStringList{"Cube", "Cube.001", "Cube.003"} << "Cube.002";
        QTest::newRow("numbered") << "Cube.001" << QStringList{"Cube", "Cube.001"} << "Cube.002";
        QTest::newRow("anchor") << "Anchor" << QStringList{"Anchor"} << "Anchor.001";
        QTest::newRow("dot not number") << "v1.5a" << QStringList{"v1.5a"} << "v1.5a.001";
        QTest::newRow("trailing dot") << "a." << QStringList{"a."} << "a..001";
    }
    void uniqueNameIsBlenderStyle() {
        QFETCH(QString, name);
        QFETCH(QStringList, taken);
        QFETCH(QString, expected);
        const std::string result = rl::uniqueName(
            name.toStdString(), [&](const std::string& n) { return taken.contains(QString::fromStdString(n)); });
        QCOMPARE(QString::fromStdString(result), expected);
    }

    // Import adds the other file's bodies as one undo step; clashing names get .001 (.002 the second time), a
    // renamed Anchor stays an anchor, the imported bodies end selected; undo takes exactly them out again.
    void importMergesWithRenamesAndUndo() {
        BoxAnswerer boxes;
        rl::MainWindow window;
        QVERIFY(showAndOpen(window, kScenes + "stack.obj"));
        rl::SceneDocument* document = window.document();
        const rl::Scene original = document->scene();
        const QStringList originalNames = bodyNames(document);
        // One change signal for the whole import: views rebuild once, not once per body.
        QSignalSpy inserted(document, &rl::SceneDocument::bodyInserted);
        QSignalSpy removed(document, &rl::SceneDocument::bodyRemoved);
        QVERIFY(window.files()->importScenes({kScenes + "stack.obj"}));
        QCOMPARE(inserted.size(), 1);
        QCOMPARE(inserted[0], (QVariantList{11, 11}));
        QCOMPARE(document->bodyCount(), 22);
        QCOMPARE(document->undoStack()->count(), 1);
        QCOMPARE(document->undoStack()->undoText(), QStringLiteral("Import stack.obj"));
        QStringList names = bodyNames(document);
        QCOMPARE(names.mid(0, 11), originalNames);
        QCOMPARE(names[11], QStringLiteral("Anchor.001"));
        QVERIFY(document->body(11).anchor);
        QCOMPARE(names[12], QStringLiteral("Cube.010")); // Cube .. Cube.009 exist: the lowest free number
        QCOMPARE(names[13], QStringLiteral("Cube.011"));
        names.removeDuplicates();
        QCOMPARE(names.size(), 22);
        QCOMPARE(window.selectedBodies().size(), 11);
        QCOMPARE(window.selectedBodies().first(), 11);
        QVERIFY(window.statusBar()->currentMessage().contains("11 renamed"));
        for (int i = 0; i < 11; ++i) { // everything but the name is as in the file
            rl::BodyDef imported = document->body(11 + i);
            imported.name = original.bodies[size_t(i)].name;
            QVERIFY(imported == original.bodies[size_t(i)]);
        }

        // Two files at once: one step.
        QVERIFY(window.files()->importScenes({kScenes + "stack.obj", kScenes + "mixed.obj"}));
        QCOMPARE(document->undoStack()->count(), 2);
        QCOMPARE(document->body(22).name, std::string("Anchor.002"));
        QCOMPARE(document->bodyCount(), 22 + 11 + 9);

        document->undoStack()->undo();
        QCOMPARE(document->bodyCount(), 22);
        document->undoStack()->undo();
        QCOMPARE(removed.size(), 2);
        QCOMPARE(removed[1], (QVariantList{11, 11}));
        QString why;
        QVERIFY2(sameDefinitions(document->scene(), original, &why), qPrintable(why));
        QVERIFY(!document->isModified());
        document->undoStack()->redo();
        QCOMPARE(bodyNames(document).value(11), QStringLiteral("Anchor.001"));
        QVERIFY2(boxes.seen.isEmpty(), qPrintable(boxes.names()));
    }

    // A material that the imported file defines differently is added under a new name, so no body's physics
    // change; an identical one is shared; undo restores the material list.
    void importRenamesClashingMaterials() {
        QTemporaryDir dir;
        const QByteArray head = R"({"format": "rigidlab-scene", "version": 1, "materials": {"Bouncy": )";
        writeFile(dir.filePath("a.rlscene"), head + R"({"density": 500, "friction": 0.2, "restitution": 0.9}},
                  "bodies": [{"name": "Ball", "shape": {"sphere": 0.5}, "material": "Bouncy"}]})");
        writeFile(dir.filePath("b.rlscene"), head + R"({"density": 800, "friction": 0.2, "restitution": 0.5},
                                "Same": {"density": 1, "friction": 0, "restitution": 0}},
                  "bodies": [{"name": "Ball", "shape": {"sphere": 0.5}, "material": "bouncy"},
                             {"name": "Other", "shape": {"sphere": 0.5}, "material": "Steel"}]})");
        rl::MainWindow window;
        QVERIFY(showAndOpen(window, dir.filePath("a.rlscene")));
        rl::SceneDocument* document = window.document();
        QVERIFY(window.files()->importScenes({dir.filePath("b.rlscene")}));
        QCOMPARE(document->scene().materials.size(), size_t(3));
        QCOMPARE(document->scene().materials[1].name, std::string("Bouncy.001"));
        QCOMPARE(document->scene().materials[1].density, 800.0);
        QCOMPARE(document->body(1).name, std::string("Ball.001"));
        QCOMPARE(document->body(1).material, std::string("Bouncy.001"));
        QCOMPARE(document->body(2).material, std::string("Steel"));
        QCOMPARE(document->scene().effectiveMaterial(document->body(0)).density, 500.0);
        // Importing b again reuses Bouncy.001 and Same (their values match).
        QVERIFY(window.files()->importScenes({dir.filePath("b.rlscene")}));
        QCOMPARE(document->scene().materials.size(), size_t(3));
        QCOMPARE(document->body(3).material, std::string("Bouncy.001"));
        document->undoStack()->undo();
        document->undoStack()->undo();
        QCOMPARE(document->scene().materials.size(), size_t(1));
        QCOMPARE(document->bodyCount(), 1);
    }

    // Save / Discard / Cancel on close, New and Open, answered by pressing the box's buttons.
    void unsavedChangesPrompt_data() {
        QTest::addColumn<QString>("trigger");
        QTest::addColumn<int>("button");
        QTest::addColumn<bool>("proceeds");
        QTest::addColumn<bool>("saved");
        for (const char* trigger : {"close", "new", "open"}) {
            QTest::addRow("%s save", trigger) << trigger << int(QMessageBox::Save) << true << true;
            QTest::addRow("%s discard", trigger) << trigger << int(QMessageBox::Discard) << true << false;
            QTest::addRow("%s cancel", trigger) << trigger << int(QMessageBox::Cancel) << false << false;
        }
    }
    void unsavedChangesPrompt() {
        QFETCH(QString, trigger);
        QFETCH(int, button);
        QFETCH(bool, proceeds);
        QFETCH(bool, saved);
        QTemporaryDir dir;
        const QString path = dir.filePath("scene.rlscene");
        auto* window = new rl::MainWindow;
        window->setAttribute(Qt::WA_DeleteOnClose, false);
        QVERIFY(showAndOpen(*window, kScenes + "stack.obj"));
        QVERIFY(window->files()->saveAs(path));
        editBody(window->document(), 1, [](rl::BodyDef& b) { b.anchor = true; });

        BoxAnswerer boxes(BoxAnswerer::press(QMessageBox::StandardButton(button)));
        bool done = false;
        if (trigger == "close")
            done = window->close();
        else if (trigger == "new")
            done = window->files()->newScene();
        else
            done = window->files()->open(kScenes + "mixed.obj");
        QCOMPARE(done, proceeds);
        QCOMPARE(boxes.seen.size(), 1);
        QCOMPARE(boxes.seen[0].name, QStringLiteral("UnsavedChangesBox"));
        QVERIFY2(boxes.seen[0].text.contains("scene.rlscene"), qPrintable(boxes.seen[0].text));
        QCOMPARE(rl::importScene(path.toStdString())->bodies[1].anchor, saved);
        if (trigger == "close")
            QCOMPARE(window->isVisible(), !proceeds);
        else if (trigger == "new")
            QCOMPARE(window->document()->bodyCount(), proceeds ? 0 : 11);
        else
            QCOMPARE(window->document()->bodyCount(), proceeds ? 9 : 11);
        if (!proceeds) { // the work is still there, unsaved
            QVERIFY(window->document()->isModified());
            QVERIFY(window->document()->body(1).anchor);
        }
        delete window;
        QCOMPARE(boxes.seen.size(), 1);
    }

    // Save in the prompt on an untitled scene asks for a path; cancelling that dialog cancels the close.
    void promptSaveOnUntitledAsksForPath() {
        QTemporaryDir dir;
        rl::MainWindow window;
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        QVERIFY(window.files()->importScenes({kScenes + "stack.obj"}));
        QVERIFY(window.document()->filePath().isEmpty());
        QVERIFY(window.windowTitle().startsWith("Untitled"));
        QString answer;
        window.files()->setSavePathProvider([&](const QString&) { return answer; });
        BoxAnswerer boxes(BoxAnswerer::press(QMessageBox::Save));
        QVERIFY(!window.close());
        QVERIFY(window.isVisible());
        answer = dir.filePath("named.rlscene");
        QVERIFY(window.close());
        QCOMPARE(rl::importScene(answer.toStdString())->bodies.size(), size_t(11));
        QCOMPARE(boxes.seen.size(), 2);
    }

    // Autosave writes the unsaved scene to the recovery file, removes it when the scene is clean again and when the
    // window closes normally.
    void autosaveWritesRecoveryFile() {
        BoxAnswerer boxes;
        QString recovery;
        {
            rl::MainWindow window;
            QVERIFY(showAndOpen(window, kScenes + "stack.obj"));
            rl::FileController* files = window.files();
            QCOMPARE(files->autosaveInterval(), 2 * 60 * 1000); // the default
            files->setAutosaveInterval(50);
            recovery = files->recoveryFilePath();
            QVERIFY(recovery.startsWith(QStandardPaths::writableLocation(QStandardPaths::AppDataLocation)));
            QTest::qWait(200);
            QVERIFY(!QFile::exists(recovery)); // nothing unsaved, nothing written

            editBody(window.document(), 4, [](rl::BodyDef& b) { b.position.y += 1.0; });
            QTRY_VERIFY_WITH_TIMEOUT(QFile::exists(recovery), 10000);
            rl::Result<rl::Scene> copy = rl::importScene(recovery.toStdString());
            QVERIFY(copy.ok());
            QString why;
            QVERIFY2(sameDefinitions(*copy, window.document()->scene(), &why), qPrintable(why));

            window.document()->undoStack()->undo();
            QTRY_VERIFY_WITH_TIMEOUT(!QFile::exists(recovery), 10000);
            window.document()->undoStack()->redo();
            QTRY_VERIFY_WITH_TIMEOUT(QFile::exists(recovery), 10000);
            files->setAutosaveInterval(0);
            QCOMPARE(files->autosaveInterval(), 0);
        }
        // The window went away normally (as after Discard on close): its copy and lock are gone.
        QVERIFY(!QFile::exists(recovery));
        QCOMPARE(QDir(rl::RecoveryStore::directory()).entryList(QDir::Files), QStringList());
        QVERIFY2(boxes.seen.isEmpty(), qPrintable(boxes.names()));
    }

    // A recovery file whose editor is gone (as after a crash) is offered at start-up; Restore brings the scene
    // back as unsaved work under its old file name, and the copy goes away. A running editor's copy is not offered.
    void crashRecoveryRestores_data() {
        QTest::addColumn<QString>("choice");
        QTest::newRow("restore") << "restore";
        QTest::newRow("discard") << "discard";
        QTest::newRow("not now") << "not now";
    }
    void crashRecoveryRestores() {
        QFETCH(QString, choice);
        QTemporaryDir dir;
        const QString path = dir.filePath("scene.rlscene");
        rl::Scene edited;
        QString crashed;
        {
            BoxAnswerer boxes;
            rl::MainWindow first;
            QVERIFY(showAndOpen(first, kScenes + "stack.obj"));
            QVERIFY(first.files()->saveAs(path));
            editBody(first.document(), 5, [](rl::BodyDef& b) { b.position.x += 0.25; });
            first.files()->setAutosaveInterval(50);
            QTRY_VERIFY_WITH_TIMEOUT(QFile::exists(first.files()->recoveryFilePath()), 10000);
            edited = first.document()->scene();

            // While the first editor runs, a second one does not offer its copy.
            {
                rl::MainWindow second;
                QVERIFY(!second.files()->offerRecovery());
                QTest::qWait(100); // its own start-up check runs too
            }
            QVERIFY2(boxes.seen.isEmpty(), qPrintable(boxes.names()));

            // What a crash leaves: the copy and its source note with no living owner.
            const QFileInfo copy(first.files()->recoveryFilePath());
            crashed = copy.absolutePath() + "/crashed.rlscene";
            QVERIFY(QFile::copy(copy.absoluteFilePath(), crashed));
            QVERIFY(QFile::copy(copy.absolutePath() + "/" + copy.completeBaseName() + ".source",
                                copy.absolutePath() + "/crashed.source"));
            first.files()->setAutosaveInterval(0);
        }
        // The clean exit removed the first editor's own copy.
        QCOMPARE(QDir(rl::RecoveryStore::directory()).entryList(QDir::Files),
                 QStringList({"crashed.rlscene", "crashed.source"}));

        const char* button = choice == "restore" ? "RestoreButton" : nullptr;
        BoxAnswerer boxes(button                ? BoxAnswerer::pressNamed(button)
                          : choice == "discard" ? BoxAnswerer::press(QMessageBox::Discard)
                                                : BoxAnswerer::Answer{});
        rl::MainWindow restarted; // offers the copy from its start-up check
        restarted.show();
        QTRY_COMPARE_WITH_TIMEOUT(boxes.seen.size(), 1, 10000);
        QCOMPARE(boxes.seen[0].name, QStringLiteral("RecoveryBox"));
        QVERIFY(boxes.seen[0].text.contains("scene.rlscene"));
        rl::SceneDocument* document = restarted.document();
        if (choice == "restore") {
            QTRY_COMPARE_WITH_TIMEOUT(document->bodyCount(), 11, 10000);
            QString why;
            QVERIFY2(sameDefinitions(document->scene(), edited, &why), qPrintable(why));
            QVERIFY(document->isModified());
            QCOMPARE(document->filePath(), path);
            QTRY_VERIFY(restarted.windowTitle().startsWith("scene.rlscene[*]") && restarted.isWindowModified());
            QVERIFY(!QFile::exists(crashed));
            QVERIFY(QFile::exists(restarted.files()->recoveryFilePath())); // its own copy replaces it
            // Save writes the restored work to its file.
            QVERIFY(restarted.files()->save());
            QString why2;
            QVERIFY2(sameDefinitions(*rl::importScene(path.toStdString()), edited, &why2), qPrintable(why2));
        } else {
            QTest::qWait(100);
            QCOMPARE(document->bodyCount(), 0);
            QCOMPARE(QFile::exists(crashed), choice == "not now");
        }
    }

    // A copy left by a crash is not put in front of a scene named on the command line (a modal box there took the
    // first key of a scripted session and Enter replaced the scene asked for): the status bar says it was kept, and
    // the copy stays for a start without a file. A copy of the very file being opened is still offered.
    void recoveryDoesNotReplaceTheSceneAskedFor() {
        // Leave an orphan behind, as a crash does.
        QString crashed;
        {
            BoxAnswerer boxes;
            rl::MainWindow first;
            QVERIFY(showAndOpen(first, kScenes + "stack.obj"));
            editBody(first.document(), 5, [](rl::BodyDef& b) { b.position.x += 0.25; });
            first.files()->setAutosaveInterval(50);
            QTRY_VERIFY_WITH_TIMEOUT(QFile::exists(first.files()->recoveryFilePath()), 10000);
            const QFileInfo copy(first.files()->recoveryFilePath());
            crashed = copy.absolutePath() + "/crashed.rlscene";
            QVERIFY(QFile::copy(copy.absoluteFilePath(), crashed));
            QVERIFY(QFile::copy(copy.absolutePath() + "/" + copy.completeBaseName() + ".source",
                                copy.absolutePath() + "/crashed.source"));
            first.files()->setAutosaveInterval(0);
        }
        {
            BoxAnswerer boxes(BoxAnswerer::pressNamed("RestoreButton"));
            rl::MainWindow restarted; // main.cpp: construct, show, open the file named on the command line
            restarted.show();
            QVERIFY(restarted.openFile(kScenes + "mixed.obj"));
            QTest::qWait(500); // the start-up check has run
            QVERIFY2(boxes.seen.isEmpty(), qPrintable(boxes.names()));
            QCOMPARE(restarted.document()->filePath(), QFileInfo(kScenes + "mixed.obj").absoluteFilePath());
            QVERIFY(!restarted.document()->isModified());
            QVERIFY(restarted.statusBar()->currentMessage().contains("stack.obj"));
            QVERIFY(QFile::exists(crashed));
        }
        {
            BoxAnswerer boxes(BoxAnswerer::press(QMessageBox::Discard));
            rl::MainWindow restarted; // no file: offered, and discarded here
            restarted.show();
            QTRY_COMPARE_WITH_TIMEOUT(boxes.seen.size(), 1, 10000);
            QTRY_VERIFY(!QFile::exists(crashed));
        }
    }

    // Files dropped on the window: one scene opens; several: the first opens and the rest are imported in one
    // step; a file that is no scene gets a message.
    void dropOpensFiles_data() {
        QTest::addColumn<QStringList>("files");
        QTest::addColumn<int>("bodies");
        QTest::addColumn<int>("undoSteps");
        QTest::addColumn<QString>("title");
        QTest::addColumn<int>("boxes");
        QTest::newRow("one scene") << QStringList{kScenes + "stack.obj"} << 11 << 0 << "stack.obj" << 0;
        QTest::newRow("two scenes") << QStringList{kScenes + "mixed.obj", kScenes + "stack.obj"} << 20 << 1
                                    << "mixed.obj" << 0;
        QTest::newRow("three scenes") << QStringList{kScenes + "stack.obj", kScenes + "mixed.obj",
                                                     kData + "formats/design_example.rlscene"}
                                      << 25 << 1 << "stack.obj" << 0;
        QTest::newRow("not a scene") << QStringList{kData + "import/bad/not_a_scene.xyz"} << 0 << 0 << "Untitled" << 1;
        QTest::newRow("scene and text") << QStringList{kData + "import/bad/not_a_scene.xyz", kScenes + "stack.obj"}
                                        << 11 << 0 << "stack.obj" << 0;
    }
    void dropOpensFiles() {
        QFETCH(QStringList, files);
        QFETCH(int, bodies);
        QFETCH(int, undoSteps);
        QFETCH(QString, title);
        QFETCH(int, boxes);
        BoxAnswerer answerer;
        rl::MainWindow window;
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        QList<QUrl> urls;
        for (const QString& file : files)
            urls << QUrl::fromLocalFile(file);
        QMimeData mime;
        mime.setUrls(urls);
        const QPoint at = window.rect().center();
        QDragEnterEvent enter(at, Qt::CopyAction, &mime, Qt::LeftButton, Qt::NoModifier);
        QApplication::sendEvent(&window, &enter);
        QVERIFY(enter.isAccepted());
        QDropEvent drop(QPointF(at), Qt::CopyAction, &mime, Qt::LeftButton, Qt::NoModifier);
        QApplication::sendEvent(&window, &drop);
        QCOMPARE(window.document()->bodyCount(), bodies);
        QCOMPARE(window.document()->undoStack()->count(), undoSteps);
        QVERIFY2(window.windowTitle().startsWith(title), qPrintable(window.windowTitle()));
        QCOMPARE(answerer.seen.size(), boxes);
        if (boxes)
            QVERIFY(answerer.seen[0].text.contains("not_a_scene.xyz"));
    }

    // The viewport draws into a native child window, and a drag may be delivered to that window (Qt's xcb drag
    // sources target the deepest window under the cursor): dropping a scene there opens it all the same.
    void dropOnTheViewportWindowOpensFiles() {
        rl::MainWindow window;
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        QWindow* native = window.viewport()->nativeWindow();
        QVERIFY(native);
        QMimeData mime;
        mime.setUrls({QUrl::fromLocalFile(kScenes + "stack.obj")});
        const QPointF at(window.viewport()->width() / 2.0, window.viewport()->height() / 2.0);
        QDragEnterEvent enter(at.toPoint(), Qt::CopyAction, &mime, Qt::LeftButton, Qt::NoModifier);
        QCoreApplication::sendEvent(native, &enter);
        QVERIFY(enter.isAccepted());
        QCOMPARE(enter.dropAction(), Qt::CopyAction);
        // As Qt sends a move after an accepted enter: accepted with the last action unless a widget refuses it.
        QDragMoveEvent move(at.toPoint() + QPoint(5, 5), Qt::CopyAction, &mime, Qt::LeftButton, Qt::NoModifier);
        move.setDropAction(Qt::CopyAction);
        move.accept();
        QCoreApplication::sendEvent(native, &move);
        QVERIFY(move.isAccepted());
        QDropEvent drop(at + QPointF(5, 5), Qt::CopyAction, &mime, Qt::LeftButton, Qt::NoModifier);
        QCoreApplication::sendEvent(native, &drop);
        QCOMPARE(window.document()->bodyCount(), 11);
        QVERIFY2(window.windowTitle().startsWith("stack.obj"), qPrintable(window.windowTitle()));
    }

    // Revert to Saved: back to the saved scene through the undo stack (Redo brings the changes back), or from the
    // file when the saved state is not in the history (a restored autosave); Cancel keeps the changes.
    void revertToSaved_data() {
        QTest::addColumn<bool>("confirm");
        QTest::addColumn<bool>("fromFile");
        QTest::newRow("undo") << true << false;
        QTest::newRow("from file") << true << true;
        QTest::newRow("cancel") << false << false;
    }
    void revertToSaved() {
        QFETCH(bool, confirm);
        QFETCH(bool, fromFile);
        QTemporaryDir dir;
        const QString path = dir.filePath("scene.rlscene");
        rl::MainWindow window;
        QVERIFY(showAndOpen(window, kScenes + "stack.obj"));
        rl::SceneDocument* document = window.document();
        auto* action = window.findChild<QAction*>("RevertAction");
        QVERIFY(action);
        QVERIFY(!action->isEnabled());
        QVERIFY(window.files()->saveAs(path));
        const rl::Scene saved = document->scene();
        editBody(document, 1, [](rl::BodyDef& b) { b.anchor = true; });
        editBody(document, 2, [](rl::BodyDef& b) { b.position.z = 3.0; });
        if (fromFile)
            document->markModified(); // as after restoring an autosave: no clean state in the history
        QVERIFY(action->isEnabled());
        const rl::Scene edited = document->scene();
        BoxAnswerer boxes(confirm ? BoxAnswerer::pressNamed("RevertButton") : BoxAnswerer::Answer{});
        action->trigger();
        QCOMPARE(boxes.seen.size(), 1);
        QCOMPARE(boxes.seen[0].name, QStringLiteral("RevertBox"));
        QString why;
        QVERIFY2(sameDefinitions(document->scene(), confirm ? saved : edited, &why), qPrintable(why));
        QCOMPARE(document->isModified(), !confirm);
        QCOMPARE(action->isEnabled(), !confirm);
        if (confirm && !fromFile) {
            QVERIFY(document->undoStack()->canRedo());
            document->undoStack()->redo();
            document->undoStack()->redo();
            QVERIFY2(sameDefinitions(document->scene(), edited, &why), qPrintable(why));
        }
    }

    // File > New: an empty untitled scene, clean, with the default world.
    void newSceneIsEmptyAndClean() {
        rl::MainWindow window;
        QVERIFY(showAndOpen(window, kData + "formats/design_example.rlscene"));
        auto* action = window.findChild<QAction*>("NewAction");
        QVERIFY(action);
        QCOMPARE(action->shortcut(), QKeySequence(QKeySequence::New));
        action->trigger();
        QCOMPARE(window.document()->bodyCount(), 0);
        QVERIFY(window.document()->scene().materials.empty());
        QVERIFY(window.document()->scene().world == rl::WorldSettings{});
        QVERIFY(!window.document()->isModified());
        QVERIFY(window.windowTitle().startsWith("Untitled"));
    }

    // The File menu holds the actions in order, with the standard shortcuts.
    void fileMenuLayout() {
        rl::MainWindow window;
        QMenu* menu = window.menu(rl::MainWindow::Menu::File);
        QStringList names;
        for (QAction* action : menu->actions())
            names << (action->isSeparator() ? QStringLiteral("-")
                      : action->menu()      ? action->menu()->objectName()
                                            : action->objectName());
        const QStringList expected{"NewAction",    "OpenAction",   "RecentMenu", "ImportAction", "-", "SaveAction",
                                   "SaveAsAction", "RevertAction", "-",          "ExportMenu",   "-"};
        QCOMPARE(names.mid(0, expected.size()), expected);
        QCOMPARE(names.last(), QStringLiteral("QuitAction"));
        QCOMPARE(window.findChild<QAction*>("SaveAsAction")->shortcut(), QKeySequence("Ctrl+Shift+S"));
        QCOMPARE(window.findChild<QAction*>("SaveAction")->shortcut(), QKeySequence(QKeySequence::Save));
        QCOMPARE(window.findChild<QAction*>("OpenAction")->shortcut(), QKeySequence(QKeySequence::Open));
    }
};

QTEST_MAIN(TestFiles)
#include "tst_files.moc"
