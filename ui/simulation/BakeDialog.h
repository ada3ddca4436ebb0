// Simulation > Bake…: how long to bake, as a duration in seconds or as the last frame (the two stay in step at the
// scene's frame rate). The bake always starts from the edit pose at frame 0.
#pragma once

#include <QDialog>

class QDoubleSpinBox;
class QSpinBox;

namespace rl {

class BakeDialog : public QDialog {
    Q_OBJECT
public:
    BakeDialog(double fps, int lastFrame, QWidget* parent = nullptr);

    // Frames after frame 0; the bake holds lastFrame() + 1 frames.
    int lastFrame() const;

private:
    double m_fps;
    QDoubleSpinBox* m_seconds = nullptr;
    QSpinBox* m_lastFrame = nullptr;
    bool m_syncing = false;
};

} // namespace rl
