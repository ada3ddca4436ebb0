// Every label that shows a mnemonic (&Name) has a buddy: without one Qt paints the ampersand literally ("&Frames:")
// and Alt+letter does nothing. Checked on each dialog and on the main window with all its docks.
#include "MainWindow.h"
#include "analysis/CompareBakesDialog.h"
#include "analysis/ExportDialog.h"
#include "analysis/PreflightDialog.h"
#include "simulation/BakeDialog.h"
#include "ui/GuiTestSetup.h"

#include <QDialog>
#include <QLabel>
#include <QTest>

#include <functional>
#include <memory>

using Factory = std::function<std::unique_ptr<QWidget>()>;
Q_DECLARE_METATYPE(Factory)

class TestDialogLabels : public QObject {
    Q_OBJECT
public:
    static void initMain() { rl::test::prepareGuiTest(); }

private slots:
    void mnemonicLabelsHaveBuddies_data() {
        QTest::addColumn<Factory>("make");
        QTest::newRow("bake") << Factory([] { return std::make_unique<rl::BakeDialog>(60.0, 0, 600); });
        QTest::newRow("export csv") << Factory([] {
            return std::make_unique<rl::ExportDialog>(rl::ExportRequest::Format::Csv, 601, 9, 60.0, true, QList<int>{1},
                                                      QStringLiteral("/tmp/x.csv"));
        });
        QTest::newRow("export bake") << Factory([] {
            return std::make_unique<rl::ExportDialog>(rl::ExportRequest::Format::Bake, 601, 9, 60.0, true, QList<int>{},
                                                      QStringLiteral("/tmp/x.bake"));
        });
        QTest::newRow("compare bakes") << Factory(
            [] { return std::make_unique<rl::CompareBakesDialog>([] { return std::shared_ptr<const rl::Bake>(); }); });
        QTest::newRow("preflight") << Factory([] {
            return std::make_unique<rl::PreflightDialog>(rl::Scene{}, std::vector<rl::PreflightFinding>{},
                                                         rl::PreflightDialog::Mode::ConfirmBake);
        });
        QTest::newRow("main window") << Factory([] { return std::make_unique<rl::MainWindow>(); });
    }
    void mnemonicLabelsHaveBuddies() {
        QFETCH(Factory, make);
        std::unique_ptr<QWidget> widget = make();
        QStringList bad;
        for (QLabel* label : widget->findChildren<QLabel*>()) {
            QString text = label->text();
            if (Qt::mightBeRichText(text))
                continue;
            text.replace(QLatin1String("&&"), QString());
            if (text.contains(QLatin1Char('&')) && !label->buddy())
                bad.append(label->text());
        }
        QVERIFY2(bad.isEmpty(), qPrintable(QStringLiteral("labels without a buddy: ") + bad.join(QLatin1String(", "))));
    }

    // The pre-flight check warns; it does not stand in the way: Enter bakes as asked, Escape cancels. (Cancel was the
    // default, so Ctrl+B, Enter, Enter on any scene with a torus or Suzanne baked nothing.)
    void preflightEnterBakesEscapeCancels_data() {
        QTest::addColumn<int>("key");
        QTest::addColumn<int>("result");
        QTest::newRow("enter") << int(Qt::Key_Return) << int(QDialog::Accepted);
        QTest::newRow("escape") << int(Qt::Key_Escape) << int(QDialog::Rejected);
    }
    void preflightEnterBakesEscapeCancels() {
        QFETCH(int, key);
        QFETCH(int, result);
        rl::Scene scene;
        rl::BodyDef body;
        body.name = "Torus";
        scene.bodies.push_back(body);
        rl::PreflightFinding finding;
        finding.kind = rl::PreflightKind::ConcaveDynamic;
        finding.body = 0;
        rl::PreflightDialog dialog(scene, {finding}, rl::PreflightDialog::Mode::ConfirmBake);
        dialog.show();
        QVERIFY(QTest::qWaitForWindowExposed(&dialog));
        QTest::keyClick(&dialog, Qt::Key(key));
        QCOMPARE(dialog.result(), result);
        QVERIFY(!dialog.isVisible());
    }
};

QTEST_MAIN(TestDialogLabels)
#include "tst_dialoglabels.moc"
