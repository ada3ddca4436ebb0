#include "MainWindow.h"

#include "analysis/AnalysisController.h"
#include "document/SceneDocument.h"
#include "edit/EditController.h"
#include "files/FileController.h"
#include "inspector/InspectorWidget.h"
#include "outliner/OutlinerModel.h"
#include "overlays/OverlayController.h"
#include "settings/SettingsController.h"
#include "simulation/SimulationController.h"
#include "viewport/ScenePresenter.h"
#include "viewport/Viewport.h"
#include "widgets/StableLabel.h"

#include <QAbstractSpinBox>
#include <QAction>
#include <QActionGroup>
#include <QApplication>
#include <QCloseEvent>
#include <QComboBox>
#include <QDockWidget>
#include <QDragEnterEvent>
#include <QDropEvent>
#include <QFileDialog>
#include <QFileInfo>
#include <QHeaderView>
#include <QItemSelectionModel>
#include <QKeyEvent>
#include <QLabel>
#include <QLineEdit>
#include <QMenuBar>
#include <QMessageBox>
#include <QMimeData>
#include <QScreen>
#include <QSettings>
#include <QShowEvent>
#include <QSortFilterProxyModel>
#include <QStatusBar>
#include <QTimer>
#include <QToolBar>
#include <QTreeView>
#include <QUndoView>
#include <QVBoxLayout>

#include <algorithm>

