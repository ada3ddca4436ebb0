// File menu: New, Open, Import, Save, Save As, Recent, drag and drop, the unsaved-changes prompt and autosave.
#pragma once

#include <QObject>
#include <QStringList>

namespace rl {

class MainWindow;

class FileController : public QObject {
    Q_OBJECT
public:
    explicit FileController(MainWindow* window);

    // Opens a scene file into the document (asks to save unsaved changes first); errors go to a message box.
    bool openScene(const QString& path);
    // Files dropped on the window: scenes open (or .bake files, through MainWindow::openFile).
    void openDroppedFiles(const QStringList& paths);
    // Asks what to do with unsaved changes. False when the user cancels.
    bool maybeSave();

private:
    MainWindow* m_window;
};

} // namespace rl
