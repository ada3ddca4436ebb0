// Analysis menu: accuracy panel, re-bake diff, pre-flight check; the UI's exporters (File > Export).
#pragma once

#include <QObject>

namespace rl {

class MainWindow;

class AnalysisController : public QObject {
    Q_OBJECT
public:
    explicit AnalysisController(MainWindow* window);

    // Runs the pre-flight check on the document's scene before a bake. Returns true when the bake should go on
    // (no findings, or the user chose to bake anyway).
    bool confirmPreflight();

private:
    MainWindow* m_window;
};

} // namespace rl
