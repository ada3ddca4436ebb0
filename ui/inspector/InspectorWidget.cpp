#include "inspector/InspectorWidget.h"

#include "document/CoreText.h"
#include "document/SceneDocument.h"
#include "document/UndoIds.h"
#include "document/commands/SetBodiesCommand.h"
#include "document/commands/SetBodyCommand.h"
#include "materials/MaterialLibrary.h"
#include "scene/BodyProperties.h"
#include "settings/MessageBar.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QScrollArea>
#include <QSignalBlocker>
#include <QVBoxLayout>

#include <algorithm>
#include <set>

namespace rl {

namespace {

// Euler angles in degrees, XYZ: the body is turned about world X, then world Y, then world Z (q = qz * qy * qx),
// which is glm's convention for quat(vec3) and eulerAngles().
Vec3 eulerDegrees(const Quat& q) {
    return glm::degrees(glm::eulerAngles(q));
}
Quat fromEulerDegrees(const Vec3& degrees) {
    return glm::normalize(Quat(glm::radians(degrees)));
}

// The common value of a field over the selected bodies, or nullopt when they differ.
template <class T, class Get>
std::optional<T> common(const std::vector<const BodyDef*>& bodies, Get get) {
    if (bodies.empty())
        return std::nullopt;
    const T first = get(*bodies.front());
    for (const BodyDef* body : bodies)
        if (!(get(*body) == first))
            return std::nullopt;
    return first;
}

QString formatVec(const Vec3& v, int decimals) {
    return QStringLiteral("%1, %2, %3")
        .arg(v.x, 0, 'g', decimals)
        .arg(v.y, 0, 'g', decimals)
        .arg(v.z, 0, 'g', decimals);
}

constexpr double kVecRange = 1e6; // metres and m/s: far beyond any scene the editor is meant for

} // namespace

QString InspectorWidget::mixedText() {
    return QStringLiteral("\u2014");
}

QString InspectorWidget::message() const {
    return m_message->text();
}

InspectorWidget::InspectorWidget(SceneDocument* document, QWidget* parent) : QWidget(parent), m_document(document) {
    setObjectName("Inspector");
    auto* outer = new QVBoxLayout(this);
    outer->setContentsMargins(0, 0, 0, 0);
    m_emptyLabel = new QLabel(tr("Select a body to inspect it."), this);
    m_emptyLabel->setAlignment(Qt::AlignCenter);
    m_emptyLabel->setWordWrap(true);
    outer->addWidget(m_emptyLabel);
    m_message = new MessageBar(this);
    m_message->setObjectName("InspectorMessage");
    outer->addWidget(m_message);

    auto* scroll = new QScrollArea(this);
    m_scroll = scroll;
    scroll->setWidgetResizable(true);
    scroll->setFrameShape(QFrame::NoFrame);
    m_content = new QWidget(scroll);
    auto* sections = new QVBoxLayout(m_content);
    sections->setContentsMargins(4, 4, 4, 4);
    scroll->setWidget(m_content);
    outer->addWidget(scroll);
    scroll->setObjectName("InspectorScroll");

    auto makeSection = [&](const QString& title) {
        auto* box = new QGroupBox(title, m_content);
        auto* form = new QFormLayout(box);
        form->setFieldGrowthPolicy(QFormLayout::AllNonFixedFieldsGrow);
        form->setLabelAlignment(Qt::AlignRight | Qt::AlignVCenter);
        sections->addWidget(box);
        return form;
    };

    // Body
    QFormLayout* body = makeSection(tr("Body"));
    m_name = new QLineEdit(m_content);
    m_name->setObjectName("InspectorName");
    connect(m_name, &QLineEdit::editingFinished, this, [this] {
        const QString text = m_name->text().trimmed();
        if (text.isEmpty())
            return; // an empty field means "mixed" (or a cleared name, which a body may not have)
        applyEdit(tr("Rename"), SetBodyNameId, [&](BodyDef& b) { b.name = text.toStdString(); });
    });
    body->addRow(tr("Name"), m_name);
    m_anchor = new QCheckBox(tr("Static (does not move)"), m_content);
    m_anchor->setObjectName("InspectorAnchor");
    connect(m_anchor, &QCheckBox::clicked, this, [this](bool checked) {
        m_anchor->setTristate(false); // once clicked, the mixed state is gone
        applyEdit(checked ? tr("Anchor") : tr("Unanchor"), NoMergeId, [&](BodyDef& b) { b.anchor = checked; });
    });
    body->addRow(tr("Anchor"), m_anchor);
    m_material = new QComboBox(m_content);
    m_material->setObjectName("InspectorMaterial");
    m_material->setPlaceholderText(mixedText());
    connect(m_material, &QComboBox::activated, this, [this](int index) {
        const std::string name = m_material->itemText(index).toStdString();
        applyEdit(tr("Set Material"), NoMergeId, [&](BodyDef& b) { b.material = name; });
    });
    body->addRow(tr("Material"), m_material);

    // Material overrides
    QFormLayout* overrides = makeSection(tr("Overrides"));
    overrides->setLabelAlignment(Qt::AlignLeft | Qt::AlignVCenter); // the check boxes in one column
    m_density = makeOverride("InspectorDensity", MaterialLibrary::kMaxDensity, 1, 10.0, tr(" kg/m³"), tr("Set Density"),
                             SetBodyDensityId, &BodyDef::density, tr("Density must be above 0 kg/m³."), false);
    overrides->addRow(m_density.enabled, m_density.value);
    m_mass = makeOverride("InspectorMass", 1e9, 3, 0.1, tr(" kg"), tr("Set Mass"), SetBodyMassId, &BodyDef::mass,
                          tr("Mass must be above 0 kg."), false);
    overrides->addRow(m_mass.enabled, m_mass.value);
    m_friction =
        makeOverride("InspectorFriction", MaterialLibrary::kMaxFriction, 3, 0.05, QString(), tr("Set Friction"),
                     SetBodyFrictionId, &BodyDef::friction, tr("Friction must be 0 or more."), true);
    overrides->addRow(m_friction.enabled, m_friction.value);
    m_restitution =
        makeOverride("InspectorRestitution", 1.0, 3, 0.05, QString(), tr("Set Restitution"), SetBodyRestitutionId,
                     &BodyDef::restitution, tr("Restitution must be between 0 (no bounce) and 1 (elastic)."), true);
    overrides->addRow(m_restitution.enabled, m_restitution.value);
    m_density.enabled->setText(tr("Density"));
    m_mass.enabled->setText(tr("Mass"));
    m_friction.enabled->setText(tr("Friction"));
    m_restitution.enabled->setText(tr("Restitution"));

    // Placement
    QFormLayout* placement = makeSection(tr("Placement"));
    m_position = makeVec3("InspectorPosition", kVecRange, 4, 0.1, QString(), tr("Move"), SetBodyPositionId,
                          [](BodyDef& b, int axis, double v) { b.position[axis] = v; });
    m_rotation = makeVec3("InspectorRotation", 360.0, 2, 5.0, QString(), tr("Rotate"), SetBodyRotationId,
                          [](BodyDef& b, int axis, double v) {
                              Vec3 euler = eulerDegrees(b.orientation);
                              euler[axis] = v;
                              b.orientation = fromEulerDegrees(euler);
                          });
    auto addVecRow = [](QFormLayout* form, const QString& label, const Vec3Row& row) {
        auto* line = new QHBoxLayout;
        line->setSpacing(2);
        for (QDoubleSpinBox* box : row)
            line->addWidget(box, 1);
        form->addRow(label, line);
    };
    addVecRow(placement, tr("Position (m)"), m_position);
    addVecRow(placement, tr("Rotation XYZ (°)"), m_rotation);

    // Initial motion
    QFormLayout* motion = makeSection(tr("Initial motion"));
    m_velocity = makeVec3("InspectorVelocity", kVecRange, 3, 0.1, QString(), tr("Set Velocity"), SetBodyVelocityId,
                          [](BodyDef& b, int axis, double v) { b.velocity[axis] = v; });
    m_angularVelocity =
        makeVec3("InspectorAngularVelocity", kVecRange, 3, 0.1, QString(), tr("Set Angular Velocity"),
                 SetBodyAngularVelocityId, [](BodyDef& b, int axis, double v) { b.angularVelocity[axis] = v; });
    addVecRow(motion, tr("Velocity (m/s)"), m_velocity);
    addVecRow(motion, tr("Angular velocity (rad/s)"), m_angularVelocity);

    // Computed (read-only)
    QFormLayout* computed = makeSection(tr("Computed"));
    auto makeLabel = [&](const QString& objectName) {
        auto* label = new QLabel(m_content);
        label->setObjectName(objectName);
        label->setTextInteractionFlags(Qt::TextSelectableByMouse);
        label->setWordWrap(true);
        return label;
    };
    m_volumeLabel = makeLabel("InspectorVolume");
    m_massLabel = makeLabel("InspectorComputedMass");
    m_comLabel = makeLabel("InspectorCom");
    m_inertiaLabel = makeLabel("InspectorInertia");
    m_hullLabel = makeLabel("InspectorHull");
    m_warningsLabel = makeLabel("InspectorWarnings");
    computed->addRow(tr("Volume"), m_volumeLabel);
    computed->addRow(tr("Mass"), m_massLabel);
    computed->addRow(tr("Centre of mass"), m_comLabel);
    computed->addRow(tr("Principal inertia"), m_inertiaLabel);
    computed->addRow(tr("Hull vertices"), m_hullLabel);
    computed->addRow(tr("Warnings"), m_warningsLabel);
    sections->addStretch(1);

    connect(m_document, &SceneDocument::sceneReset, this, [this] { setSelection({}); });
    connect(m_document, &SceneDocument::bodyChanged, this, &InspectorWidget::refresh);
    connect(m_document, &SceneDocument::materialsChanged, this, &InspectorWidget::refresh);
    connect(m_document, &SceneDocument::bodyInserted, this, &InspectorWidget::refresh);
    connect(m_document, &SceneDocument::bodyRemoved, this, &InspectorWidget::refresh);
    m_document->endEditGestureOnFinish(this);
    refresh();
}

QDoubleSpinBox* InspectorWidget::makeSpinBox(const QString& objectName, double min, double max, int decimals,
                                             double step, const QString& suffix) {
    auto* box = new QDoubleSpinBox(m_content);
    box->setObjectName(objectName);
    // The minimum is a sentinel shown as "—" for values that differ between the selected bodies.
    box->setRange(min, max);
    box->setSpecialValueText(mixedText());
    box->setDecimals(decimals);
    box->setSingleStep(step);
    box->setSuffix(suffix);
    box->setKeyboardTracking(false); // typing commits on Enter or focus out; arrows commit per step and merge
    box->setAccelerated(true);
    box->setMinimumWidth(40);
    return box;
}

InspectorWidget::OverrideRow InspectorWidget::makeOverride(const QString& objectName, double max, int decimals,
                                                           double step, const QString& suffix, const QString& text,
                                                           int mergeId, std::optional<Real> BodyDef::*field,
                                                           const QString& rangeMessage, bool zeroAllowed) {
    OverrideRow row;
    row.enabled = new QCheckBox(m_content);
    row.enabled->setObjectName(objectName + "Enabled");
    row.value = makeSpinBox(objectName, -1.0, max, decimals, step, suffix);
    const QString toggleText = text;
    connect(row.enabled, &QCheckBox::clicked, this, [this, row, field, toggleText](bool checked) {
        row.enabled->setTristate(false);
        const Real shown = row.value->value() > row.value->minimum() ? row.value->value() : 0.0;
        applyEdit(toggleText, NoMergeId, [&](BodyDef& b) {
            if (!checked)
                b.*field = std::nullopt;
            else if (!(b.*field))
                b.*field = shown; // start from the effective material value the box shows
        });
    });
    connect(row.value, &QDoubleSpinBox::valueChanged, this,
            [this, row, field, text, mergeId, rangeMessage, zeroAllowed](double value) {
                if (value <= row.value->minimum())
                    return; // the "mixed" sentinel is not a value
                if (value < 0.0 || (value == 0.0 && !zeroAllowed)) {
                    m_message->showMessage(rangeMessage, MessageBar::Kind::Error);
                    refresh(); // the box shows the value the bodies keep
                    return;
                }
                m_message->clearMessage();
                applyEdit(text, mergeId, [&](BodyDef& b) { b.*field = value; });
            });
    return row;
}

InspectorWidget::Vec3Row InspectorWidget::makeVec3(const QString& objectName, double range, int decimals, double step,
                                                   const QString& suffix, const QString& text, int mergeId,
                                                   const std::function<void(BodyDef&, int, double)>& set) {
    Vec3Row row{};
    const char* axes[] = {"X", "Y", "Z"};
    for (int axis = 0; axis < 3; ++axis) {
        // One step below the range is the "mixed" sentinel.
        QDoubleSpinBox* box = makeSpinBox(objectName + axes[axis], -range - step, range, decimals, step, suffix);
        box->setToolTip(QString::fromLatin1(axes[axis]));
        connect(box, &QDoubleSpinBox::valueChanged, this, [this, box, axis, set, text, mergeId](double value) {
            if (value <= box->minimum())
                return;
            applyEdit(text, mergeId + axis, [&](BodyDef& b) { set(b, axis, value); });
        });
        row[static_cast<size_t>(axis)] = box;
    }
    return row;
}

void InspectorWidget::setSelection(const QList<int>& bodies) {
    if (bodies != m_selection)
        m_message->clearMessage(); // a refusal is about the bodies it was shown for
    m_selection = bodies;
    refresh();
}

void InspectorWidget::applyEdit(const QString& text, int mergeId, const std::function<void(BodyDef&)>& edit) {
    if (m_selection.isEmpty())
        return;
    std::vector<BodyDef> after;
    bool changed = false;
    for (int index : m_selection) {
        BodyDef body = m_document->body(index);
        edit(body);
        changed = changed || !(body == m_document->body(index));
        after.push_back(std::move(body));
    }
    if (!changed)
        return;
    if (m_selection.size() == 1)
        m_document->undoStack()->push(
            new SetBodyCommand(m_document, m_selection.first(), std::move(after.front()), text, mergeId));
    else
        m_document->undoStack()->push(new SetBodiesCommand(m_document, m_selection, std::move(after), text, mergeId));
}

void InspectorWidget::showValue(QDoubleSpinBox* box, std::optional<double> value) {
    const QSignalBlocker blocker(box);
    box->setValue(value ? *value : box->minimum());
}

void InspectorWidget::showOverride(OverrideRow row, const std::vector<std::optional<Real>>& values,
                                   std::optional<double> fallback) {
    const QSignalBlocker blockBox(row.enabled);
    const QSignalBlocker blockValue(row.value);
    std::set<bool> set;
    for (const auto& v : values)
        set.insert(v.has_value());
    if (set.size() > 1) {
        row.enabled->setTristate(true);
        row.enabled->setCheckState(Qt::PartiallyChecked);
    } else {
        row.enabled->setTristate(false);
        row.enabled->setChecked(!set.empty() && *set.begin());
    }
    const bool allSet = set.size() == 1 && *set.begin();
    const bool noneSet = set.size() == 1 && !*set.begin();
    // One value shows where every body has the same; unset overrides show the material's value, greyed out, so the
    // user sees what the body uses.
    double shown = row.value->minimum();
    if (allSet && std::all_of(values.begin(), values.end(), [&](const auto& v) { return *v == *values.front(); }))
        shown = *values.front();
    else if (noneSet && fallback)
        shown = *fallback;
    row.value->setValue(shown);
    row.value->setEnabled(allSet);
}

void InspectorWidget::refresh() {
    QList<int> valid;
    for (int index : m_selection)
        if (index >= 0 && index < m_document->bodyCount())
            valid.append(index);
    m_selection = valid;
    std::vector<const BodyDef*> bodies;
    for (int index : m_selection)
        bodies.push_back(&m_document->body(index));
    m_emptyLabel->setVisible(bodies.empty());
    m_scroll->setVisible(!bodies.empty());
    if (bodies.empty())
        return;

    {
        const QSignalBlocker blocker(m_name);
        const auto name = common<std::string>(bodies, [](const BodyDef& b) { return b.name; });
        m_name->setText(name ? QString::fromStdString(*name) : QString());
        m_name->setPlaceholderText(name ? QString() : mixedText());
    }
    {
        const QSignalBlocker blocker(m_anchor);
        const auto anchor = common<bool>(bodies, [](const BodyDef& b) { return b.anchor; });
        m_anchor->setTristate(!anchor);
        m_anchor->setCheckState(!anchor ? Qt::PartiallyChecked : (*anchor ? Qt::Checked : Qt::Unchecked));
    }
    {
        const QSignalBlocker blocker(m_material);
        m_material->clear();
        QStringList names; // the library's order: presets, then the scene's own materials
        for (const LibraryEntry& entry : MaterialLibrary::entries(m_document->scene()))
            names.append(QString::fromStdString(entry.material.name));
        for (const BodyDef* b : bodies) // a name the scene does not define still shows (it falls back to Default)
            if (!names.contains(QString::fromStdString(b->material), Qt::CaseInsensitive))
                names.append(QString::fromStdString(b->material));
        m_material->addItems(names);
        // Material names compare ignoring case, as the core looks them up ("wood" in a file is Wood).
        const auto material =
            common<QString>(bodies, [](const BodyDef& b) { return QString::fromStdString(b.material).toCaseFolded(); });
        int current = -1;
        for (qsizetype i = 0; material && i < names.size(); ++i)
            if (names[i].toCaseFolded() == *material)
                current = static_cast<int>(i);
        m_material->setCurrentIndex(current);
    }
    auto values = [&](std::optional<Real> BodyDef::*field) {
        std::vector<std::optional<Real>> out;
        for (const BodyDef* b : bodies)
            out.push_back(b->*field);
        return out;
    };
    // Unset overrides show the value the material gives, when the selected bodies agree on it.
    const Scene& scene = m_document->scene();
    auto material = [&](Real MaterialDef::*field) {
        return common<double>(
            bodies, [&](const BodyDef& b) { return scene.findMaterial(b.material).value_or(MaterialDef{}).*field; });
    };
    std::optional<double> computedMass;
    if (bodies.size() == 1)
        if (const Result<BodyProperties> props = computeBodyProperties(scene, *bodies.front()))
            computedMass = props->mass;
    showOverride(m_density, values(&BodyDef::density), material(&MaterialDef::density));
    showOverride(m_mass, values(&BodyDef::mass), computedMass);
    showOverride(m_friction, values(&BodyDef::friction), material(&MaterialDef::friction));
    showOverride(m_restitution, values(&BodyDef::restitution), material(&MaterialDef::restitution));

    for (int axis = 0; axis < 3; ++axis) {
        const size_t a = static_cast<size_t>(axis);
        showValue(m_position[a], common<double>(bodies, [&](const BodyDef& b) { return b.position[axis]; }));
        showValue(m_rotation[a],
                  common<double>(bodies, [&](const BodyDef& b) { return eulerDegrees(b.orientation)[axis]; }));
        showValue(m_velocity[a], common<double>(bodies, [&](const BodyDef& b) { return b.velocity[axis]; }));
        showValue(m_angularVelocity[a],
                  common<double>(bodies, [&](const BodyDef& b) { return b.angularVelocity[axis]; }));
    }
    refreshComputed();
}

void InspectorWidget::refreshComputed() {
    const Scene& scene = m_document->scene();
    if (m_selection.size() != 1) {
        // Several bodies: totals where they make sense.
        Real volume = 0.0, mass = 0.0;
        Vec3 weighted{0.0};
        int failures = 0;
        for (int index : m_selection) {
            const Result<BodyProperties> props = computeBodyProperties(scene, m_document->body(index));
            if (!props) {
                ++failures;
                continue;
            }
            volume += props->volume;
            mass += props->mass;
            weighted += props->mass * props->com;
        }
        m_volumeLabel->setText(tr("%1 m³ (total)").arg(volume, 0, 'g', 5));
        m_massLabel->setText(tr("%1 kg (total)").arg(mass, 0, 'g', 5));
        m_comLabel->setText(mass > 0.0 ? formatVec(weighted / mass, 4) : mixedText());
        m_inertiaLabel->setText(mixedText());
        m_hullLabel->setText(mixedText());
        m_warningsLabel->setText(failures ? tr("%n bodies cannot be simulated", "", failures) : tr("none"));
        return;
    }
    const Result<BodyProperties> props = computeBodyProperties(scene, m_document->body(m_selection.first()));
    if (!props) {
        for (QLabel* label : {m_volumeLabel, m_massLabel, m_comLabel, m_inertiaLabel, m_hullLabel})
            label->setText(mixedText());
        m_warningsLabel->setText(QString::fromStdString(props.error().toString()));
        return;
    }
    m_volumeLabel->setText(tr("%1 m³").arg(props->volume, 0, 'g', 5));
    m_massLabel->setText(tr("%1 kg").arg(props->mass, 0, 'g', 5));
    m_comLabel->setText(formatVec(props->com, 4));
    m_inertiaLabel->setText(tr("%1 kg m²").arg(formatVec(props->principalMoments, 4)));
    m_hullLabel->setText(props->hullVertexCount > 0 ? QString::number(props->hullVertexCount) : tr("none (sphere)"));
    QStringList warnings;
    for (const std::string& warning : props->warnings)
        warnings.append(coreText(warning));
    m_warningsLabel->setText(warnings.isEmpty() ? tr("none") : warnings.join('\n'));
}

} // namespace rl
