// The inspector in the main window: edits go through undo commands, multi-selection shows mixed values and edits
// every selected body in one undo step.
#include "MainWindow.h"
#include "document/SceneDocument.h"
#include "inspector/InspectorWidget.h"
#include "scene/BodyProperties.h"
#include "scene/SceneLibrary.h"
#include "ui/GuiTestSetup.h"
#include "ui/Screenshot.h"
#include "viewport/Viewport.h"

#include <QAction>
#include <QCheckBox>
#include <QComboBox>
#include <QDir>
#include <QDoubleSpinBox>
#include <QLabel>
#include <QLineEdit>
#include <QSurfaceFormat>
#include <QTest>
#include <QTranslator>

class TestInspector : public QObject {
    Q_OBJECT
public:
    static void initMain() { rl::test::prepareGuiTest(); }

private:
    template <class T>
    static T* child(rl::MainWindow& window, const char* name) {
        T* widget = window.inspector()->findChild<T*>(QString::fromLatin1(name));
        if (!widget)
            qFatal("no inspector child %s", name);
        return widget;
    }

    static bool openStack(rl::MainWindow& window) {
        window.show();
        return QTest::qWaitForWindowExposed(&window) &&
               window.openFile(QStringLiteral(RL_SOURCE_DIR "/resources/scenes/stack.obj"));
    }

private slots:
    // The override check boxes stand in one column, as a list does (right-aligned they sat at four different x).
    void overrideCheckBoxesLineUp() {
        rl::MainWindow window;
        QVERIFY(openStack(window));
        window.setSelectedBodies({1});
        QList<int> lefts;
        for (const char* name : {"InspectorDensityEnabled", "InspectorMassEnabled", "InspectorFrictionEnabled",
                                 "InspectorRestitutionEnabled"}) {
            auto* box = child<QCheckBox>(window, name);
            QTRY_VERIFY(box->isVisible());
            lefts.append(box->mapTo(window.inspector(), QPoint(0, 0)).x());
        }
        for (int left : lefts)
            QCOMPARE(left, lefts.first());
    }

    void anchorCheckBoxUndoRedo() {
        rl::MainWindow window;
        QVERIFY(openStack(window));
        rl::SceneDocument* document = window.document();
        QVERIFY(!document->body(1).anchor);
        window.setSelectedBodies({1});
        QCOMPARE(window.inspector()->selection(), QList<int>{1});
        auto* anchor = child<QCheckBox>(window, "InspectorAnchor");
        QVERIFY(anchor->isVisible());
        QCOMPARE(anchor->checkState(), Qt::Unchecked);
        QTest::mouseClick(anchor, Qt::LeftButton, {}, QPoint(6, anchor->height() / 2));
        QVERIFY(document->body(1).anchor);
        QCOMPARE(document->undoStack()->count(), 1);
        document->undoStack()->undo();
        QVERIFY(!document->body(1).anchor);
        QCOMPARE(anchor->checkState(), Qt::Unchecked); // the view follows the document
        document->undoStack()->redo();
        QVERIFY(document->body(1).anchor);
        QCOMPARE(anchor->checkState(), Qt::Checked);
    }

