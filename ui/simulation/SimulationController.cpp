#include "simulation/SimulationController.h"

#include "MainWindow.h"
#include "bake/Bake.h"
#include "timeline/TimelineWidget.h"

#include <QDockWidget>

namespace rl {

SimulationController::SimulationController(MainWindow* window) : QObject(window), m_window(window) {
    auto* dock = new QDockWidget(tr("Timeline"), window);
    dock->setObjectName("TimelineDock");
    m_timeline = new TimelineWidget(dock);
    dock->setWidget(m_timeline);
    window->addDockWidget(Qt::BottomDockWidgetArea, dock);
}

SimulationController::~SimulationController() = default;

bool SimulationController::openBake(const QString&) {
    return false;
}

} // namespace rl
