#include "edit/BodyNames.h"

#include <cstdio>

namespace rl {

std::string baseBodyName(std::string_view name) {
    const size_t dot = name.rfind('.');
    if (dot == std::string_view::npos || dot + 1 == name.size() || dot == 0)
        return std::string(name);
    for (size_t i = dot + 1; i < name.size(); ++i)
        if (name[i] < '0' || name[i] > '9')
            return std::string(name);
    return std::string(name.substr(0, dot));
}

std::string uniqueBodyName(const Scene& scene, std::string_view wanted, const std::set<std::string>& alsoTaken) {
    std::set<std::string> taken = alsoTaken;
    for (const BodyDef& body : scene.bodies)
        taken.insert(body.name);
    if (!wanted.empty() && !taken.contains(std::string(wanted)))
        return std::string(wanted);
    const std::string base = wanted.empty() ? std::string("Body") : baseBodyName(wanted);
    for (int n = 1;; ++n) {
        char suffix[16];
        std::snprintf(suffix, sizeof suffix, ".%03d", n);
        std::string candidate = base + suffix;
        if (!taken.contains(candidate))
            return candidate;
    }
}

} // namespace rl
