#include "common/Result.h"

namespace rl {

std::string Error::toString() const {
    std::string out;
    if (!file.empty()) {
        out += file;
        if (line > 0)
            out += ":" + std::to_string(line);
        out += ": ";
    } else if (line > 0) {
        out += "line " + std::to_string(line) + ": ";
    }
    if (!object.empty())
        out += "'" + object + "': ";
    out += message;
    return out;
}

} // namespace rl
