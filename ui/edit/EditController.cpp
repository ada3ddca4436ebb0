#include "edit/EditController.h"

#include "MainWindow.h"
#include "document/SceneDocument.h"
#include "document/commands/AddBodyCommand.h"
#include "document/commands/DuplicateBodiesCommand.h"
#include "document/commands/RemoveBodiesCommand.h"
#include "document/commands/SetBodiesCommand.h"
#include "document/commands/SetBodyCommand.h"
#include "document/commands/TransformBodiesCommand.h"
#include "edit/BodyNames.h"
#include "outliner/OutlinerModel.h"
#include "viewport/Viewport.h"

#include <QAbstractProxyModel>
#include <QAction>
#include <QActionGroup>
#include <QCursor>
#include <QHeaderView>
#include <QItemSelectionModel>
#include <QMenu>
#include <QMessageBox>
#include <QPainter>
#include <QPainterPath>
#include <QStatusBar>
#include <QStyle>
#include <QToolBar>
#include <QTreeView>
#include <QUndoStack>

#include <glm/gtc/constants.hpp>

#include <set>

namespace rl {

namespace {

// The anchor toggle's toolbar icon: a pin, as in the outliner's anchor column.
QIcon makeAnchorIcon() {
    QPixmap pixmap(24, 24);
    pixmap.fill(Qt::transparent);
    QPainter p(&pixmap);
    p.setRenderHint(QPainter::Antialiasing);
    const QColor colour(52, 120, 200);
    p.setPen(QPen(colour, 2.0, Qt::SolidLine, Qt::RoundCap));
    p.setBrush(colour);
    p.drawEllipse(QPointF(12, 7), 4.5, 4.5);
    p.drawLine(QPointF(12, 12), QPointF(12, 21));
    p.drawLine(QPointF(6.5, 14.5), QPointF(17.5, 14.5));
    return QIcon(pixmap);
}

// Tool icons drawn in code, in the gizmo's colours, so the editor needs no image files.
QIcon makeToolIcon(GizmoTool tool) {
    QPixmap pixmap(24, 24);
    pixmap.fill(Qt::transparent);
    QPainter p(&pixmap);
    p.setRenderHint(QPainter::Antialiasing);
    const QColor red(232, 64, 80), green(120, 200, 40), blue(64, 128, 240), light(220, 220, 220);
    switch (tool) {
    case GizmoTool::Select: {
        QPainterPath arrow;
        arrow.moveTo(7, 3);
        arrow.lineTo(7, 19);
        arrow.lineTo(11, 15);
        arrow.lineTo(14, 21);
        arrow.lineTo(16.5, 20);
        arrow.lineTo(13.5, 14);
        arrow.lineTo(19, 14);
        arrow.closeSubpath();
        p.setPen(QPen(QColor(30, 30, 30), 1.2));
        p.setBrush(light);
        p.drawPath(arrow);
        break;
    }
    case GizmoTool::Move: {
        const QPointF c(12, 12);
        const std::pair<QPointF, QColor> tips[] = {
            {{21, 12}, red}, {{12, 3}, green}, {{3, 12}, red}, {{12, 21}, green}};
        for (const auto& [tip, colour] : tips) {
            p.setPen(QPen(colour, 2.0, Qt::SolidLine, Qt::RoundCap));
            p.drawLine(c, tip);
            const QPointF u = (tip - c) / 9.0;
            const QPointF n(-u.y(), u.x());
            p.setPen(Qt::NoPen);
            p.setBrush(colour);
            p.drawPolygon(QPolygonF({tip + 1.5 * u, tip - 3.5 * u + 3.0 * n, tip - 3.5 * u - 3.0 * n}));
        }
        break;
    }
    case GizmoTool::Rotate:
        p.setBrush(Qt::NoBrush);
        p.setPen(QPen(red, 2.0));
        p.drawEllipse(QPointF(12, 12), 9.0, 4.0);
        p.setPen(QPen(green, 2.0));
        p.drawEllipse(QPointF(12, 12), 4.0, 9.0);
        p.setPen(QPen(blue, 2.0));
        p.drawEllipse(QPointF(12, 12), 9.0, 9.0);
        break;
    }
    return QIcon(pixmap);
}

} // namespace

EditController::EditController(MainWindow* window) : QObject(window), m_window(window) {
    QMenu* editMenu = window->menu(MainWindow::Menu::Edit);
    QToolBar* toolBar = window->addToolBar(tr("Edit"));
    toolBar->setObjectName("EditToolBar");
    SceneDocument* document = window->document();
    QUndoStack* stack = document->undoStack();
    Viewport* viewport = window->viewport();

    QAction* undoAction = stack->createUndoAction(this, tr("&Undo"));
    undoAction->setObjectName("UndoAction");
    undoAction->setShortcut(QKeySequence::Undo);
    // Themed icons where a theme is installed, else the style's: a toolbar button without an icon shows its text,
    // and the undo text changes with every edit, which made the toolbar jump.
    QStyle* style = window->style();
    undoAction->setIcon(QIcon::fromTheme("edit-undo", style->standardIcon(QStyle::SP_ArrowBack)));
    QAction* redoAction = stack->createRedoAction(this, tr("&Redo"));
    redoAction->setObjectName("RedoAction");
    // Ctrl+Shift+Z as in Blender, Ctrl+Y as on Windows.
    redoAction->setShortcuts({QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_Z), QKeySequence(Qt::CTRL | Qt::Key_Y)});
    redoAction->setIcon(QIcon::fromTheme("edit-redo", style->standardIcon(QStyle::SP_ArrowForward)));

