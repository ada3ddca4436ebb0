#include "world/WorldSettingsWidget.h"

#include "document/CoreText.h"
#include "document/SceneDocument.h"
#include "document/commands/SetWorldSettingsCommand.h"
#include "materials/MaterialLibrary.h"
#include "settings/MessageBar.h"
#include "world/World.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QGridLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QScrollArea>
#include <QSignalBlocker>
#include <QSpinBox>
#include <QStandardItemModel>
#include <QTimer>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>

namespace rl {

namespace {

// Limits World::create checks (core/world/World.cpp); the fields reach beyond them so that a typed value outside
// is refused with a message instead of being clamped silently.
constexpr double kMaxFps = 100000.0;
constexpr int kMaxSteps = 1000;
constexpr double kMaxGravity = 1000.0; // m/s², a hundred times Earth's
constexpr double kMaxDamping = 1000.0; // 1/s
constexpr int kFieldWidth = 150;       // px: numbers need no more, and a row of fields reads better than a wall

struct GravityPreset {
    const char* name;
    double magnitude; // m/s², pointing down (-Y)
};
// Surface gravity: Earth as the scene default (9.81), the Moon and Mars as commonly quoted.
constexpr GravityPreset kGravityPresets[] = {
    {QT_TRANSLATE_NOOP("rl::WorldSettingsWidget", "Earth"), 9.81},
    {QT_TRANSLATE_NOOP("rl::WorldSettingsWidget", "Moon"), 1.62},
    {QT_TRANSLATE_NOOP("rl::WorldSettingsWidget", "Mars"), 3.71},
    {QT_TRANSLATE_NOOP("rl::WorldSettingsWidget", "Zero g"), 0.0},
};
constexpr int kGravityPresetCount = static_cast<int>(std::size(kGravityPresets));

QString effectLabel(Effect e) {
    switch (e) {
    case Effect::Gravity:
        return WorldSettingsWidget::tr("Gravity");
    case Effect::Rotation:
        return WorldSettingsWidget::tr("Rotation");
    case Effect::Friction:
        return WorldSettingsWidget::tr("Friction");
    case Effect::Restitution:
        return WorldSettingsWidget::tr("Restitution");
    case Effect::Damping:
        return WorldSettingsWidget::tr("Damping");
    case Effect::Sleeping:
        return WorldSettingsWidget::tr("Sleeping");
    case Effect::Ccd:
        return WorldSettingsWidget::tr("CCD");
    }
    return {};
}

QString effectToolTip(Effect e) {
    switch (e) {
    case Effect::Gravity:
        return WorldSettingsWidget::tr("Auto: on when a dynamic body exists and gravity is not zero");
    case Effect::Rotation:
        return WorldSettingsWidget::tr("Auto: on unless every dynamic body is a sphere that cannot start spinning");
    case Effect::Friction:
        return WorldSettingsWidget::tr("Auto: on when some pair of bodies has a combined friction above zero");
    case Effect::Restitution:
        return WorldSettingsWidget::tr("Auto: on when some pair of bodies has a combined restitution above zero");
    case Effect::Damping:
        return WorldSettingsWidget::tr("Auto: on when linear or angular damping is above zero");
    case Effect::Sleeping:
        return WorldSettingsWidget::tr("Auto: on when gravity acts and there is an anchor to come to rest on");
    case Effect::Ccd:
        return WorldSettingsWidget::tr("Continuous collision detection. Auto: on when some body may move more than "
                                       "half its size in one frame");
    }
    return {};
}

// The core's reasons read "auto: <why>", "forced on" or "forced off"; the panel shows the why, translated.
QString reasonText(const std::string& reason) {
    const std::string prefix = "auto: ";
    return coreText(reason.rfind(prefix, 0) == 0 ? reason.substr(prefix.size()) : reason);
}

} // namespace

WorldSettingsWidget::WorldSettingsWidget(SceneDocument* document, QWidget* parent)
    : QWidget(parent), m_document(document), m_decisionTimer(new QTimer(this)) {
    setObjectName("WorldSettingsWidget");
    auto* outer = new QVBoxLayout(this);
    outer->setContentsMargins(0, 0, 0, 0);
    auto* scroll = new QScrollArea(this);
    scroll->setWidgetResizable(true);
    scroll->setFrameShape(QFrame::NoFrame);
    scroll->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff); // the panel wraps to the dock's width
    auto* content = new QWidget(scroll);
    content->setObjectName("WorldSettingsContent");
    scroll->setWidget(content);
    outer->addWidget(scroll);
    auto* sections = new QVBoxLayout(content);
    sections->setContentsMargins(4, 4, 4, 4);

