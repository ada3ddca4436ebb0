// The accuracy study: fitted convergence orders per integrator and problem, errors shrinking with the step, the fit
// itself on synthetic data, and the CSV and SVG outputs (well-formed, complete, numbers that read back exactly).
#include "analysis/Accuracy.h"

#include <QFileInfo>
#include <QTemporaryDir>
#include <QTest>
#include <QXmlStreamReader>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <map>
#include <sstream>

using namespace rl;

Q_DECLARE_METATYPE(rl::Integrator)

namespace {

const AccuracyReport& report() {
    static const AccuracyReport study = runAccuracyStudy();
    return study;
}

const AccuracyOrder* findOrder(const std::string& problem, Integrator integrator) {
    for (const AccuracyOrder& order : report().orders)
        if (order.problem == problem && order.integrator == integrator)
            return &order;
    return nullptr;
}

std::vector<AccuracyRow> rowsOf(const std::string& problem, Integrator integrator) {
    std::vector<AccuracyRow> rows;
    for (const AccuracyRow& row : report().rows)
        if (row.problem == problem && row.integrator == integrator)
            rows.push_back(row);
    std::sort(rows.begin(), rows.end(),
              [](const AccuracyRow& a, const AccuracyRow& b) { return a.dt / a.substeps > b.dt / b.substeps; });
    return rows;
}

constexpr Real kExact = -1.0; // in the tables below: the integrator is exact on the problem (fit returns NaN)

} // namespace

class TestAccuracy : public QObject {
    Q_OBJECT

private slots:
    void initTestCase();
    void fittedOrders_data();
    void fittedOrders();
    void originalExperimentRows();
    void errorsDecreaseWithStep_data();
    void errorsDecreaseWithStep();
    void eventLocationBeatsPerStepContacts();
    void fitOnSyntheticData();
    void csvReadsBack();
    void svgIsWellFormed();
    void writersReportBadPaths();
};

void TestAccuracy::initTestCase() {
    QVERIFY(!report().rows.empty());
    for (const AccuracyRow& row : report().rows) {
        QVERIFY(std::isfinite(row.error) && row.error >= 0.0);
        QVERIFY(row.cpuSeconds > 0.0);
    }
    // Printed so that a run of the test shows the measured table (the figures are never asserted).
    qInfo("%s", formatAccuracyTable(report()).c_str());
}

void TestAccuracy::fittedOrders_data() {
    QTest::addColumn<QString>("problem");
    QTest::addColumn<Integrator>("integrator");
    QTest::addColumn<Real>("order");
    auto add = [](const char* problem, Real explicitEuler, Real symplecticEuler, Real verlet, Real rk4) {
        const std::pair<Integrator, Real> expected[] = {{Integrator::ExplicitEuler, explicitEuler},
                                                        {Integrator::SymplecticEuler, symplecticEuler},
                                                        {Integrator::Verlet, verlet},
                                                        {Integrator::Rk4, rk4}};
        for (const auto& [integrator, order] : expected)
            QTest::newRow((std::string(problem) + " " + std::string(integratorName(integrator))).c_str())
                << QString(problem) << integrator << order;
    };
    // The expectation on the original experiment: 1, 1, 2, 4.
    add("oscillator", 1.0, 1.0, 2.0, 4.0);
    // Free flight: Verlet and RK4 integrate constant gravity exactly; with drag the orders show.
    add("projectile", 1.0, 1.0, kExact, kExact);
    add("projectile-drag", 1.0, 1.0, 2.0, 4.0);
    add("tumbling-orientation", 1.0, 1.0, 2.0, 4.0);
    // Implicit midpoint keeps |L| and energy exactly (Gyroscopic.h).
    add("tumbling-momentum", 1.0, kExact, 2.0, 4.0);
    // A contact impulse between the phases makes every scheme first order (Integrator.h).
    add("incline", 1.0, 1.0, 1.0, 1.0);
    add("bounce-per-step", 1.0, 1.0, 1.0, 1.0);
    add("bounce-exact", 1.0, 1.0, kExact, kExact);
}

void TestAccuracy::fittedOrders() {
    QFETCH(QString, problem);
    QFETCH(Integrator, integrator);
    QFETCH(Real, order);
    const AccuracyOrder* fitted = findOrder(problem.toStdString(), integrator);
    QVERIFY(fitted);
    if (order == kExact) {
        QVERIFY2(std::isnan(fitted->order), qPrintable(QString::number(fitted->order)));
        for (const AccuracyRow& row : rowsOf(problem.toStdString(), integrator))
            QVERIFY(row.error < 1e-11);
        return;
    }
    QVERIFY2(fitted->points >= 2, "too few rows in the asymptotic range");
    QVERIFY2(std::abs(fitted->order - order) <= 0.15, qPrintable(QString::number(fitted->order)));
}

