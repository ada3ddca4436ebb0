// File > Export through the editor's own code path (the Export dialog, the worker thread, the core writers): the CSV
// and the .bake of stack.obj baked for 1 s must equal, byte for byte, what `rigidlab-cli bake` writes for the same
// scene and settings (issue 6, acceptance); selections and frame ranges give exactly the matching rows; a cancelled
// or failed export leaves the target as it was.
#define RL_CLI_PATH RL_BINARY_DIR "/app/rigidlab-cli"
#include "MainWindow.h"
#include "analysis/AnalysisController.h"
#include "analysis/ExportJob.h"
#include "app/CliRunner.h"
#include "bake/Bake.h"
#include "document/SceneDocument.h"
#include "io/SceneImport.h"
#include "simulation/SimulationController.h"
#include "ui/GuiTestSetup.h"
#include "world/Baker.h"

#include <QAction>
#include <QApplication>
#include <QDir>
#include <QFile>
#include <QLineEdit>
#include <QPushButton>
#include <QRadioButton>
#include <QSignalSpy>
#include <QSpinBox>
#include <QTemporaryDir>
#include <QTest>
#include <QTimer>

#include <functional>
#include <memory>

using namespace rl;

namespace {

const QString kStack = QStringLiteral(RL_SOURCE_DIR "/resources/scenes/stack.obj");

QByteArray readAll(const QString& path) {
    QFile file(path);
    return file.open(QIODevice::ReadOnly) ? file.readAll() : QByteArray();
}

// Calls `act` on the first modal dialog with this object name that comes up (polled, so it works inside exec()).
void onModal(const QString& name, std::function<void(QWidget*)> act) {
    auto* timer = new QTimer;
    timer->setInterval(30);
    QObject::connect(timer, &QTimer::timeout, [timer, name, act] {
        QWidget* modal = QApplication::activeModalWidget();
        if (modal && modal->objectName() == name) {
            timer->stop();
            timer->deleteLater();
            act(modal);
        }
    });
    timer->start();
}

// Fills in the Export dialog and presses Export.
void fillExportDialog(QWidget* dialog, const QString& path, bool selected, int first = -1, int last = -1) {
    dialog->findChild<QLineEdit*>("ExportPath")->setText(path);
    if (const QString dir = qEnvironmentVariable("RL_SCREENSHOT_DIR"); !dir.isEmpty())
        dialog->grab().save(dir + "/export_dialog.png");
    if (selected)
        dialog->findChild<QRadioButton*>("ExportSelectedBodies")->setChecked(true);
    if (first >= 0) {
        dialog->findChild<QRadioButton*>("ExportFrameRange")->setChecked(true);
        dialog->findChild<QSpinBox*>("ExportFirstFrame")->setValue(first);
        dialog->findChild<QSpinBox*>("ExportLastFrame")->setValue(last);
    }
    dialog->findChild<QPushButton*>("ExportOk")->click();
}

// Exports the window's current bake through `action` (File > Export) and the dialog to `out`. Empty when the file
// equals `expected` byte for byte, else what went wrong.
QString exportAndCompare(QWidget& window, const QString& action, const QString& out, const QString& expected) {
    onModal("ExportDialog", [out](QWidget* dialog) { fillExportDialog(dialog, out, false); });
    QAction* trigger = window.findChild<QAction*>(action);
    if (!trigger || !trigger->isEnabled())
        return action + QStringLiteral(" is missing or disabled");
    trigger->trigger(); // returns when the dialog was answered and the export finished
    if (!QTest::qWaitFor([&] { return QFile::exists(out); }, 30000))
        return out + QStringLiteral(" was not written");
    const QByteArray ui = readAll(out);
    const QByteArray cli = readAll(expected);
    if (cli.isEmpty())
        return expected + QStringLiteral(" is empty");
    if (ui != cli)
        return QStringLiteral("%1 (%2 bytes) differs from %3 (%4 bytes)")
            .arg(out)
            .arg(ui.size())
            .arg(expected)
            .arg(cli.size());
    return {};
}

} // namespace

