#include "analysis/AnalysisController.h"

#include "MainWindow.h"

namespace rl {

AnalysisController::AnalysisController(MainWindow* window) : QObject(window), m_window(window) {}

bool AnalysisController::confirmPreflight() {
    return true;
}

} // namespace rl