namespace rl {

MainWindow::MainWindow(QWidget* parent)
    : QMainWindow(parent), m_document(new SceneDocument(this)), m_presenter(std::make_unique<ScenePresenter>()) {
    setObjectName("MainWindow");
    m_viewport = new Viewport(this);
    m_viewport->setObjectName("Viewport");
    m_viewport->setMinimumSize(480, 360);
    m_viewport->setPickFunction([this](const ViewRay& ray) { return m_presenter->pick(ray); });
    setCentralWidget(m_viewport);

    // Qt retries a keypad key without its keypad modifier, so the keypad's Del (numpad "." with Num Lock off) would
    // trigger Delete; the viewport uses it to frame the selection, as Blender does (see eventFilter).
    m_viewport->installEventFilter(this);
    setAcceptDrops(true);
    createMenus();
    createDocks();
    // Controllers add their menus, toolbars and docks; the order only matters for toolbars and dock tabs.
    m_files = new FileController(this);
    m_edit = new EditController(this);
    m_settings = new SettingsController(this);
    m_overlays = new OverlayController(this);
    m_simulation = new SimulationController(this);
    m_analysis = new AnalysisController(this);
    menu(Menu::Help)->addAction(tr("&About RigidLab"), this, [this] {
        QMessageBox::about(this, tr("About RigidLab"),
                           tr("<b>RigidLab</b> %1<br>An editor and simulator for 3D rigid-body scenes.")
                               .arg(QApplication::applicationVersion()));
    });

    m_selectionLabel = new QLabel(this);
    m_bodyCountLabel = new QLabel(this);
    m_frameTimeLabel = new QLabel(this);
    m_selectionLabel->setObjectName("SelectionLabel");
    m_bodyCountLabel->setObjectName("BodyCountLabel");
    m_frameTimeLabel->setObjectName("FrameTimeLabel");
    statusBar()->addPermanentWidget(m_selectionLabel);
    statusBar()->addPermanentWidget(m_bodyCountLabel);
    statusBar()->addPermanentWidget(m_frameTimeLabel);
    // Fixed minimum widths, so that a changing read-out does not make its neighbours jump.
    m_selectionLabel->setMinimumWidth(fontMetrics().horizontalAdvance(tr("nothing selected")) + 8);
    m_frameTimeLabel->setMinimumWidth(fontMetrics().horizontalAdvance(tr("frame %1 ms").arg(999.9, 0, 'f', 1)) + 8);
    // The read-out changes with every frame, and a label that changes after paintGL makes the whole window compose
    // once more (a second full composition per frame under a software GL). So it shows the latest frame time at
    // most four times a second: the first frame at once, later ones when the timer fires.
    auto* frameTimeTimer = new QTimer(this);
    frameTimeTimer->setSingleShot(true);
    frameTimeTimer->setInterval(250);
    const auto showFrameTime = [this] {
        setStableText(m_frameTimeLabel, tr("frame %1 ms").arg(m_viewport->lastFrameMs(), 0, 'f', 1));
    };
    connect(frameTimeTimer, &QTimer::timeout, this, showFrameTime);
    connect(m_viewport, &Viewport::frameRendered, this, [this, frameTimeTimer, showFrameTime] {
        if (m_frameTimeLabel->text().isEmpty())
            showFrameTime();
        else if (!frameTimeTimer->isActive())
            frameTimeTimer->start();
    });
    connect(m_viewport, &Viewport::selectionChanged, this, [this](const QList<int>& picked, bool extend) {
        QList<int> next = extend ? m_selection : QList<int>{};
        for (int body : picked) {
            if (extend && next.contains(body))
                next.removeAll(body); // Ctrl/Shift-click toggles, as in Blender
            else if (!next.contains(body))
                next.append(body);
        }
        setSelectedBodies(next);
    });
    connect(m_outlinerView->selectionModel(), &QItemSelectionModel::selectionChanged, this, [this] {
        if (m_syncingSelection)
            return;
        QList<int> bodies;
        for (const QModelIndex& index : m_outlinerView->selectionModel()->selectedRows())
            bodies.append(index.data(OutlinerModel::BodyIndexRole).toInt());
        setSelectedBodies(bodies);
    });

    connect(m_document, &SceneDocument::sceneReset, this, &MainWindow::rebuildViewport);
    connect(m_document, &SceneDocument::bodyChanged, this, &MainWindow::rebuildViewport);
    connect(m_document, &SceneDocument::bodyInserted, this, &MainWindow::rebuildViewport);
    connect(m_document, &SceneDocument::bodyRemoved, this, &MainWindow::rebuildViewport);
    connect(m_document, &SceneDocument::sceneReset, this, &MainWindow::updateStatus);
    connect(m_document, &SceneDocument::bodyInserted, this, &MainWindow::updateStatus);
    connect(m_document, &SceneDocument::bodyRemoved, this, &MainWindow::updateStatus);
    connect(m_document, &SceneDocument::bodyChanged, this, &MainWindow::updateStatus); // an anchor toggled
    connect(m_document, &SceneDocument::filePathChanged, this, &MainWindow::updateTitle);
    connect(m_document->undoStack(), &QUndoStack::cleanChanged, this, &MainWindow::updateTitle);

    QSettings settings;
    m_restoredGeometry = restoreGeometry(settings.value("mainwindow/geometry").toByteArray());
    if (!m_restoredGeometry)
        resize(1280, 800); // placed on its screen at the first show (showEvent)
    restoreState(settings.value("mainwindow/state").toByteArray());
    // The viewport holds the keyboard from the start, so that Space, A, G or the arrows act before any click.
    m_viewport->setFocus(Qt::OtherFocusReason);
    // Watches our dialogs closing (see eventFilter).
    qApp->installEventFilter(this);
    connect(qApp, &QGuiApplication::focusWindowChanged, this, [this](QWindow* window) {
        if (window)
            m_lastFocusWindow = window;
    });
    updateTitle();
    updateStatus();
    setSelectedBodies({}); // the selection read-out from the start, not only after the first pick
}

MainWindow::~MainWindow() {
    // The document outlives the docks and the viewport during destruction: stop its signals reaching them first.
    disconnect(m_document, nullptr, this, nullptr);
    disconnect(m_document->undoStack(), nullptr, this, nullptr);
}

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

    auto* inspectorDock = new QDockWidget(tr("Inspector"), this);
    inspectorDock->setObjectName("InspectorDock");
    m_inspector = new InspectorWidget(m_document, inspectorDock);
    inspectorDock->setWidget(m_inspector);
    addDockWidget(Qt::RightDockWidgetArea, inspectorDock);
    connect(this, &MainWindow::selectionChanged, m_inspector, &InspectorWidget::setSelection);

