// The core (no Qt) reports body warnings and effect reasons as fixed English phrases. The editor shows them through
// this translation context, so a German user reads them in German; a phrase the catalogue does not know (a new one
// in the core) still shows, in English.
#pragma once

#include <QString>

#include <string>

namespace rl {

// The core phrase in the user's language.
QString coreText(const std::string& phrase);

} // namespace rl
