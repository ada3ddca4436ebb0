// Simulation menu and toolbar: live run on a worker thread (Play, Pause, Step, Reset), background bake, playback and
// scrubbing of the bake through the timeline dock, and opening .bake files.
#pragma once

#include <QObject>

#include <memory>

namespace rl {

class Bake;
class MainWindow;
class TimelineWidget;

class SimulationController : public QObject {
    Q_OBJECT
public:
    explicit SimulationController(MainWindow* window);
    ~SimulationController() override;

    // The bake the timeline shows, or null. Shared so that exporters and panels can hold it while a new one replaces
    // it.
    std::shared_ptr<const Bake> currentBake() const { return m_bake; }
    // Opens a .bake (ours or the original project's) for playback; ours also restores the scene from its OBJ part.
    bool openBake(const QString& path);
    TimelineWidget* timeline() const { return m_timeline; }

signals:
    void bakeChanged();

private:
    MainWindow* m_window;
    TimelineWidget* m_timeline = nullptr;
    std::shared_ptr<const Bake> m_bake;
};

} // namespace rl
