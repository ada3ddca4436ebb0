#include "settings/SettingsController.h"

#include "MainWindow.h"
#include "materials/MaterialsWidget.h"
#include "world/WorldSettingsWidget.h"

#include <QAction>
#include <QDockWidget>
#include <QMenu>

namespace rl {

SettingsController::SettingsController(MainWindow* window) : QObject(window), m_window(window) {
    m_worldDock = new QDockWidget(tr("World"), window);
    m_worldDock->setObjectName("WorldSettingsDock");
    m_world = new WorldSettingsWidget(window->document(), m_worldDock);
    m_worldDock->setWidget(m_world);

    m_materialsDock = new QDockWidget(tr("Materials"), window);
    m_materialsDock->setObjectName("MaterialsDock");
    m_materials = new MaterialsWidget(window->document(), m_materialsDock);
    m_materialsDock->setWidget(m_materials);

    // Tabs next to the inspector on the right, which stays in front: these panels are visited, the inspector lives.
    QDockWidget* inspector = window->findChild<QDockWidget*>("InspectorDock");
    window->addDockWidget(Qt::RightDockWidgetArea, m_materialsDock);
    window->addDockWidget(Qt::RightDockWidgetArea, m_worldDock);
    if (inspector) {
        window->tabifyDockWidget(inspector, m_materialsDock);
        window->tabifyDockWidget(m_materialsDock, m_worldDock);
        inspector->raise();
    }

    QMenu* menu = window->menu(MainWindow::Menu::Window);
    QAction* worldAction = m_worldDock->toggleViewAction();
    worldAction->setObjectName("WorldSettingsDockAction");
    worldAction->setText(tr("&World Settings"));
    QAction* materialsAction = m_materialsDock->toggleViewAction();
    materialsAction->setObjectName("MaterialsDockAction");
    materialsAction->setText(tr("&Materials"));
    menu->addAction(worldAction);
    menu->addAction(materialsAction);
}

} // namespace rl
