#include "overlays/OverlayPainter.h"

#include "overlays/OverlayProjection.h"
#include "viewport/Camera.h"

#include <QFontMetrics>
#include <QPainter>
#include <QPainterPath>

#include <algorithm>
#include <array>
#include <cmath>

namespace rl {

namespace {

// What QPainter's raster engine charges per segment depends on the pen: wide or capped pens go through the general
// stroker (measured: 5,000 velocity arrows at 1.5 px, ~200 ms), one-pixel cosmetic pens through the fast line
// drawer, which antialiases cheaply and is cheaper still without antialiasing. So a layer keeps its styled pen only
// while it is small, then goes thin, then thin and aliased.
constexpr int kStyledLineLimit = 600;
constexpr int kAntialiasLineLimit = 4000;
constexpr size_t kSmallDotsAbove = 500;
constexpr int kTrailFadeSteps = 4; // trails fade from old to new in this many alpha steps (one drawLines each)

bool isThin(const std::vector<QLineF>& lines) {
    return lines.size() > static_cast<size_t>(kStyledLineLimit);
}

void drawBatch(QPainter& painter, const std::vector<QLineF>& lines, QPen pen, OverlayPaintStats& stats) {
    if (lines.empty())
        return;
    painter.setRenderHint(QPainter::Antialiasing, lines.size() <= static_cast<size_t>(kAntialiasLineLimit));
    if (isThin(lines)) {
        pen.setWidth(0); // cosmetic one-pixel line
        pen.setCapStyle(Qt::FlatCap);
    }
    painter.setPen(pen);
    painter.drawLines(lines.data(), static_cast<int>(lines.size()));
    stats.lines += static_cast<int>(lines.size());
}

// A contact dot (dark rim, coloured disc) rendered once per size and device pixel ratio: blitting it is far cheaper
// than stroking a wide round-capped point per contact (measured: 2,784 contacts took 75 ms of CPU with round points).
const QImage& contactDot(qreal ratio, double diameter) {
    static QImage sprites[2];
    QImage& sprite = sprites[diameter < kContactDotPixels ? 1 : 0];
    const double logical = diameter + 3.0;
    const int side = static_cast<int>(std::ceil(logical * ratio));
    if (sprite.isNull() || sprite.devicePixelRatio() != ratio || sprite.width() != side) {
        sprite = QImage(side, side, QImage::Format_ARGB32_Premultiplied);
        sprite.setDevicePixelRatio(ratio);
        sprite.fill(Qt::transparent);
        QPainter p(&sprite);
        p.setRenderHint(QPainter::Antialiasing, true);
        const QPointF centre(side / ratio / 2.0, side / ratio / 2.0);
        p.setPen(Qt::NoPen);
        p.setBrush(overlay_colours::outline());
        p.drawEllipse(centre, logical / 2.0, logical / 2.0);
        p.setBrush(overlay_colours::contact());
        p.drawEllipse(centre, diameter / 2.0, diameter / 2.0);
    }
    return sprite;
}

// Two short strokes back from the tip of an arrow, in screen space.
void addArrowHead(std::vector<QLineF>& lines, const QLineF& shaft) {
    const double length = shaft.length();
    if (length < 1e-3)
        return;
    const QPointF tip = shaft.p2();
    const QPointF back = (shaft.p1() - tip) / length; // unit, from the tip towards the tail
    const double head = std::min(8.0, 0.4 * length);
    constexpr double kCos = 0.8829476, kSin = 0.4694716; // 28 degrees either side of the shaft
    const QPointF left(back.x() * kCos - back.y() * kSin, back.x() * kSin + back.y() * kCos);
    const QPointF right(back.x() * kCos + back.y() * kSin, -back.x() * kSin + back.y() * kCos);
    lines.emplace_back(tip, tip + left * head);
    lines.emplace_back(tip, tip + right * head);
}

void paintLegend(QPainter& painter, const std::vector<OverlayLegendEntry>& legend) {
    QFont font = painter.font();
    font.setPixelSize(11);
    painter.setFont(font);
    const QFontMetrics metrics(font);
    constexpr int kRow = 18, kGlyph = 22, kPad = 8;
    int textWidth = 0;
    for (const OverlayLegendEntry& entry : legend)
        textWidth = std::max(textWidth, metrics.horizontalAdvance(entry.label));
    const QRectF box(10, 10, kPad + kGlyph + 6 + textWidth + kPad, kPad + kRow * legend.size() + kPad - 4);
    painter.setRenderHint(QPainter::Antialiasing, true);
    painter.setPen(QPen(QColor(255, 255, 255, 28), 1.0));
    painter.setBrush(QColor(18, 18, 22, 185));
    painter.drawRoundedRect(box, 5, 5);
    for (size_t row = 0; row < legend.size(); ++row) {
        const OverlayLegendEntry& entry = legend[row];
        const double y = box.top() + kPad + row * kRow + kRow / 2.0 - 2.0;
        const double x0 = box.left() + kPad, x1 = x0 + kGlyph;
        const QPointF mid((x0 + x1) / 2.0, y);
        painter.setBrush(Qt::NoBrush);
        painter.setPen(QPen(entry.colour, 1.6, Qt::SolidLine, Qt::RoundCap));
        switch (entry.glyph) {
        case OverlayLegendEntry::Glyph::Dot:
            painter.setPen(QPen(entry.colour, kContactDotPixels, Qt::SolidLine, Qt::RoundCap));
            painter.drawPoint(mid);
            break;
        case OverlayLegendEntry::Glyph::Arrow: {
            std::vector<QLineF> lines{QLineF(x0 + 2, y, x1 - 2, y)};
            addArrowHead(lines, lines.front());
            painter.drawLines(lines.data(), static_cast<int>(lines.size()));
            break;
        }
        case OverlayLegendEntry::Glyph::Cross:
            painter.drawLine(mid - QPointF(kCrossPixels, 0), mid + QPointF(kCrossPixels, 0));
            painter.drawLine(mid - QPointF(0, kCrossPixels), mid + QPointF(0, kCrossPixels));
            break;
        case OverlayLegendEntry::Glyph::Box:
            painter.setPen(QPen(entry.colour, 1.2));
            painter.drawRect(QRectF(x0 + 4, y - 5, kGlyph - 8, 10));
            break;
        case OverlayLegendEntry::Glyph::Line:
            painter.drawLine(QPointF(x0 + 2, y), QPointF(x1 - 2, y));
            break;
        case OverlayLegendEntry::Glyph::Swatch:
            painter.setPen(Qt::NoPen);
            painter.setBrush(entry.colour);
            painter.drawRoundedRect(QRectF(x0 + 4, y - 5, kGlyph - 8, 10), 2, 2);
            break;
        }
        painter.setPen(QColor(222, 222, 226));
        painter.drawText(QRectF(x1 + 6, y - kRow / 2.0, textWidth + 2, kRow), Qt::AlignLeft | Qt::AlignVCenter,
                         entry.label);
    }
}

} // namespace

OverlayPaintStats paintOverlays(QPainter& painter, const Camera& camera, const QSize& size,
                                const OverlayPaintInput& input) {
    OverlayPaintStats stats;
    const ScreenProjector projector(camera, QSizeF(size));
    // Arrows, normals and crosses have a fixed screen size at the target's depth (nearer ones look bigger, as in
    // Blender), so they read the same on a 1 cm part and on a 100 m field.
    const float worldPerPixel = camera.worldPerPixelAtTarget();
    painter.save();

    if (const OverlayFrame* frame = input.frame) {
        std::vector<QLineF> lines;

        if (input.aabbs && !frame->aabbs.empty()) {
            lines.reserve(frame->aabbs.size() * 12);
            const glm::mat4 m = camera.viewProjection();
            for (const Bounds& box : frame->aabbs) {
                if (box.isEmpty())
                    continue;
                // Corner i takes max on axis k when bit k of i is set; the matrix columns are summed per axis.
                const std::array<glm::vec4, 2> cx{m[0] * box.min.x, m[0] * box.max.x};
                const std::array<glm::vec4, 2> cy{m[1] * box.min.y, m[1] * box.max.y};
                const std::array<glm::vec4, 2> cz{m[2] * box.min.z + m[3], m[2] * box.max.z + m[3]};
                std::array<glm::vec4, 8> corners;
                uint8_t all = 0xff, any = 0;
                for (int i = 0; i < 8; ++i) {
                    corners[i] = cx[i & 1] + cy[(i >> 1) & 1] + cz[(i >> 2) & 1];
                    const uint8_t code = projector.outcode(corners[i]);
                    all &= code;
                    any |= code;
                }
                if (all) {
                    ++stats.culled; // every corner beyond one plane: the box is off-screen or behind the eye
                    continue;
                }
                if (!any) {
                    // Wholly inside the frustum: project each corner once, no clipping.
                    std::array<QPointF, 8> p;
                    for (int i = 0; i < 8; ++i)
                        p[i] = projector.pixel(corners[i]);
                    for (int bit = 1; bit < 8; bit <<= 1)
                        for (int i = 0; i < 8; ++i)
                            if (!(i & bit))
                                lines.emplace_back(p[i], p[i | bit]);
                    continue;
                }
                QLineF line;
                for (int bit = 1; bit < 8; bit <<= 1)
                    for (int i = 0; i < 8; ++i)
                        if (!(i & bit) && projector.clipSegment(corners[i], corners[i | bit], line))
                            lines.push_back(line);
            }
            drawBatch(painter, lines, QPen(overlay_colours::aabb(), 1.0), stats);
        }

        if (input.trails && !input.trails->empty()) {
            std::array<std::vector<QLineF>, kTrailFadeSteps> faded;
            QLineF line;
            for (const std::vector<glm::vec3>& trail : *input.trails) {
                const size_t segments = trail.size() > 1 ? trail.size() - 1 : 0;
                glm::vec4 previous = segments ? projector.clip(trail.front()) : glm::vec4(0.0f);
                for (size_t s = 0; s < segments; ++s) {
                    const glm::vec4 next = projector.clip(trail[s + 1]);
                    const size_t step = std::min<size_t>(kTrailFadeSteps - 1, s * kTrailFadeSteps / segments);
                    if (projector.clipSegment(previous, next, line))
                        faded[step].push_back(line);
                    previous = next;
                }
            }
            for (int step = 0; step < kTrailFadeSteps; ++step) {
                QColor colour = overlay_colours::trail();
                colour.setAlpha(70 + (255 - 70) * step / (kTrailFadeSteps - 1));
                drawBatch(painter, faded[step], QPen(colour, 2.0, Qt::SolidLine, Qt::RoundCap, Qt::RoundJoin), stats);
            }
        }

        if (input.velocities && !frame->linearVelocities.empty()) {
            lines.clear();
            const size_t count = std::min(frame->centres.size(), frame->linearVelocities.size());
            lines.reserve(count * 3);
            QLineF shaft;
            for (size_t i = 0; i < count; ++i) {
                const glm::vec3 v = frame->linearVelocities[i];
                const float speed = glm::length(v);
                const float pixels = std::min(speed * kVelocityPixelsPerMps, kVelocityMaxPixels);
                if (!(pixels >= kVelocityMinPixels))
                    continue; // resting (or NaN): no arrow
                const glm::vec3 tail = frame->centres[i];
                const glm::vec3 tip = tail + v * (pixels * worldPerPixel / speed);
                const glm::vec4 a = projector.clip(tail), b = projector.clip(tip);
                if (projector.outcode(a, 8.0f) & projector.outcode(b, 8.0f)) {
                    ++stats.culled;
                    continue;
                }
                bool tipClipped = false;
                if (!projector.clipSegment(a, b, shaft, tipClipped)) {
                    ++stats.culled;
                    continue;
                }
                if (shaft.length() < kVelocityMinPixels)
                    continue; // far away or seen end-on: too short to read as an arrow
                lines.push_back(shaft);
                if (!tipClipped)
                    addArrowHead(lines, shaft);
            }
            drawBatch(painter, lines, QPen(overlay_colours::velocity(), 1.5, Qt::SolidLine, Qt::RoundCap), stats);
        }

        if (input.centres && !frame->centres.empty()) {
            lines.clear();
            lines.reserve(frame->centres.size() * 2);
            for (const glm::vec3& centre : frame->centres) {
                const glm::vec4 c = projector.clip(centre);
                if (projector.outcode(c, kCrossPixels)) {
                    ++stats.culled;
                    continue;
                }
                // Snapped to pixel centres so that the thin strokes stay crisp.
                QPointF p = projector.pixel(c);
                p = QPointF(std::floor(p.x()) + 0.5, std::floor(p.y()) + 0.5);
                lines.emplace_back(p.x() - kCrossPixels, p.y(), p.x() + kCrossPixels, p.y());
                lines.emplace_back(p.x(), p.y() - kCrossPixels, p.x(), p.y() + kCrossPixels);
            }
            // A dark halo first so that the white cross reads on light bodies too (not when many are drawn thin).
            if (!isThin(lines))
                drawBatch(painter, lines, QPen(overlay_colours::outline(), 3.5, Qt::SolidLine, Qt::SquareCap), stats);
            drawBatch(painter, lines, QPen(overlay_colours::centre(), 1.5, Qt::SolidLine, Qt::FlatCap), stats);
        }

        if (input.contacts && !frame->contacts.empty()) {
            lines.clear();
            std::vector<QPointF> dots;
            dots.reserve(frame->contacts.size());
            lines.reserve(frame->contacts.size());
            QLineF normal;
            const float normalWorld = kNormalPixels * worldPerPixel;
            for (const OverlayContact& contact : frame->contacts) {
                const glm::vec4 a = projector.clip(contact.point);
                const glm::vec4 b = projector.clip(contact.point + contact.normal * normalWorld);
                const bool dotVisible = projector.outcode(a, kContactDotPixels) == 0;
                const bool normalVisible = projector.clipSegment(a, b, normal);
                if (!dotVisible && !normalVisible) {
                    ++stats.culled;
                    continue;
                }
                if (dotVisible)
                    dots.push_back(projector.pixel(a));
                if (normalVisible)
                    lines.push_back(normal);
            }
            drawBatch(painter, lines, QPen(overlay_colours::normal(), 1.5, Qt::SolidLine, Qt::RoundCap), stats);
            if (!dots.empty()) {
                // Piles have thousands of contacts: smaller dots keep the bodies under them visible.
                const double diameter = dots.size() > kSmallDotsAbove ? kContactDotPixels - 2.0 : kContactDotPixels;
                const QImage& dot = contactDot(painter.device() ? painter.device()->devicePixelRatio() : 1.0, diameter);
                const double half = dot.width() / dot.devicePixelRatio() / 2.0;
                for (const QPointF& p : dots)
                    painter.drawImage(QPointF(p.x() - half, p.y() - half), dot);
                stats.points += static_cast<int>(dots.size());
            }
        }
    }

    if (!input.legend.empty())
        paintLegend(painter, input.legend);
    painter.restore();
    return stats;
}

} // namespace rl
