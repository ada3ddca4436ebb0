#include "scene/Scene.h"

#include <algorithm>
#include <cctype>
#include <cmath>

namespace rl {

namespace {

bool equalsIgnoreCase(std::string_view a, std::string_view b) {
    return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin(), [](char x, char y) {
               return std::tolower(static_cast<unsigned char>(x)) == std::tolower(static_cast<unsigned char>(y));
           });
}

} // namespace

const std::vector<MaterialDef>& materialPresets() {
    // Values from the original project (DESIGN.md §3).
    static const std::vector<MaterialDef> kPresets = {
        {"Default", 1000.0, 0.5, 0.0},  {"Steel", 7850.0, 0.5, 0.6}, {"Wood", 700.0, 0.45, 0.35},
        {"Rubber", 1100.0, 1.0, 0.8},   {"Ice", 917.0, 0.03, 0.05},  {"Concrete", 2400.0, 0.7, 0.1},
        {"Plastic", 950.0, 0.35, 0.45},
    };
    return kPresets;
}

std::optional<MaterialDef> findPreset(std::string_view name) {
    for (const MaterialDef& m : materialPresets())
        if (equalsIgnoreCase(m.name, name))
            return m;
    return std::nullopt;
}

Real combine(CombineRule rule, Real a, Real b) {
    switch (rule) {
    case CombineRule::GeometricMean:
        return std::sqrt(std::max(0.0, a * b));
    case CombineRule::Average:
        return 0.5 * (a + b);
    case CombineRule::Min:
        return std::min(a, b);
    case CombineRule::Max:
        return std::max(a, b);
    case CombineRule::Multiply:
        return a * b;
    }
    return a;
}

namespace {
constexpr std::string_view kCombineNames[] = {"geometric-mean", "average", "min", "max", "multiply"};
constexpr std::string_view kIntegratorNames[] = {"explicit-euler", "symplectic-euler", "verlet", "rk4"};
constexpr std::string_view kEffectNames[] = {"gravity", "rotation", "friction", "restitution",
                                             "damping", "sleeping", "ccd"};
} // namespace

std::string_view combineRuleName(CombineRule rule) {
    return kCombineNames[static_cast<int>(rule)];
}

std::optional<CombineRule> parseCombineRule(std::string_view name) {
    for (int i = 0; i < 5; ++i)
        if (equalsIgnoreCase(kCombineNames[i], name))
            return static_cast<CombineRule>(i);
    return std::nullopt;
}

std::string_view integratorName(Integrator integrator) {
    return kIntegratorNames[static_cast<int>(integrator)];
}

std::optional<Integrator> parseIntegrator(std::string_view name) {
    for (int i = 0; i < 4; ++i)
        if (equalsIgnoreCase(kIntegratorNames[i], name))
            return static_cast<Integrator>(i);
    return std::nullopt;
}

std::string_view effectName(Effect effect) {
    return kEffectNames[static_cast<int>(effect)];
}

std::string EffectsSetting::toString() const {
    bool allAuto = true, allOff = true;
    for (EffectMode m : modes) {
        allAuto = allAuto && m == EffectMode::Auto;
        allOff = allOff && m == EffectMode::Off;
    }
    if (allAuto)
        return "auto";
    if (allOff)
        return "none";
    std::string out = "auto";
    for (int i = 0; i < kEffectCount; ++i) {
        if (modes[i] == EffectMode::Auto)
            continue;
        out += modes[i] == EffectMode::On ? ",+" : ",-";
        out += kEffectNames[i];
    }
    return out;
}

std::optional<EffectsSetting> EffectsSetting::parse(std::string_view text, std::string* error) {
    auto fail = [&](std::string message) -> std::optional<EffectsSetting> {
        if (error)
            *error = std::move(message);
        return std::nullopt;
    };
    std::vector<std::string_view> tokens;
    size_t start = 0;
    while (start <= text.size()) {
        size_t comma = text.find(',', start);
        if (comma == std::string_view::npos)
            comma = text.size();
        std::string_view token = text.substr(start, comma - start);
        while (!token.empty() && std::isspace(static_cast<unsigned char>(token.front())))
            token.remove_prefix(1);
        while (!token.empty() && std::isspace(static_cast<unsigned char>(token.back())))
            token.remove_suffix(1);
        if (token.empty())
            return fail("empty effect name in '" + std::string(text) + "'");
        tokens.push_back(token);
        start = comma + 1;
    }

    EffectsSetting result;
    bool base = false; // the first token set a base (auto/none/all/linear-only)
    for (size_t i = 0; i < tokens.size(); ++i) {
        std::string_view t = tokens[i];
        if (equalsIgnoreCase(t, "auto") || equalsIgnoreCase(t, "none") || equalsIgnoreCase(t, "all") ||
            equalsIgnoreCase(t, "linear-only")) {
            if (i != 0)
                return fail("'" + std::string(t) + "' must come first in an effects list");
            EffectMode m = equalsIgnoreCase(t, "none")  ? EffectMode::Off
                           : equalsIgnoreCase(t, "all") ? EffectMode::On
                                                        : EffectMode::Auto;
            result.modes.fill(m);
            if (equalsIgnoreCase(t, "linear-only"))
                result.set(Effect::Rotation, EffectMode::Off);
            base = true;
            continue;
        }
        EffectMode mode = EffectMode::On;
        if (t.front() == '+' || t.front() == '-') {
            mode = t.front() == '+' ? EffectMode::On : EffectMode::Off;
            t.remove_prefix(1);
        } else if (t.size() > 3 && equalsIgnoreCase(t.substr(0, 3), "no-")) {
            mode = EffectMode::Off;
            t.remove_prefix(3);
        }
        int found = -1;
        for (int k = 0; k < kEffectCount; ++k)
            if (equalsIgnoreCase(kEffectNames[k], t))
                found = k;
        if (found < 0)
            return fail("unknown effect '" + std::string(t) +
                        "' (expected gravity, rotation, friction, restitution, damping, sleeping or ccd)");
        if (!base && i == 0) {
            // A plain list: what it names is on, everything else off.
            result.modes.fill(EffectMode::Off);
            base = true;
        }
        result.modes[found] = mode;
    }
    return result;
}

bool isAnchorName(std::string_view objectName) {
    std::string stripped;
    stripped.reserve(objectName.size());
    for (size_t i = 0; i < objectName.size();) {
        if (objectName[i] == '.' && i + 1 < objectName.size() &&
            std::isdigit(static_cast<unsigned char>(objectName[i + 1]))) {
            ++i;
            while (i < objectName.size() && std::isdigit(static_cast<unsigned char>(objectName[i])))
                ++i;
            continue;
        }
        stripped += objectName[i++];
    }
    return stripped == "Anchor";
}

std::optional<MaterialDef> Scene::findMaterial(std::string_view name) const {
    for (const MaterialDef& m : materials)
        if (equalsIgnoreCase(m.name, name))
            return m;
    return findPreset(name);
}

MaterialDef Scene::effectiveMaterial(const BodyDef& body) const {
    MaterialDef m = findMaterial(body.material).value_or(*findPreset("Default"));
    if (body.density)
        m.density = *body.density;
    if (body.friction)
        m.friction = *body.friction;
    if (body.restitution)
        m.restitution = *body.restitution;
    return m;
}

} // namespace rl