    m_message = new MessageBar(content);
    m_message->setObjectName("WorldMessage");
    sections->addWidget(m_message);

    auto makeSection = [&](const QString& title, const char* objectName) {
        auto* box = new QGroupBox(title, content);
        box->setObjectName(QLatin1String(objectName));
        auto* form = new QFormLayout(box);
        form->setFieldGrowthPolicy(QFormLayout::AllNonFixedFieldsGrow);
        form->setLabelAlignment(Qt::AlignRight | Qt::AlignVCenter);
        sections->addWidget(box);
        return form;
    };
    auto makeDouble = [&](const QString& objectName, double min, double max, int decimals, double step,
                          const QString& suffix) {
        auto* box = new QDoubleSpinBox(content);
        box->setObjectName(objectName);
        box->setRange(min, max);
        box->setDecimals(decimals);
        box->setSingleStep(step);
        box->setSuffix(suffix);
        box->setKeyboardTracking(false);
        box->setAccelerated(true);
        box->setAlignment(Qt::AlignRight);
        box->setMaximumWidth(kFieldWidth);
        return box;
    };
    auto makeInt = [&](const QString& objectName, int max) {
        auto* box = new QSpinBox(content);
        box->setObjectName(objectName);
        box->setRange(0, max);
        box->setKeyboardTracking(false);
        box->setAlignment(Qt::AlignRight);
        box->setMaximumWidth(kFieldWidth);
        return box;
    };

    // Gravity
    QFormLayout* gravity = makeSection(tr("Gravity"), "WorldGravityBox");
    m_gravityPreset = new QComboBox(content);
    m_gravityPreset->setObjectName("GravityPreset");
    for (const GravityPreset& preset : kGravityPresets)
        m_gravityPreset->addItem(preset.magnitude > 0.0 ? tr("%1 (%2 m/s²)").arg(tr(preset.name)).arg(preset.magnitude)
                                                        : tr(preset.name));
    m_gravityPreset->addItem(tr("Custom"));
    // "Custom" only names a vector that matches no preset; picking it changes nothing.
    if (auto* model = qobject_cast<QStandardItemModel*>(m_gravityPreset->model()))
        model->item(kGravityPresetCount)->setEnabled(false);
    m_gravityPreset->setToolTip(tr("Sets gravity straight down (−Y) with the planet's surface gravity"));
    connect(m_gravityPreset, &QComboBox::activated, this, [this](int index) {
        if (index < 0 || index >= kGravityPresetCount)
            return;
        WorldSettings w = m_document->scene().world;
        w.gravity = Vec3(0.0, -kGravityPresets[index].magnitude, 0.0);
        applySettings(w, tr("Set Gravity"));
    });
    gravity->addRow(tr("Preset"), m_gravityPreset);
    auto* vector = new QHBoxLayout;
    vector->setSpacing(2);
    const char* axes[] = {"X", "Y", "Z"};
    for (int axis = 0; axis < 3; ++axis) {
        QDoubleSpinBox* box =
            makeDouble(QStringLiteral("Gravity") + axes[axis], -kMaxGravity, kMaxGravity, 3, 0.1, QString());
        box->setToolTip(tr("Gravity %1 in m/s² (Y is up)").arg(QLatin1String(axes[axis])));
        connect(box, &QDoubleSpinBox::valueChanged, this, [this, axis](double v) {
            WorldSettings w = m_document->scene().world;
            w.gravity[axis] = v;
            applySettings(w, tr("Set Gravity"), SetWorldGravityId + axis);
        });
        vector->addWidget(box, 1);
        m_gravity[static_cast<size_t>(axis)] = box;
    }
    gravity->addRow(tr("X, Y, Z (m/s²)"), vector);
    m_gravityMagnitude = new QLabel(content);
    m_gravityMagnitude->setObjectName("GravityMagnitude");
    gravity->addRow(tr("Magnitude"), m_gravityMagnitude);

