#include "analysis/CompareBakesDialog.h"

#include "io/BakeLoad.h"

#include <QApplication>
#include <QDialogButtonBox>
#include <QDoubleSpinBox>
#include <QFileDialog>
#include <QFormLayout>
#include <QGridLayout>
#include <QGroupBox>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QRadioButton>
#include <QSortFilterProxyModel>
#include <QTableView>
#include <QVBoxLayout>

#include <cmath>

namespace rl {

void BakeDiffModel::setResult(const BakeDiffResult& result) {
    beginResetModel();
    m_result = result;
    endResetModel();
}

int BakeDiffModel::rowCount(const QModelIndex& parent) const {
    return parent.isValid() ? 0 : static_cast<int>(m_result.bodies.size());
}

int BakeDiffModel::columnCount(const QModelIndex& parent) const {
    return parent.isValid() ? 0 : ColumnCount;
}

QVariant BakeDiffModel::data(const QModelIndex& index, int role) const {
    if (!index.isValid() || index.row() >= rowCount())
        return {};
    const BakeBodyDiff& d = m_result.bodies[static_cast<size_t>(index.row())];
    if (role == BodyIndexRole)
        return static_cast<int>(d.body);
    if (role == Qt::TextAlignmentRole)
        return index.column() == NameColumn ? QVariant(Qt::AlignLeft | Qt::AlignVCenter)
                                            : QVariant(Qt::AlignRight | Qt::AlignVCenter);
    if (role == Qt::ForegroundRole && !d.firstDivergingFrame)
        return QApplication::palette().color(QPalette::Disabled, QPalette::Text);
    auto number = [](double v) -> QVariant { return std::isinf(v) ? QVariant(tr("NaN")) : QVariant(v); };
    if (role == SortRole) {
        switch (index.column()) {
        case BodyColumn:
            return static_cast<qulonglong>(d.body);
        case NameColumn:
            return QString::fromStdString(d.name);
        case FirstFrameColumn:
            // Bodies that never diverge sort after every diverging one.
            return d.firstDivergingFrame ? static_cast<qulonglong>(*d.firstDivergingFrame)
                                         : std::numeric_limits<qulonglong>::max();
        case PositionColumn:
            return d.maxPositionDelta;
        case PositionFrameColumn:
            return static_cast<qulonglong>(d.maxPositionFrame);
        case RotationColumn:
            return d.maxRotationDegrees;
        case RotationFrameColumn:
            return static_cast<qulonglong>(d.maxRotationFrame);
        }
    }
    if (role != Qt::DisplayRole)
        return {};
    switch (index.column()) {
    case BodyColumn:
        return static_cast<qulonglong>(d.body);
    case NameColumn:
        return QString::fromStdString(d.name);
    case FirstFrameColumn:
        return d.firstDivergingFrame ? QString::number(*d.firstDivergingFrame) : tr("—");
    case PositionColumn:
        return std::isinf(d.maxPositionDelta) ? number(d.maxPositionDelta)
                                              : QVariant(QString::number(d.maxPositionDelta * 1000.0, 'g', 4));
    case PositionFrameColumn:
        return static_cast<qulonglong>(d.maxPositionFrame);
    case RotationColumn:
        return std::isinf(d.maxRotationDegrees) ? number(d.maxRotationDegrees)
                                                : QVariant(QString::number(d.maxRotationDegrees, 'g', 4));
    case RotationFrameColumn:
        return static_cast<qulonglong>(d.maxRotationFrame);
    }
    return {};
}

QVariant BakeDiffModel::headerData(int section, Qt::Orientation orientation, int role) const {
    if (orientation != Qt::Horizontal || role != Qt::DisplayRole)
        return {};
    switch (section) {
    case BodyColumn:
        return tr("#");
    case NameColumn:
        return tr("Body");
    case FirstFrameColumn:
        return tr("First diverging frame");
    case PositionColumn:
        return tr("Max Δ position (mm)");
    case PositionFrameColumn:
        return tr("at frame");
    case RotationColumn:
        return tr("Max Δ rotation (°)");
    case RotationFrameColumn:
        return tr("at frame");
    }
    return {};
}

CompareBakesDialog::CompareBakesDialog(std::function<std::shared_ptr<const Bake>()> currentBake, QWidget* parent)
    : QDialog(parent), m_currentBake(std::move(currentBake)) {
    setObjectName("CompareBakesDialog");
    setWindowTitle(tr("Compare Bakes"));
    auto* layout = new QVBoxLayout(this);

    auto* sources = new QGroupBox(tr("Bakes"), this);
    auto* grid = new QGridLayout(sources);
    m_useCurrent = new QRadioButton(tr("Current bake"), sources);
    m_useCurrent->setObjectName("CompareUseCurrent");
    m_useFileA = new QRadioButton(tr("File A:"), sources);
    m_useFileA->setObjectName("CompareUseFileA");
    m_fileA = new QLineEdit(sources);
    m_fileA->setObjectName("CompareFileA");
    m_fileB = new QLineEdit(sources);
    m_fileB->setObjectName("CompareFileB");
    auto* browseA = new QPushButton(tr("Browse…"), sources);
    auto* browseB = new QPushButton(tr("Browse…"), sources);
    grid->addWidget(m_useCurrent, 0, 0, 1, 3);
    grid->addWidget(m_useFileA, 1, 0);
    grid->addWidget(m_fileA, 1, 1);
    grid->addWidget(browseA, 1, 2);
    grid->addWidget(new QLabel(tr("File B:"), sources), 2, 0);
    grid->addWidget(m_fileB, 2, 1);
    grid->addWidget(browseB, 2, 2);
    grid->setColumnStretch(1, 1);
    layout->addWidget(sources);
    const bool haveCurrent = m_currentBake && m_currentBake();
    m_useCurrent->setEnabled(haveCurrent);
    (haveCurrent ? m_useCurrent : m_useFileA)->setChecked(true);

    auto* row = new QHBoxLayout;
    m_positionTolerance = new QDoubleSpinBox(this);
    m_positionTolerance->setObjectName("ComparePositionTolerance");
    m_positionTolerance->setDecimals(4);
    m_positionTolerance->setRange(0.0, 1000.0);
    m_positionTolerance->setValue(BakeDiffOptions{}.positionTolerance * 1000.0);
    m_positionTolerance->setSuffix(tr(" mm"));
    m_rotationTolerance = new QDoubleSpinBox(this);
    m_rotationTolerance->setObjectName("CompareRotationTolerance");
    m_rotationTolerance->setDecimals(4);
    m_rotationTolerance->setRange(0.0, 180.0);
    m_rotationTolerance->setValue(BakeDiffOptions{}.rotationToleranceDegrees);
    m_rotationTolerance->setSuffix(tr(" °"));
    auto* compareButton = new QPushButton(tr("&Compare"), this);
    compareButton->setObjectName("CompareButton");
    compareButton->setDefault(true);
    row->addWidget(new QLabel(tr("Tolerance:"), this));
    row->addWidget(m_positionTolerance);
    row->addWidget(m_rotationTolerance);
    row->addStretch(1);
    row->addWidget(compareButton);
    layout->addLayout(row);

    m_summary = new QLabel(tr("Choose two bakes and press Compare."), this);
    m_summary->setObjectName("CompareSummary");
    m_summary->setWordWrap(true);
    m_summary->setTextInteractionFlags(Qt::TextSelectableByMouse);
    layout->addWidget(m_summary);

    m_model = new BakeDiffModel(this);
    m_proxy = new QSortFilterProxyModel(this);
    m_proxy->setSourceModel(m_model);
    m_proxy->setSortRole(BakeDiffModel::SortRole);
    m_table = new QTableView(this);
    m_table->setObjectName("CompareTable");
    m_table->setModel(m_proxy);
    m_table->setSortingEnabled(true);
    m_table->sortByColumn(BakeDiffModel::PositionColumn, Qt::DescendingOrder);
    m_table->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_table->setSelectionMode(QAbstractItemView::SingleSelection);
    m_table->setAlternatingRowColors(true);
    m_table->verticalHeader()->hide();
    m_table->verticalHeader()->setDefaultSectionSize(m_table->fontMetrics().lineSpacing() + 6);
    m_table->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    m_table->horizontalHeader()->setSectionResizeMode(BakeDiffModel::NameColumn, QHeaderView::Stretch);
    layout->addWidget(m_table, 1);

    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Close, this);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    layout->addWidget(buttons);

