// Edit and Add menus: undo/redo, delete, anchor toggle, duplicate, add primitives, and the viewport's gizmo tools.
#pragma once

#include <QObject>

namespace rl {

class MainWindow;

class EditController : public QObject {
    Q_OBJECT
public:
    explicit EditController(MainWindow* window);

    void deleteSelection();
    void toggleAnchor();

private:
    MainWindow* m_window;
};

} // namespace rl
