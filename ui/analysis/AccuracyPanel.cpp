#include "analysis/AccuracyPanel.h"

#include "analysis/Background.h"

#include <QChart>
#include <QChartView>
#include <QCheckBox>
#include <QComboBox>
#include <QDialogButtonBox>
#include <QDoubleSpinBox>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLegendMarker>
#include <QLineSeries>
#include <QLogValueAxis>
#include <QProgressBar>
#include <QPushButton>
#include <QSplitter>
#include <QStandardItemModel>
#include <QTabWidget>
#include <QTableView>
#include <QTimer>
#include <QVBoxLayout>

#include <cmath>
#include <map>
#include <optional>

namespace rl {

namespace {

constexpr Integrator kIntegrators[] = {Integrator::ExplicitEuler, Integrator::SymplecticEuler, Integrator::Verlet,
                                       Integrator::Rk4};

QString integratorLabel(Integrator integrator) {
    const std::string_view name = integratorName(integrator);
    return QString::fromUtf8(name.data(), static_cast<int>(name.size()));
}

// One colour per integrator in every chart of the panel.
QColor integratorColor(Integrator integrator) {
    switch (integrator) {
    case Integrator::ExplicitEuler:
        return QColor(0xd6, 0x27, 0x28);
    case Integrator::SymplecticEuler:
        return QColor(0x1f, 0x77, 0xb4);
    case Integrator::Verlet:
        return QColor(0x2c, 0xa0, 0x2c);
    case Integrator::Rk4:
        return QColor(0x94, 0x67, 0xbd);
    }
    return Qt::black;
}

// A table cell showing `text` that sorts by `value`.
QStandardItem* cell(const QString& text, double value) {
    auto* item = new QStandardItem(text);
    item->setData(value, Qt::UserRole);
    item->setTextAlignment(Qt::AlignRight | Qt::AlignVCenter);
    item->setEditable(false);
    return item;
}

QStandardItem* textCell(const QString& text) {
    auto* item = new QStandardItem(text);
    item->setData(text, Qt::UserRole);
    item->setEditable(false);
    return item;
}

QString sci(double v) {
    if (std::isinf(v))
        return QObject::tr("diverged");
    return QString::number(v, 'g', 3);
}

// Replaces the chart's content with one polyline per integrator, on log axes spanning whole decades around the data.
// Points that a log axis cannot show (zero, infinite) are left out.
void fillLogLogChart(QChart* chart, const std::map<Integrator, QList<QPointF>>& data, const QString& xTitle,
                     const QString& yTitle) {
    chart->removeAllSeries();
    for (QAbstractAxis* axis : chart->axes())
        chart->removeAxis(axis);
    double xMin = INFINITY, xMax = 0.0, yMin = INFINITY, yMax = 0.0;
    for (const auto& [integrator, points] : data)
        for (const QPointF& p : points) {
            xMin = std::min(xMin, p.x());
            xMax = std::max(xMax, p.x());
            yMin = std::min(yMin, p.y());
            yMax = std::max(yMax, p.y());
        }
    auto* xAxis = new QLogValueAxis(chart);
    auto* yAxis = new QLogValueAxis(chart);
    xAxis->setTitleText(xTitle);
    yAxis->setTitleText(yTitle);
    for (QLogValueAxis* axis : {xAxis, yAxis}) {
        axis->setBase(10.0);
        axis->setLabelFormat("%g");
        axis->setMinorTickCount(8);
        axis->setMinorGridLineVisible(true);
        QPen minor = axis->minorGridLinePen();
        minor.setColor(QColor(0, 0, 0, 20));
        axis->setMinorGridLinePen(minor);
    }
    if (xMax > 0.0 && yMax > 0.0) {
        xAxis->setRange(std::pow(10.0, std::floor(std::log10(xMin))), std::pow(10.0, std::ceil(std::log10(xMax))));
        const double lo = std::floor(std::log10(yMin)), hi = std::ceil(std::log10(yMax));
        yAxis->setRange(std::pow(10.0, lo), std::pow(10.0, std::max(hi, lo + 1.0)));
    }
    chart->addAxis(xAxis, Qt::AlignBottom);
    chart->addAxis(yAxis, Qt::AlignLeft);
    for (const auto& [integrator, points] : data) {
        auto* series = new QLineSeries(chart);
        series->setName(integratorLabel(integrator));
        series->setPointsVisible(true);
        QPen pen(integratorColor(integrator));
        pen.setWidthF(2.0);
        series->setPen(pen);
        series->append(points);
        chart->addSeries(series);
        series->attachAxis(xAxis);
        series->attachAxis(yAxis);
    }
}

QChartView* makeChartView(QChart* chart, QWidget* parent) {
    chart->legend()->setAlignment(Qt::AlignBottom);
    chart->setMargins(QMargins(4, 4, 4, 4));
    auto* view = new QChartView(chart, parent);
    view->setRenderHint(QPainter::Antialiasing);
    view->setMinimumSize(420, 320);
    return view;
}

QTableView* makeTableView(QStandardItemModel* model, QWidget* parent) {
    auto* view = new QTableView(parent);
    model->setSortRole(Qt::UserRole);
    view->setModel(model);
    view->setSortingEnabled(true);
    view->setAlternatingRowColors(true);
    view->setSelectionBehavior(QAbstractItemView::SelectRows);
    view->verticalHeader()->hide();
    view->verticalHeader()->setDefaultSectionSize(view->fontMetrics().lineSpacing() + 6);
    // The numbers share the width the splitter leaves; the integrator's name keeps its own.
    view->horizontalHeader()->setSectionResizeMode(QHeaderView::Stretch);
    view->horizontalHeader()->setSectionResizeMode(0, QHeaderView::Interactive); // sized after each fill
    view->horizontalHeader()->setMinimumSectionSize(56);
    return view;
}

} // namespace

struct AccuracyPanel::SceneJob {
    std::atomic<size_t> done{0};
    std::atomic<size_t> total{0};
    std::atomic<bool> cancel{false};
    SceneAccuracyOptions options;
    std::optional<Result<SceneAccuracyResult>> result;
};

AccuracyPanel::AccuracyPanel(std::function<Scene()> sceneSource, QWidget* parent)
    : QDialog(parent), m_sceneSource(std::move(sceneSource)) {
    setObjectName("AccuracyPanel");
    setWindowTitle(tr("Accuracy"));
    auto* layout = new QVBoxLayout(this);
    m_tabs = new QTabWidget(this);
    m_tabs->setObjectName("AccuracyTabs");
    m_tabs->addTab(createStudyTab(), tr("Integrators on exact solutions"));
    m_tabs->addTab(createSceneTab(), tr("This scene"));
    layout->addWidget(m_tabs);
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Close, this);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    layout->addWidget(buttons);
    resize(1180, 640);
}