    auto* historyDock = new QDockWidget(tr("History"), this);
    historyDock->setObjectName("HistoryDock");
    auto* history = new QUndoView(m_document->undoStack(), historyDock);
    history->setObjectName("HistoryView");
    history->setEmptyLabel(tr("<opened scene>"));
    historyDock->setWidget(history);
    addDockWidget(Qt::RightDockWidgetArea, historyDock);
    tabifyDockWidget(inspectorDock, historyDock);
    inspectorDock->raise();
    // Closed docks come back from the Window menu; the controllers add theirs after these.
    for (QDockWidget* created : {dock, inspectorDock, historyDock})
        menu(Menu::Window)->addAction(created->toggleViewAction());
    resizeDocks({inspectorDock}, {380}, Qt::Horizontal); // a saved window state overrides this
}

void MainWindow::createMenus() {
    m_menus.resize(static_cast<int>(Menu::Help) + 1);
    auto add = [this](Menu which, const QString& title, const char* name) {
        QMenu* created = menuBar()->addMenu(title);
        created->setObjectName(QLatin1String(name));
        m_menus[static_cast<int>(which)] = created;
    };
    add(Menu::File, tr("&File"), "FileMenu");
    add(Menu::Edit, tr("&Edit"), "EditMenu");
    add(Menu::Add, tr("A&dd"), "AddMenu"); // not "&Add": Alt+A toggles the anchor
    add(Menu::View, tr("&View"), "ViewMenu");
    add(Menu::Simulation, tr("&Simulation"), "SimulationMenu");
    add(Menu::Analysis, tr("A&nalysis"), "AnalysisMenu");
    add(Menu::Window, tr("&Window"), "WindowMenu");
    add(Menu::Help, tr("&Help"), "HelpMenu");
    // The camera's framing keys, listed where users look for them. The text after the tab only shows the key: the
    // viewport handles F and Home itself (the timeline uses Home too, and the keypad's Home is the top view).
    QAction* frameSelected =
        menu(Menu::View)->addAction(tr("Frame &Selected\tF"), this, [this] { m_viewport->frameSelection(); });
    frameSelected->setObjectName("FrameSelectedAction");
    QAction* frameAll = menu(Menu::View)->addAction(tr("Frame &All\tHome"), this, [this] { m_viewport->frameAll(); });
    frameAll->setObjectName("FrameAllAction");
    menu(Menu::View)->addSeparator();
    createLanguageMenu();
    // File > Export is a submenu the file controller places; others add their exporters to it.
    auto* exportMenu = new QMenu(tr("&Export"), this);
    exportMenu->setObjectName("ExportMenu");
    m_menus[static_cast<int>(Menu::Export)] = exportMenu;
}

void MainWindow::createLanguageMenu() {
    // The language is read once at start-up (app/rigidlab/main.cpp): the "ui/language" setting, else the system
    // locale. Switching asks for a restart rather than re-translating every open widget.
    QMenu* languageMenu = menu(Menu::View)->addMenu(tr("&Language"));
    languageMenu->setObjectName("LanguageMenu");
    auto* group = new QActionGroup(languageMenu);
    const QString current = QSettings().value("ui/language").toString();
    const QList<QPair<QString, QString>> languages = {{QString(), tr("System default")},
                                                      {QStringLiteral("en"), QStringLiteral("English")},
                                                      {QStringLiteral("de"), QStringLiteral("Deutsch")}};
    for (const auto& [code, name] : languages) {
        QAction* action = languageMenu->addAction(name);
        action->setObjectName(QStringLiteral("LanguageAction_") + (code.isEmpty() ? QStringLiteral("system") : code));
        action->setCheckable(true);
        action->setChecked(code == current);
        group->addAction(action);
        connect(action, &QAction::triggered, this, [this, code] {
            QSettings().setValue("ui/language", code);
            statusBar()->showMessage(tr("The language changes when RigidLab is restarted."), 8000);
        });
    }
}

