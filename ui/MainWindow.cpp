#include "MainWindow.h"

#include "document/SceneDocument.h"
#include "outliner/OutlinerModel.h"

#include <QAction>
#include <QApplication>
#include <QCloseEvent>
#include <QDockWidget>
#include <QFileDialog>
#include <QFileInfo>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QMenuBar>
#include <QMessageBox>
#include <QSettings>
#include <QSortFilterProxyModel>
#include <QStatusBar>
#include <QTreeView>
#include <QVBoxLayout>

namespace rl {

MainWindow::MainWindow(QWidget* parent) : QMainWindow(parent), m_document(new SceneDocument(this)) {
    setObjectName("MainWindow");
    auto* central = new QWidget(this);
    central->setObjectName("ViewportArea");
    central->setMinimumSize(640, 480);
    setCentralWidget(central);

    createDocks();
    createActions();

    m_bodyCountLabel = new QLabel(this);
    statusBar()->addPermanentWidget(m_bodyCountLabel);

    connect(m_document, &SceneDocument::sceneReset, this, &MainWindow::updateStatus);
    connect(m_document, &SceneDocument::bodyInserted, this, &MainWindow::updateStatus);
    connect(m_document, &SceneDocument::bodyRemoved, this, &MainWindow::updateStatus);
    connect(m_document, &SceneDocument::filePathChanged, this, &MainWindow::updateTitle);
    connect(m_document->undoStack(), &QUndoStack::cleanChanged, this, &MainWindow::updateTitle);

    QSettings settings;
    if (!restoreGeometry(settings.value("mainwindow/geometry").toByteArray()))
        resize(1280, 800);
    restoreState(settings.value("mainwindow/state").toByteArray());
    updateTitle();
    updateStatus();
}

MainWindow::~MainWindow() = default;

void MainWindow::createDocks() {
    auto* dock = new QDockWidget(tr("Outliner"), this);
    dock->setObjectName("OutlinerDock");
    auto* panel = new QWidget(dock);
    auto* layout = new QVBoxLayout(panel);
    layout->setContentsMargins(2, 2, 2, 2);
    auto* filter = new QLineEdit(panel);
    filter->setObjectName("OutlinerFilter");
    filter->setPlaceholderText(tr("Filter by name"));
    filter->setClearButtonEnabled(true);
    layout->addWidget(filter);

    m_outlinerModel = new OutlinerModel(m_document, this);
    m_outlinerProxy = new QSortFilterProxyModel(this);
    m_outlinerProxy->setSourceModel(m_outlinerModel);
    m_outlinerProxy->setFilterCaseSensitivity(Qt::CaseInsensitive);
    m_outlinerProxy->setFilterKeyColumn(OutlinerModel::NameColumn);
    connect(filter, &QLineEdit::textChanged, m_outlinerProxy, &QSortFilterProxyModel::setFilterFixedString);

    m_outlinerView = new QTreeView(panel);
    m_outlinerView->setObjectName("OutlinerView");
    m_outlinerView->setModel(m_outlinerProxy);
    m_outlinerView->setRootIsDecorated(false);
    m_outlinerView->setUniformRowHeights(true);
    m_outlinerView->setSelectionMode(QAbstractItemView::ExtendedSelection);
    m_outlinerView->header()->setStretchLastSection(false);
    m_outlinerView->header()->setSectionResizeMode(OutlinerModel::NameColumn, QHeaderView::Stretch);
    m_outlinerView->header()->setSectionResizeMode(OutlinerModel::MaterialColumn, QHeaderView::ResizeToContents);
    layout->addWidget(m_outlinerView);
    dock->setWidget(panel);
    addDockWidget(Qt::LeftDockWidgetArea, dock);
}

void MainWindow::createActions() {
    QMenu* fileMenu = menuBar()->addMenu(tr("&File"));
    QAction* openAction = fileMenu->addAction(tr("&Open..."), this, [this] {
        const QString path = QFileDialog::getOpenFileName(
            this, tr("Open Scene"), QString(),
            tr("Scenes (*.rlscene *.obj *.gltf *.glb *.fbx *.ply *.stl *.dae *.3ds);;All files (*)"));
        if (!path.isEmpty())
            openFile(path);
    });
    openAction->setShortcut(QKeySequence::Open);
    fileMenu->addSeparator();
    QAction* quitAction = fileMenu->addAction(tr("&Quit"), this, &QWidget::close);
    quitAction->setShortcut(QKeySequence::Quit);

    QMenu* helpMenu = menuBar()->addMenu(tr("&Help"));
    helpMenu->addAction(tr("&About RigidLab"), this, [this] {
        QMessageBox::about(this, tr("About RigidLab"),
                           tr("<b>RigidLab</b> %1<br>An editor and simulator for 3D rigid-body scenes.")
                               .arg(QApplication::applicationVersion()));
    });
}

bool MainWindow::openFile(const QString& path) {
    QString error;
    if (!m_document->load(path, &error)) {
        QMessageBox::critical(this, tr("Cannot open scene"), error);
        return false;
    }
    statusBar()->showMessage(tr("Opened %1").arg(QFileInfo(path).fileName()), 5000);
    return true;
}

void MainWindow::updateTitle() {
    setWindowTitle(tr("%1[*] - RigidLab").arg(m_document->displayName()));
    setWindowModified(m_document->isModified());
}

void MainWindow::updateStatus() {
    int anchors = 0;
    for (const BodyDef& body : m_document->scene().bodies)
        anchors += body.anchor ? 1 : 0;
    m_bodyCountLabel->setText(tr("%n bodies", "", m_document->bodyCount()) + QStringLiteral(" · ") +
                              tr("%n anchors", "", anchors));
}

void MainWindow::closeEvent(QCloseEvent* event) {
    QSettings settings;
    settings.setValue("mainwindow/geometry", saveGeometry());
    settings.setValue("mainwindow/state", saveState());
    event->accept();
}

} // namespace rl
