// Simulation > Bake…: which frames to bake, as a frame range or as a duration in seconds from its first frame (the
// two stay in step at the scene's frame rate). The simulation starts from the edit pose at the first frame, as
// Blender's rigid-body cache starts at its start frame; before it the bodies hold the edit pose.
#pragma once

#include <QDialog>

class QDoubleSpinBox;
class QSpinBox;

namespace rl {

class BakeDialog : public QDialog {
    Q_OBJECT
public:
    BakeDialog(double fps, int firstFrame, int lastFrame, QWidget* parent = nullptr);

    // The frame at which the simulation starts (0: at once).
    int firstFrame() const;
    // The last frame; the bake holds lastFrame() + 1 frames, always from frame 0.
    int lastFrame() const;

private:
    double m_fps;
    QDoubleSpinBox* m_seconds = nullptr;
    QSpinBox* m_firstFrame = nullptr;
    QSpinBox* m_lastFrame = nullptr;
    bool m_syncing = false;
};

} // namespace rl