    m_deleteAction =
        new QAction(QIcon::fromTheme("edit-delete", style->standardIcon(QStyle::SP_TrashIcon)), tr("&Delete"), this);
    m_deleteAction->setObjectName("DeleteAction");
    m_deleteAction->setShortcut(QKeySequence::Delete);
    m_deleteAction->setStatusTip(tr("Delete the selected bodies"));
    connect(m_deleteAction, &QAction::triggered, this, &EditController::deleteSelection);

    // Alt+A: Shift+A is Blender's "Add" and A "Select all".
    m_anchorAction = new QAction(makeAnchorIcon(), tr("Toggle &Anchor"), this);
    m_anchorAction->setObjectName("ToggleAnchorAction");
    m_anchorAction->setShortcut(QKeySequence(Qt::ALT | Qt::Key_A));
    m_anchorAction->setStatusTip(tr("Make the selected bodies static, or dynamic again when all are static"));
    connect(m_anchorAction, &QAction::triggered, this, &EditController::toggleAnchor);

    // Ctrl+D everywhere, Shift+D as in Blender; both start a move of the copies (Escape leaves them in place).
    m_duplicateAction = new QAction(QIcon::fromTheme("edit-copy"), tr("D&uplicate"), this);
    m_duplicateAction->setObjectName("DuplicateAction");
    m_duplicateAction->setShortcuts({QKeySequence(Qt::CTRL | Qt::Key_D), QKeySequence(Qt::SHIFT | Qt::Key_D)});
    m_duplicateAction->setStatusTip(tr("Copy the selected bodies and move the copies with the mouse; click to place"));
    connect(m_duplicateAction, &QAction::triggered, this, [this] { duplicateSelection(true); });

    m_renameAction = new QAction(tr("Re&name..."), this);
    m_renameAction->setObjectName("RenameAction");
    m_renameAction->setShortcut(QKeySequence(Qt::Key_F2));
    m_renameAction->setStatusTip(tr("Rename the active body in the outliner"));
    connect(m_renameAction, &QAction::triggered, this, &EditController::renameActive);