    // Time stepping
    QFormLayout* stepping = makeSection(tr("Time stepping"), "WorldSteppingBox");
    m_fps = makeDouble("WorldFps", 0.0, 10.0 * kMaxFps, 2, 10.0, tr(" Hz"));
    m_fps->setToolTip(tr("Frames per second; one simulation step per frame (above 0, at most %L1 Hz)").arg(kMaxFps));
    connect(m_fps, &QDoubleSpinBox::valueChanged, this,
            [this](double v) { edit(&WorldSettings::fps, v, tr("Set Frame Rate"), SetWorldFpsId); });
    stepping->addRow(tr("Frame rate"), m_fps);
    m_substeps = makeInt("WorldSubsteps", 100 * kMaxSteps);
    m_substeps->setSuffix(tr(" per frame"));
    m_substeps->setToolTip(tr("Solver substeps per frame, 1 to %1. More substeps make stacks stiffer and contacts "
                              "more accurate.")
                               .arg(kMaxSteps));
    connect(m_substeps, &QSpinBox::valueChanged, this,
            [this](int v) { edit(&WorldSettings::substeps, v, tr("Set Substeps"), SetWorldSubstepsId); });
    stepping->addRow(tr("Substeps"), m_substeps);
    m_iterations = makeInt("WorldIterations", 100 * kMaxSteps);
    m_iterations->setSuffix(tr(" per substep"));
    m_iterations->setToolTip(tr("Velocity iterations of the contact solver per substep, 1 to %1").arg(kMaxSteps));
    connect(m_iterations, &QSpinBox::valueChanged, this,
            [this](int v) { edit(&WorldSettings::iterations, v, tr("Set Iterations"), SetWorldIterationsId); });
    stepping->addRow(tr("Iterations"), m_iterations);
    m_integrator = new QComboBox(content);
    m_integrator->setObjectName("WorldIntegrator");
    const QString integratorTips[] = {
        tr("First order; gains energy (the original project's choice)"),
        tr("First order at the same cost; energy stays bounded (default)"),
        tr("Second order; exact for free fall"),
        tr("Fourth order in free flight; costs more per step"),
    };
    const QString integratorLabels[] = {tr("Explicit Euler"), tr("Symplectic Euler"), tr("Verlet"), tr("RK4")};
    for (int i = 0; i < 4; ++i) {
        m_integrator->addItem(integratorLabels[i], QString::fromLatin1(integratorName(static_cast<Integrator>(i))));
        m_integrator->setItemData(i, integratorTips[i], Qt::ToolTipRole);
    }
    m_integrator->setToolTip(tr("Where contacts act, every scheme is first order"));
    connect(m_integrator, &QComboBox::activated, this, [this](int index) {
        edit(&WorldSettings::integrator, static_cast<Integrator>(index), tr("Set Integrator"), -1);
    });
    stepping->addRow(tr("Integrator"), m_integrator);
    m_stepInfo = new QLabel(content);
    m_stepInfo->setObjectName("WorldStepInfo");
    m_stepInfo->setForegroundRole(QPalette::PlaceholderText);
    m_stepInfo->setWordWrap(true);
    stepping->addRow(m_stepInfo);

    // Damping
    QFormLayout* damping = makeSection(tr("Damping"), "WorldDampingBox");
    m_linearDamping = makeDouble("WorldLinearDamping", 0.0, kMaxDamping, 3, 0.01, tr(" 1/s"));
    m_linearDamping->setToolTip(tr("Velocity lost per second, as a rate"));
    connect(m_linearDamping, &QDoubleSpinBox::valueChanged, this, [this](double v) {
        edit(&WorldSettings::linearDamping, v, tr("Set Linear Damping"), SetWorldLinearDampingId);
    });
    damping->addRow(tr("Linear"), m_linearDamping);
    m_angularDamping = makeDouble("WorldAngularDamping", 0.0, kMaxDamping, 3, 0.01, tr(" 1/s"));
    m_angularDamping->setToolTip(tr("Angular velocity lost per second, as a rate"));
    connect(m_angularDamping, &QDoubleSpinBox::valueChanged, this, [this](double v) {
        edit(&WorldSettings::angularDamping, v, tr("Set Angular Damping"), SetWorldAngularDampingId);
    });
    damping->addRow(tr("Angular"), m_angularDamping);

