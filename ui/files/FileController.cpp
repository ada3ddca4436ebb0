#include "files/FileController.h"

#include "MainWindow.h"
#include "document/SceneDocument.h"
#include "viewport/Viewport.h"

#include <QAction>
#include <QFileDialog>
#include <QFileInfo>
#include <QMenu>
#include <QMessageBox>
#include <QStatusBar>

namespace rl {

FileController::FileController(MainWindow* window) : QObject(window), m_window(window) {
    QMenu* fileMenu = window->menu(MainWindow::Menu::File);
    QAction* openAction = fileMenu->addAction(tr("&Open..."), this, [this] {
        const QString path = QFileDialog::getOpenFileName(
            m_window, tr("Open Scene"), QString(),
            tr("Scenes (*.rlscene *.obj *.gltf *.glb *.fbx *.ply *.stl *.dae *.3ds *.bake);;All files (*)"));
        if (!path.isEmpty())
            m_window->openFile(path);
    });
    openAction->setShortcut(QKeySequence::Open);
    fileMenu->addSeparator();
    fileMenu->addMenu(window->menu(MainWindow::Menu::Export));
    fileMenu->addSeparator();
    QAction* quitAction = fileMenu->addAction(tr("&Quit"), window, &QWidget::close);
    quitAction->setShortcut(QKeySequence::Quit);
}

bool FileController::openScene(const QString& path) {
    QString error;
    if (!m_window->document()->load(path, &error)) {
        QMessageBox::critical(m_window, tr("Cannot open scene"), error);
        return false;
    }
    m_window->statusBar()->showMessage(tr("Opened %1").arg(QFileInfo(path).fileName()), 5000);
    m_window->viewport()->frameAll();
    return true;
}

void FileController::openDroppedFiles(const QStringList& paths) {
    if (!paths.isEmpty())
        m_window->openFile(paths.first());
}

bool FileController::maybeSave() {
    return true;
}

} // namespace rl
