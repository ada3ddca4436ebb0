// The Materials dock: the library table and editor (add, edit, rename, duplicate, delete, reset preset, each one undo
// step), refusals of invalid input, the inspector following library changes, and the pair matrix against the core's
// combine rules.
#include "MainWindow.h"
#include "document/SceneDocument.h"
#include "document/commands/SetWorldSettingsCommand.h"
#include "inspector/InspectorWidget.h"
#include "materials/MaterialLibrary.h"
#include "materials/MaterialLibraryModel.h"
#include "materials/MaterialPairModel.h"
#include "materials/MaterialsWidget.h"
#include "settings/SettingsController.h"
#include "ui/GuiTestSetup.h"
#include "ui/Screenshot.h"

#include <QComboBox>
#include <QDir>
#include <QDockWidget>
#include <QDoubleSpinBox>
#include <QLabel>
#include <QLineEdit>
#include <QMenu>
#include <QSlider>
#include <QTabWidget>
#include <QTableView>
#include <QTest>
#include <QToolButton>

using namespace rl;

class TestMaterials : public QObject {
    Q_OBJECT
public:
    static void initMain() { rl::test::prepareGuiTest(); }

private:
    template <class T>
    static T* child(QWidget* parent, const char* name) {
        T* widget = parent->findChild<T*>(QString::fromLatin1(name));
        if (!widget)
            qFatal("no child %s", name);
        return widget;
    }

    // Opens a sample scene and brings the Materials dock to the front.
    static bool open(MainWindow& window, const char* scene = "stack.obj") {
        window.show();
        if (!QTest::qWaitForWindowExposed(&window))
            return false;
        if (!window.openFile(QStringLiteral(RL_SOURCE_DIR "/resources/scenes/") + QLatin1String(scene)))
            return false;
        window.settings()->materialsDock()->show();
        window.settings()->materialsDock()->raise();
        return true;
    }

    static const MaterialDef& entry(MainWindow& window, const QString& name) {
        const MaterialLibraryModel* model = window.settings()->materials()->libraryModel();
        const int row = model->rowOf(name);
        if (row < 0)
            qFatal("no material %s", qPrintable(name));
        return model->entries()[static_cast<size_t>(row)].material;
    }

private slots:
    void dockAndWindowMenu() {
        MainWindow window;
        QVERIFY(open(window));
        auto* action = window.findChild<QAction*>("MaterialsDockAction");
        QVERIFY(action);
        QVERIFY(window.menu(MainWindow::Menu::Window)->actions().contains(action));
        QVERIFY(window.settings()->materialsDock()->isVisible());
        action->trigger();
        QVERIFY(!window.settings()->materialsDock()->isVisible());
        action->trigger();
        QVERIFY(window.settings()->materialsDock()->isVisible());
    }

    void libraryListsPresetsWithUsers() {
        MainWindow window;
        QVERIFY(open(window));
        const MaterialLibraryModel* model = window.settings()->materials()->libraryModel();
        QCOMPARE(model->rowCount(), static_cast<int>(materialPresets().size()));
        for (size_t i = 0; i < materialPresets().size(); ++i) {
            QCOMPARE(model->entries()[i].material, materialPresets()[i]);
            QVERIFY(model->entries()[i].preset);
            QVERIFY(!model->entries()[i].modified);
        }
        // stack.obj: one concrete anchor and ten wooden cubes.
        auto users = [&](const char* name) {
            return model->data(model->index(model->rowOf(name), MaterialLibraryModel::UsersColumn)).toInt();
        };
        QCOMPARE(users("Concrete"), 1);
        QCOMPARE(users("Wood"), window.document()->bodyCount() - 1);
        QCOMPARE(users("Steel"), 0);
    }