    // Contacts
    QFormLayout* contacts = makeSection(tr("Contact combine rules"), "WorldCombineBox");
    auto makeRuleBox = [&](const QString& objectName, const QString& a, const QString& b) {
        auto* box = new QComboBox(content);
        box->setObjectName(objectName);
        for (int i = 0; i < 5; ++i) {
            const auto rule = static_cast<CombineRule>(i);
            box->addItem(
                QStringLiteral("%1   %2").arg(MaterialLibrary::ruleLabel(rule), MaterialLibrary::formula(rule, a, b)),
                QString::fromLatin1(combineRuleName(rule)));
        }
        return box;
    };
    m_frictionCombine = makeRuleBox("WorldFrictionCombine", QStringLiteral("μa"), QStringLiteral("μb"));
    m_frictionCombine->setToolTip(tr("How the friction of two materials combines at a contact"));
    connect(m_frictionCombine, &QComboBox::activated, this, [this](int index) {
        edit(&WorldSettings::frictionCombine, static_cast<CombineRule>(index), tr("Set Friction Rule"), -1);
    });
    contacts->addRow(tr("Friction"), m_frictionCombine);
    m_restitutionCombine = makeRuleBox("WorldRestitutionCombine", QStringLiteral("ea"), QStringLiteral("eb"));
    m_restitutionCombine->setToolTip(tr("How the restitution of two materials combines at a contact"));
    connect(m_restitutionCombine, &QComboBox::activated, this, [this](int index) {
        edit(&WorldSettings::restitutionCombine, static_cast<CombineRule>(index), tr("Set Restitution Rule"), -1);
    });
    contacts->addRow(tr("Restitution"), m_restitutionCombine);

    // Effects
    auto* effectsBox = new QGroupBox(tr("Effects"), content);
    effectsBox->setObjectName("WorldEffectsBox");
    auto* effectsLayout = new QVBoxLayout(effectsBox);
    auto* intro =
        new QLabel(tr("Auto simulates only what the scene calls for; a skipped effect costs nothing."), effectsBox);
    intro->setWordWrap(true);
    intro->setForegroundRole(QPalette::PlaceholderText);
    effectsLayout->addWidget(intro);
    auto* grid = new QGridLayout;
    grid->setHorizontalSpacing(8);
    grid->setColumnStretch(2, 1);
    for (int i = 0; i < kEffectCount; ++i) {
        const auto effect = static_cast<Effect>(i);
        const QString key = QString::fromLatin1(effectName(effect));
        auto* label = new QLabel(effectLabel(effect), effectsBox);
        label->setToolTip(effectToolTip(effect));
        auto* mode = new QComboBox(effectsBox);
        mode->setObjectName(QStringLiteral("EffectMode_") + key);
        mode->addItems({tr("Auto"), tr("On"), tr("Off")}); // the order of rl::EffectMode
        mode->setToolTip(effectToolTip(effect));
        connect(mode, &QComboBox::activated, this, [this, effect](int index) {
            WorldSettings w = m_document->scene().world;
            w.effects.set(effect, static_cast<EffectMode>(index));
            applySettings(w, tr("Set Effect %1").arg(effectLabel(effect)));
        });
        auto* status = new QLabel(effectsBox);
        status->setObjectName(QStringLiteral("EffectStatus_") + key);
        status->setWordWrap(true);
        status->setTextFormat(Qt::RichText);
        label->setBuddy(mode);
        grid->addWidget(label, i, 0, Qt::AlignRight | Qt::AlignVCenter);
        grid->addWidget(mode, i, 1, Qt::AlignVCenter);
        grid->addWidget(status, i, 2, Qt::AlignVCenter);
        m_effectModes[static_cast<size_t>(i)] = mode;
        m_effectStatus[static_cast<size_t>(i)] = status;
    }
    effectsLayout->addLayout(grid);
    m_linearOnly = new QCheckBox(tr("Linear only: no rotation (the original project's mode)"), effectsBox);
    m_linearOnly->setObjectName("WorldLinearOnly");
    m_linearOnly->setToolTip(tr("The same as Rotation: Off"));
    connect(m_linearOnly, &QCheckBox::toggled, this, [this](bool checked) {
        WorldSettings w = m_document->scene().world;
        w.effects.set(Effect::Rotation, checked ? EffectMode::Off : EffectMode::Auto);
        applySettings(w, checked ? tr("Linear Only") : tr("Allow Rotation"));
    });
    effectsLayout->addWidget(m_linearOnly);
    m_effectsProblem = new QLabel(effectsBox);
    m_effectsProblem->setObjectName("EffectsProblem");
    m_effectsProblem->setWordWrap(true);
    m_effectsProblem->hide();
    effectsLayout->addWidget(m_effectsProblem);
    auto* effectButtons = new QHBoxLayout;
    auto* allAuto = new QPushButton(tr("All Auto"), effectsBox);
    allAuto->setObjectName("EffectsAllAuto");
    connect(allAuto, &QPushButton::clicked, this, [this] {
        WorldSettings w = m_document->scene().world;
        w.effects = EffectsSetting{};
        applySettings(w, tr("All Effects Auto"));
    });
    effectButtons->addWidget(allAuto);
    effectButtons->addStretch(1);
    effectsLayout->addLayout(effectButtons);
    sections->addWidget(effectsBox);