    // Selection. A and Ctrl+Shift+A act in the viewport (the outliner has its own Ctrl+A); Alt+A, Blender's
    // "select none", is the anchor toggle here.
    QAction* selectAllAction = new QAction(tr("Select &All"), this);
    selectAllAction->setObjectName("SelectAllAction");
    selectAllAction->setShortcut(QKeySequence(Qt::Key_A));
    connect(selectAllAction, &QAction::triggered, this, &EditController::selectAll);
    QAction* selectNoneAction = new QAction(tr("Select &None"), this);
    selectNoneAction->setObjectName("SelectNoneAction");
    selectNoneAction->setShortcut(QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_A));
    connect(selectNoneAction, &QAction::triggered, this, &EditController::selectNone);
    QAction* invertAction = new QAction(tr("&Invert Selection"), this);
    invertAction->setObjectName("InvertSelectionAction");
    invertAction->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_I));
    connect(invertAction, &QAction::triggered, this, &EditController::invertSelection);

    // Blender's modal grab and rotate.
    QAction* grabAction = new QAction(tr("&Grab"), this);
    grabAction->setObjectName("GrabAction");
    grabAction->setShortcut(QKeySequence(Qt::Key_G));
    grabAction->setStatusTip(tr("Move the selection with the mouse in the view plane; click to confirm, Esc cancels"));
    connect(grabAction, &QAction::triggered, this,
            [this] { m_window->viewport()->startModalTransform(GizmoTool::Move); });
    QAction* spinAction = new QAction(tr("R&otate"), this);
    spinAction->setObjectName("ModalRotateAction");
    spinAction->setShortcut(QKeySequence(Qt::Key_R));
    spinAction->setStatusTip(tr("Turn the selection about the view axis with the mouse; click to confirm"));
    connect(spinAction, &QAction::triggered, this,
            [this] { m_window->viewport()->startModalTransform(GizmoTool::Rotate); });

    // Single keys act only while the viewport has the focus, as Blender's do under the mouse; they must not fire
    // while the user types in a panel.
    for (QAction* action : {selectAllAction, selectNoneAction, grabAction, spinAction}) {
        action->setShortcutContext(Qt::WidgetWithChildrenShortcut);
        viewport->addAction(action);
    }

    auto updateEnabled = [this, grabAction, spinAction] {
        const bool any = !m_window->selectedBodies().isEmpty();
        m_deleteAction->setEnabled(any);
        m_anchorAction->setEnabled(any);
        m_duplicateAction->setEnabled(any);
        m_renameAction->setEnabled(any);
        grabAction->setEnabled(any);
        spinAction->setEnabled(any);
    };
    connect(window, &MainWindow::selectionChanged, this, updateEnabled);
    updateEnabled();

    createToolActions();

    editMenu->addAction(undoAction);
    editMenu->addAction(redoAction);
    editMenu->addSeparator();
    editMenu->addAction(m_duplicateAction);
    editMenu->addAction(m_deleteAction);
    editMenu->addAction(m_renameAction);
    editMenu->addAction(m_anchorAction);
    editMenu->addSeparator();
    editMenu->addAction(selectAllAction);
    editMenu->addAction(selectNoneAction);
    editMenu->addAction(invertAction);
    editMenu->addSeparator();
    QMenu* toolMenu = editMenu->addMenu(tr("&Tool"));
    toolMenu->setObjectName("ToolMenu");
    toolMenu->addActions(m_tools->actions());
    editMenu->addAction(grabAction);
    editMenu->addAction(spinAction);
    toolBar->addAction(undoAction);
    toolBar->addAction(redoAction);
    toolBar->addSeparator();
    toolBar->addAction(m_deleteAction);
    toolBar->addAction(m_anchorAction);

    // Add menu: Shift+A opens it at the mouse in the viewport.
    QMenu* addMenu = window->menu(MainWindow::Menu::Add);
    // "&Add" would make Alt+A the menu's mnemonic and the anchor toggle's Alt+A ambiguous (neither would fire).
    addMenu->setTitle(tr("A&dd"));
    const std::pair<Primitive, const char*> primitives[] = {{Primitive::Box, "AddCubeAction"},
                                                            {Primitive::Sphere, "AddSphereAction"},
                                                            {Primitive::Cylinder, "AddCylinderAction"},
                                                            {Primitive::Cone, "AddConeAction"}};
    for (const auto& [kind, name] : primitives) {
        QAction* add = addMenu->addAction(primitiveLabel(kind));
        add->setObjectName(QLatin1String(name));
        add->setStatusTip(
            tr("Add a %1 on the ground, or on top of the selection").arg(primitiveLabel(kind).remove('&')));
        connect(add, &QAction::triggered, this, [this, kind = kind] { addPrimitive(kind); });
    }
    QAction* addPopup = new QAction(tr("Add Menu"), this);
    addPopup->setObjectName("AddMenuPopupAction");
    addPopup->setShortcut(QKeySequence(Qt::SHIFT | Qt::Key_A));
    addPopup->setShortcutContext(Qt::WidgetWithChildrenShortcut);
    viewport->addAction(addPopup);
    connect(addPopup, &QAction::triggered, this, [this, addMenu] { addMenu->popup(QCursor::pos()); });

    connect(viewport, &Viewport::transformFinished, this, &EditController::onTransformFinished);
    connect(viewport, &Viewport::transformCancelled, this, [this] { m_moveAfterDuplicate = false; });
    setUpOutliner();
}

