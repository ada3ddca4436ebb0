// Shared helpers of the simulation and bake-playback UI tests: a shown main window, scenes, the displayed pose of a
// body, and a guard that closes an unexpected modal dialog (a pre-flight finding, an error box) instead of hanging.
#pragma once

#include "MainWindow.h"
#include "bake/Bake.h"
#include "document/SceneDocument.h"
#include "overlays/OverlayController.h"
#include "scene/BodyProperties.h"
#include "simulation/SimulationController.h"
#include "viewport/ScenePresenter.h"
#include "viewport/Viewport.h"

#include <QApplication>
#include <QDialog>
#include <QMessageBox>
#include <QTest>
#include <QTimer>

#include <glm/gtc/matrix_inverse.hpp>

namespace rl::test {

// Rejects any modal dialog that shows up while it lives, and remembers its title, so a test fails with a reason
// instead of blocking on exec().
class ModalGuard : public QObject {
public:
    ModalGuard() {
        m_timer.setInterval(200);
        QObject::connect(&m_timer, &QTimer::timeout, [this] {
            if (QWidget* modal = QApplication::activeModalWidget()) {
                m_seen.append(modal->windowTitle() + QStringLiteral(": ") + modal->objectName());
                if (auto* dialog = qobject_cast<QDialog*>(modal))
                    dialog->reject();
                else
                    modal->close();
            }
        });
        m_timer.start();
    }
    QStringList seen() const { return m_seen; }

private:
    QTimer m_timer;
    QStringList m_seen;
};

// Shows the window with every overlay off (their state persists in QSettings between tests), so that images and
// overlay frames depend only on the test itself.
inline bool showWindow(MainWindow& window) {
    for (int kind = 0; kind < OverlayController::KindCount; ++kind)
        window.overlays()->setEnabled(static_cast<OverlayController::Kind>(kind), false);
    window.resize(1280, 800);
    window.show();
    window.activateWindow();
    return QTest::qWaitForWindowExposed(&window) && QTest::qWaitForWindowActive(&window);
}

// The viewport's matrix of body i as edited (the presenter's edit pose) and as shown now.
inline glm::mat4 editModel(MainWindow& window, int i) {
    return window.presenter()->viewportScene().instances.at(static_cast<size_t>(i)).model;
}
inline glm::mat4 shownModel(MainWindow& window, int i) {
    return window.viewport()->scene().instances.at(static_cast<size_t>(i)).model;
}

// Where the viewport shows body i's edit-pose centre of mass now: the shown matrix applied to the edit matrix's
// inverse, applied to the centre. Independent of how the controller computes its matrices.
inline glm::dvec3 shownCentre(MainWindow& window, int i, const glm::dvec3& editCentre) {
    const glm::dmat4 motion = glm::dmat4(shownModel(window, i)) * glm::inverse(glm::dmat4(editModel(window, i)));
    return glm::dvec3(motion * glm::dvec4(editCentre, 1.0));
}
// The rotation part of that motion, as a quaternion.
inline glm::dquat shownRotation(MainWindow& window, int i) {
    const glm::dmat4 motion = glm::dmat4(shownModel(window, i)) * glm::inverse(glm::dmat4(editModel(window, i)));
    return glm::quat_cast(glm::dmat3(motion));
}

inline glm::dvec3 editCentre(MainWindow& window, int i) {
    const Scene& scene = window.document()->scene();
    Result<BodyProperties> props = computeBodyProperties(scene, scene.bodies.at(static_cast<size_t>(i)));
    return props ? props->com : glm::dvec3(0.0);
}

} // namespace rl::test