    void editPresetThenReset_data() {
        QTest::addColumn<QString>("field");
        QTest::addColumn<double>("value");
        QTest::newRow("density") << "MaterialDensity" << 850.0;
        QTest::newRow("friction") << "MaterialFriction" << 0.8;
        QTest::newRow("restitution") << "MaterialRestitution" << 0.25;
    }
    void editPresetThenReset() {
        QFETCH(QString, field);
        QFETCH(double, value);
        MainWindow window;
        QVERIFY(open(window));
        SceneDocument* document = window.document();
        MaterialsWidget* materials = window.settings()->materials();
        materials->setCurrentMaterial("Wood");
        QCOMPARE(child<QLineEdit>(materials, "MaterialName")->text(), QStringLiteral("Wood"));
        auto* spin = materials->findChild<QDoubleSpinBox*>(field);
        QVERIFY(spin);
        spin->setValue(value);
        QCOMPARE(document->undoStack()->count(), 1);
        QCOMPARE(document->scene().materials.size(), size_t(1));
        const MaterialDef edited = document->scene().materials.front();
        QCOMPARE(edited.name, std::string("Wood"));
        const double stored = field == "MaterialDensity"    ? edited.density
                              : field == "MaterialFriction" ? edited.friction
                                                            : edited.restitution;
        QCOMPARE(stored, value);
        // Bodies get the edited values.
        QCOMPARE(document->scene().effectiveMaterial(document->body(1)), edited);
        const int row = materials->libraryModel()->rowOf("Wood");
        QVERIFY(materials->libraryModel()->entries()[static_cast<size_t>(row)].modified);
        auto* reset = child<QToolButton>(materials, "MaterialResetButton");
        QVERIFY(reset->isEnabled());
        reset->click();
        QCOMPARE(document->undoStack()->count(), 2);
        QVERIFY(document->scene().materials.empty());
        QCOMPARE(entry(window, "Wood"), *findPreset("Wood"));
        QVERIFY(!reset->isEnabled());
        QCOMPARE(spin->value(), field == "MaterialDensity" ? 700.0 : field == "MaterialFriction" ? 0.45 : 0.35);
        document->undoStack()->undo();
        QCOMPARE(document->scene().materials.front(), edited);
        document->undoStack()->undo();
        QVERIFY(document->scene().materials.empty());
        document->undoStack()->redo();
        QCOMPARE(document->scene().materials.front(), edited);
        QCOMPARE(spin->value(), value);
    }

    void addRenameDuplicateDelete() {
        MainWindow window;
        QVERIFY(open(window));
        SceneDocument* document = window.document();
        MaterialsWidget* materials = window.settings()->materials();
        child<QToolButton>(materials, "MaterialAddButton")->click();
        QCOMPARE(materials->currentMaterial(), QStringLiteral("Material"));
        QCOMPARE(document->scene().materials.size(), size_t(1));
        QCOMPARE(document->scene().materials.front().density, findPreset("Default")->density);

        // Rename through the editor.
        auto* name = child<QLineEdit>(materials, "MaterialName");
        name->setText("Foam");
        emit name->editingFinished();
        QCOMPARE(document->scene().materials.front().name, std::string("Foam"));
        QCOMPARE(materials->currentMaterial(), QStringLiteral("Foam"));
        child<QDoubleSpinBox>(materials, "MaterialDensity")->setValue(30.0);

        // The inspector's material list follows the library, and a body can use the new material.
        window.setSelectedBodies({2});
        auto* combo = window.inspector()->findChild<QComboBox*>("InspectorMaterial");
        QVERIFY(combo);
        const int foam = combo->findText("Foam");
        QVERIFY(foam >= 0);
        combo->setCurrentIndex(foam);
        emit combo->activated(foam);
        QCOMPARE(document->body(2).material, std::string("Foam"));
        QCOMPARE(document->scene().effectiveMaterial(document->body(2)).density, 30.0);

        // A rename reaches the body in the same undo step.
        const int before = document->undoStack()->count();
        name->setText("Soft foam");
        emit name->editingFinished();
        QCOMPARE(document->undoStack()->count(), before + 1);
        QCOMPARE(document->body(2).material, std::string("Soft foam"));
        QVERIFY(combo->findText("Soft foam") >= 0);
        QCOMPARE(combo->findText("Foam"), -1);
        QCOMPARE(combo->currentText(), QStringLiteral("Soft foam"));
        document->undoStack()->undo();
        QCOMPARE(document->body(2).material, std::string("Foam"));
        QCOMPARE(document->scene().materials.front().name, std::string("Foam"));
        document->undoStack()->redo();

        // Duplicate copies values under a new name.
        child<QToolButton>(materials, "MaterialDuplicateButton")->click();
        QCOMPARE(materials->currentMaterial(), QStringLiteral("Soft foam copy"));
        MaterialDef copy = entry(window, "Soft foam copy");
        copy.name = "Soft foam";
        QCOMPARE(copy, entry(window, "Soft foam"));

        // Delete a material in use: its body moves to Default in the same step, and the panel says so.
        materials->setCurrentMaterial("Soft foam");
        const int beforeDelete = document->undoStack()->count();
        auto* remove = child<QToolButton>(materials, "MaterialDeleteButton");
        QVERIFY(remove->isEnabled());
        remove->click();
        QCOMPARE(document->undoStack()->count(), beforeDelete + 1);
        QCOMPARE(materials->libraryModel()->rowOf("Soft foam"), -1);
        QCOMPARE(document->body(2).material, std::string("Default"));
        QVERIFY2(materials->message().contains("Default") && materials->message().contains("1 bod"),
                 qPrintable(materials->message()));
        QCOMPARE(combo->currentText(), QStringLiteral("Default"));
        document->undoStack()->undo();
        QCOMPARE(document->body(2).material, std::string("Soft foam"));
        QVERIFY(materials->libraryModel()->rowOf("Soft foam") >= 0);
        document->undoStack()->redo();
        QCOMPARE(document->body(2).material, std::string("Default"));
        // Everything undoes back to the opened scene.
        while (document->undoStack()->canUndo())
            document->undoStack()->undo();
        QVERIFY(document->scene().materials.empty());
        QCOMPARE(document->body(2).material, std::string("Wood"));
    }