    auto browse = [this](QLineEdit* edit) {
        const QString path =
            QFileDialog::getOpenFileName(this, tr("Open Bake"), edit->text(), tr("Bake files (*.bake);;All files (*)"));
        if (!path.isEmpty())
            edit->setText(path);
    };
    connect(browseA, &QPushButton::clicked, this, [this, browse] {
        browse(m_fileA);
        m_useFileA->setChecked(true);
    });
    connect(browseB, &QPushButton::clicked, this, [this, browse] { browse(m_fileB); });
    connect(m_useCurrent, &QRadioButton::toggled, this, &CompareBakesDialog::updateSources);
    connect(compareButton, &QPushButton::clicked, this, &CompareBakesDialog::compare);
    connect(m_table, &QTableView::clicked, this,
            [this](const QModelIndex& index) { emit bodyActivated(index.data(BakeDiffModel::BodyIndexRole).toInt()); });
    updateSources();
    resize(860, 520);
}

void CompareBakesDialog::showEvent(QShowEvent* event) {
    // A bake may have appeared (or gone) since the dialog was last open.
    const bool haveCurrent = m_currentBake && m_currentBake();
    m_useCurrent->setEnabled(haveCurrent);
    if (!haveCurrent && m_useCurrent->isChecked())
        m_useFileA->setChecked(true);
    QDialog::showEvent(event);
}