    auto* bottom = new QHBoxLayout;
    bottom->addStretch(1);
    auto* defaults = new QPushButton(tr("Restore Defaults"), content);
    defaults->setObjectName("WorldRestoreDefaults");
    const WorldSettings standard;
    defaults->setToolTip(tr("Earth gravity, %1 Hz, %2 substeps × %3 iterations, symplectic Euler, no damping, "
                            "geometric-mean friction, maximum restitution, every effect on Auto")
                             .arg(standard.fps)
                             .arg(standard.substeps)
                             .arg(standard.iterations));
    connect(defaults, &QPushButton::clicked, this,
            [this] { applySettings(WorldSettings{}, tr("Restore World Defaults")); });
    bottom->addWidget(defaults);
    sections->addLayout(bottom);
    sections->addStretch(1);
    // One label width for every group, so that the fields line up down the panel.
    int labelWidth = 0;
    const QList<QFormLayout*> forms = content->findChildren<QFormLayout*>();
    for (QFormLayout* form : forms)
        for (int row = 0; row < form->rowCount(); ++row)
            if (QLayoutItem* item = form->itemAt(row, QFormLayout::LabelRole); item && item->widget())
                labelWidth = std::max(labelWidth, item->widget()->sizeHint().width());
    for (QFormLayout* form : forms)
        for (int row = 0; row < form->rowCount(); ++row)
            if (QLayoutItem* item = form->itemAt(row, QFormLayout::LabelRole); item && item->widget())
                item->widget()->setMinimumWidth(labelWidth);

    // The decision needs a World built from the scene, so it waits until edits pause.
    m_decisionTimer->setSingleShot(true);
    m_decisionTimer->setInterval(150);
    connect(m_decisionTimer, &QTimer::timeout, this, &WorldSettingsWidget::decideNow);
    connect(document, &SceneDocument::sceneReset, this, [this] {
        m_message->clearMessage();
        refresh();
        scheduleDecision();
    });
    connect(document, &SceneDocument::worldSettingsChanged, this, [this] {
        refresh();
        scheduleDecision();
    });
    for (auto signal : {&SceneDocument::materialsChanged})
        connect(document, signal, this, &WorldSettingsWidget::scheduleDecision);
    connect(document, &SceneDocument::bodyChanged, this, &WorldSettingsWidget::scheduleDecision);
    connect(document, &SceneDocument::bodyInserted, this, &WorldSettingsWidget::scheduleDecision);
    connect(document, &SceneDocument::bodyRemoved, this, &WorldSettingsWidget::scheduleDecision);
    m_document->endEditGestureOnFinish(this);
    refresh();
    scheduleDecision();
}

