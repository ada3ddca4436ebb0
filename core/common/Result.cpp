#include "common/Result.h"

namespace rl {

std::string Error::toString() const {
    std::string out;
    if (!file.empty()) {
        out += file;
        if (line > 0)
            out += ":" + std::to_string(line);
        if (line > 0 && column > 0)
            out += ":" + std::to_string(column);
        out += ": ";
    } else if (line > 0) {
        out += "line " + std::to_string(line);
        if (column > 0)
            out += ", column " + std::to_string(column);
        out += ": ";
    }
    if (!object.empty())
        out += "'" + object + "': ";
    out += message;
    return out;
}

} // namespace rl