    void presetsKeepNameAndStay() {
        MainWindow window;
        QVERIFY(open(window));
        MaterialsWidget* materials = window.settings()->materials();
        materials->setCurrentMaterial("Steel");
        QVERIFY(!child<QToolButton>(materials, "MaterialDeleteButton")->isEnabled());
        QVERIFY(child<QLineEdit>(materials, "MaterialName")->isReadOnly());
        materials->deleteMaterial();
        QVERIFY(materials->message().contains("preset"));
        MaterialDef renamed = *findPreset("Steel");
        renamed.name = "Iron";
        QVERIFY(!materials->applyMaterial("Steel", renamed, "Rename"));
        QVERIFY(materials->message().contains("keeps its name"));
        QCOMPARE(window.document()->undoStack()->count(), 0);
    }

    void invalidInputRefused_data() {
        QTest::addColumn<QString>("name");
        QTest::addColumn<double>("density");
        QTest::addColumn<double>("friction");
        QTest::addColumn<double>("restitution");
        QTest::addColumn<QString>("expected"); // a part of the message
        QTest::newRow("empty name") << "" << 1000.0 << 0.5 << 0.0 << "needs a name";
        QTest::newRow("blank name") << "  " << 1000.0 << 0.5 << 0.0 << "needs a name";
        QTest::newRow("preset name") << "wood" << 1000.0 << 0.5 << 0.0 << "built-in preset";
        QTest::newRow("taken name") << "Other" << 1000.0 << 0.5 << 0.0 << "already has";
        QTest::newRow("zero density") << "Mine" << 0.0 << 0.5 << 0.0 << "Density";
        QTest::newRow("negative density") << "Mine" << -5.0 << 0.5 << 0.0 << "Density";
        QTest::newRow("huge density") << "Mine" << 2e6 << 0.5 << 0.0 << "Density";
        QTest::newRow("nan density") << "Mine" << std::nan("") << 0.5 << 0.0 << "Density";
        QTest::newRow("negative friction") << "Mine" << 1000.0 << -0.1 << 0.0 << "Friction";
        QTest::newRow("huge friction") << "Mine" << 1000.0 << 11.0 << 0.0 << "Friction";
        QTest::newRow("restitution above 1") << "Mine" << 1000.0 << 0.5 << 1.5 << "Restitution";
        QTest::newRow("negative restitution") << "Mine" << 1000.0 << 0.5 << -0.5 << "Restitution";
    }
    void invalidInputRefused() {
        QFETCH(QString, name);
        QFETCH(double, density);
        QFETCH(double, friction);
        QFETCH(double, restitution);
        QFETCH(QString, expected);
        MainWindow window;
        QVERIFY(open(window));
        SceneDocument* document = window.document();
        MaterialsWidget* materials = window.settings()->materials();
        materials->addMaterial();
        materials->addMaterial();
        QVERIFY(materials->applyMaterial("Material", {"Mine", 1000.0, 0.5, 0.0}, "Rename"));
        QVERIFY(materials->applyMaterial("Material 2", {"Other", 1000.0, 0.5, 0.0}, "Rename"));
        const Scene before = document->scene();
        const int steps = document->undoStack()->count();
        const MaterialDef bad{name.toStdString(), density, friction, restitution};
        QVERIFY(!materials->applyMaterial("Mine", bad, "Edit"));
        QVERIFY2(materials->message().contains(expected), qPrintable(materials->message()));
        QVERIFY(document->scene() == before);
        QCOMPARE(document->undoStack()->count(), steps);
        // The same rule holds for a new material.
        if (name != "Mine") {
            QVERIFY(!MaterialLibrary::problem(document->scene(), QString(), bad).isEmpty());
        }
    }