AccuracyPanel::~AccuracyPanel() {
    if (m_sceneState)
        m_sceneState->cancel = true;
}

QWidget* AccuracyPanel::createStudyTab() {
    auto* tab = new QWidget(this);
    auto* layout = new QVBoxLayout(tab);
    auto* row = new QHBoxLayout;
    m_problem = new QComboBox(tab);
    m_problem->setObjectName("AccuracyProblem");
    m_problem->setEnabled(false);
    m_problem->setMinimumContentsLength(22);
    m_runStudy = new QPushButton(tr("&Run study"), tab);
    m_runStudy->setObjectName("AccuracyRunStudy");
    m_studyProgress = new QProgressBar(tab);
    m_studyProgress->setRange(0, 0); // the study reports no progress: busy indicator
    m_studyProgress->setMaximumWidth(160);
    m_studyProgress->hide();
    m_studyStatus = new QLabel(tr("Every integrator on problems with exact answers, at several step sizes."), tab);
    m_studyStatus->setObjectName("AccuracyStudyStatus");
    row->addWidget(new QLabel(tr("Problem:"), tab));
    row->addWidget(m_problem);
    row->addWidget(m_runStudy);
    row->addWidget(m_studyProgress);
    row->addWidget(m_studyStatus, 1);
    layout->addLayout(row);

    auto* splitter = new QSplitter(tab);
    m_studyChart = new QChart;
    m_studyChart->setTitle(tr("Error against CPU time"));
    m_studyView = makeChartView(m_studyChart, splitter);
    m_studyView->setObjectName("AccuracyStudyChart");
    m_studyModel = new QStandardItemModel(0, 6, this);
    m_studyModel->setHorizontalHeaderLabels(
        {tr("Integrator"), tr("Steps"), tr("Substeps"), tr("Step (s)"), tr("Error"), tr("CPU (µs)")});
    m_studyTableView = makeTableView(m_studyModel, splitter);
    m_studyTableView->setObjectName("AccuracyStudyTable");
    splitter->addWidget(m_studyView);
    splitter->addWidget(m_studyTableView);
    splitter->setStretchFactor(0, 3);
    splitter->setStretchFactor(1, 2);
    splitter->setSizes({680, 470});
    layout->addWidget(splitter, 1);

    connect(m_runStudy, &QPushButton::clicked, this, &AccuracyPanel::runStudy);
    connect(m_problem, &QComboBox::currentIndexChanged, this, &AccuracyPanel::showProblem);
    return tab;
}