class TestExport : public QObject {
    Q_OBJECT
public:
    static void initMain() { rl::test::prepareGuiTest(); }

private:
    QTemporaryDir m_dir;
    QString m_cliCsv, m_cliBake;
    std::shared_ptr<const Bake> m_bake;
    std::unique_ptr<MainWindow> m_window;

private slots:
    void initTestCase() {
        QVERIFY(m_dir.isValid());
        QVERIFY2(QFile::exists(RL_CLI_PATH), "build rigidlab-cli first: this test compares with its output");
        m_cliCsv = m_dir.filePath("cli.csv");
        m_cliBake = m_dir.filePath("cli.bake");
        const rl::test::CliRun run =
            rl::test::runCli({"bake", kStack, "--seconds", "1", "--csv", m_cliCsv, "-o", m_cliBake, "--quiet"});
        QCOMPARE(run.exitCode, 0);

        // The same scene and settings baked the way the editor does: core's Baker on the document's scene.
        m_window = std::make_unique<MainWindow>();
        m_window->show();
        QVERIFY(QTest::qWaitForWindowExposed(m_window.get()));
        QString error;
        QVERIFY2(m_window->document()->load(kStack, &error), qPrintable(error));
        Result<World> world = World::create(m_window->document()->scene());
        QVERIFY(world);
        Bake bake = startBake(*world);
        bake.setSceneObjText(m_window->document()->scene().sourceObjText);
        BakeRequest request;
        request.frames = 60;
        QVERIFY(bakeRun(*world, bake, request));
        m_bake = std::make_shared<const Bake>(std::move(bake));
        m_window->analysis()->setBakeSource([this] { return m_bake; });
    }

    void cleanupTestCase() { m_window.reset(); }

    void exportMatchesCli_data() {
        QTest::addColumn<QString>("action");
        QTest::addColumn<QString>("fileName");
        QTest::newRow("csv") << "ExportCsvAction"
                             << "ui.csv";
        QTest::newRow("bake") << "ExportBakeAction"
                              << "ui.bake";
    }
    void exportMatchesCli() {
        QFETCH(QString, action);
        QFETCH(QString, fileName);
        const QString problem = exportAndCompare(*m_window, action, m_dir.filePath(fileName),
                                                 fileName.endsWith(".csv") ? m_cliCsv : m_cliBake);
        QVERIFY2(problem.isEmpty(), qPrintable(problem));
    }

    // The whole path a user takes: open the scene, bake 1 s with the editor's own bake (Simulation > Bake on its
    // worker thread), export; the files equal the CLI's byte for byte.
    void editorBakeExportsWhatTheCliWrites_data() { exportMatchesCli_data(); }
    void editorBakeExportsWhatTheCliWrites() {
        QFETCH(QString, action);
        QFETCH(QString, fileName);
        MainWindow window;
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        QString error;
        QVERIFY2(window.document()->load(kStack, &error), qPrintable(error));
        SimulationController* sim = window.simulation();
        QSignalSpy finished(sim, &SimulationController::bakeFinished);
        QVERIFY(sim->startBake(60));
        QVERIFY(finished.wait(120000) || finished.count() == 1);
        QVERIFY(sim->currentBake());
        QCOMPARE(static_cast<int>(sim->currentBake()->frameCount()), 61);
        const QString problem = exportAndCompare(window, action, m_dir.filePath(QStringLiteral("editor_") + fileName),
                                                 fileName.endsWith(".csv") ? m_cliCsv : m_cliBake);
        QVERIFY2(problem.isEmpty(), qPrintable(problem));
    }

    void selectionAndRange_data() {
        QTest::addColumn<QList<int>>("selection");
        QTest::addColumn<int>("first");
        QTest::addColumn<int>("last");
        QTest::newRow("two bodies, frames 10-20") << QList<int>{1, 3} << 10 << 20;
        QTest::newRow("all bodies, last frame") << QList<int>{} << 60 << 60;
        QTest::newRow("one body, every frame") << QList<int>{10} << -1 << -1;
    }
    void selectionAndRange() {
        QFETCH(QList<int>, selection);
        QFETCH(int, first);
        QFETCH(int, last);
        m_window->setSelectedBodies(selection);
        const QString out =
            m_dir.filePath(QStringLiteral("sel_%1_%2_%3.csv").arg(selection.size()).arg(first).arg(last));
        onModal("ExportDialog",
                [&](QWidget* dialog) { fillExportDialog(dialog, out, !selection.isEmpty(), first, last); });
        QVERIFY(m_window->analysis()->exportCurrentBake(ExportRequest::Format::Csv));
        // Expected: the CLI's full CSV filtered to those frames and bodies (frame-major, bodies in ascending order).
        const QList<QByteArray> cliLines = readAll(m_cliCsv).split('\n');
        QByteArray expected = cliLines[0] + '\n';
        for (const QByteArray& line : cliLines.mid(1)) {
            if (line.isEmpty())
                continue;
            const QList<QByteArray> fields = line.split(',');
            const int frame = fields[0].toInt(), body = fields[2].toInt();
            if ((first < 0 || (frame >= first && frame <= last)) && (selection.isEmpty() || selection.contains(body)))
                expected += line + '\n';
        }
        const QByteArray ui = readAll(out);
        QCOMPARE(ui.count('\n'), expected.count('\n'));
        QVERIFY(ui == expected);
        m_window->setSelectedBodies({});
    }

