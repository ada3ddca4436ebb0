#include "settings/Translation.h"

#include <QLocale>
#include <QTranslator>

namespace rl {

bool loadEditorTranslation(QTranslator& translator, const QLocale& locale) {
    const QString directory = QStringLiteral(":/i18n");
    return translator.load(locale, QStringLiteral("rigidlab"), QStringLiteral("_"), directory) ||
           translator.load(QStringLiteral("rigidlab_en"), directory);
}

} // namespace rl