void EditController::createToolActions() {
    Viewport* viewport = m_window->viewport();
    m_tools = new QActionGroup(this);
    m_tools->setExclusive(true);
    auto make = [&](GizmoTool tool, const QString& text, Qt::Key key, const char* name, const QString& tip) {
        QAction* action = new QAction(makeToolIcon(tool), text, m_tools);
        action->setObjectName(QLatin1String(name));
        action->setCheckable(true);
        action->setShortcut(QKeySequence(key));
        action->setShortcutContext(Qt::WidgetWithChildrenShortcut);
        action->setToolTip(QStringLiteral("%1 (%2)").arg(QString(text).remove('&'),
                                                         QKeySequence(key).toString(QKeySequence::NativeText)));
        action->setStatusTip(tip);
        viewport->addAction(action);
        connect(action, &QAction::triggered, viewport, [viewport, tool] { viewport->setTool(tool); });
        return action;
    };
    m_selectTool = make(GizmoTool::Select, tr("&Select"), Qt::Key_Q, "SelectToolAction",
                        tr("Select tool: click or drag a box to select"));
    m_moveTool = make(GizmoTool::Move, tr("&Move"), Qt::Key_W, "MoveToolAction",
                      tr("Move tool: drag an arrow or a square of the gizmo; Ctrl snaps to 0.1 m"));
    m_rotateTool = make(GizmoTool::Rotate, tr("&Rotate"), Qt::Key_E, "RotateToolAction",
                        tr("Rotate tool: drag a ring of the gizmo; Ctrl snaps to 15 degrees"));
    toolAction(viewport->tool())->setChecked(true);
    connect(viewport, &Viewport::toolChanged, this, [this](GizmoTool tool) { toolAction(tool)->setChecked(true); });

    QToolBar* tools = new QToolBar(tr("Tools"), m_window);
    tools->setObjectName("ToolsToolBar");
    tools->setIconSize(QSize(24, 24));
    tools->addActions(m_tools->actions());
    m_window->addToolBar(Qt::LeftToolBarArea, tools);
}

QAction* EditController::toolAction(GizmoTool tool) const {
    switch (tool) {
    case GizmoTool::Select:
        return m_selectTool;
    case GizmoTool::Move:
        return m_moveTool;
    case GizmoTool::Rotate:
        return m_rotateTool;
    }
    return m_selectTool;
}