QWidget* AccuracyPanel::createSceneTab() {
    auto* tab = new QWidget(this);
    auto* layout = new QVBoxLayout(tab);
    auto* settings = new QGroupBox(tr("Settings to compare"), tab);
    auto* grid = new QHBoxLayout(settings);
    m_duration = new QDoubleSpinBox(settings);
    m_duration->setObjectName("AccuracySceneDuration");
    m_duration->setRange(0.1, 10.0);
    m_duration->setSingleStep(0.5);
    m_duration->setValue(2.0);
    m_duration->setSuffix(tr(" s"));
    grid->addWidget(new QLabel(tr("Duration:"), settings));
    grid->addWidget(m_duration);
    grid->addSpacing(12);
    grid->addWidget(new QLabel(tr("Substeps:"), settings));
    for (int substeps : {1, 2, 4, 8, 16}) {
        auto* box = new QCheckBox(QString::number(substeps), settings);
        box->setObjectName(QStringLiteral("AccuracySubsteps%1").arg(substeps));
        box->setChecked(true);
        box->setProperty("substeps", substeps);
        m_substepBoxes.append(box);
        grid->addWidget(box);
    }
    grid->addSpacing(12);
    grid->addWidget(new QLabel(tr("Integrators:"), settings));
    for (Integrator integrator : kIntegrators) {
        auto* box = new QCheckBox(integratorLabel(integrator), settings);
        box->setObjectName(QStringLiteral("AccuracyIntegrator_") + integratorLabel(integrator));
        box->setChecked(true);
        box->setProperty("integrator", static_cast<int>(integrator));
        m_integratorBoxes.append(box);
        grid->addWidget(box);
    }
    grid->addStretch(1);
    layout->addWidget(settings);

    auto* row = new QHBoxLayout;
    m_runScene = new QPushButton(tr("&Compare"), tab);
    m_runScene->setObjectName("AccuracyRunScene");
    m_cancelScene = new QPushButton(tr("Cancel"), tab);
    m_cancelScene->setObjectName("AccuracyCancelScene");
    m_cancelScene->setEnabled(false);
    m_sceneProgress = new QProgressBar(tab);
    m_sceneProgress->setObjectName("AccuracySceneProgress");
    m_sceneProgress->setMaximumWidth(220);
    m_sceneProgress->setValue(0);
    m_sceneStatus = new QLabel(tr("Bakes the scene under each setting and compares it with a reference bake at RK4 and "
                                  "64 substeps: position error (RMS over bodies and frames) against CPU time."),
                               tab);
    m_sceneStatus->setObjectName("AccuracySceneStatus");
    m_sceneStatus->setWordWrap(true);
    row->addWidget(m_runScene);
    row->addWidget(m_cancelScene);
    row->addWidget(m_sceneProgress);
    row->addWidget(m_sceneStatus, 1);
    layout->addLayout(row);

    auto* splitter = new QSplitter(tab);
    m_sceneChart = new QChart;
    m_sceneChart->setTitle(tr("Position error against CPU time"));
    m_sceneView = makeChartView(m_sceneChart, splitter);
    m_sceneView->setObjectName("AccuracySceneChart");
    m_sceneModel = new QStandardItemModel(0, 5, this);
    m_sceneModel->setHorizontalHeaderLabels(
        {tr("Integrator"), tr("Substeps"), tr("RMS error (m)"), tr("Max error (m)"), tr("CPU (ms)")});
    m_sceneTableView = makeTableView(m_sceneModel, splitter);
    m_sceneTableView->setObjectName("AccuracySceneTable");
    splitter->addWidget(m_sceneView);
    splitter->addWidget(m_sceneTableView);
    splitter->setStretchFactor(0, 3);
    splitter->setStretchFactor(1, 2);
    splitter->setSizes({680, 470});
    layout->addWidget(splitter, 1);

    connect(m_runScene, &QPushButton::clicked, this, &AccuracyPanel::runSceneComparison);
    connect(m_cancelScene, &QPushButton::clicked, this, &AccuracyPanel::cancelSceneComparison);
    return tab;
}