void TestAccuracy::originalExperimentRows() {
    // The original project's experiment: sin t over [0, 2 pi] with 10, 20 and 40 steps, for every integrator.
    for (Integrator integrator :
         {Integrator::ExplicitEuler, Integrator::SymplecticEuler, Integrator::Verlet, Integrator::Rk4}) {
        const auto rows = rowsOf("oscillator", integrator);
        for (int steps : {10, 20, 40}) {
            const auto it =
                std::find_if(rows.begin(), rows.end(), [&](const AccuracyRow& r) { return r.steps == steps; });
            QVERIFY(it != rows.end());
            QVERIFY(std::abs(it->dt - 2.0 * kPi / steps) < 1e-15);
            QCOMPARE(it->substeps, 1);
        }
    }
    // At every step count the ranking is the textbook one: RK4 < Verlet < symplectic Euler < explicit Euler.
    const auto e = rowsOf("oscillator", Integrator::ExplicitEuler),
               s = rowsOf("oscillator", Integrator::SymplecticEuler), v = rowsOf("oscillator", Integrator::Verlet),
               r = rowsOf("oscillator", Integrator::Rk4);
    QCOMPARE(e.size(), r.size());
    for (size_t i = 0; i < e.size(); ++i) {
        QVERIFY(r[i].error < v[i].error);
        QVERIFY(v[i].error < s[i].error);
        QVERIFY(s[i].error < e[i].error);
    }
}

void TestAccuracy::errorsDecreaseWithStep_data() {
    QTest::addColumn<QString>("problem");
    for (const std::string& problem : report().problems)
        QTest::newRow(problem.c_str()) << QString::fromStdString(problem);
}

void TestAccuracy::errorsDecreaseWithStep() {
    // Halving the step must reduce the error wherever the error is above rounding (by a factor of at least 1.5: every
    // scheme here is at least first order).
    QFETCH(QString, problem);
    for (Integrator integrator :
         {Integrator::ExplicitEuler, Integrator::SymplecticEuler, Integrator::Verlet, Integrator::Rk4}) {
        const auto rows = rowsOf(problem.toStdString(), integrator);
        QVERIFY(rows.size() >= 6);
        for (size_t i = 1; i < rows.size(); ++i) {
            if (rows[i].error < 1e-11)
                continue;
            QVERIFY2(rows[i].error * 1.5 < rows[i - 1].error,
                     qPrintable(QString("%1 row %2: %3 after %4")
                                    .arg(QString::fromUtf8(integratorName(integrator).data()))
                                    .arg(i)
                                    .arg(rows[i].error)
                                    .arg(rows[i - 1].error)));
        }
    }
}

void TestAccuracy::eventLocationBeatsPerStepContacts() {
    // Locating the impact inside the substep removes the contact's own first-order error: for the schemes that are
    // exact in free flight the apexes become exact; for the others the error is no larger than with per-step contacts
    // at the coarsest substep count.
    for (Integrator integrator : {Integrator::Verlet, Integrator::Rk4}) {
        const auto exact = rowsOf("bounce-exact", integrator), perStep = rowsOf("bounce-per-step", integrator);
        for (size_t i = 0; i < exact.size(); ++i)
            QVERIFY(exact[i].error < 1e-3 * perStep[i].error);
    }
}

void TestAccuracy::fitOnSyntheticData() {
    // e = 3 h^2.5 exactly: the slope is 2.5. Points outside (floor, ceiling) must be ignored.
    std::vector<Real> steps, errors;
    for (Real h = 0.5; h > 1e-3; h *= 0.5) {
        steps.push_back(h);
        errors.push_back(3.0 * std::pow(h, 2.5));
    }
    steps.push_back(1e-4);
    errors.push_back(1e-20); // "rounding"
    steps.push_back(2.0);
    errors.push_back(50.0); // "pre-asymptotic"
    int points = 0;
    const Real order = fitConvergenceOrder(steps, errors, 1e-11, 1.0, &points);
    QVERIFY(std::abs(order - 2.5) < 1e-12);
    QCOMPARE(points, 9);
    QVERIFY(std::abs(fitConvergenceOrder(steps, errors, 1e-11, 1e-3, &points) - 2.5) < 1e-12);
    QCOMPARE(points, 5);
    QVERIFY(std::isnan(fitConvergenceOrder(std::vector<Real>{0.1}, std::vector<Real>{0.01}, 1e-11, 1.0, &points)));
    QCOMPARE(points, 1);
    QVERIFY(std::isnan(fitConvergenceOrder(std::vector<Real>{0.1, 0.1}, std::vector<Real>{0.01, 0.02}, 1e-11, 1.0)));
}