void EditController::setUpOutliner() {
    QTreeView* view = m_window->outlinerView();
    view->header()->setSectionResizeMode(OutlinerModel::AnchorColumn, QHeaderView::ResizeToContents);
    view->setEditTriggers(QAbstractItemView::EditKeyPressed | QAbstractItemView::DoubleClicked);
    // The pin column toggles that row's anchor with one click.
    connect(view, &QTreeView::clicked, this, [this](const QModelIndex& index) {
        if (index.isValid() && index.column() == OutlinerModel::AnchorColumn)
            toggleAnchorOf(index.data(OutlinerModel::BodyIndexRole).toInt());
    });
    view->setContextMenuPolicy(Qt::CustomContextMenu);
    connect(view, &QWidget::customContextMenuRequested, this, &EditController::showOutlinerMenu);

    // The outliner model is the view's proxy's source; a refused rename says why.
    QAbstractItemModel* model = view->model();
    while (auto* proxy = qobject_cast<QAbstractProxyModel*>(model))
        model = proxy->sourceModel();
    if (auto* outliner = qobject_cast<OutlinerModel*>(model)) {
        connect(outliner, &OutlinerModel::renameRefused, this, [this](const QString& message) {
            m_window->statusBar()->showMessage(message, 6000);
            auto* box = new QMessageBox(QMessageBox::Warning, tr("Rename"), message, QMessageBox::Ok, m_window);
            box->setObjectName("RenameRefusedMessage");
            box->setAttribute(Qt::WA_DeleteOnClose);
            box->open(); // window-modal, does not block the caller
        });
    }
}

void EditController::showOutlinerMenu(const QPoint& position) {
    QTreeView* view = m_window->outlinerView();
    const QModelIndex index = view->indexAt(position);
    if (index.isValid() && !view->selectionModel()->isRowSelected(index.row(), index.parent()))
        m_window->setSelectedBodies({index.data(OutlinerModel::BodyIndexRole).toInt()});
    QMenu menu(view);
    menu.addAction(m_renameAction);
    menu.addAction(m_anchorAction);
    QAction* duplicate = menu.addAction(m_duplicateAction->icon(), m_duplicateAction->text().remove('&'));
    duplicate->setEnabled(m_duplicateAction->isEnabled());
    connect(duplicate, &QAction::triggered, this, [this] { duplicateSelection(false); });
    menu.addAction(m_deleteAction);
    menu.exec(view->viewport()->mapToGlobal(position));
}

void EditController::deleteSelection() {
    const QList<int> bodies = m_window->selectedBodies();
    if (bodies.isEmpty())
        return;
    m_window->setSelectedBodies({}); // the indices shift once the bodies are gone
    m_window->document()->undoStack()->push(new RemoveBodiesCommand(m_window->document(), bodies));
}

void EditController::toggleAnchor() {
    const QList<int> selection = m_window->selectedBodies();
    if (selection.isEmpty())
        return;
    SceneDocument* document = m_window->document();
    bool allAnchored = true;
    for (int body : selection)
        allAnchored = allAnchored && document->body(body).anchor;
    std::vector<BodyDef> after;
    for (int body : selection) {
        after.push_back(document->body(body));
        after.back().anchor = !allAnchored;
    }
    document->undoStack()->push(
        new SetBodiesCommand(document, selection, std::move(after), allAnchored ? tr("Unanchor") : tr("Anchor")));
}

void EditController::toggleAnchorOf(int body) {
    SceneDocument* document = m_window->document();
    if (body < 0 || body >= document->bodyCount())
        return;
    BodyDef after = document->body(body);
    after.anchor = !after.anchor;
    const QString name = QString::fromStdString(after.name);
    document->undoStack()->push(new SetBodyCommand(
        document, body, after, after.anchor ? tr("Anchor %1").arg(name) : tr("Unanchor %1").arg(name)));
}

int EditController::addPrimitive(Primitive kind) {
    SceneDocument* document = m_window->document();
    BodyDef body = makePrimitiveBody(kind);
    body.name = uniqueBodyName(document->scene(), body.name);
    // On top of the selection (where it will drop onto it), else standing on the ground at the origin.
    const double half = primitiveHalfHeight(kind);
    const Bounds selected =
        m_window->selectedBodies().isEmpty() ? Bounds{} : m_window->viewport()->scene().bounds(true);
    if (selected.isEmpty()) {
        body.position = Vec3(0.0, half, 0.0);
    } else {
        const glm::vec3 c = selected.centre();
        body.position = Vec3(c.x, static_cast<double>(selected.max.y) + half, c.z);
    }
    const int index = document->bodyCount();
    document->undoStack()->push(new AddBodyCommand(document, index, std::move(body)));
    m_window->setSelectedBodies({index});
    return index;
}