void CompareBakesDialog::updateSources() {
    m_fileA->setEnabled(!m_useCurrent->isChecked());
}

void CompareBakesDialog::setFileA(const QString& path) {
    m_fileA->setText(path);
    m_useFileA->setChecked(true);
}

void CompareBakesDialog::setFileB(const QString& path) {
    m_fileB->setText(path);
}

void CompareBakesDialog::setUseCurrentBake(bool useCurrent) {
    (useCurrent ? m_useCurrent : m_useFileA)->setChecked(true);
}

QString CompareBakesDialog::summary() const {
    return m_summary->text();
}

std::shared_ptr<const Bake> CompareBakesDialog::load(const QString& path, QString* error) const {
    if (path.trimmed().isEmpty()) {
        *error = tr("Choose a .bake file.");
        return nullptr;
    }
    Result<LoadedBake> loaded = loadBake(path.trimmed().toStdString());
    if (!loaded) {
        *error = QString::fromStdString(loaded.error().toString());
        return nullptr;
    }
    return std::make_shared<const Bake>(std::move(loaded->bake));
}

bool CompareBakesDialog::compare() {
    QString error;
    std::shared_ptr<const Bake> a;
    if (m_useCurrent->isChecked()) {
        a = m_currentBake ? m_currentBake() : nullptr;
        if (!a)
            error = tr("There is no current bake: bake the scene or choose file A.");
    } else {
        a = load(m_fileA->text(), &error);
    }
    std::shared_ptr<const Bake> b = a ? load(m_fileB->text(), &error) : nullptr;
    if (!a || !b) {
        m_model->setResult({});
        m_summary->setText(tr("<b>Cannot compare:</b> %1").arg(error.toHtmlEscaped()));
        return false;
    }
    BakeDiffOptions options;
    options.positionTolerance = m_positionTolerance->value() / 1000.0;
    options.rotationToleranceDegrees = m_rotationTolerance->value();
    QApplication::setOverrideCursor(Qt::WaitCursor);
    const BakeDiffResult result = diffBakes(*a, *b, options);
    QApplication::restoreOverrideCursor();
    m_model->setResult(result);
    if (!result.comparable()) {
        m_summary->setText(
            tr("<b>Cannot compare:</b> %1").arg(QString::fromStdString(result.incompatibility).toHtmlEscaped()));
        return false;
    }
    QString text;
    if (result.firstDivergingFrame) {
        const size_t frame = *result.firstDivergingFrame;
        text = tr("<b>The bakes diverge at frame %1</b> (t = %2 s), first in body %3 '%4'.")
                   .arg(frame)
                   .arg(a->frameTime(frame), 0, 'f', 3)
                   .arg(*result.firstDivergingBody)
                   .arg(QString::fromStdString(result.bodies[*result.firstDivergingBody].name).toHtmlEscaped());
    } else {
        text = tr("<b>Equal within the tolerance</b> over %n frame(s).", "", static_cast<int>(result.framesCompared));
    }
    if (result.framesA != result.framesB)
        text += QLatin1Char(' ') + tr("The frame counts differ: %1 and %2; the first %3 were compared.")
                                       .arg(result.framesA)
                                       .arg(result.framesB)
                                       .arg(result.framesCompared);
    int diverging = 0;
    for (const BakeBodyDiff& d : result.bodies)
        diverging += d.firstDivergingFrame ? 1 : 0;
    text += QLatin1Char(' ') +
            tr("%1 of %2 bodies differ by more than the tolerance.").arg(diverging).arg(result.bodies.size());
    m_summary->setText(text);
    return true;
}

} // namespace rl
