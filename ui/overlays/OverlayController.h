// View > Overlays: contact points and normals, velocity arrows, centres of mass, AABBs, sleeping bodies coloured
// differently and motion trails for the selected bodies. Each is a checkable action; the controller draws the
// enabled ones over the viewport from the OverlayFrame the simulation controller hands it.
#pragma once

#include "overlays/OverlayFrame.h"

#include <QObject>

namespace rl {

class MainWindow;

class OverlayController : public QObject {
    Q_OBJECT
public:
    enum Kind { Contacts, Velocities, Centres, Aabbs, Sleeping, Trails, KindCount };

    explicit OverlayController(MainWindow* window);

    bool isEnabled(Kind kind) const { return m_enabled[kind]; }
    void setEnabled(Kind kind, bool on);
    // The state now on screen. Cheap to call every displayed frame.
    void setFrame(OverlayFrame frame);
    // Back to the edit pose: clears the frame and the trails.
    void clear();

signals:
    void enabledChanged(int kind, bool on);

private:
    MainWindow* m_window;
    bool m_enabled[KindCount] = {};
    OverlayFrame m_frame;
};

} // namespace rl
