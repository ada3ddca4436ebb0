// The World settings dock and the Materials dock (material library editor and pairwise table).
#pragma once

#include <QObject>

namespace rl {

class MainWindow;

class SettingsController : public QObject {
    Q_OBJECT
public:
    explicit SettingsController(MainWindow* window);

private:
    MainWindow* m_window;
};

} // namespace rl
