// The World settings dock and the Materials dock (material library editor and pairwise table), with their toggle
// actions in the Window menu.
#pragma once

#include <QObject>

class QDockWidget;

namespace rl {

class MainWindow;
class MaterialsWidget;
class WorldSettingsWidget;

class SettingsController : public QObject {
    Q_OBJECT
public:
    explicit SettingsController(MainWindow* window);

    MaterialsWidget* materials() const { return m_materials; }
    WorldSettingsWidget* worldSettings() const { return m_world; }
    QDockWidget* materialsDock() const { return m_materialsDock; }
    QDockWidget* worldDock() const { return m_worldDock; }

private:
    MainWindow* m_window;
    MaterialsWidget* m_materials = nullptr;
    WorldSettingsWidget* m_world = nullptr;
    QDockWidget* m_materialsDock = nullptr;
    QDockWidget* m_worldDock = nullptr;
};

} // namespace rl