    void cancelledExportLeavesTargetAlone_data() {
        QTest::addColumn<int>("format");
        QTest::newRow("csv") << static_cast<int>(ExportRequest::Format::Csv);
        QTest::newRow("bake") << static_cast<int>(ExportRequest::Format::Bake);
    }
    void cancelledExportLeavesTargetAlone() {
        QFETCH(int, format);
        QTemporaryDir dir;
        const QString target = dir.filePath("target");
        {
            QFile f(target);
            QVERIFY(f.open(QIODevice::WriteOnly));
            f.write("previous content\n");
        }
        ExportRequest request;
        request.format = static_cast<ExportRequest::Format>(format);
        request.path = target;
        size_t calls = 0, lastTotal = 0;
        // Cancel halfway through.
        const Status s = runExport(*m_bake, request, [&](size_t done, size_t total) {
            ++calls;
            lastTotal = total;
            return done * 2 < total;
        });
        QVERIFY(!s);
        QCOMPARE(QString::fromStdString(s.error().message), QString("export cancelled"));
        QVERIFY(calls > 1);
        QVERIFY(lastTotal > 0);
        QCOMPARE(readAll(target), QByteArray("previous content\n"));
        QCOMPARE(QDir(dir.path()).entryList(QDir::Files | QDir::Hidden), QStringList{"target"}); // no temporary left
        // Without cancelling, progress reaches the total.
        size_t finalDone = 0, finalTotal = 0;
        QVERIFY(runExport(*m_bake, request, [&](size_t done, size_t total) {
            finalDone = done;
            finalTotal = total;
            return true;
        }));
        QCOMPARE(finalDone, finalTotal);
    }

    void cancelFromTheProgressDialog() {
        // The progress dialog of a large bake (600 bodies x 2,000 frames, 1.2 million CSV rows) comes up; its Cancel
        // stops the worker and nothing is written. The dialog is told to show at once: with the default delay of
        // 400 ms, a fast machine wrote the file before it showed (4 failures in 5 runs on 2026-11-25).
        std::vector<BakeBodyInfo> bodies(600);
        for (size_t b = 0; b < bodies.size(); ++b)
            bodies[b].name = "Box." + std::to_string(b);
        auto big = std::make_shared<Bake>(bodies, 60.0);
        big->reserveFrames(2000);
        for (size_t f = 0; f < 2000; ++f) {
            big->addFrame();
            for (size_t b = 0; b < bodies.size(); ++b)
                big->setState(f, b, {{0.001f * f, 0.5f + 0.01f * b, 0.0f}, glm::quat(1, 0, 0, 0), {0.06f, 0, 0}, {}});
        }
        QTemporaryDir dir;
        ExportRequest request;
        request.path = dir.filePath("big.csv");
        bool sawDialog = false;
        onModal("ExportProgress", [&sawDialog](QWidget* dialog) {
            sawDialog = true;
            if (const QString shots = qEnvironmentVariable("RL_SCREENSHOT_DIR"); !shots.isEmpty())
                dialog->grab().save(shots + "/export_progress.png");
            dialog->findChild<QPushButton*>()->click();
        });
        QString error = "unset";
        m_window->analysis()->setExportProgressDelay(0);
        const bool exported = m_window->analysis()->exportBake(big, request, &error);
        m_window->analysis()->setExportProgressDelay(400);
        QVERIFY(!exported);
        QVERIFY(sawDialog);
        QVERIFY(error.isEmpty()); // a cancel is not an error to show
        QCOMPARE(QDir(dir.path()).entryList(QDir::Files | QDir::Hidden), QStringList{});
    }

    void failedExportReportsThePath() {
        ExportRequest request;
        request.path = m_dir.filePath("no/such/dir/out.csv");
        QString error;
        QVERIFY(!m_window->analysis()->exportBake(m_bake, request, &error));
        QVERIFY2(error.contains("no/such/dir/out.csv"), qPrintable(error));
    }

    void actionsNeedABake() {
        m_window->analysis()->setBakeSource([] { return std::shared_ptr<const Bake>(); });
        QVERIFY(!m_window->findChild<QAction*>("ExportCsvAction")->isEnabled());
        QVERIFY(!m_window->findChild<QAction*>("ExportBakeAction")->isEnabled());
        m_window->analysis()->setBakeSource([this] { return m_bake; });
        QVERIFY(m_window->findChild<QAction*>("ExportCsvAction")->isEnabled());
    }
};

QTEST_MAIN(TestExport)
#include "tst_export.moc"
