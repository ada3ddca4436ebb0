// The World settings panel: gravity, time stepping (fps, substeps, iterations, integrator), damping, the combine
// rules of contacts, and the effects the world simulates (each Auto, On or Off). For effects left on Auto it shows
// what the core decides for the scene at hand and why (rl::decideEffects), updated as the scene changes.
// Every change is one undo step (SetWorldSettingsCommand); spin-box drags merge. Invalid values are refused with a
// message that says what is allowed.
#pragma once

#include "scene/WorldSettings.h"
#include "world/Effects.h"

#include <QWidget>

#include <array>
#include <optional>

class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QSpinBox;
class QTimer;

namespace rl {

class SceneDocument;
class MessageBar;

class WorldSettingsWidget : public QWidget {
    Q_OBJECT
public:
    explicit WorldSettingsWidget(SceneDocument* document, QWidget* parent = nullptr);

    // Why the world cannot run with these settings (the limits World::create checks), or an empty string.
    static QString problem(const WorldSettings& settings);

    // Stores settings as one undo step (merging with the previous edit of the same mergeId); refused with a message
    // when problem() objects.
    bool applySettings(const WorldSettings& settings, const QString& text, int mergeId = -1);

    QString message() const;

    // What the core decides for the current scene: the effects that run and why. nullopt when the scene cannot be
    // simulated (the effects panel then says why). Updated shortly after every change; decideNow() forces it.
    const std::optional<EffectsDecision>& decision() const { return m_decision; }
    void decideNow();

signals:
    // The effects panel shows a new decision.
    void decisionUpdated();

protected:
    void showEvent(QShowEvent* event) override;

private:
    void refresh();
    void scheduleDecision();
    void refreshEffects();
    template <class T>
    void edit(T WorldSettings::*field, T value, const QString& text, int mergeId);

    SceneDocument* m_document;
    MessageBar* m_message = nullptr;

    QComboBox* m_gravityPreset = nullptr;
    std::array<QDoubleSpinBox*, 3> m_gravity{};
    QLabel* m_gravityMagnitude = nullptr;
    QDoubleSpinBox* m_fps = nullptr;
    QSpinBox* m_substeps = nullptr;
    QSpinBox* m_iterations = nullptr;
    QComboBox* m_integrator = nullptr;
    QLabel* m_stepInfo = nullptr;
    QDoubleSpinBox* m_linearDamping = nullptr;
    QDoubleSpinBox* m_angularDamping = nullptr;
    QComboBox* m_frictionCombine = nullptr;
    QComboBox* m_restitutionCombine = nullptr;
    std::array<QComboBox*, kEffectCount> m_effectModes{};
    std::array<QLabel*, kEffectCount> m_effectStatus{};
    QCheckBox* m_linearOnly = nullptr;
    QLabel* m_effectsProblem = nullptr;

    QTimer* m_decisionTimer = nullptr;
    bool m_decisionStale = true;
    std::optional<EffectsDecision> m_decision;
    std::optional<EffectsDecision> m_autoDecision; // every effect on Auto: what Auto would pick for forced ones
    QString m_decisionError;
};

} // namespace rl
