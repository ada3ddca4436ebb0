// The editor's undo commands: undo and redo restore the document exactly, and consecutive edits with a merge id merge.
#include "document/SceneDocument.h"
#include "document/UndoIds.h"
#include "document/commands/AddBodyCommand.h"
#include "document/commands/RemoveBodiesCommand.h"
#include "document/commands/RenameBodyCommand.h"
#include "document/commands/SetBodiesCommand.h"
#include "document/commands/SetBodyCommand.h"

#include <QSignalSpy>
#include <QTest>

namespace {

rl::BodyDef makeBody(const std::string& name, double x) {
    rl::BodyDef body;
    body.name = name;
    body.position = rl::Vec3(x, 0.5, 0.0);
    body.material = "Wood";
    return body;
}

rl::Scene makeScene() {
    rl::Scene scene;
    for (int i = 0; i < 4; ++i)
        scene.bodies.push_back(makeBody("Body" + std::to_string(i), i));
    scene.bodies[0].anchor = true;
    scene.bodies[2].friction = 0.25;
    return scene;
}

} // namespace

class TestCommands : public QObject {
    Q_OBJECT
private slots:
    void setBodyUndoRedo() {
        rl::SceneDocument document;
        document.reset(makeScene(), QString());
        const rl::Scene original = document.scene();
        rl::BodyDef edited = document.body(1);
        edited.anchor = true;
        edited.mass = 3.0;
        edited.orientation = glm::normalize(rl::Quat(0.9, 0.1, 0.2, 0.3));
        QSignalSpy changed(&document, &rl::SceneDocument::bodyChanged);
        document.undoStack()->push(new rl::SetBodyCommand(&document, 1, edited, QStringLiteral("Edit")));
        QVERIFY(document.body(1) == edited);
        QCOMPARE(changed.count(), 1);
        QCOMPARE(changed.first().first().toInt(), 1);
        QVERIFY(document.isModified());
        document.undoStack()->undo();
        QVERIFY(document.scene() == original);
        QVERIFY(!document.isModified());
        document.undoStack()->redo();
        QVERIFY(document.body(1) == edited);
        QCOMPARE(document.undoStack()->undoText(), QStringLiteral("Edit"));
    }

    void setBodyMergesWithinSameIdAndBody() {
        rl::SceneDocument document;
        document.reset(makeScene(), QString());
        const rl::Scene original = document.scene();
        for (int step = 1; step <= 5; ++step) {
            rl::BodyDef body = document.body(2);
            body.friction = 0.1 * step;
            document.undoStack()->push(
                new rl::SetBodyCommand(&document, 2, body, QStringLiteral("Friction"), rl::SetBodyFrictionId));
        }
        QCOMPARE(document.undoStack()->count(), 1);
        QCOMPARE(*document.body(2).friction, 0.5);
        // Another body, or another id, starts a new step.
        rl::BodyDef other = document.body(3);
        other.friction = 0.7;
        document.undoStack()->push(
            new rl::SetBodyCommand(&document, 3, other, QStringLiteral("Friction"), rl::SetBodyFrictionId));
        rl::BodyDef restitution = document.body(3);
        restitution.restitution = 0.4;
        document.undoStack()->push(
            new rl::SetBodyCommand(&document, 3, restitution, QStringLiteral("Restitution"), rl::SetBodyRestitutionId));
        QCOMPARE(document.undoStack()->count(), 3);
        document.undoStack()->undo();
        document.undoStack()->undo();
        document.undoStack()->undo();
        QVERIFY(document.scene() == original);
        // Commands without an id never merge.
        for (int step = 1; step <= 2; ++step) {
            rl::BodyDef body = document.body(2);
            body.anchor = step == 1;
            document.undoStack()->push(new rl::SetBodyCommand(&document, 2, body, QStringLiteral("Anchor")));
        }
        QCOMPARE(document.undoStack()->count(), 2);
    }

    void mergeBackToStartIsObsolete() {
        rl::SceneDocument document;
        document.reset(makeScene(), QString());
        rl::BodyDef body = document.body(1);
        body.position.x = 10.0;
        document.undoStack()->push(
            new rl::SetBodyCommand(&document, 1, body, QStringLiteral("Move"), rl::SetBodyPositionId));
        body.position.x = 1.0; // back where it was
        document.undoStack()->push(
            new rl::SetBodyCommand(&document, 1, body, QStringLiteral("Move"), rl::SetBodyPositionId));
        QCOMPARE(document.undoStack()->count(), 0);
        QVERIFY(document.body(1) == makeScene().bodies[1]);
    }

