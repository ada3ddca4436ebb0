#include "settings/SettingsController.h"

#include "MainWindow.h"

namespace rl {

SettingsController::SettingsController(MainWindow* window) : QObject(window), m_window(window) {}

} // namespace rl
