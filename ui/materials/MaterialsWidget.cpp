#include "materials/MaterialsWidget.h"

#include "document/SceneDocument.h"
#include "document/commands/SetBodiesCommand.h"
#include "document/commands/SetMaterialsCommand.h"
#include "materials/MaterialLibraryModel.h"
#include "materials/MaterialPairModel.h"
#include "settings/MessageBar.h"

#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QIcon>
#include <QItemSelectionModel>
#include <QLabel>
#include <QLineEdit>
#include <QSignalBlocker>
#include <QSlider>
#include <QTabWidget>
#include <QTableView>
#include <QToolButton>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>

namespace rl {

namespace {

// Slider positions per unit of friction or restitution: steps of 0.005.
constexpr int kSliderScale = 200;
// The friction slider covers the range of real material pairs; the spin box goes on to MaterialLibrary::kMaxFriction.
constexpr double kFrictionSliderMax = 2.0;

QToolButton* makeButton(QWidget* parent, const QString& objectName, const QString& icon, const QString& text,
                        const QString& toolTip) {
    auto* button = new QToolButton(parent);
    button->setObjectName(objectName);
    button->setText(text);
    button->setToolTip(toolTip);
    const QIcon themed = QIcon::fromTheme(icon);
    if (!themed.isNull()) {
        button->setIcon(themed);
        button->setToolButtonStyle(Qt::ToolButtonTextBesideIcon);
    }
    button->setAutoRaise(true);
    return button;
}

QDoubleSpinBox* makeSpin(QWidget* parent, const QString& objectName, double max, int decimals, double step,
                         const QString& suffix) {
    auto* box = new QDoubleSpinBox(parent);
    box->setObjectName(objectName);
    box->setRange(0.0, max);
    box->setDecimals(decimals);
    box->setSingleStep(step);
    box->setSuffix(suffix);
    box->setKeyboardTracking(false); // typing commits on Enter or focus out; arrows commit per step and merge
    box->setAccelerated(true);
    box->setAlignment(Qt::AlignRight);
    return box;
}

// "1 body", "3 bodies". (Plural forms by hand: the project has no English translation file that would supply
// them for tr("%n bodies", "", n).)
QString bodyCount(int n) {
    return n == 1 ? MaterialsWidget::tr("1 body") : MaterialsWidget::tr("%1 bodies").arg(n);
}

} // namespace

MaterialsWidget::MaterialsWidget(SceneDocument* document, QWidget* parent)
    : QWidget(parent), m_document(document), m_library(new MaterialLibraryModel(document, this)),
      m_pairs(new MaterialPairModel(document, this)) {
    setObjectName("MaterialsWidget");
    auto* outer = new QVBoxLayout(this);
    outer->setContentsMargins(4, 4, 4, 4);
    outer->setSpacing(4);

    // Library: tool buttons over the table.
    auto* buttons = new QHBoxLayout;
    buttons->setSpacing(2);
    m_addButton = makeButton(this, "MaterialAddButton", "list-add", tr("Add"), tr("Add a new material"));
    m_duplicateButton = makeButton(this, "MaterialDuplicateButton", "edit-copy", tr("Duplicate"),
                                   tr("Add a copy of the selected material"));
    m_deleteButton = makeButton(this, "MaterialDeleteButton", "edit-delete", tr("Delete"),
                                tr("Delete the selected material; bodies that use it move to Default"));
    m_resetButton = makeButton(this, "MaterialResetButton", "edit-undo", tr("Reset preset"),
                               tr("Give the selected preset its built-in values back"));
    for (QToolButton* b : {m_addButton, m_duplicateButton, m_deleteButton, m_resetButton})
        buttons->addWidget(b);
    buttons->addStretch(1);
    connect(m_addButton, &QToolButton::clicked, this, &MaterialsWidget::addMaterial);
    connect(m_duplicateButton, &QToolButton::clicked, this, &MaterialsWidget::duplicateMaterial);
    connect(m_deleteButton, &QToolButton::clicked, this, &MaterialsWidget::deleteMaterial);
    connect(m_resetButton, &QToolButton::clicked, this, &MaterialsWidget::resetPreset);

    // Two pages: the library with its editor, and the pairs in use. Both follow every edit as it happens.
    auto* tabs = new QTabWidget(this);
    tabs->setObjectName("MaterialsTabs");
    tabs->setDocumentMode(true);
    auto* top = new QWidget(tabs);
    auto* topLayout = new QVBoxLayout(top);
    topLayout->setContentsMargins(0, 4, 0, 0);
    topLayout->setSpacing(4);
    topLayout->addLayout(buttons);

    m_table = new QTableView(top);
    m_table->setObjectName("MaterialTable");
    m_table->setModel(m_library);
    m_table->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_table->setSelectionMode(QAbstractItemView::SingleSelection);
    m_table->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_table->setAlternatingRowColors(true);
    m_table->verticalHeader()->hide();
    m_table->verticalHeader()->setDefaultSectionSize(m_table->fontMetrics().height() + 6);
    m_table->horizontalHeader()->setSectionResizeMode(MaterialLibraryModel::NameColumn, QHeaderView::Stretch);
    for (int c = MaterialLibraryModel::DensityColumn; c < MaterialLibraryModel::ColumnCount; ++c)
        m_table->horizontalHeader()->setSectionResizeMode(c, QHeaderView::ResizeToContents);
    // Tall enough for every preset without scrolling; custom materials scroll.
    m_table->setMinimumHeight(m_table->horizontalHeader()->sizeHint().height() +
                              (static_cast<int>(materialPresets().size()) + 1) *
                                  m_table->verticalHeader()->defaultSectionSize() +
                              2 * m_table->frameWidth());
    topLayout->addWidget(m_table, 1);

    m_message = new MessageBar(top);
    m_message->setObjectName("MaterialMessage");
    topLayout->addWidget(m_message);

    // Editor of the selected material.
    m_editor = new QGroupBox(tr("Selected material"), top);
    m_editor->setObjectName("MaterialEditor");
    auto* form = new QFormLayout(m_editor);
    form->setLabelAlignment(Qt::AlignRight | Qt::AlignVCenter);
    form->setFieldGrowthPolicy(QFormLayout::AllNonFixedFieldsGrow);
    m_kindLabel = new QLabel(m_editor);
    m_kindLabel->setObjectName("MaterialKind");
    m_kindLabel->setWordWrap(true);
    m_kindLabel->setForegroundRole(QPalette::PlaceholderText);
    form->addRow(m_kindLabel);
    m_name = new QLineEdit(m_editor);
    m_name->setObjectName("MaterialName");
    connect(m_name, &QLineEdit::editingFinished, this, [this] {
        const int row = m_library->rowOf(m_current);
        if (row < 0 || m_name->text() == m_current)
            return;
        MaterialDef m = m_library->entries()[static_cast<size_t>(row)].material;
        m.name = m_name->text().toStdString();
        if (!applyMaterial(m_current, m, tr("Rename Material")))
            refreshEditor(); // show the name the material still has
    });
    form->addRow(tr("Name"), m_name);

    m_density = makeSpin(m_editor, "MaterialDensity", MaterialLibrary::kMaxDensity, 1, 10.0, tr(" kg/m³"));
    m_density->setToolTip(tr("Mass per volume; above 0, at most %1 kg/m³").arg(MaterialLibrary::kMaxDensity, 0, 'g'));
    connect(m_density, &QDoubleSpinBox::valueChanged, this, [this](double v) {
        editField(v, &MaterialDef::density, tr("Set Material Density"), SetMaterialDensityId);
    });
    form->addRow(tr("Density"), m_density);

    auto sliderRow = [&](QDoubleSpinBox* spin, QSlider*& slider, const QString& objectName, double sliderMax) {
        slider = new QSlider(Qt::Horizontal, m_editor);
        slider->setObjectName(objectName);
        slider->setRange(0, static_cast<int>(std::lround(sliderMax * kSliderScale)));
        slider->setPageStep(kSliderScale / 10);
        // The slider moves the spin box, which makes the edit: one path, and a drag merges into one undo step.
        connect(slider, &QSlider::valueChanged, spin,
                [spin](int position) { spin->setValue(static_cast<double>(position) / kSliderScale); });
        connect(spin, &QDoubleSpinBox::valueChanged, slider, [slider](double v) {
            const QSignalBlocker blocker(slider);
            slider->setValue(static_cast<int>(std::lround(v * kSliderScale)));
        });
        auto* line = new QHBoxLayout;
        line->addWidget(slider, 1);
        spin->setMinimumWidth(spin->fontMetrics().horizontalAdvance(QStringLiteral("00.000")) + 30);
        line->addWidget(spin);
        return line;
    };
    m_friction = makeSpin(m_editor, "MaterialFriction", MaterialLibrary::kMaxFriction, 3, 0.05, QString());
    m_friction->setToolTip(tr("Coulomb friction coefficient μ, 0 to %1").arg(MaterialLibrary::kMaxFriction));
    connect(m_friction, &QDoubleSpinBox::valueChanged, this, [this](double v) {
        editField(v, &MaterialDef::friction, tr("Set Material Friction"), SetMaterialFrictionId);
    });
    form->addRow(tr("Friction μ"),
                 sliderRow(m_friction, m_frictionSlider, "MaterialFrictionSlider", kFrictionSliderMax));
    m_restitution = makeSpin(m_editor, "MaterialRestitution", 1.0, 3, 0.05, QString());
    m_restitution->setToolTip(tr("Restitution e: 0 = no bounce, 1 = elastic"));
    connect(m_restitution, &QDoubleSpinBox::valueChanged, this, [this](double v) {
        editField(v, &MaterialDef::restitution, tr("Set Material Restitution"), SetMaterialRestitutionId);
    });
    form->addRow(tr("Restitution e"), sliderRow(m_restitution, m_restitutionSlider, "MaterialRestitutionSlider", 1.0));
    topLayout->addWidget(m_editor);

    // Pairs in use.
    topLayout->addStretch(0);
    auto* pairsBox = new QWidget(tabs);
    pairsBox->setObjectName("MaterialPairsBox");
    auto* pairsLayout = new QVBoxLayout(pairsBox);
    pairsLayout->setContentsMargins(0, 4, 0, 0);
    m_pairRules = new QLabel(pairsBox);
    m_pairRules->setObjectName("MaterialPairRules");
    m_pairRules->setWordWrap(true);
    pairsLayout->addWidget(m_pairRules);
    m_pairTable = new QTableView(pairsBox);
    m_pairTable->setObjectName("MaterialPairTable");
    m_pairTable->setModel(m_pairs);
    m_pairTable->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_pairTable->setSelectionMode(QAbstractItemView::SingleSelection);
    m_pairTable->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    m_pairTable->verticalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    m_pairTable->setMinimumHeight(80);
    pairsLayout->addWidget(m_pairTable, 1);
    m_pairNote = new QLabel(pairsBox);
    m_pairNote->setObjectName("MaterialPairNote");
    m_pairNote->setWordWrap(true);
    m_pairNote->setForegroundRole(QPalette::PlaceholderText);
    pairsLayout->addWidget(m_pairNote);
    tabs->addTab(top, tr("Library"));
    tabs->addTab(pairsBox, tr("Contact pairs"));
    tabs->setTabToolTip(1, tr("Friction and restitution of every pair of materials the scene's bodies use"));
    outer->addWidget(tabs, 1);

    connect(
        m_table->selectionModel(), &QItemSelectionModel::currentRowChanged, this, [this](const QModelIndex& current) {
            if (!current.isValid())
                return;
            m_current = m_library->data(m_library->index(current.row(), MaterialLibraryModel::NameColumn)).toString();
            m_currentRow = current.row();
            refreshEditor();
        });
    // After every change of the library, select the material being edited again (the model resets).
    connect(m_library, &QAbstractItemModel::modelReset, this, [this] {
        // A material gone by name (an undone rename, a deletion) is followed by its place in the table.
        int row = m_library->rowOf(m_current);
        if (row < 0)
            row = std::min(m_currentRow, m_library->rowCount() - 1);
        selectRow(std::max(row, 0));
        refreshEditor();
    });
    connect(m_library, &QAbstractItemModel::dataChanged, this, [this] { refreshButtons(); });
    connect(m_pairs, &MaterialPairModel::updated, this, &MaterialsWidget::refreshPairs);
    connect(document, &SceneDocument::sceneReset, m_message, &MessageBar::clearMessage);

    m_document->endEditGestureOnFinish(this);
    selectRow(0);
    refreshEditor();
    refreshPairs();
}

QString MaterialsWidget::message() const {
    return m_message->text();
}

void MaterialsWidget::setCurrentMaterial(const QString& name) {
    const int row = m_library->rowOf(name);
    if (row >= 0)
        selectRow(row);
}

void MaterialsWidget::selectRow(int row) {
    if (row < 0 || row >= m_library->rowCount()) {
        m_current.clear();
        return;
    }
    m_current = m_library->data(m_library->index(row, MaterialLibraryModel::NameColumn)).toString();
    m_currentRow = row;
    m_table->selectionModel()->setCurrentIndex(m_library->index(row, 0),
                                               QItemSelectionModel::ClearAndSelect | QItemSelectionModel::Rows);
    refreshEditor();
}

void MaterialsWidget::refreshEditor() {
    const int row = m_library->rowOf(m_current);
    m_editor->setEnabled(row >= 0);
    refreshButtons();
    if (row < 0)
        return;
    const LibraryEntry& entry = m_library->entries()[static_cast<size_t>(row)];
    const MaterialDef& m = entry.material;
    const QSignalBlocker b1(m_name), b2(m_density), b3(m_friction), b4(m_restitution), b5(m_frictionSlider),
        b6(m_restitutionSlider);
    m_name->setText(QString::fromStdString(m.name));
    m_name->setReadOnly(entry.preset);
    m_name->setToolTip(entry.preset ? tr("Presets keep their names; duplicate one to make your own") : QString());
    m_density->setValue(m.density);
    m_friction->setValue(m.friction);
    m_frictionSlider->setValue(static_cast<int>(std::lround(m.friction * kSliderScale)));
    m_restitution->setValue(m.restitution);
    m_restitutionSlider->setValue(static_cast<int>(std::lround(m.restitution * kSliderScale)));
    const QString used = entry.users == 0 ? tr("No body uses it.") : tr("Used by %1.").arg(bodyCount(entry.users));
    if (entry.preset && entry.modified) {
        const MaterialDef preset = *findPreset(m.name);
        m_kindLabel->setText(tr("Built-in preset, changed for this scene (built-in: %1 kg/m³, μ %2, e %3). %4")
                                 .arg(preset.density)
                                 .arg(preset.friction)
                                 .arg(preset.restitution)
                                 .arg(used));
    } else if (entry.preset) {
        m_kindLabel->setText(tr("Built-in preset; changes apply to this scene only. %1").arg(used));
    } else {
        m_kindLabel->setText(tr("Material of this scene. %1").arg(used));
    }
}

void MaterialsWidget::refreshButtons() {
    const int row = m_library->rowOf(m_current);
    const bool valid = row >= 0;
    const LibraryEntry* entry = valid ? &m_library->entries()[static_cast<size_t>(row)] : nullptr;
    m_duplicateButton->setEnabled(valid);
    m_deleteButton->setEnabled(valid && !entry->preset);
    m_deleteButton->setToolTip(valid && entry->preset
                                   ? tr("Presets cannot be deleted; Reset preset gives back their built-in values")
                                   : tr("Delete the selected material; bodies that use it move to Default"));
    m_resetButton->setEnabled(valid && entry->preset && entry->modified);
}

void MaterialsWidget::refreshPairs() {
    const WorldSettings& world = m_document->scene().world;
    m_pairRules->setText(
        tr("Each cell: friction μ / restitution e. μ = %1 (%2), e = %3 (%4); World settings choose the rules.")
            .arg(MaterialLibrary::formula(world.frictionCombine, QStringLiteral("μa"), QStringLiteral("μb")),
                 MaterialLibrary::ruleLabel(world.frictionCombine),
                 MaterialLibrary::formula(world.restitutionCombine, QStringLiteral("ea"), QStringLiteral("eb")),
                 MaterialLibrary::ruleLabel(world.restitutionCombine)));
    QStringList notes;
    if (m_pairs->rowCount() == 0)
        notes.append(tr("No bodies in the scene."));
    if (m_pairs->overridingBodies() > 0)
        notes.append(tr("Not included: %1 with their own friction or restitution (set in the inspector).")
                         .arg(bodyCount(m_pairs->overridingBodies())));
    m_pairNote->setText(notes.join(QLatin1Char(' ')));
    m_pairNote->setVisible(!notes.isEmpty());
}

void MaterialsWidget::editField(double value, double MaterialDef::*field, const QString& text, int mergeId) {
    const int row = m_library->rowOf(m_current);
    if (row < 0)
        return;
    MaterialDef m = m_library->entries()[static_cast<size_t>(row)].material;
    m.*field = value;
    if (!applyMaterial(m_current, m, text, mergeId))
        refreshEditor();
}

bool MaterialsWidget::applyMaterial(const QString& oldName, const MaterialDef& material, const QString& text,
                                    int mergeId) {
    const Scene& scene = m_document->scene();
    const QString problem = MaterialLibrary::problem(scene, oldName, material);
    if (!problem.isEmpty()) {
        m_message->showMessage(problem, MessageBar::Kind::Error);
        return false;
    }
    const int row = m_library->rowOf(oldName);
    if (row >= 0 && m_library->entries()[static_cast<size_t>(row)].material == material)
        return true; // nothing changes
    if (m_message->kind() == MessageBar::Kind::Error)
        m_message->clearMessage(); // the refusal is out of date
    const QString newName = QString::fromStdString(material.name);
    const bool renamed = !oldName.isEmpty() && newName != oldName;
    const QList<int> users = renamed ? MaterialLibrary::users(scene, oldName) : QList<int>{};
    std::vector<MaterialDef> materials = MaterialLibrary::withMaterial(scene, oldName, material);
    // The model resets when the command runs; the editor keeps showing this material under its new name.
    m_current = newName;
    if (users.isEmpty()) {
        m_document->undoStack()->push(new SetMaterialsCommand(m_document, std::move(materials), text, mergeId,
                                                              newName.toLower() + QString::number(mergeId)));
        return true;
    }
    // A rename reaches the bodies that use the material in the same undo step.
    auto* command = new QUndoCommand(text);
    std::vector<BodyDef> bodies;
    for (int index : users) {
        BodyDef body = m_document->body(index);
        body.material = material.name;
        bodies.push_back(std::move(body));
    }
    new SetMaterialsCommand(m_document, std::move(materials), text, -1, {}, command);
    new SetBodiesCommand(m_document, users, std::move(bodies), text, -1, command);
    m_document->undoStack()->push(command);
    m_message->showMessage(
        tr("Renamed \"%1\" to \"%2\" on %3 too.").arg(oldName, newName, bodyCount(static_cast<int>(users.size()))),
        MessageBar::Kind::Info);
    return true;
}

void MaterialsWidget::addMaterial() {
    MaterialDef m = *findPreset("Default");
    m.name = MaterialLibrary::uniqueName(m_document->scene(), tr("Material")).toStdString();
    if (applyMaterial(QString(), m, tr("Add Material")))
        setCurrentMaterial(QString::fromStdString(m.name));
}

void MaterialsWidget::duplicateMaterial() {
    const int row = m_library->rowOf(m_current);
    if (row < 0)
        return;
    MaterialDef m = m_library->entries()[static_cast<size_t>(row)].material;
    m.name = MaterialLibrary::uniqueName(m_document->scene(), tr("%1 copy").arg(m_current)).toStdString();
    if (applyMaterial(QString(), m, tr("Duplicate Material")))
        setCurrentMaterial(QString::fromStdString(m.name));
}

void MaterialsWidget::deleteMaterial() {
    const int row = m_library->rowOf(m_current);
    if (row < 0)
        return;
    const LibraryEntry& entry = m_library->entries()[static_cast<size_t>(row)];
    if (entry.preset) {
        m_message->showMessage(tr("\"%1\" is a built-in preset and cannot be deleted; Reset preset gives back its "
                                  "built-in values.")
                                   .arg(m_current),
                               MessageBar::Kind::Error);
        return;
    }
    const Scene& scene = m_document->scene();
    const QString name = m_current;
    const QList<int> users = MaterialLibrary::users(scene, name);
    const QString text = tr("Delete Material %1").arg(name);
    auto* command = new QUndoCommand(text);
    new SetMaterialsCommand(m_document, MaterialLibrary::without(scene, name), text, -1, {}, command);
    if (!users.isEmpty()) {
        std::vector<BodyDef> bodies;
        for (int index : users) {
            BodyDef body = m_document->body(index);
            body.material = "Default";
            bodies.push_back(std::move(body));
        }
        new SetBodiesCommand(m_document, users, std::move(bodies), text, -1, command);
    }
    // Select the row above the deleted one when the model resets.
    m_current = m_library->data(m_library->index(std::max(0, row - 1), MaterialLibraryModel::NameColumn)).toString();
    m_document->undoStack()->push(command);
    if (users.isEmpty())
        m_message->showMessage(tr("Deleted \"%1\"; no body used it.").arg(name), MessageBar::Kind::Info);
    else
        m_message->showMessage(tr("Deleted \"%1\" and moved the %2 that used it to Default (Undo brings it back).")
                                   .arg(name, bodyCount(static_cast<int>(users.size()))),
                               MessageBar::Kind::Info);
}

void MaterialsWidget::resetPreset() {
    const int row = m_library->rowOf(m_current);
    if (row < 0)
        return;
    const LibraryEntry& entry = m_library->entries()[static_cast<size_t>(row)];
    if (!entry.preset || !entry.modified)
        return;
    const QString name = m_current;
    m_document->undoStack()->push(new SetMaterialsCommand(
        m_document, MaterialLibrary::without(m_document->scene(), name), tr("Reset Preset %1").arg(name)));
    m_message->clearMessage();
}

} // namespace rl