    void setBodiesIsOneStep() {
        rl::SceneDocument document;
        document.reset(makeScene(), QString());
        const rl::Scene original = document.scene();
        std::vector<rl::BodyDef> after{document.body(0), document.body(3)};
        after[0].material = "Steel";
        after[1].material = "Steel";
        after[1].velocity = rl::Vec3(1.0, 2.0, 3.0);
        document.undoStack()->push(
            new rl::SetBodiesCommand(&document, {0, 3}, after, QStringLiteral("Material"), rl::SetBodyMaterialId));
        QCOMPARE(document.undoStack()->count(), 1);
        QVERIFY(document.body(0) == after[0]);
        QVERIFY(document.body(3) == after[1]);
        QVERIFY(document.body(1) == original.bodies[1]);
        // Same bodies and id: merged; different bodies: not.
        after[0].material = "Ice";
        document.undoStack()->push(
            new rl::SetBodiesCommand(&document, {0, 3}, after, QStringLiteral("Material"), rl::SetBodyMaterialId));
        QCOMPARE(document.undoStack()->count(), 1);
        document.undoStack()->push(new rl::SetBodiesCommand(&document, {1, 3}, {document.body(1), after[1]},
                                                            QStringLiteral("Material"), rl::SetBodyMaterialId));
        QCOMPARE(document.undoStack()->count(), 2);
        document.undoStack()->undo();
        document.undoStack()->undo();
        QVERIFY(document.scene() == original);
        document.undoStack()->redo();
        QCOMPARE(document.body(0).material, std::string("Ice"));
        QVERIFY(document.body(3) == after[1]);
    }

    void addBodyUndoRedo() {
        rl::SceneDocument document;
        document.reset(makeScene(), QString());
        const rl::Scene original = document.scene();
        const rl::BodyDef added = makeBody("Added", 9.0);
        document.undoStack()->push(new rl::AddBodyCommand(&document, 2, added));
        QCOMPARE(document.bodyCount(), 5);
        QVERIFY(document.body(2) == added);
        QVERIFY(document.body(3) == original.bodies[2]);
        QVERIFY(document.undoStack()->undoText().contains(QStringLiteral("Added")));
        document.undoStack()->undo();
        QVERIFY(document.scene() == original);
        document.undoStack()->redo();
        QVERIFY(document.body(2) == added);
    }

    void removeBodiesUndoRedo_data() {
        QTest::addColumn<QList<int>>("indices");
        QTest::newRow("one") << QList<int>{1};
        QTest::newRow("first and last") << QList<int>{0, 3};
        QTest::newRow("unsorted") << QList<int>{2, 0, 1};
        QTest::newRow("all") << QList<int>{0, 1, 2, 3};
    }
    void removeBodiesUndoRedo() {
        QFETCH(QList<int>, indices);
        rl::SceneDocument document;
        document.reset(makeScene(), QString());
        const rl::Scene original = document.scene();
        document.undoStack()->push(new rl::RemoveBodiesCommand(&document, indices));
        QCOMPARE(document.bodyCount(), 4 - static_cast<int>(indices.size()));
        std::vector<rl::BodyDef> kept;
        for (int i = 0; i < 4; ++i)
            if (!indices.contains(i))
                kept.push_back(original.bodies[static_cast<size_t>(i)]);
        QVERIFY(document.scene().bodies == kept);
        document.undoStack()->undo();
        QVERIFY(document.scene() == original);
        document.undoStack()->redo();
        QVERIFY(document.scene().bodies == kept);
    }

    void renameUndoRedoAndMerge() {
        rl::SceneDocument document;
        document.reset(makeScene(), QString());
        const rl::Scene original = document.scene();
        document.undoStack()->push(new rl::RenameBodyCommand(&document, 1, QStringLiteral("Crate")));
        QCOMPARE(document.body(1).name, std::string("Crate"));
        QVERIFY(document.undoStack()->undoText().contains(QStringLiteral("Crate")));
        document.undoStack()->push(new rl::RenameBodyCommand(&document, 1, QStringLiteral("Crate A")));
        QCOMPARE(document.undoStack()->count(), 1);
        rl::BodyDef expected = original.bodies[1];
        expected.name = "Crate A";
        QVERIFY(document.body(1) == expected);
        document.undoStack()->undo();
        QVERIFY(document.scene() == original);
        document.undoStack()->redo();
        QVERIFY(document.body(1) == expected);
    }
};

QTEST_GUILESS_MAIN(TestCommands)
#include "tst_commands.moc"