QList<int> EditController::duplicateSelection(bool moveAfter) {
    const QList<int> selection = m_window->selectedBodies();
    if (selection.isEmpty())
        return {};
    Viewport* viewport = m_window->viewport();
    if (viewport->isTransforming())
        viewport->cancelTransform();
    SceneDocument* document = m_window->document();
    std::vector<BodyDef> copies;
    std::set<std::string> taken;
    for (int body : selection) {
        BodyDef copy = document->body(body);
        copy.name = uniqueBodyName(document->scene(), copy.name, taken);
        taken.insert(copy.name);
        copies.push_back(std::move(copy));
    }
    if (!moveAfter) {
        // Beside the originals, clear of them along +X.
        const Bounds box = viewport->scene().bounds(true);
        const double offset = box.isEmpty() ? 1.0 : static_cast<double>(box.size().x) + 0.2;
        for (BodyDef& copy : copies)
            copy.position.x += offset;
    }
    auto* command = new DuplicateBodiesCommand(document, std::move(copies));
    const QList<int> indices = command->copyIndices();
    document->undoStack()->push(command);
    m_window->setSelectedBodies(indices);
    if (moveAfter)
        m_moveAfterDuplicate = viewport->startModalTransform(GizmoTool::Move);
    return indices;
}

void EditController::onTransformFinished(const QList<int>& bodies, const RigidDelta& delta) {
    SceneDocument* document = m_window->document();
    for (int body : bodies)
        if (body < 0 || body >= document->bodyCount())
            return; // the scene changed under the drag
    const int mergeId = m_moveAfterDuplicate ? DuplicateBodiesCommand::kMergeId : -1;
    m_moveAfterDuplicate = false;
    document->undoStack()->push(new TransformBodiesCommand(document, bodies, delta, mergeId));
}

void EditController::renameActive() {
    const QList<int> selection = m_window->selectedBodies();
    if (selection.isEmpty())
        return;
    QTreeView* view = m_window->outlinerView();
    int body = selection.first();
    const QModelIndex current = view->currentIndex();
    if (current.isValid() && selection.contains(current.data(OutlinerModel::BodyIndexRole).toInt()))
        body = current.data(OutlinerModel::BodyIndexRole).toInt();
    // Find the body's row in the (possibly filtered) view.
    QAbstractItemModel* model = view->model();
    for (int row = 0; row < model->rowCount(); ++row) {
        const QModelIndex index = model->index(row, OutlinerModel::NameColumn);
        if (index.data(OutlinerModel::BodyIndexRole).toInt() == body) {
            view->scrollTo(index);
            view->selectionModel()->setCurrentIndex(index, QItemSelectionModel::NoUpdate); // keeps the selection
            view->setFocus(Qt::ShortcutFocusReason);
            view->edit(index);
            return;
        }
    }
    m_window->statusBar()->showMessage(tr("The body is hidden by the outliner's filter; clear it to rename."), 6000);
}

void EditController::selectAll() {
    QList<int> all;
    for (int i = 0; i < m_window->document()->bodyCount(); ++i)
        all.append(i);
    m_window->setSelectedBodies(all);
}

void EditController::selectNone() {
    m_window->setSelectedBodies({});
}

void EditController::invertSelection() {
    std::vector<bool> selected(static_cast<size_t>(m_window->document()->bodyCount()), false);
    for (int body : m_window->selectedBodies())
        selected[static_cast<size_t>(body)] = true;
    QList<int> inverted;
    for (size_t i = 0; i < selected.size(); ++i)
        if (!selected[i])
            inverted.append(static_cast<int>(i));
    m_window->setSelectedBodies(inverted);
}

} // namespace rl