QMenu* MainWindow::menu(Menu which) const {
    return m_menus.value(static_cast<int>(which));
}

void MainWindow::rebuildViewport() {
    m_presenter->rebuild(m_document->scene());
    m_viewport->setScene(m_presenter->viewportScene());
    emit viewportRebuilt();
    // Keep only selected bodies that still exist.
    QList<int> kept;
    for (int body : m_selection)
        if (body < m_document->bodyCount())
            kept.append(body);
    m_selection.clear();
    setSelectedBodies(kept);
}

void MainWindow::setSelectedBodies(const QList<int>& bodies) {
    QList<int> sorted = bodies;
    std::sort(sorted.begin(), sorted.end());
    sorted.erase(std::unique(sorted.begin(), sorted.end()), sorted.end());
    if (sorted != m_selection || m_viewport->selection() != sorted) {
        m_selection = sorted;
        m_viewport->setSelection(m_selection);
        syncOutlinerSelection();
        emit selectionChanged(m_selection);
    }
    if (m_selection.isEmpty())
        m_selectionLabel->setText(tr("nothing selected"));
    else if (m_selection.size() == 1)
        m_selectionLabel->setText(
            tr("selected: %1").arg(QString::fromStdString(m_document->body(m_selection.first()).name)));
    else
        m_selectionLabel->setText(tr("%n selected", "", m_selection.size()));
}

void MainWindow::syncOutlinerSelection() {
    m_syncingSelection = true;
    QItemSelection selection;
    for (int body : m_selection) {
        const QModelIndex source = m_outlinerModel->index(body, 0);
        const QModelIndex index = m_outlinerProxy->mapFromSource(source);
        if (index.isValid())
            selection.select(index, index.siblingAtColumn(OutlinerModel::ColumnCount - 1));
    }
    m_outlinerView->selectionModel()->select(selection, QItemSelectionModel::ClearAndSelect);
    if (!m_selection.isEmpty()) {
        const QModelIndex current = m_outlinerProxy->mapFromSource(m_outlinerModel->index(m_selection.last(), 0));
        if (current.isValid())
            m_outlinerView->scrollTo(current);
    }
    m_syncingSelection = false;
}

