#include "document/CoreText.h"

#include <QCoreApplication>

namespace rl {

namespace {

// Every phrase the core can give, listed here for lupdate (the core cannot call tr()). Keep in step with
// core/scene/BodyProperties.cpp (warnings) and core/world/Effects.cpp (reasons): tst_translations asks the core for
// every reason (all combinations of scene facts and modes) and every warning, and checks each has a German translation.
[[maybe_unused]] constexpr const char* kPhrases[] = {
    QT_TRANSLATE_NOOP("rl::CoreText", "concave: simulated as its convex hull"),
    QT_TRANSLATE_NOOP("rl::CoreText", "smaller than 2 cm: may need more substeps"),
    QT_TRANSLATE_NOOP("rl::CoreText",
                      "named as Blender's legacy OBJ exporter names an object Anchor whose mesh has another name "
                      "(object_mesh), which the anchor rule makes dynamic: for an anchor, give the mesh the object's "
                      "name or export with File > Export > Wavefront (.obj)"),
    QT_TRANSLATE_NOOP("rl::CoreText", "forced on"),
    QT_TRANSLATE_NOOP("rl::CoreText", "forced off"),
    QT_TRANSLATE_NOOP("rl::CoreText", "dynamic bodies and non-zero gravity"),
    QT_TRANSLATE_NOOP("rl::CoreText", "no dynamic body or zero gravity"),
    QT_TRANSLATE_NOOP("rl::CoreText", "some pair has friction above zero"),
    QT_TRANSLATE_NOOP("rl::CoreText", "every pair's combined friction is zero"),
    QT_TRANSLATE_NOOP("rl::CoreText", "bodies can rotate"),
    QT_TRANSLATE_NOOP("rl::CoreText", "only frictionless, non-spinning spheres (rotation cannot change)"),
    QT_TRANSLATE_NOOP("rl::CoreText", "some pair has restitution above zero"),
    QT_TRANSLATE_NOOP("rl::CoreText", "every pair's combined restitution is zero"),
    QT_TRANSLATE_NOOP("rl::CoreText", "damping is set"),
    QT_TRANSLATE_NOOP("rl::CoreText", "no damping is set"),
    QT_TRANSLATE_NOOP("rl::CoreText", "bodies can come to rest on anchors"),
    QT_TRANSLATE_NOOP("rl::CoreText", "nothing to come to rest on (no gravity or no anchor)"),
    QT_TRANSLATE_NOOP("rl::CoreText", "some body may move more than half its size in one frame"),
    QT_TRANSLATE_NOOP("rl::CoreText", "no body moves fast relative to its size"),
};

} // namespace

QString coreText(const std::string& phrase) {
    return QCoreApplication::translate("rl::CoreText", phrase.c_str());
}

} // namespace rl