    void frictionOverride() {
        rl::MainWindow window;
        QVERIFY(openStack(window));
        rl::SceneDocument* document = window.document();
        window.setSelectedBodies({2});
        QVERIFY(!document->body(2).friction);
        auto* enabled = child<QCheckBox>(window, "InspectorFrictionEnabled");
        auto* value = child<QDoubleSpinBox>(window, "InspectorFriction");
        QVERIFY(!value->isEnabled());
        const double woodFriction = document->scene().effectiveMaterial(document->body(2)).friction;
        QCOMPARE(value->value(), woodFriction); // an unset override shows the material's value
        QTest::mouseClick(enabled, Qt::LeftButton, {}, QPoint(6, enabled->height() / 2));
        QVERIFY(document->body(2).friction.has_value());
        QCOMPARE(*document->body(2).friction, woodFriction);
        QVERIFY(value->isEnabled());
        // Typing a value commits once, on Enter.
        value->setFocus();
        value->selectAll();
        QTest::keyClicks(value, "0.85");
        QCOMPARE(*document->body(2).friction, woodFriction); // keyboard tracking is off
        QTest::keyClick(value, Qt::Key_Return);
        QCOMPARE(*document->body(2).friction, 0.85);
        const int steps = document->undoStack()->count();
        // Enter finished that edit: arrow steps after it are a new step (and merge with each other).
        value->stepUp();
        value->stepUp();
        QCOMPARE(*document->body(2).friction, 0.95);
        QCOMPARE(document->undoStack()->count(), steps + 1);
        document->undoStack()->undo();
        QCOMPARE(*document->body(2).friction, 0.85);
        document->undoStack()->undo();
        QCOMPARE(*document->body(2).friction, woodFriction);
        document->undoStack()->undo();
        QVERIFY(!document->body(2).friction);
        QVERIFY(!value->isEnabled());
    }

    void positionAndRotation() {
        rl::MainWindow window;
        QVERIFY(openStack(window));
        rl::SceneDocument* document = window.document();
        window.setSelectedBodies({3});
        const rl::BodyDef before = document->body(3);
        child<QDoubleSpinBox>(window, "InspectorPositionY")->setValue(7.5);
        QCOMPARE(document->body(3).position.y, 7.5);
        QCOMPARE(document->body(3).position.x, before.position.x);
        child<QDoubleSpinBox>(window, "InspectorRotationZ")->setValue(90.0);
        const rl::Vec3 turned = document->body(3).orientation * rl::Vec3(1.0, 0.0, 0.0);
        QVERIFY(glm::length(turned - rl::Vec3(0.0, 1.0, 0.0)) < 1e-9); // +90° about Z takes X to Y
        QCOMPARE(document->undoStack()->count(), 2);
        document->undoStack()->undo();
        document->undoStack()->undo();
        QVERIFY(document->body(3) == before);
    }

    void multiSelectionMaterial() {
        rl::MainWindow window;
        QVERIFY(openStack(window));
        rl::SceneDocument* document = window.document();
        // Body 0 is the concrete anchor, body 1 a wooden cube.
        QVERIFY(document->body(0).material != document->body(1).material);
        window.setSelectedBodies({1});
        child<QDoubleSpinBox>(window, "InspectorPositionY")->setValue(3.0); // OBJ bodies all sit at the origin
        QVERIFY(document->body(0).position.y != document->body(1).position.y);
        window.setSelectedBodies({0, 1});
        auto* material = child<QComboBox>(window, "InspectorMaterial");
        QCOMPARE(material->currentIndex(), -1);
        QVERIFY(material->currentText().isEmpty());
        QCOMPARE(child<QCheckBox>(window, "InspectorAnchor")->checkState(), Qt::PartiallyChecked);
        QCOMPARE(child<QDoubleSpinBox>(window, "InspectorPositionY")->text(), rl::InspectorWidget::mixedText());
        QVERIFY(child<QLineEdit>(window, "InspectorName")->text().isEmpty());
        const std::vector<rl::BodyDef> before = document->scene().bodies;

        const int steel = material->findText(QStringLiteral("Steel"));
        QVERIFY(steel >= 0);
        material->setCurrentIndex(steel);
        emit material->activated(steel); // what a user's pick in the popup emits
        QCOMPARE(document->body(0).material, std::string("Steel"));
        QCOMPARE(document->body(1).material, std::string("Steel"));
        QCOMPARE(document->undoStack()->count(), 2);
        QCOMPARE(material->currentText(), QStringLiteral("Steel"));
        document->undoStack()->undo();
        QVERIFY(document->scene().bodies == before);
        QCOMPARE(material->currentIndex(), -1);
    }