void AccuracyPanel::runStudy() {
    if (m_studyRunning)
        return;
    m_studyRunning = true;
    m_runStudy->setEnabled(false);
    m_studyProgress->show();
    m_studyStatus->setText(tr("Running the study (each row is timed several times)…"));
    auto report = std::make_shared<AccuracyReport>();
    runInBackground(
        this, [report] { *report = runAccuracyStudy(); },
        [this, report] {
            m_report = report;
            m_studyRunning = false;
            m_runStudy->setEnabled(true);
            m_studyProgress->hide();
            const QString previous = m_problem->currentText();
            m_problem->blockSignals(true);
            m_problem->clear();
            for (const std::string& problem : report->problems)
                m_problem->addItem(QString::fromStdString(problem));
            const int keep = m_problem->findText(previous);
            m_problem->setCurrentIndex(keep >= 0 ? keep : 0);
            m_problem->blockSignals(false);
            m_problem->setEnabled(true);
            m_studyStatus->setText(tr("%n rows. Points with zero error (exact up to rounding) are not drawn.", "",
                                      static_cast<int>(report->rows.size())));
            showProblem();
            emit studyFinished();
        });
}

void AccuracyPanel::showProblem() {
    if (!m_report)
        return;
    const std::string problem = m_problem->currentText().toStdString();
    std::map<Integrator, QList<QPointF>> data;
    m_studyModel->removeRows(0, m_studyModel->rowCount());
    for (const AccuracyRow& row : m_report->rows) {
        if (row.problem != problem)
            continue;
        const double us = row.cpuSeconds * 1e6;
        if (row.error > 0.0 && std::isfinite(row.error))
            data[row.integrator].append(QPointF(us, row.error));
        m_studyModel->appendRow({textCell(integratorLabel(row.integrator)), cell(QString::number(row.steps), row.steps),
                                 cell(QString::number(row.substeps), row.substeps),
                                 cell(sci(row.dt / row.substeps), row.dt / row.substeps),
                                 cell(sci(row.error), row.error), cell(QString::number(us, 'f', 2), us)});
    }
    for (auto& [integrator, points] : data)
        std::sort(points.begin(), points.end(), [](const QPointF& a, const QPointF& b) { return a.x() < b.x(); });
    m_studyTableView->resizeColumnToContents(0);
    fillLogLogChart(m_studyChart, data, tr("CPU time per run (µs)"), tr("Error"));
    m_studyChart->setTitle(tr("%1: error against CPU time").arg(m_problem->currentText()));
}

