// Edit and Add menus: undo/redo, delete, anchor toggle, duplicate, rename, selection, add primitives, and the
// viewport's transform tools (select, move, rotate) with their gizmo drags turned into undo steps.
#pragma once

#include "edit/Primitives.h"
#include "viewport/Gizmo.h"

#include <QList>
#include <QObject>

class QAction;
class QActionGroup;
class QModelIndex;
class QPoint;

namespace rl {

class MainWindow;

class EditController : public QObject {
    Q_OBJECT
public:
    explicit EditController(MainWindow* window);

    void deleteSelection();
    void toggleAnchor();
    // Toggles one body's anchor flag (the outliner's pin column): one undo step.
    void toggleAnchorOf(int body);
    // Adds a primitive resting on the ground at the origin, or on top of the selection; selects it. One undo step.
    int addPrimitive(Primitive kind);
    // Copies the selection with new names and selects the copies. With moveAfter, a modal move follows in the
    // viewport (Blender's Shift+D); the copies and that move are one undo step. Returns the copies' indices.
    QList<int> duplicateSelection(bool moveAfter = true);
    // Opens the outliner's in-place editor on the active body (the outliner's current row when selected, else the
    // first selected body).
    void renameActive();
    void selectAll();
    void selectNone();
    void invertSelection();

    QAction* toolAction(GizmoTool tool) const;

private:
    void createToolActions();
    void setUpOutliner();
    void showOutlinerMenu(const QPoint& position);
    void onTransformFinished(const QList<int>& bodies, const RigidDelta& delta);

    MainWindow* m_window;
    QActionGroup* m_tools = nullptr;
    QAction* m_selectTool = nullptr;
    QAction* m_moveTool = nullptr;
    QAction* m_rotateTool = nullptr;
    QAction* m_renameAction = nullptr;
    QAction* m_duplicateAction = nullptr;
    QAction* m_deleteAction = nullptr;
    QAction* m_anchorAction = nullptr;
    // Set while the modal move after a duplicate runs: its result merges into the duplicate's undo step.
    bool m_moveAfterDuplicate = false;
};

} // namespace rl