    void editMenuActions() {
        rl::MainWindow window;
        QVERIFY(openStack(window));
        rl::SceneDocument* document = window.document();
        const std::vector<rl::BodyDef> before = document->scene().bodies;
        auto* toggle = window.findChild<QAction*>("ToggleAnchorAction");
        auto* remove = window.findChild<QAction*>("DeleteAction");
        QVERIFY(toggle && remove);
        QVERIFY(!remove->isEnabled());
        window.setSelectedBodies({0, 4});
        toggle->trigger(); // mixed -> all anchored
        QVERIFY(document->body(0).anchor && document->body(4).anchor);
        toggle->trigger(); // all anchored -> none
        QVERIFY(!document->body(0).anchor && !document->body(4).anchor);
        remove->trigger();
        QCOMPARE(document->bodyCount(), static_cast<int>(before.size()) - 2);
        QVERIFY(window.selectedBodies().isEmpty());
        auto* undo = window.findChild<QAction*>("UndoAction");
        QVERIFY(undo);
        QCOMPARE(undo->shortcut(), QKeySequence(QKeySequence::Undo));
        for (int i = 0; i < 3; ++i)
            undo->trigger();
        QVERIFY(document->scene().bodies == before);
    }

    void deleteKeyAndKeypadDelete() {
        rl::MainWindow window;
        QVERIFY(openStack(window));
        rl::SceneDocument* document = window.document();
        const int count = document->bodyCount();
        window.setSelectedBodies({5});
        window.activateWindow();
        QVERIFY(QTest::qWaitForWindowActive(&window)); // window shortcuts need the active window
        window.viewport()->setFocus();
        // The keypad's Del frames the selection in the viewport; it must not delete.
        QTest::keyClick(window.viewport(), Qt::Key_Delete, Qt::KeypadModifier);
        QCOMPARE(document->bodyCount(), count);
        QTest::keyClick(window.viewport(), Qt::Key_Delete);
        QCOMPARE(document->bodyCount(), count - 1);
        document->undoStack()->undo();
        QCOMPARE(document->bodyCount(), count);
    }

    void renameSelectedBodies() {
        rl::MainWindow window;
        QVERIFY(openStack(window));
        rl::SceneDocument* document = window.document();
        window.setSelectedBodies({2, 3});
        auto* name = child<QLineEdit>(window, "InspectorName");
        name->setText(QStringLiteral("Crate"));
        emit name->editingFinished();
        QCOMPARE(document->body(2).name, std::string("Crate"));
        QCOMPARE(document->body(3).name, std::string("Crate"));
        QCOMPARE(name->text(), QStringLiteral("Crate"));
        QCOMPARE(document->undoStack()->count(), 1);
        document->undoStack()->undo();
        QCOMPARE(document->body(2).name, std::string("Cube.001"));
        QCOMPARE(document->body(3).name, std::string("Cube.002"));
        QVERIFY(name->text().isEmpty()); // mixed again
    }

