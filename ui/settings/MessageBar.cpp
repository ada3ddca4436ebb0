#include "settings/MessageBar.h"

#include <QHBoxLayout>
#include <QLabel>
#include <QStyle>
#include <QToolButton>

namespace rl {

MessageBar::MessageBar(QWidget* parent) : QFrame(parent), m_label(new QLabel(this)), m_close(new QToolButton(this)) {
    setFrameShape(QFrame::StyledPanel);
    setAutoFillBackground(true);
    auto* layout = new QHBoxLayout(this);
    layout->setContentsMargins(6, 4, 2, 4);
    m_label->setWordWrap(true);
    m_label->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_label->setObjectName("MessageText");
    layout->addWidget(m_label, 1);
    m_close->setAutoRaise(true);
    m_close->setIcon(style()->standardIcon(QStyle::SP_TitleBarCloseButton));
    m_close->setToolTip(tr("Close"));
    layout->addWidget(m_close, 0, Qt::AlignTop);
    connect(m_close, &QToolButton::clicked, this, &MessageBar::clearMessage);
    hide();
}

void MessageBar::showMessage(const QString& text, Kind kind) {
    m_kind = kind;
    m_label->setText(text);
    QPalette p = palette();
    // Light tints that keep the text readable in the default palette.
    p.setColor(QPalette::Window, kind == Kind::Error ? QColor(0xfb, 0xe3, 0xe4) : QColor(0xe3, 0xef, 0xfb));
    p.setColor(QPalette::WindowText, kind == Kind::Error ? QColor(0x8a, 0x1f, 0x11) : QColor(0x1d, 0x3f, 0x6e));
    setPalette(p);
    m_label->setPalette(p);
    show();
}

void MessageBar::clearMessage() {
    m_label->clear();
    hide();
}

QString MessageBar::text() const {
    return isHidden() ? QString() : m_label->text();
}

} // namespace rl
