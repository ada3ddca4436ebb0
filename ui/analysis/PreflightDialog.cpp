#include "analysis/PreflightDialog.h"

#include <QCheckBox>
#include <QDialogButtonBox>
#include <QHeaderView>
#include <QLabel>
#include <QPushButton>
#include <QStyle>
#include <QTreeWidget>
#include <QVBoxLayout>

namespace rl {

namespace {

QString bodyName(const Scene& scene, size_t index) {
    return index < scene.bodies.size() ? QString::fromStdString(scene.bodies[index].name)
                                       : QString::number(static_cast<qulonglong>(index));
}

} // namespace

QString PreflightDialog::kindTitle(PreflightKind kind) {
    switch (kind) {
    case PreflightKind::TinyBody:
        return tr("Very small body");
    case PreflightKind::Tunnelling:
        return tr("May pass through");
    case PreflightKind::ConcaveDynamic:
        return tr("Concave body");
    case PreflightKind::MassRatio:
        return tr("Extreme mass ratio");
    case PreflightKind::InvalidBody:
        return tr("Cannot be simulated");
    }
    return QString();
}

QString PreflightDialog::describe(const Scene& scene, const PreflightFinding& f) {
    const QString name = bodyName(scene, f.body);
    switch (f.kind) {
    case PreflightKind::TinyBody:
        return tr("'%1' is %2 cm across, below %3 cm.").arg(name).arg(f.value * 100.0, 0, 'g', 3).arg(f.limit * 100.0);
    case PreflightKind::Tunnelling:
        return tr("'%1' may reach %2 m/s and move %3 m per frame, more than its thickness of %4 m.")
            .arg(name)
            .arg(f.speed, 0, 'g', 3)
            .arg(f.value, 0, 'g', 3)
            .arg(f.limit, 0, 'g', 3);
    case PreflightKind::ConcaveDynamic:
        return tr("'%1' is concave: it collides as its convex hull, so its hollows are filled.").arg(name);
    case PreflightKind::MassRatio:
        return tr("'%1' touches '%2' at the start; '%2' is %3 times heavier.")
            .arg(name, bodyName(scene, f.other.value_or(0)))
            .arg(f.value, 0, 'f', 0);
    case PreflightKind::InvalidBody:
        return QString::fromStdString(f.message);
    }
    return QString();
}

QString PreflightDialog::suggestFix(const Scene& scene, const PreflightFinding& f) {
    switch (f.kind) {
    case PreflightKind::TinyBody:
        return tr("Coordinates are metres: if the model was made in centimetres, scale it up by 100. Contacts start "
                  "2 cm before bodies touch, so smaller bodies jitter and sink.");
    case PreflightKind::Tunnelling:
        if (scene.world.effects.mode(Effect::Ccd) == EffectMode::Off)
            return tr("CCD is switched off for this scene: turn it back on, or raise the frame rate to at least %1 "
                      "fps, or make the body thicker.")
                .arg(f.suggestedFps, 0, 'f', 0);
        return tr("CCD sweeps such bodies; to be safe without it, raise the frame rate to at least %1 fps or make "
                  "the body thicker.")
            .arg(f.suggestedFps, 0, 'f', 0);
    case PreflightKind::ConcaveDynamic:
        return tr("Split it into convex parts in Blender (one object each), make it an anchor, or accept the hull.");
    case PreflightKind::MassRatio:
        return tr("Bring the masses closer (below %1:1), or raise substeps and iterations; otherwise the lighter body "
                  "may sink or jitter.")
            .arg(f.limit, 0, 'f', 0);
    case PreflightKind::InvalidBody:
        return tr("Fix the body's shape, size or mass; the bake cannot run with it.");
    }
    return QString();
}

PreflightDialog::PreflightDialog(const Scene& scene, std::vector<PreflightFinding> findings, Mode mode, QWidget* parent)
    : QDialog(parent), m_findings(std::move(findings)) {
    setObjectName("PreflightDialog");
    setWindowTitle(tr("Pre-flight check"));
    auto* layout = new QVBoxLayout(this);

    auto* header = new QHBoxLayout;
    auto* icon = new QLabel(this);
    const QStyle::StandardPixmap pixmap =
        m_findings.empty() ? QStyle::SP_MessageBoxInformation : QStyle::SP_MessageBoxWarning;
    icon->setPixmap(style()->standardIcon(pixmap).pixmap(32, 32));
    header->addWidget(icon, 0, Qt::AlignTop);
    auto* summary = new QLabel(this);
    summary->setObjectName("PreflightSummary");
    summary->setWordWrap(true);
    if (m_findings.empty())
        summary->setText(tr("No problems found in this scene."));
    else if (mode == Mode::ConfirmBake)
        summary->setText(tr("%n finding(s) in this scene may make the bake inaccurate or unstable. Bake anyway?", "",
                            static_cast<int>(m_findings.size())));
    else
        summary->setText(tr("%n finding(s) in this scene may make a bake inaccurate or unstable.", "",
                            static_cast<int>(m_findings.size())));
    header->addWidget(summary, 1);
    layout->addLayout(header);

    m_list = new QTreeWidget(this);
    m_list->setObjectName("PreflightList");
    m_list->setColumnCount(3);
    m_list->setHeaderLabels({tr("Problem"), tr("Body"), tr("Details")});
    m_list->setRootIsDecorated(false);
    m_list->setAlternatingRowColors(true);
    m_list->setSelectionMode(QAbstractItemView::SingleSelection);
    m_list->header()->setStretchLastSection(true);
    m_list->header()->setSectionResizeMode(0, QHeaderView::ResizeToContents);
    m_list->header()->setSectionResizeMode(1, QHeaderView::ResizeToContents);
    for (const PreflightFinding& f : m_findings) {
        auto* item = new QTreeWidgetItem(m_list);
        item->setText(0, kindTitle(f.kind));
        item->setIcon(0, style()->standardIcon(f.kind == PreflightKind::InvalidBody ? QStyle::SP_MessageBoxCritical
                                                                                    : QStyle::SP_MessageBoxWarning));
        item->setText(1, bodyName(scene, f.body));
        item->setText(2, describe(scene, f));
        item->setData(0, Qt::UserRole, static_cast<qulonglong>(f.body));
        item->setData(2, Qt::UserRole, suggestFix(scene, f));
        item->setToolTip(2, describe(scene, f) + QLatin1Char('\n') + tr("Fix: %1").arg(suggestFix(scene, f)));
    }
    m_list->setVisible(!m_findings.empty());
    connect(m_list, &QTreeWidget::itemClicked, this,
            [this](QTreeWidgetItem* item) { emit bodyActivated(item->data(0, Qt::UserRole).toInt()); });
    layout->addWidget(m_list, 1);

    // The fix of the current finding, below the list, where it has room to wrap.
    m_fix = new QLabel(this);
    m_fix->setObjectName("PreflightFix");
    m_fix->setWordWrap(true);
    m_fix->setTextFormat(Qt::RichText);
    m_fix->setMinimumHeight(fontMetrics().lineSpacing() * 3);
    m_fix->setAlignment(Qt::AlignLeft | Qt::AlignTop);
    m_fix->setFrameShape(QFrame::StyledPanel);
    m_fix->setMargin(6);
    m_fix->setVisible(!m_findings.empty());
    layout->addWidget(m_fix);
    connect(m_list, &QTreeWidget::currentItemChanged, this, [this](QTreeWidgetItem* item) {
        if (!item)
            return;
        m_fix->setText(tr("<b>Suggested fix for '%1':</b> %2")
                           .arg(item->text(1).toHtmlEscaped(), item->data(2, Qt::UserRole).toString().toHtmlEscaped()));
    });
    if (m_list->topLevelItemCount() > 0)
        m_list->setCurrentItem(m_list->topLevelItem(0));

    auto* buttons = new QDialogButtonBox(this);
    if (mode == Mode::ConfirmBake) {
        m_dontShow = new QCheckBox(tr("Don't show again for this scene"), this);
        m_dontShow->setObjectName("PreflightDontShow");
        layout->addWidget(m_dontShow);
        QPushButton* bake = buttons->addButton(tr("Bake anyway"), QDialogButtonBox::AcceptRole);
        bake->setObjectName("PreflightBakeAnyway");
        // The findings are warnings: Enter bakes as the user asked, Escape cancels.
        bake->setDefault(true);
        QPushButton* cancel = buttons->addButton(QDialogButtonBox::Cancel);
        cancel->setObjectName("PreflightCancel");
    } else {
        QPushButton* close = buttons->addButton(QDialogButtonBox::Close);
        close->setObjectName("PreflightClose");
    }
    connect(buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    layout->addWidget(buttons);
    resize(m_findings.empty() ? QSize(420, 140) : QSize(860, 400));
}

bool PreflightDialog::dontShowAgain() const {
    return m_dontShow && m_dontShow->isChecked();
}

} // namespace rl
