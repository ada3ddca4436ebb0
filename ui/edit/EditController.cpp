#include "edit/EditController.h"

#include "MainWindow.h"
#include "document/SceneDocument.h"
#include "document/commands/RemoveBodiesCommand.h"
#include "document/commands/SetBodiesCommand.h"

#include <QAction>
#include <QMenu>
#include <QToolBar>
#include <QUndoStack>

namespace rl {

EditController::EditController(MainWindow* window) : QObject(window), m_window(window) {
    QMenu* editMenu = window->menu(MainWindow::Menu::Edit);
    QToolBar* toolBar = window->addToolBar(tr("Edit"));
    toolBar->setObjectName("EditToolBar");
    QUndoStack* stack = window->document()->undoStack();

    QAction* undoAction = stack->createUndoAction(this, tr("&Undo"));
    undoAction->setObjectName("UndoAction");
    undoAction->setShortcut(QKeySequence::Undo);
    undoAction->setIcon(QIcon::fromTheme("edit-undo"));
    QAction* redoAction = stack->createRedoAction(this, tr("&Redo"));
    redoAction->setObjectName("RedoAction");
    // Ctrl+Shift+Z as in Blender, Ctrl+Y as on Windows.
    redoAction->setShortcuts({QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_Z), QKeySequence(Qt::CTRL | Qt::Key_Y)});
    redoAction->setIcon(QIcon::fromTheme("edit-redo"));

    QAction* deleteAction = new QAction(QIcon::fromTheme("edit-delete"), tr("&Delete"), this);
    deleteAction->setObjectName("DeleteAction");
    deleteAction->setShortcut(QKeySequence::Delete);
    deleteAction->setStatusTip(tr("Delete the selected bodies"));
    connect(deleteAction, &QAction::triggered, this, &EditController::deleteSelection);

    // Alt+A: Shift+A is Blender's "Add" and Ctrl+A "Select all".
    QAction* anchorAction = new QAction(tr("Toggle &Anchor"), this);
    anchorAction->setObjectName("ToggleAnchorAction");
    anchorAction->setShortcut(QKeySequence(Qt::ALT | Qt::Key_A));
    anchorAction->setStatusTip(tr("Make the selected bodies static, or dynamic again when all are static"));
    connect(anchorAction, &QAction::triggered, this, &EditController::toggleAnchor);

    auto updateEnabled = [this, deleteAction, anchorAction] {
        const bool any = !m_window->selectedBodies().isEmpty();
        deleteAction->setEnabled(any);
        anchorAction->setEnabled(any);
    };
    connect(window, &MainWindow::selectionChanged, this, updateEnabled);
    updateEnabled();

    editMenu->addAction(undoAction);
    editMenu->addAction(redoAction);
    editMenu->addSeparator();
    editMenu->addAction(deleteAction);
    editMenu->addAction(anchorAction);
    toolBar->addAction(undoAction);
    toolBar->addAction(redoAction);
    toolBar->addSeparator();
    toolBar->addAction(deleteAction);
    toolBar->addAction(anchorAction);
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

} // namespace rl