void AccuracyPanel::runSceneComparison() {
    if (m_sceneState)
        return;
    auto job = std::make_shared<SceneJob>();
    job->options.seconds = m_duration->value();
    job->options.settings.clear();
    for (QCheckBox* integratorBox : m_integratorBoxes) {
        if (!integratorBox->isChecked())
            continue;
        for (QCheckBox* substepBox : m_substepBoxes)
            if (substepBox->isChecked())
                job->options.settings.push_back({static_cast<Integrator>(integratorBox->property("integrator").toInt()),
                                                 substepBox->property("substeps").toInt()});
    }
    if (job->options.settings.empty()) {
        m_sceneStatus->setText(tr("Tick at least one substep count and one integrator."));
        emit sceneComparisonFinished(false);
        return;
    }
    SceneJob* raw = job.get();
    job->options.progress = [raw](size_t done, size_t total) {
        raw->done = done;
        raw->total = total;
        return !raw->cancel.load();
    };
    m_sceneState = job;
    m_runScene->setEnabled(false);
    m_cancelScene->setEnabled(true);
    m_sceneProgress->setRange(0, 1000);
    m_sceneProgress->setValue(0);
    m_sceneStatus->setText(
        tr("Baking %n setting(s) and the reference…", "", static_cast<int>(job->options.settings.size())));
    auto* timer = new QTimer(this);
    timer->setInterval(100);
    connect(timer, &QTimer::timeout, this, [this, job] {
        const size_t total = job->total;
        if (total > 0)
            m_sceneProgress->setValue(static_cast<int>(1000.0 * static_cast<double>(job->done) / total));
    });
    timer->start();
    runInBackground(
        this,
        [job, scene = m_sceneSource ? m_sceneSource() : Scene{}] {
            job->result = runSceneAccuracy(scene, job->options);
        },
        [this, job, timer] {
            timer->deleteLater();
            m_sceneState.reset();
            m_runScene->setEnabled(true);
            m_cancelScene->setEnabled(false);
            const Result<SceneAccuracyResult>& result = *job->result;
            if (!result) {
                m_sceneProgress->setValue(0);
                m_sceneStatus->setText(
                    job->cancel ? tr("Cancelled.")
                                : tr("Cannot compare: %1").arg(QString::fromStdString(result.error().toString())));
                emit sceneComparisonFinished(false);
                return;
            }
            m_sceneProgress->setValue(1000);
            showSceneResult(*result, job->options.reference);
            emit sceneComparisonFinished(true);
        });
}

void AccuracyPanel::cancelSceneComparison() {
    if (m_sceneState)
        m_sceneState->cancel = true;
}

void AccuracyPanel::showSceneResult(const SceneAccuracyResult& result, const SceneAccuracySetting& reference) {
    std::map<Integrator, QList<QPointF>> data;
    m_sceneModel->removeRows(0, m_sceneModel->rowCount());
    for (const SceneAccuracyRow& row : result.rows) {
        const double ms = row.cpuSeconds * 1e3;
        if (row.rmsError > 0.0 && std::isfinite(row.rmsError))
            data[row.setting.integrator].append(QPointF(ms, row.rmsError));
        m_sceneModel->appendRow({textCell(integratorLabel(row.setting.integrator)),
                                 cell(QString::number(row.setting.substeps), row.setting.substeps),
                                 cell(sci(row.rmsError), row.rmsError), cell(sci(row.maxError), row.maxError),
                                 cell(QString::number(ms, 'f', 1), ms)});
    }
    for (auto& [integrator, points] : data)
        std::sort(points.begin(), points.end(), [](const QPointF& a, const QPointF& b) { return a.x() < b.x(); });
    m_sceneTableView->resizeColumnToContents(0);
    fillLogLogChart(m_sceneChart, data, tr("CPU time of the bake (ms)"), tr("Position error, RMS (m)"));
    QString text = tr("%1 frames of %2 dynamic bodies against %3 × %4 substeps (reference: %5 ms CPU).")
                       .arg(result.frames)
                       .arg(result.dynamicBodies)
                       .arg(integratorLabel(reference.integrator))
                       .arg(reference.substeps)
                       .arg(result.referenceCpuSeconds * 1e3, 0, 'f', 0);
    if (result.dynamicBodies < result.dynamicBodiesInScene)
        text += QLatin1Char(' ') + tr("Only the first %1 of %2 dynamic bodies were simulated.")
                                       .arg(result.dynamicBodies)
                                       .arg(result.dynamicBodiesInScene);
    m_sceneStatus->setText(text);
}

} // namespace rl