bool MainWindow::openFile(const QString& path) {
    // Absolute, so that Save, the export dialogs and the recent files name the same file from any directory (the
    // README's command passes a path relative to the checkout).
    const QString absolute = path.isEmpty() ? path : QFileInfo(path).absoluteFilePath();
    if (QFileInfo(absolute).suffix().compare(QLatin1String("bake"), Qt::CaseInsensitive) == 0)
        return m_simulation->openBake(absolute);
    return m_files->openScene(absolute);
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

bool MainWindow::eventFilter(QObject* watched, QEvent* event) {
    if (event->type() == QEvent::Hide && watched != this && watched->isWidgetType()) {
        auto* hidden = static_cast<QWidget*>(watched);
        // Qt deactivates a closing dialog before its Hide event: ask whether it was the last of our windows to have
        // the keyboard instead.
        if (hidden->isWindow() && m_lastFocusWindow && hidden->windowHandle() == m_lastFocusWindow) {
            bool ours = false;
            for (QWidget* w = hidden->parentWidget(); w && !ours; w = w->parentWidget())
                ours = w == this;
            // One of our dialogs had the keyboard and closes: take it back. A window manager would give it to us;
            // without one (a scripted session under Xvfb) the keyboard went nowhere until the next click.
            if (ours)
                QTimer::singleShot(0, this, [this] {
                    const QWidget* active = QApplication::activeWindow();
                    if (isVisible() && !QApplication::activeModalWidget() && (!active || !active->isVisible()))
                        activateWindow();
                });
        }
    }
    if (event->type() == QEvent::Show && watched->isWidgetType()) {
        // Qt's own file dialog (used where the desktop offers none) opens so narrow that the size, type and date
        // columns are elided: give it room, centred where it was, within the screen.
        if (auto* dialog = qobject_cast<QFileDialog*>(watched); dialog && dialog->screen()) {
            const QRect available = dialog->screen()->availableGeometry();
            const QSize want = dialog->size().expandedTo(QSize(900, 560)).boundedTo(available.size());
            if (want != dialog->size()) {
                QRect rect(QPoint(0, 0), want);
                const QWidget* over = dialog->parentWidget() ? dialog->parentWidget()->window() : nullptr;
                rect.moveCenter(over ? over->geometry().center() : available.center());
                rect.moveLeft(std::clamp(rect.left(), available.left(), available.right() - want.width() + 1));
                rect.moveTop(std::clamp(rect.top(), available.top(), available.bottom() - want.height() + 1));
                dialog->setGeometry(rect);
            }
            // The name takes the room; size, type and date are never elided.
            if (auto* details = dialog->findChild<QTreeView*>(QStringLiteral("treeView"))) {
                QHeaderView* header = details->header();
                header->setStretchLastSection(false);
                header->setSectionResizeMode(0, QHeaderView::Stretch);
                for (int column = 1; column < header->count(); ++column)
                    header->setSectionResizeMode(column, QHeaderView::ResizeToContents);
            }
        }
    }
    if (watched == m_viewport && event->type() == QEvent::Enter && isActiveWindow()) {
        // The keys follow the mouse, as in Blender: W, G, A or F act on the viewport under it after a click in the
        // outliner. A text field or spin box being typed in keeps the keyboard.
        QWidget* focus = QApplication::focusWidget();
        const bool typing =
            focus && (qobject_cast<QLineEdit*>(focus) || qobject_cast<QAbstractSpinBox*>(focus) ||
                      (qobject_cast<QComboBox*>(focus) && static_cast<QComboBox*>(focus)->isEditable()));
        if (!typing)
            m_viewport->setFocus(Qt::MouseFocusReason);
    }
    if (watched == m_viewport && event->type() == QEvent::ShortcutOverride) {
        auto* key = static_cast<QKeyEvent*>(event);
        if (key->key() == Qt::Key_Delete && (key->modifiers() & Qt::KeypadModifier)) {
            event->accept(); // the viewport gets it as a key press
            return true;
        }
    }
    return QMainWindow::eventFilter(watched, event);
}

void MainWindow::dragEnterEvent(QDragEnterEvent* event) {
    if (event->mimeData()->hasUrls())
        event->acceptProposedAction();
}

void MainWindow::dropEvent(QDropEvent* event) {
    QStringList paths;
    for (const QUrl& url : event->mimeData()->urls())
        if (url.isLocalFile())
            paths.append(url.toLocalFile());
    if (!paths.isEmpty()) {
        event->acceptProposedAction();
        m_files->openDroppedFiles(paths);
    }
}

QRect MainWindow::firstGeometry(const QRect& available) {
    QSize size = available.size();
    if (size.width() > 1440 || size.height() > 900)
        size = (QSizeF(size) * 0.9).toSize().expandedTo(QSize(1280, 800)).boundedTo(available.size());
    QRect rect(QPoint(0, 0), size);
    rect.moveCenter(available.center());
    return rect;
}

void MainWindow::showEvent(QShowEvent* event) {
    QMainWindow::showEvent(event);
    if (m_shownOnce)
        return;
    m_shownOnce = true;
    if (!m_restoredGeometry && screen())
        setGeometry(firstGeometry(screen()->availableGeometry()));
    // Take the keyboard once shown: with no window manager (a scripted session under Xvfb) nothing else would give
    // the window the input focus, and every key would be lost until the first click.
    QTimer::singleShot(0, this, [this] {
        activateWindow();
        raise();
    });
}

void MainWindow::closeEvent(QCloseEvent* event) {
    if (!m_files->maybeSave()) {
        event->ignore();
        return;
    }
    QSettings settings;
    settings.setValue("mainwindow/geometry", saveGeometry());
    settings.setValue("mainwindow/state", saveState());
    event->accept();
}

} // namespace rl
