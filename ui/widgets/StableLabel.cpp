#include "widgets/StableLabel.h"

#include <QLabel>

#include <algorithm>

namespace rl {

void setStableText(QLabel* label, const QString& text) {
    if (label->text() == text)
        return;
    const QMargins margins = label->contentsMargins();
    const int width =
        label->fontMetrics().horizontalAdvance(text) + margins.left() + margins.right() + 2 * label->margin() + 4;
    const int height = label->fontMetrics().height() + margins.top() + margins.bottom() + 2 * label->margin();
    if (label->minimumWidth() != label->maximumWidth() || width > label->maximumWidth() ||
        label->minimumHeight() != label->maximumHeight())
        label->setFixedSize(std::max(width, label->minimumWidth()), std::max(height, label->minimumHeight()));
    label->setText(text);
}

} // namespace rl
