// Which translation the editor loads: the one for the locale (the "ui/language" setting, else the system's), else
// English. English is a file too: it holds the plural forms ("1 anchor", "1 finding"), which the sources write as
// "%n anchor(s)"; without it a French or C locale read "1 anchors".
#pragma once

class QLocale;
class QTranslator;

namespace rl {

// Loads rigidlab_<language>.qm from the resources into translator; true when a file was found (always, unless the
// resources are missing).
bool loadEditorTranslation(QTranslator& translator, const QLocale& locale);

} // namespace rl