    void densityAndMassOverrides() {
        rl::MainWindow window;
        QVERIFY(openStack(window));
        rl::SceneDocument* document = window.document();
        window.setSelectedBodies({1});
        const rl::BodyDef before = document->body(1);
        const auto props = rl::computeBodyProperties(document->scene(), before);
        QVERIFY(props);
        auto* massLabel = child<QLabel>(window, "InspectorComputedMass");
        QCOMPARE(massLabel->text(), QStringLiteral("%1 kg").arg(props->mass, 0, 'g', 5));
        QCOMPARE(child<QLabel>(window, "InspectorVolume")->text(),
                 QStringLiteral("%1 m³").arg(props->volume, 0, 'g', 5));

        // Density: the box starts from the material's value, and the computed mass follows.
        auto* densityOn = child<QCheckBox>(window, "InspectorDensityEnabled");
        auto* density = child<QDoubleSpinBox>(window, "InspectorDensity");
        QCOMPARE(density->value(), 700.0); // wood
        densityOn->click();
        QCOMPARE(*document->body(1).density, 700.0);
        density->setValue(1400.0);
        QCOMPARE(*document->body(1).density, 1400.0);
        QCOMPARE(massLabel->text(), QStringLiteral("%1 kg").arg(2.0 * props->mass, 0, 'g', 5));

        // Mass: overrides density x volume.
        auto* massOn = child<QCheckBox>(window, "InspectorMassEnabled");
        auto* mass = child<QDoubleSpinBox>(window, "InspectorMass");
        massOn->click();
        QVERIFY(document->body(1).mass.has_value());
        mass->setValue(5.0);
        QCOMPARE(*document->body(1).mass, 5.0);
        QCOMPARE(massLabel->text(), QStringLiteral("5 kg"));
        QCOMPARE(document->undoStack()->count(), 4);
        while (document->undoStack()->canUndo())
            document->undoStack()->undo();
        QVERIFY(document->body(1) == before);
        QVERIFY(!density->isEnabled() && !mass->isEnabled());
    }

    void restitutionAndInitialMotion_data() {
        QTest::addColumn<QString>("field");
        QTest::addColumn<double>("value");
        QTest::newRow("velocity x") << "InspectorVelocityX" << 1.5;
        QTest::newRow("velocity y") << "InspectorVelocityY" << -2.0;
        QTest::newRow("velocity z") << "InspectorVelocityZ" << 0.25;
        QTest::newRow("angular velocity x") << "InspectorAngularVelocityX" << 3.0;
        QTest::newRow("angular velocity y") << "InspectorAngularVelocityY" << -1.0;
        QTest::newRow("angular velocity z") << "InspectorAngularVelocityZ" << 0.5;
        QTest::newRow("position x") << "InspectorPositionX" << 2.0;
        QTest::newRow("rotation x (degrees)") << "InspectorRotationX" << 30.0;
    }
    void restitutionAndInitialMotion() {
        QFETCH(QString, field);
        QFETCH(double, value);
        rl::MainWindow window;
        QVERIFY(openStack(window));
        rl::SceneDocument* document = window.document();
        window.setSelectedBodies({2});
        const rl::BodyDef before = document->body(2);
        auto* box = window.inspector()->findChild<QDoubleSpinBox*>(field);
        QVERIFY(box);
        box->setValue(value);
        QCOMPARE(document->undoStack()->count(), 1);
        const rl::BodyDef& after = document->body(2);
        const int axis = field.back().toLatin1() - 'X';
        if (field.startsWith("InspectorVelocity"))
            QCOMPARE(after.velocity[axis], value);
        else if (field.startsWith("InspectorAngularVelocity"))
            QCOMPARE(after.angularVelocity[axis], value);
        else if (field.startsWith("InspectorPosition"))
            QCOMPARE(after.position[axis], value);
        else
            QVERIFY(std::abs(glm::degrees(glm::eulerAngles(after.orientation))[axis] - value) < 1e-9);
        // Arrow steps of the same field merge into the same undo step.
        box->stepUp();
        box->stepUp();
        QCOMPARE(document->undoStack()->count(), 1);
        document->undoStack()->undo();
        QVERIFY(document->body(2) == before);

        // Restitution override, as the other overrides.
        child<QCheckBox>(window, "InspectorRestitutionEnabled")->click();
        child<QDoubleSpinBox>(window, "InspectorRestitution")->setValue(0.6);
        QCOMPARE(*document->body(2).restitution, 0.6);
        QCOMPARE(document->scene().effectiveMaterial(document->body(2)).restitution, 0.6);
    }