    void typedInvalidValueShowsMessage() {
        MainWindow window;
        QVERIFY(open(window));
        MaterialsWidget* materials = window.settings()->materials();
        materials->setCurrentMaterial("Rubber");
        auto* density = child<QDoubleSpinBox>(materials, "MaterialDensity");
        density->setFocus();
        density->selectAll();
        QTest::keyClicks(density, "0");
        QTest::keyClick(density, Qt::Key_Return);
        QVERIFY2(materials->message().contains("Density"), qPrintable(materials->message()));
        QCOMPARE(density->value(), 1100.0); // the field shows the value the material keeps
        QCOMPARE(window.document()->undoStack()->count(), 0);
        // A valid edit clears the refusal.
        density->setValue(1200.0);
        QVERIFY(materials->message().isEmpty());
        QCOMPARE(window.document()->undoStack()->count(), 1);
        // The name field refuses a taken name and shows the old one again.
        materials->addMaterial();
        auto* name = child<QLineEdit>(materials, "MaterialName");
        name->setText("Ice");
        emit name->editingFinished();
        QVERIFY(materials->message().contains("preset"));
        QCOMPARE(name->text(), QStringLiteral("Material"));
    }

    void sliderDragIsOneUndoStep() {
        MainWindow window;
        QVERIFY(open(window));
        SceneDocument* document = window.document();
        MaterialsWidget* materials = window.settings()->materials();
        materials->setCurrentMaterial("Concrete");
        auto* slider = child<QSlider>(materials, "MaterialFrictionSlider");
        auto* spin = child<QDoubleSpinBox>(materials, "MaterialFriction");
        QCOMPARE(spin->value(), 0.7);
        slider->setSliderDown(true);
        for (int position : {150, 160, 170, 180, 190, 200})
            slider->setValue(position);
        slider->setSliderDown(false);
        QCOMPARE(document->undoStack()->count(), 1);
        QCOMPARE(entry(window, "Concrete").friction, 1.0);
        QCOMPARE(spin->value(), 1.0);
        // The release ended the drag: a spin-box step of the same field afterwards is a step of its own, and its
        // arrow steps merge with each other; another field is a new step.
        spin->stepDown();
        spin->stepDown();
        QCOMPARE(document->undoStack()->count(), 2);
        QCOMPARE(entry(window, "Concrete").friction, 0.9);
        child<QSlider>(materials, "MaterialRestitutionSlider")->setValue(100);
        QCOMPARE(document->undoStack()->count(), 3);
        QCOMPARE(entry(window, "Concrete").restitution, 0.5);
        document->undoStack()->undo();
        document->undoStack()->undo();
        QCOMPARE(entry(window, "Concrete").friction, 1.0); // back to where the drag left it
        document->undoStack()->undo();
        QCOMPARE(entry(window, "Concrete"), *findPreset("Concrete"));
        QCOMPARE(slider->value(), 140);
    }

    void inspectorFollowsLibraryValues() {
        MainWindow window;
        QVERIFY(open(window));
        MaterialsWidget* materials = window.settings()->materials();
        window.setSelectedBodies({1});
        auto* friction = window.inspector()->findChild<QDoubleSpinBox*>("InspectorFriction");
        QVERIFY(friction);
        QCOMPARE(friction->value(), 0.45); // Wood's, shown while the body has no override
        materials->setCurrentMaterial("Wood");
        child<QDoubleSpinBox>(materials, "MaterialFriction")->setValue(0.3);
        QCOMPARE(friction->value(), 0.3);
    }