QString WorldSettingsWidget::problem(const WorldSettings& w) {
    if (!std::isfinite(w.fps) || !(w.fps > 0.0) || w.fps > kMaxFps)
        return tr("The frame rate must be above 0 and at most %L1 Hz (got %2 Hz).").arg(kMaxFps).arg(w.fps);
    if (w.substeps < 1 || w.substeps > kMaxSteps)
        return tr("Substeps must be between 1 and %1 per frame (got %2).").arg(kMaxSteps).arg(w.substeps);
    if (w.iterations < 1 || w.iterations > kMaxSteps)
        return tr("Iterations must be between 1 and %1 per substep (got %2).").arg(kMaxSteps).arg(w.iterations);
    for (int axis = 0; axis < 3; ++axis)
        if (!std::isfinite(w.gravity[axis]) || std::abs(w.gravity[axis]) > kMaxGravity)
            return tr("Each component of gravity must be a number between −%1 and %1 m/s².").arg(kMaxGravity);
    if (!std::isfinite(w.linearDamping) || w.linearDamping < 0.0 || w.linearDamping > kMaxDamping)
        return tr("Linear damping must be between 0 and %1 1/s (got %2).").arg(kMaxDamping).arg(w.linearDamping);
    if (!std::isfinite(w.angularDamping) || w.angularDamping < 0.0 || w.angularDamping > kMaxDamping)
        return tr("Angular damping must be between 0 and %1 1/s (got %2).").arg(kMaxDamping).arg(w.angularDamping);
    return {};
}

bool WorldSettingsWidget::applySettings(const WorldSettings& settings, const QString& text, int mergeId) {
    const QString why = problem(settings);
    if (!why.isEmpty()) {
        m_message->showMessage(why, MessageBar::Kind::Error);
        refresh(); // the fields show the settings the scene keeps
        return false;
    }
    m_message->clearMessage();
    if (settings == m_document->scene().world)
        return true;
    m_document->undoStack()->push(new SetWorldSettingsCommand(m_document, settings, text, mergeId));
    return true;
}

template <class T>
void WorldSettingsWidget::edit(T WorldSettings::*field, T value, const QString& text, int mergeId) {
    WorldSettings w = m_document->scene().world;
    w.*field = value;
    applySettings(w, text, mergeId);
}

QString WorldSettingsWidget::message() const {
    return m_message->text();
}

void WorldSettingsWidget::refresh() {
    const WorldSettings& w = m_document->scene().world;
    const QSignalBlocker b0(m_gravityPreset), b1(m_fps), b2(m_substeps), b3(m_iterations), b4(m_integrator),
        b5(m_linearDamping), b6(m_angularDamping), b7(m_frictionCombine), b8(m_restitutionCombine), b9(m_linearOnly);
    int preset = kGravityPresetCount; // Custom
    for (int i = 0; i < kGravityPresetCount; ++i)
        if (w.gravity == Vec3(0.0, -kGravityPresets[i].magnitude, 0.0) ||
            (kGravityPresets[i].magnitude == 0.0 && glm::length(w.gravity) == 0.0))
            preset = i;
    m_gravityPreset->setCurrentIndex(preset);
    for (int axis = 0; axis < 3; ++axis) {
        const QSignalBlocker blocker(m_gravity[static_cast<size_t>(axis)]);
        m_gravity[static_cast<size_t>(axis)]->setValue(w.gravity[axis]);
    }
    m_gravityMagnitude->setText(tr("%L1 m/s²").arg(glm::length(w.gravity), 0, 'g', 4));
    m_fps->setValue(w.fps);
    m_substeps->setValue(w.substeps);
    m_iterations->setValue(w.iterations);
    m_integrator->setCurrentIndex(static_cast<int>(w.integrator));
    const double stepMs = 1000.0 / w.fps;
    m_stepInfo->setText(tr("Step %L1 ms, substep %L2 ms; %3 solver passes per frame")
                            .arg(stepMs, 0, 'g', 3)
                            .arg(stepMs / w.substeps, 0, 'g', 3)
                            .arg(w.substeps * w.iterations));
    m_linearDamping->setValue(w.linearDamping);
    m_angularDamping->setValue(w.angularDamping);
    m_frictionCombine->setCurrentIndex(static_cast<int>(w.frictionCombine));
    m_restitutionCombine->setCurrentIndex(static_cast<int>(w.restitutionCombine));
    for (int i = 0; i < kEffectCount; ++i) {
        const QSignalBlocker blocker(m_effectModes[static_cast<size_t>(i)]);
        m_effectModes[static_cast<size_t>(i)]->setCurrentIndex(
            static_cast<int>(w.effects.modes[static_cast<size_t>(i)]));
    }
    m_linearOnly->setChecked(w.effects.mode(Effect::Rotation) == EffectMode::Off);
    refreshEffects();
}