    void overrideOutOfRangeRefused_data() {
        QTest::addColumn<QString>("field");
        QTest::addColumn<double>("value");
        QTest::addColumn<QString>("expected");
        QTest::newRow("density 0") << "InspectorDensity" << 0.0 << "Density";
        QTest::newRow("density negative") << "InspectorDensity" << -0.5 << "Density";
        QTest::newRow("mass 0") << "InspectorMass" << 0.0 << "Mass";
        QTest::newRow("friction negative") << "InspectorFriction" << -0.2 << "Friction";
        QTest::newRow("restitution negative") << "InspectorRestitution" << -0.2 << "Restitution";
    }
    void overrideOutOfRangeRefused() {
        QFETCH(QString, field);
        QFETCH(double, value);
        QFETCH(QString, expected);
        rl::MainWindow window;
        QVERIFY(openStack(window));
        rl::SceneDocument* document = window.document();
        window.setSelectedBodies({3});
        child<QCheckBox>(window, (field + "Enabled").toLatin1().constData())->click();
        const rl::BodyDef before = document->body(3);
        const int steps = document->undoStack()->count();
        auto* box = window.inspector()->findChild<QDoubleSpinBox*>(field);
        const double shown = box->value();
        box->setValue(value);
        QVERIFY(document->body(3) == before);
        QCOMPARE(document->undoStack()->count(), steps);
        QCOMPARE(box->value(), shown);
        QVERIFY2(window.inspector()->message().contains(expected), qPrintable(window.inspector()->message()));
        // The same material with a value in range is accepted, and the refusal goes away.
        box->setValue(0.5);
        QVERIFY(window.inspector()->message().isEmpty());
        QVERIFY(!(document->body(3) == before));
    }

    void multiSelectionOverrideAppliesToAll() {
        rl::MainWindow window;
        QVERIFY(openStack(window));
        rl::SceneDocument* document = window.document();
        window.setSelectedBodies({1, 2, 3});
        auto* enabled = child<QCheckBox>(window, "InspectorFrictionEnabled");
        auto* value = child<QDoubleSpinBox>(window, "InspectorFriction");
        enabled->click();
        value->setValue(0.3);
        for (int body : {1, 2, 3})
            QCOMPARE(*document->body(body).friction, 0.3);
        QCOMPARE(document->undoStack()->count(), 2);
        // One body differs: the selection shows the value as mixed, and the check box stays checked.
        window.setSelectedBodies({2});
        value->setValue(0.9);
        window.setSelectedBodies({1, 2, 3});
        QCOMPARE(value->text(), rl::InspectorWidget::mixedText());
        QCOMPARE(enabled->checkState(), Qt::Checked);
        // Some bodies with the override and some without: partially checked.
        window.setSelectedBodies({3, 4});
        QCOMPARE(enabled->checkState(), Qt::PartiallyChecked);
        QCOMPARE(child<QLabel>(window, "InspectorInertia")->text(), rl::InspectorWidget::mixedText());
        QVERIFY(child<QLabel>(window, "InspectorComputedMass")->text().contains("total"));
    }

    void materialNamesIgnoreCase() {
        rl::Scene scene = rl::scenes::stack(2);
        scene.bodies[1].material = "wood";
        scene.bodies[2].material = "Wood";
        rl::MainWindow window;
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        window.document()->reset(scene, QString());
        window.setSelectedBodies({1, 2});
        auto* material = child<QComboBox>(window, "InspectorMaterial");
        QCOMPARE(material->currentText(), QStringLiteral("Wood"));
        QCOMPARE(material->findText("wood", Qt::MatchFixedString | Qt::MatchCaseSensitive), -1); // listed once
        // The list is the library's order: the presets first.
        QCOMPARE(material->itemText(0), QStringLiteral("Default"));
        QCOMPARE(material->count(), static_cast<int>(rl::materialPresets().size()));
    }