    void pairTableMatchesCore_data() {
        QTest::addColumn<int>("frictionRule");
        QTest::addColumn<int>("restitutionRule");
        for (int f = 0; f < 5; ++f) {
            const int r = 4 - f; // every rule for both, in different combinations
            QTest::addRow("friction %s, restitution %s", combineRuleName(static_cast<CombineRule>(f)).data(),
                          combineRuleName(static_cast<CombineRule>(r)).data())
                << f << r;
        }
    }
    void pairTableMatchesCore() {
        QFETCH(int, frictionRule);
        QFETCH(int, restitutionRule);
        MainWindow window;
        QVERIFY(open(window, "mixed.obj"));
        SceneDocument* document = window.document();
        WorldSettings world = document->scene().world;
        world.frictionCombine = static_cast<CombineRule>(frictionRule);
        world.restitutionCombine = static_cast<CombineRule>(restitutionRule);
        document->undoStack()->push(new SetWorldSettingsCommand(document, world, "Rules"));
        MaterialsWidget* materials = window.settings()->materials();
        // Edit one material so that a scene value (not only a preset) is part of the check.
        materials->setCurrentMaterial("Rubber");
        child<QDoubleSpinBox>(materials, "MaterialFriction")->setValue(0.9);

        const Scene& scene = document->scene();
        const MaterialPairModel* pairs = materials->pairModel();
        // Every material some body uses appears once, and nothing else.
        QStringList used;
        for (const BodyDef& body : scene.bodies) {
            const QString name = QString::fromStdString(scene.findMaterial(body.material)->name);
            if (!used.contains(name, Qt::CaseInsensitive))
                used.append(name);
        }
        QCOMPARE(pairs->rowCount(), used.size());
        QVERIFY(pairs->rowCount() >= 5);
        for (const QString& name : used)
            QVERIFY2(pairs->materials().contains(name, Qt::CaseInsensitive), qPrintable(name));
        for (int i = 0; i < pairs->rowCount(); ++i)
            for (int j = 0; j < pairs->columnCount(); ++j) {
                const MaterialDef a = *scene.findMaterial(pairs->materials()[i].toStdString());
                const MaterialDef b = *scene.findMaterial(pairs->materials()[j].toStdString());
                const QModelIndex cell = pairs->index(i, j);
                QCOMPARE(cell.data(MaterialPairModel::FrictionRole).toDouble(),
                         combine(world.frictionCombine, a.friction, b.friction));
                QCOMPARE(cell.data(MaterialPairModel::RestitutionRole).toDouble(),
                         combine(world.restitutionCombine, a.restitution, b.restitution));
                QCOMPARE(cell.data(MaterialPairModel::FrictionRole),
                         pairs->index(j, i).data(MaterialPairModel::FrictionRole));
                QCOMPARE(cell.data(MaterialPairModel::RestitutionRole),
                         pairs->index(j, i).data(MaterialPairModel::RestitutionRole));
            }
    }

    void pairTableFollowsEdits() {
        MainWindow window;
        QVERIFY(open(window));
        SceneDocument* document = window.document();
        MaterialsWidget* materials = window.settings()->materials();
        const MaterialPairModel* pairs = materials->pairModel();
        QCOMPARE(pairs->materials(), (QStringList{"Wood", "Concrete"})); // library order
        const int wood = 0, concrete = 1;
        auto friction = [&](int i, int j) {
            return pairs->index(i, j).data(MaterialPairModel::FrictionRole).toDouble();
        };
        QCOMPARE(friction(wood, concrete), std::sqrt(0.45 * 0.7));
        materials->setCurrentMaterial("Wood");
        child<QDoubleSpinBox>(materials, "MaterialFriction")->setValue(0.2);
        QCOMPARE(friction(wood, concrete), std::sqrt(0.2 * 0.7));
        QCOMPARE(friction(wood, wood), std::sqrt(0.2 * 0.2));
        // A body moving to another material adds a row.
        window.setSelectedBodies({3});
        auto* combo = window.inspector()->findChild<QComboBox*>("InspectorMaterial");
        const int steel = combo->findText("Steel");
        combo->setCurrentIndex(steel);
        emit combo->activated(steel);
        QCOMPARE(pairs->materials(), (QStringList{"Steel", "Wood", "Concrete"}));
        // A body's own friction is mentioned, not mixed into the matrix.
        auto* note = child<QLabel>(materials, "MaterialPairNote");
        QVERIFY(note->isHidden());
        BodyDef body = document->body(4);
        body.friction = 0.0;
        document->setBody(4, body);
        QVERIFY(!note->isHidden());
        QVERIFY(note->text().contains("1 bod"));
    }

    void screenshot() {
        MainWindow window;
        QVERIFY(open(window, "mixed.obj"));
        MaterialsWidget* materials = window.settings()->materials();
        materials->setCurrentMaterial("Steel");
        child<QDoubleSpinBox>(materials, "MaterialRestitution")->setValue(0.7);
        QTest::qWait(50);
        QVERIFY(rl::test::screenshot(window).save(QDir::tempPath() + "/rigidlab-materials.png"));
        QVERIFY(window.settings()->materialsDock()->grab().save(QDir::tempPath() + "/rigidlab-materials-dock.png"));
        child<QTabWidget>(materials, "MaterialsTabs")->setCurrentIndex(1);
        QTest::qWait(50);
        QVERIFY(child<QTableView>(materials, "MaterialPairTable")->isVisible());
        QVERIFY(window.settings()->materialsDock()->grab().save(QDir::tempPath() + "/rigidlab-materials-pairs.png"));
    }
};

QTEST_MAIN(TestMaterials)
#include "tst_materials.moc"
