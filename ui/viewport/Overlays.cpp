#include "viewport/Overlays.h"

#include <QPainter>
#include <QPainterPath>

#include <algorithm>
#include <array>

namespace rl {

void paintAxisGizmo(QPainter& painter, const Camera& camera, const QPointF& centre, float radiusPixels) {
    struct Axis {
        glm::vec3 direction;
        QColor colour;
        const char* label;
        float depth = 0.0f; // view-space z: larger is nearer the viewer
        QPointF tip;
    };
    std::array<Axis, 6> axes{{{{1, 0, 0}, QColor(232, 64, 80), "X", 0.0f, {}},
                              {{0, 1, 0}, QColor(120, 200, 40), "Y", 0.0f, {}},
                              {{0, 0, 1}, QColor(64, 128, 240), "Z", 0.0f, {}},
                              {{-1, 0, 0}, QColor(232, 64, 80), nullptr, 0.0f, {}},
                              {{0, -1, 0}, QColor(120, 200, 40), nullptr, 0.0f, {}},
                              {{0, 0, -1}, QColor(64, 128, 240), nullptr, 0.0f, {}}}};
    const glm::mat3 rotation(camera.view()); // world -> view, rotation part only
    for (Axis& axis : axes) {
        const glm::vec3 v = rotation * axis.direction;
        axis.depth = v.z;
        axis.tip = centre + QPointF(v.x, -v.y) * radiusPixels; // view y is up, widget y is down
    }
    // Far axes first so that near ones are painted on top.
    std::sort(axes.begin(), axes.end(), [](const Axis& a, const Axis& b) { return a.depth < b.depth; });

    painter.save();
    painter.setRenderHint(QPainter::Antialiasing, true);
    painter.setPen(Qt::NoPen);
    painter.setBrush(QColor(255, 255, 255, 18));
    painter.drawEllipse(centre, radiusPixels + 12.0, radiusPixels + 12.0);

    QFont font = painter.font();
    font.setBold(true);
    font.setPixelSize(11);
    painter.setFont(font);
    const qreal bubble = 8.0;
    for (const Axis& axis : axes) {
        if (axis.label) {
            painter.setPen(QPen(axis.colour, 2.0, Qt::SolidLine, Qt::RoundCap));
            painter.drawLine(centre, axis.tip);
            painter.setPen(Qt::NoPen);
            painter.setBrush(axis.colour);
            painter.drawEllipse(axis.tip, bubble, bubble);
            painter.setPen(QColor(20, 20, 20));
            painter.drawText(QRectF(axis.tip.x() - bubble, axis.tip.y() - bubble, 2 * bubble, 2 * bubble),
                             Qt::AlignCenter, QString::fromLatin1(axis.label));
        } else {
            // Negative axes: a dimmed ring only, as in Blender's navigation gizmo.
            QColor dim = axis.colour;
            dim.setAlpha(110);
            painter.setPen(QPen(dim, 1.5));
            painter.setBrush(QColor(axis.colour.red(), axis.colour.green(), axis.colour.blue(), 40));
            painter.drawEllipse(axis.tip, bubble - 1.5, bubble - 1.5);
        }
    }
    painter.restore();
}

} // namespace rl