void TestAccuracy::csvReadsBack() {
    const std::string csv = accuracyCsv(report());
    std::istringstream in(csv);
    std::string line;
    std::getline(in, line);
    QCOMPARE(QString::fromStdString(line), QString("problem,integrator,steps,dt,substeps,step,error,cpu_seconds"));
    size_t index = 0;
    while (std::getline(in, line)) {
        QVERIFY(index < report().rows.size());
        const AccuracyRow& row = report().rows[index++];
        std::vector<std::string> fields;
        std::istringstream cells(line);
        for (std::string cell; std::getline(cells, cell, ',');)
            fields.push_back(cell);
        QCOMPARE(fields.size(), size_t(8));
        QCOMPARE(fields[0], row.problem);
        QCOMPARE(fields[1], std::string(integratorName(row.integrator)));
        auto parse = [](const std::string& text) {
            Real value = std::nan("");
            std::from_chars(text.data(), text.data() + text.size(), value);
            return value;
        };
        QCOMPARE(parse(fields[3]), row.dt); // exact: numbers are written to round-trip
        QCOMPARE(parse(fields[6]), row.error);
        QCOMPARE(parse(fields[7]), row.cpuSeconds);
    }
    QCOMPARE(index, report().rows.size());
}

void TestAccuracy::svgIsWellFormed() {
    const std::string svg = accuracySvg(report());
    QXmlStreamReader xml(QByteArray::fromStdString(svg));
    int panels = 0, curves = 0, paretos = 0, circles = 0;
    bool sawRoot = false;
    QStringList texts;
    std::map<QString, int> curvePoints; // integrator -> points over all panels
    while (!xml.atEnd()) {
        xml.readNext();
        if (!xml.isStartElement())
            continue;
        const auto name = xml.name();
        const auto attributes = xml.attributes();
        if (name == QLatin1String("svg")) {
            sawRoot = true;
            QCOMPARE(xml.namespaceUri().toString(), QString("http://www.w3.org/2000/svg"));
        } else if (name == QLatin1String("g") && attributes.value("class") == QLatin1String("panel")) {
            ++panels;
        } else if (name == QLatin1String("polyline")) {
            const QString points = attributes.value("points").toString().trimmed();
            const QStringList pairs = points.split(' ', Qt::SkipEmptyParts);
            for (const QString& pair : pairs) {
                const QStringList xy = pair.split(',');
                QCOMPARE(xy.size(), 2);
                bool okX = false, okY = false;
                const double x = xy[0].toDouble(&okX), y = xy[1].toDouble(&okY);
                QVERIFY(okX && okY && std::isfinite(x) && std::isfinite(y));
                QVERIFY(x >= 0.0 && x <= 1200.0 && y >= 0.0 && y <= 1000.0); // inside the canvas
            }
            if (attributes.value("class") == QLatin1String("curve")) {
                ++curves;
                curvePoints[attributes.value("data-integrator").toString()] += static_cast<int>(pairs.size());
            } else if (attributes.value("class") == QLatin1String("pareto")) {
                ++paretos;
                QVERIFY(!pairs.isEmpty());
            }
        } else if (name == QLatin1String("circle")) {
            ++circles;
        } else if (name == QLatin1String("text")) {
            texts << xml.readElementText();
        }
    }
    QVERIFY2(!xml.hasError(), qPrintable(xml.errorString()));
    QVERIFY(sawRoot);
    const int problems = static_cast<int>(report().problems.size());
    QCOMPARE(panels, problems);
    QCOMPARE(curves, 4 * problems);
    QCOMPARE(paretos, problems);
    QCOMPARE(circles, static_cast<int>(report().rows.size()));
    // Every row is a vertex of its integrator's curve.
    int total = 0;
    for (const auto& [integrator, count] : curvePoints)
        total += count;
    QCOMPARE(total, static_cast<int>(report().rows.size()));
    for (const char* integrator : {"explicit-euler", "symplectic-euler", "verlet", "rk4"}) {
        QVERIFY(texts.contains(integrator)); // legend
        QVERIFY(curvePoints[integrator] > 0);
    }
    for (const std::string& problem : report().problems)
        QVERIFY(texts.contains(QString::fromStdString(problem))); // panel titles
    QVERIFY(texts.contains("1e-3") || texts.contains("1e-4"));    // decade tick labels
}

void TestAccuracy::writersReportBadPaths() {
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const std::string svgPath = dir.filePath("accuracy.svg").toStdString();
    const std::string csvPath = dir.filePath("accuracy.csv").toStdString();
    QVERIFY(writeAccuracySvg(report(), svgPath).ok());
    QVERIFY(writeAccuracyCsv(report(), csvPath).ok());
    QVERIFY(QFileInfo(QString::fromStdString(svgPath)).size() > 1000);
    const std::string missing = dir.filePath("no/such/dir/accuracy.csv").toStdString();
    const Status failed = writeAccuracyCsv(report(), missing);
    QVERIFY(!failed.ok());
    QVERIFY(!failed.error().toString().empty());
}

QTEST_APPLESS_MAIN(TestAccuracy)
#include "tst_accuracy.moc"
