// Draws one OverlayFrame over the viewport with QPainter, in widget pixels: contact dots and normals, velocity arrows,
// centre-of-mass crosses, AABB edges, trails and a legend. Geometry is culled against the view frustum and clipped at
// the near plane, and every layer goes out as one batched drawLines/drawPoints call per pen.
#pragma once

#include "overlays/OverlayFrame.h"

#include <QColor>
#include <QSize>
#include <QString>

#include <vector>

class QPainter;

namespace rl {

class Camera;

// The overlay palette: saturated colours that read on the dark grey background and against the pastel bodies.
namespace overlay_colours {
inline QColor contact() {
    return QColor(255, 56, 96);
} // contact points: hot red-pink
inline QColor normal() {
    return QColor(255, 226, 64);
} // contact normals: yellow
inline QColor velocity() {
    return QColor(64, 214, 255);
} // velocity arrows: cyan
inline QColor centre() {
    return QColor(250, 250, 250);
} // centre-of-mass crosses: white on a dark outline
inline QColor aabb() {
    return QColor(110, 235, 100);
} // bounding boxes: green
inline QColor trail() {
    return QColor(255, 160, 40);
} // trails: orange, like the selection tint
inline QColor sleeping() {
    return QColor(120, 132, 150);
} // legend swatch for washed-out sleeping bodies
inline QColor outline() {
    return QColor(12, 12, 16, 170);
} // dark halo under small marks
} // namespace overlay_colours

// Screen sizes, in logical pixels, of what the overlays draw.
inline constexpr float kVelocityPixelsPerMps = 12.0f; // arrow length per m/s at the camera target's depth
inline constexpr float kVelocityMaxPixels = 90.0f;    // cap, at the target's depth
inline constexpr float kVelocityMinPixels = 3.0f;     // shorter arrows (resting bodies) are not drawn
inline constexpr float kNormalPixels = 18.0f;         // contact normal length at the target's depth
inline constexpr float kContactDotPixels = 6.0f;
inline constexpr float kCrossPixels = 5.0f; // half size of a centre-of-mass cross

struct OverlayLegendEntry {
    enum class Glyph { Dot, Arrow, Cross, Box, Line, Swatch };
    QString label;
    QColor colour;
    Glyph glyph = Glyph::Line;
};

struct OverlayPaintInput {
    const OverlayFrame* frame = nullptr;
    bool contacts = false;
    bool velocities = false;
    bool centres = false;
    bool aabbs = false;
    // Polylines of world points, oldest first: one per selected body.
    const std::vector<std::vector<glm::vec3>>* trails = nullptr;
    std::vector<OverlayLegendEntry> legend; // empty: no legend
};

// What one paint did, for the tests and the time read-out.
struct OverlayPaintStats {
    int lines = 0;  // segments handed to QPainter
    int points = 0; // dots handed to QPainter
    int culled = 0; // items (contacts, arrows, crosses, boxes) skipped as off-screen or behind the eye
};

OverlayPaintStats paintOverlays(QPainter& painter, const Camera& camera, const QSize& size,
                                const OverlayPaintInput& input);

} // namespace rl