void WorldSettingsWidget::scheduleDecision() {
    m_decisionStale = true;
    if (isVisible())
        m_decisionTimer->start();
}

void WorldSettingsWidget::showEvent(QShowEvent* event) {
    QWidget::showEvent(event);
    if (m_decisionStale)
        m_decisionTimer->start();
}

void WorldSettingsWidget::decideNow() {
    m_decisionTimer->stop();
    m_decisionStale = false;
    const Scene& scene = m_document->scene();
    m_decision.reset();
    m_autoDecision.reset();
    m_decisionError.clear();
    Result<World> world = World::create(scene);
    if (!world) {
        m_decisionError = QString::fromStdString(world.error().toString());
    } else {
        m_decision = world->effectsDecision();
        // For effects forced on or off, also show what Auto would pick.
        if (!(scene.world.effects == EffectsSetting{})) {
            WorldOptions options;
            options.effects = EffectsSetting{};
            if (Result<World> autoWorld = World::create(scene, options))
                m_autoDecision = autoWorld->effectsDecision();
        }
    }
    refreshEffects();
    emit decisionUpdated();
}

void WorldSettingsWidget::refreshEffects() {
    const WorldSettings& w = m_document->scene().world;
    m_effectsProblem->setVisible(!m_decisionError.isEmpty());
    if (!m_decisionError.isEmpty())
        m_effectsProblem->setText(tr("Auto cannot decide for this scene: %1").arg(m_decisionError));
    const QString onColor = QStringLiteral("#1e7b34"), offColor = QStringLiteral("#7a7a7a");
    auto state = [&](bool on) {
        return QStringLiteral("<b style=\"color:%1\">%2</b>").arg(on ? onColor : offColor, on ? tr("on") : tr("off"));
    };
    for (int i = 0; i < kEffectCount; ++i) {
        const size_t k = static_cast<size_t>(i);
        QLabel* status = m_effectStatus[k];
        if (!m_decision) {
            status->setText(m_decisionError.isEmpty() ? tr("deciding…") : QStringLiteral("—"));
            status->setToolTip(QString());
            continue;
        }
        const bool on = m_decision->effects.on[k];
        const EffectMode mode = w.effects.modes[k];
        QString text;
        QString toolTip = reasonText(m_decision->reasons[k]);
        if (mode == EffectMode::Auto) {
            text = QStringLiteral("%1 · %2").arg(state(on), reasonText(m_decision->reasons[k]).toHtmlEscaped());
        } else {
            // Short, so that the row stays one line; the tooltip says why Auto would differ.
            text = state(on) + QStringLiteral(" · ") + tr("forced");
            if (m_autoDecision) {
                const bool autoOn = m_autoDecision->effects.on[k];
                text += QStringLiteral(" <span style=\"color:%1\">(%2)</span>")
                            .arg(offColor, tr("Auto: %1").arg(autoOn ? tr("on") : tr("off")));
                toolTip = tr("Auto would turn it %1: %2")
                              .arg(autoOn ? tr("on") : tr("off"), reasonText(m_autoDecision->reasons[k]));
            }
        }
        status->setText(text);
        status->setToolTip(toolTip);
    }
}

} // namespace rl