    // Two edits of one field are two undo steps when the first was finished (Enter, or the focus left the field);
    // arrow steps within one edit merge. Undo then goes back one edit at a time.
    void finishedEditsOfOneFieldAreSeparateSteps() {
        rl::MainWindow window;
        QVERIFY(openStack(window));
        rl::SceneDocument* document = window.document();
        window.setSelectedBodies({1});
        auto* enabled = child<QCheckBox>(window, "InspectorFrictionEnabled");
        QTest::mouseClick(enabled, Qt::LeftButton, {}, QPoint(6, enabled->height() / 2));
        const int start = document->undoStack()->count();
        auto* friction = child<QDoubleSpinBox>(window, "InspectorFriction");
        QTRY_VERIFY(friction->isEnabled());
        auto typeValue = [&](const QString& text) {
            friction->setFocus();
            friction->selectAll();
            QTest::keyClicks(friction, text);
            QTest::keyClick(friction, Qt::Key_Return);
        };
        typeValue("0.3");
        QCOMPARE(*document->body(1).friction, 0.3);
        QCOMPARE(document->undoStack()->count(), start + 1); // the keystrokes of one value are one step
        typeValue("0.55");
        QCOMPARE(*document->body(1).friction, 0.55);
        QCOMPARE(document->undoStack()->count(), start + 2);
        friction->stepUp();
        friction->stepUp();
        QCOMPARE(document->undoStack()->count(), start + 3);
        document->undoStack()->undo();
        QCOMPARE(*document->body(1).friction, 0.55);
        document->undoStack()->undo();
        QCOMPARE(*document->body(1).friction, 0.3);
    }

    // The computed warnings: mixed.obj's torus is concave; the warning reads in the user's language.
    void warningsNameTheConcaveBody_data() {
        QTest::addColumn<QString>("translation");
        QTest::addColumn<QString>("expected");
        QTest::newRow("English") << QString() << "concave: simulated as its convex hull";
        QTest::newRow("German") << ":/i18n/rigidlab_de.qm"
                                << "konkav: wird als seine konvexe Hülle simuliert";
    }
    void warningsNameTheConcaveBody() {
        QFETCH(QString, translation);
        QFETCH(QString, expected);
        QTranslator translator;
        if (!translation.isEmpty()) {
            QVERIFY(translator.load(translation));
            QCoreApplication::installTranslator(&translator);
        }
        {
            rl::MainWindow window;
            window.show();
            QVERIFY(QTest::qWaitForWindowExposed(&window));
            QVERIFY(window.openFile(QStringLiteral(RL_SOURCE_DIR "/resources/scenes/mixed.obj")));
            int torus = -1, cube = -1;
            for (int i = 0; i < window.document()->bodyCount(); ++i) {
                if (window.document()->body(i).name == "Torus")
                    torus = i;
                if (window.document()->body(i).name == "Cube")
                    cube = i;
            }
            QVERIFY(torus >= 0 && cube >= 0);
            auto* warnings = child<QLabel>(window, "InspectorWarnings");
            window.setSelectedBodies({torus});
            QTRY_COMPARE(warnings->text(), expected);
            window.setSelectedBodies({cube});
            QTRY_VERIFY(!warnings->text().contains(expected));
        }
        QCoreApplication::removeTranslator(&translator);
    }

    void screenshot() {
        rl::MainWindow window;
        QVERIFY(openStack(window));
        window.setSelectedBodies({1});
        QTest::qWait(50);
        QVERIFY(window.inspector()->isVisible());
        QVERIFY(child<QLabel>(window, "InspectorComputedMass")->text().contains(QStringLiteral("kg")));
        QCOMPARE(child<QLabel>(window, "InspectorHull")->text(), QStringLiteral("8")); // a cube's corners
        const QString path = QDir::tempPath() + "/rigidlab-inspector.png";
        QVERIFY(rl::test::screenshot(window).save(path));
        window.setSelectedBodies({0, 1});
        QTest::qWait(50);
        QVERIFY(rl::test::screenshot(window).save(QDir::tempPath() + "/rigidlab-inspector-multi.png"));
    }
};

QTEST_MAIN(TestInspector)
#include "tst_inspector.moc"
