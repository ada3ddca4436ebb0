#include "viewport/Gizmo.h"

#include <QCoreApplication>
#include <QFontMetricsF>
#include <QPainter>

#include <glm/gtc/constants.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace rl {

namespace {

constexpr int kRingSegments = 72;
// An arrow shorter than this share of its full screen length points (nearly) at the camera: hidden, as in Blender.
constexpr float kMinArrowShare = 0.25f;
// A plane square or ring seen closer to edge-on than this |cos| is hidden or dragged by its screen angle instead.
constexpr double kEdgeOnCosine = 0.2;

// The axis indicator's colours, so that the gizmo and the indicator agree.
const QColor kAxisColours[3] = {QColor(232, 64, 80), QColor(120, 200, 40), QColor(64, 128, 240)};
const QColor kViewColour(225, 225, 225);

int axisOf(GizmoHandle h) {
    switch (h) {
    case GizmoHandle::MoveX:
    case GizmoHandle::MoveYZ:
    case GizmoHandle::RotateX:
        return 0;
    case GizmoHandle::MoveY:
    case GizmoHandle::MoveXZ:
    case GizmoHandle::RotateY:
        return 1;
    case GizmoHandle::MoveZ:
    case GizmoHandle::MoveXY:
    case GizmoHandle::RotateZ:
        return 2;
    default:
        return -1;
    }
}

bool isArrow(GizmoHandle h) {
    return h == GizmoHandle::MoveX || h == GizmoHandle::MoveY || h == GizmoHandle::MoveZ;
}
bool isPlane(GizmoHandle h) {
    return h == GizmoHandle::MoveYZ || h == GizmoHandle::MoveXZ || h == GizmoHandle::MoveXY;
}
bool isRing(GizmoHandle h) {
    return h == GizmoHandle::RotateX || h == GizmoHandle::RotateY || h == GizmoHandle::RotateZ;
}
bool isMove(GizmoHandle h) {
    return isArrow(h) || isPlane(h) || h == GizmoHandle::MoveView;
}

glm::dvec3 unitAxis(int k) {
    glm::dvec3 a(0.0);
    a[k] = 1.0;
    return a;
}

QColor handleColour(GizmoHandle h) {
    const int k = axisOf(h);
    return k >= 0 ? kAxisColours[k] : kViewColour;
}

double segmentDistance(const QPointF& p, const QPointF& a, const QPointF& b) {
    const QPointF ab = b - a;
    const double len2 = QPointF::dotProduct(ab, ab);
    double t = len2 > 0.0 ? QPointF::dotProduct(p - a, ab) / len2 : 0.0;
    t = std::clamp(t, 0.0, 1.0);
    const QPointF d = p - (a + t * ab);
    return std::sqrt(QPointF::dotProduct(d, d));
}

// Closest point of the line centre + axis * s to the ray: the parameter s. Empty when they are nearly parallel.
std::optional<double> closestOnAxis(const glm::dvec3& centre, const glm::dvec3& axis, const ViewRay& viewRay) {
    const glm::dvec3 o(viewRay.origin);
    const glm::dvec3 d = glm::normalize(glm::dvec3(viewRay.direction));
    const double b = glm::dot(axis, d);
    const double denominator = 1.0 - b * b;
    if (denominator < 1e-6)
        return std::nullopt;
    const glm::dvec3 w = centre - o;
    return (b * glm::dot(d, w) - glm::dot(axis, w)) / denominator;
}

std::optional<glm::dvec3> hitPlane(const glm::dvec3& point, const glm::dvec3& normal, const ViewRay& viewRay) {
    const glm::dvec3 o(viewRay.origin);
    const glm::dvec3 d = glm::normalize(glm::dvec3(viewRay.direction));
    const double dn = glm::dot(d, normal);
    if (std::abs(dn) < 1e-4)
        return std::nullopt;
    const double t = glm::dot(point - o, normal) / dn;
    if (t <= 0.0)
        return std::nullopt;
    return o + t * d;
}

double snapTo(double value, double step) {
    return std::round(value / step) * step;
}

} // namespace

bool RigidDelta::isIdentity() const {
    return translation == glm::dvec3(0.0) && rotation == glm::dquat(1.0, 0.0, 0.0, 0.0);
}

void RigidDelta::applyToPose(glm::dvec3& position, glm::dquat& orientation) const {
    if (rotation == glm::dquat(1.0, 0.0, 0.0, 0.0)) {
        position += translation;
        return;
    }
    position = pivot + rotation * (position - pivot) + translation;
    orientation = glm::normalize(rotation * orientation);
}

glm::mat4 RigidDelta::matrix() const {
    if (rotation == glm::dquat(1.0, 0.0, 0.0, 0.0))
        return glm::translate(glm::mat4(1.0f), glm::vec3(translation));
    const glm::mat4 turn = glm::mat4_cast(glm::quat(rotation));
    return glm::translate(glm::mat4(1.0f), glm::vec3(pivot + translation)) * turn *
           glm::translate(glm::mat4(1.0f), -glm::vec3(pivot));
}

void TransformGizmo::layout(const Camera& camera, const glm::vec3& centre) {
    m_visible = false;
    for (size_t i = 0; i < m_shapes.size(); ++i) {
        m_shapes[i] = Shape{};
        m_shapes[i].handle = static_cast<GizmoHandle>(i);
    }
    m_centre = centre;
    m_camera = camera;
    if (m_tool == GizmoTool::Select)
        return;
    const glm::vec3 eye = camera.eye();
    m_forward = camera.forward();
    const float depth = glm::dot(centre - eye, m_forward);
    if (depth <= camera.nearPlane() * 1.5f)
        return;
    m_worldPerPixel = 2.0f * depth * std::tan(0.5f * camera.fovY()) / static_cast<float>(camera.height());
    const glm::vec3 c = camera.project(centre);
    m_centrePixel = QPointF(c.x, c.y);
    const glm::mat4 view = camera.view();
    auto pixel = [&](const glm::vec3& world) {
        const glm::vec3 p = camera.project(world);
        return QPointF(p.x, p.y);
    };
    auto viewDepth = [&](const glm::vec3& world) { return (view * glm::vec4(world, 1.0f)).z; };
    const glm::vec3 toCentre = glm::normalize(centre - eye);
    const glm::vec3 toEye = -toCentre;

    if (m_tool == GizmoTool::Move) {
        const float length = kArrowPixels * m_worldPerPixel;
        for (int k = 0; k < 3; ++k) {
            Shape& s = shape(static_cast<GizmoHandle>(static_cast<int>(GizmoHandle::MoveX) + k));
            glm::vec3 axis(0.0f);
            axis[k] = 1.0f;
            const QPointF base = pixel(centre + 0.2f * length * axis);
            const QPointF tip = pixel(centre + length * axis);
            const QPointF along = tip - m_centrePixel;
            const double screenLength = std::sqrt(QPointF::dotProduct(along, along));
            if (screenLength < kMinArrowShare * kArrowPixels)
                continue;
            const QPointF u = along / screenLength;
            const QPointF n(-u.y(), u.x());
            s.shown = true;
            s.line = QPolygonF({base, tip});
            s.area = QPolygonF({tip + 17.0 * u, tip + 7.0 * n, tip - 7.0 * n});
            s.depth = viewDepth(centre + 0.6f * length * axis);
        }
        for (int k = 0; k < 3; ++k) {
            Shape& s = shape(static_cast<GizmoHandle>(static_cast<int>(GizmoHandle::MoveYZ) + k));
            glm::vec3 normal(0.0f);
            normal[k] = 1.0f;
            if (std::abs(glm::dot(normal, toCentre)) < kEdgeOnCosine)
                continue;
            glm::vec3 i(0.0f), j(0.0f);
            i[(k + 1) % 3] = 1.0f;
            j[(k + 2) % 3] = 1.0f;
            const float s0 = 0.3f * length, s1 = 0.5f * length;
            s.shown = true;
            s.area = QPolygonF({pixel(centre + s0 * i + s0 * j), pixel(centre + s1 * i + s0 * j),
                                pixel(centre + s1 * i + s1 * j), pixel(centre + s0 * i + s1 * j)});
            s.depth = viewDepth(centre + 0.4f * length * (i + j));
        }
        Shape& disc = shape(GizmoHandle::MoveView);
        disc.shown = true;
        for (int p = 0; p <= 24; ++p) {
            const double phi = glm::two_pi<double>() * p / 24.0;
            disc.area.append(m_centrePixel + 9.0 * QPointF(std::cos(phi), std::sin(phi)));
        }
        disc.depth = viewDepth(centre) + 1e-3f; // in front of everything that starts at the centre
    } else {
        const float radius = kRingPixels * m_worldPerPixel;
        for (int k = 0; k < 3; ++k) {
            Shape& s = shape(static_cast<GizmoHandle>(static_cast<int>(GizmoHandle::RotateX) + k));
            glm::vec3 i(0.0f), j(0.0f);
            i[(k + 1) % 3] = 1.0f;
            j[(k + 2) % 3] = 1.0f;
            s.shown = true;
            for (int p = 0; p <= kRingSegments; ++p) {
                const float phi = glm::two_pi<float>() * static_cast<float>(p) / kRingSegments;
                const glm::vec3 offset = radius * (std::cos(phi) * i + std::sin(phi) * j);
                s.line.append(pixel(centre + offset));
                s.front.push_back(glm::dot(offset, toEye) >= -1e-4f * radius);
            }
            s.depth = viewDepth(centre);
        }
        Shape& outer = shape(GizmoHandle::RotateView);
        outer.shown = true;
        for (int p = 0; p <= kRingSegments; ++p) {
            const double phi = glm::two_pi<double>() * p / kRingSegments;
            outer.line.append(m_centrePixel + kViewRingPixels * QPointF(std::cos(phi), std::sin(phi)));
            outer.front.push_back(true);
        }
        outer.depth = viewDepth(centre);
    }
    m_visible = true;
}

double TransformGizmo::distanceTo(const Shape& s, const QPointF& point) const {
    if (!s.shown)
        return std::numeric_limits<double>::max();
    if (!s.area.isEmpty() && s.area.containsPoint(point, Qt::OddEvenFill))
        return 0.0;
    double best = std::numeric_limits<double>::max();
    for (qsizetype i = 0; i + 1 < s.line.size(); ++i) {
        // The back half of a ring cannot be grabbed: it lies behind the front half's handles.
        if (!s.front.empty() && !(s.front[static_cast<size_t>(i)] && s.front[static_cast<size_t>(i + 1)]))
            continue;
        best = std::min(best, segmentDistance(point, s.line[i], s.line[i + 1]));
    }
    for (qsizetype i = 0; i < s.area.size(); ++i)
        best = std::min(best, segmentDistance(point, s.area[i], s.area[(i + 1) % s.area.size()]));
    return best;
}

GizmoHandle TransformGizmo::hitTest(const QPointF& point) const {
    if (!m_visible)
        return GizmoHandle::None;
    GizmoHandle best = GizmoHandle::None;
    double bestDistance = kHitPixels;
    for (const Shape& s : m_shapes) {
        const double d = distanceTo(s, point);
        // Ties (both inside) go to the nearer handle in depth, which is drawn on top.
        if (d < bestDistance || (d == 0.0 && bestDistance == 0.0 && s.depth > shape(best).depth)) {
            bestDistance = d;
            best = s.handle;
        }
    }
    return best;
}

std::optional<QPointF> TransformGizmo::handlePoint(GizmoHandle handle) const {
    if (!m_visible || handle == GizmoHandle::None || !shape(handle).shown)
        return std::nullopt;
    const Shape& own = shape(handle);
    std::vector<QPointF> candidates;
    for (qsizetype i = 0; i + 1 < own.line.size(); ++i) {
        if (!own.front.empty() && !(own.front[static_cast<size_t>(i)] && own.front[static_cast<size_t>(i + 1)]))
            continue;
        for (double t : {0.0, 0.25, 0.5, 0.75})
            candidates.push_back(own.line[i] + t * (own.line[i + 1] - own.line[i]));
    }
    if (!own.area.isEmpty()) {
        QPointF mean(0.0, 0.0);
        for (const QPointF& p : own.area)
            mean += p;
        candidates.push_back(mean / static_cast<double>(own.area.size()));
    }
    std::optional<QPointF> best;
    double bestMargin = 0.0;
    for (const QPointF& q : candidates) {
        if (hitTest(q) != handle)
            continue;
        double nearestOther = std::numeric_limits<double>::max();
        for (const Shape& other : m_shapes)
            if (other.handle != handle)
                nearestOther = std::min(nearestOther, distanceTo(other, q));
        const double margin = nearestOther - distanceTo(own, q);
        if (!best || margin > bestMargin) {
            best = q;
            bestMargin = margin;
        }
    }
    return best;
}

QRectF TransformGizmo::paintBounds() const {
    if (!m_visible)
        return {};
    QRectF bounds(m_centrePixel - QPointF(1, 1), QSizeF(2, 2));
    for (const Shape& s : m_shapes) {
        if (!s.shown)
            continue;
        if (!s.line.isEmpty())
            bounds |= s.line.boundingRect();
        if (!s.area.isEmpty())
            bounds |= s.area.boundingRect();
    }
    if (isDragging()) {
        bounds |= QRectF(m_drag.centrePixel - QPointF(1, 1), QSizeF(2, 2));
        bounds |= QRectF(m_drag.mouse - QPointF(1, 1), QSizeF(2, 2));
        // The label under the gizmo.
        bounds |= QRectF(m_centrePixel.x() - 90.0, m_centrePixel.y() + kViewRingPixels + 6.0, 180.0, 30.0);
    }
    return bounds.adjusted(-10, -10, 10, 10);
}

void TransformGizmo::paint(QPainter& painter, GizmoHandle hovered) const {
    if (!m_visible)
        return;
    painter.save();
    painter.setRenderHint(QPainter::Antialiasing, true);
    std::vector<const Shape*> order;
    for (const Shape& s : m_shapes)
        if (s.shown && (!isDragging() || s.handle == m_drag.handle))
            order.push_back(&s);
    std::sort(order.begin(), order.end(), [](const Shape* a, const Shape* b) { return a->depth < b->depth; });
    const GizmoHandle highlighted = isDragging() ? m_drag.handle : hovered;

    if (isDragging()) {
        // Where the drag started, and for rotations the swept angle, as Blender shows them.
        QPen guide(QColor(255, 255, 255, 150), 1.0, Qt::DashLine);
        painter.setPen(guide);
        if (isMove(m_drag.handle))
            painter.drawLine(m_drag.centrePixel, m_centrePixel);
        else
            painter.drawLine(m_centrePixel, m_drag.mouse);
    }

    for (const Shape* s : order) {
        const bool hot = s->handle == highlighted;
        QColor colour = handleColour(s->handle);
        if (hot)
            colour = colour.lighter(135);
        const double width = hot ? 4.0 : 2.6;
        if (isArrow(s->handle)) {
            painter.setPen(QPen(colour, width, Qt::SolidLine, Qt::RoundCap));
            painter.drawPolyline(s->line);
            painter.setPen(QPen(colour, 1.0));
            painter.setBrush(colour);
            painter.drawPolygon(s->area);
        } else if (isPlane(s->handle)) {
            QColor fill = colour;
            fill.setAlpha(hot ? 210 : 120);
            painter.setPen(QPen(colour, hot ? 2.0 : 1.2));
            painter.setBrush(fill);
            painter.drawPolygon(s->area);
        } else if (s->handle == GizmoHandle::MoveView) {
            painter.setPen(QPen(colour, hot ? 3.0 : 2.0));
            painter.setBrush(hot ? QColor(255, 255, 255, 90) : QColor(255, 255, 255, 25));
            painter.drawPolygon(s->area);
        } else {
            // Rings: the back half thin and faint, the front half solid.
            QColor back = colour;
            back.setAlpha(70);
            for (int pass = 0; pass < 2; ++pass) {
                const bool frontPass = pass == 1;
                painter.setPen(frontPass ? QPen(colour, width, Qt::SolidLine, Qt::RoundCap)
                                         : QPen(back, 1.4, Qt::SolidLine, Qt::RoundCap));
                QPolygonF run;
                for (qsizetype i = 0; i < s->line.size(); ++i) {
                    const bool isFront = s->front[static_cast<size_t>(i)];
                    if (isFront == frontPass) {
                        run.append(s->line[i]);
                    } else {
                        if (!run.isEmpty()) {
                            run.append(s->line[i]); // close the gap to where the other half starts
                            painter.drawPolyline(run);
                        }
                        run.clear();
                    }
                }
                if (run.size() > 1)
                    painter.drawPolyline(run);
            }
        }
    }

    if (isDragging() && isRing(m_drag.handle) && !m_drag.screenAngle && m_drag.amount != 0.0) {
        // The swept sector in the ring's plane, as Blender shows it.
        const double radius = kRingPixels * m_worldPerPixel;
        const glm::dvec3 w = glm::cross(m_drag.axis, m_drag.startU);
        QPolygonF sector({m_centrePixel});
        const int steps = std::clamp(static_cast<int>(std::abs(m_drag.amount) / 0.05), 2, 400);
        for (int i = 0; i <= steps; ++i) {
            const double phi = m_drag.amount * i / steps;
            const glm::dvec3 p = m_drag.centre + radius * (std::cos(phi) * m_drag.startU + std::sin(phi) * w);
            const glm::vec3 q = m_camera.project(glm::vec3(p));
            sector.append(QPointF(q.x, q.y));
        }
        QColor fill = handleColour(m_drag.handle);
        fill.setAlpha(60);
        painter.setPen(Qt::NoPen);
        painter.setBrush(fill);
        painter.drawPolygon(sector);
    }

    if (isDragging()) {
        const QString text = dragText();
        QFont font = painter.font();
        font.setPixelSize(12);
        painter.setFont(font);
        const QFontMetricsF metrics(font);
        const double width = metrics.horizontalAdvance(text) + 14.0;
        const QRectF box(m_centrePixel.x() - 0.5 * width, m_centrePixel.y() + kViewRingPixels + 8.0, width, 20.0);
        painter.setPen(Qt::NoPen);
        painter.setBrush(QColor(20, 20, 22, 190));
        painter.drawRoundedRect(box, 4.0, 4.0);
        painter.setPen(QColor(235, 235, 235));
        painter.drawText(box, Qt::AlignCenter, text);
    }
    painter.restore();
}

bool TransformGizmo::beginDrag(GizmoHandle handle, const Camera& camera, const QPointF& mouse) {
    m_drag = DragState{};
    if (!m_visible || handle == GizmoHandle::None || !shape(handle).shown)
        return false;
    const ViewRay ray = camera.unproject(static_cast<float>(mouse.x()), static_cast<float>(mouse.y()));
    DragState drag;
    drag.handle = handle;
    drag.centre = glm::dvec3(m_centre);
    drag.centrePixel = m_centrePixel;
    drag.mouse = mouse;
    drag.startMouse = mouse;
    drag.delta.pivot = drag.centre;
    const glm::dvec3 toEye = glm::normalize(glm::dvec3(camera.eye()) - drag.centre);
    const int k = axisOf(handle);
    if (isArrow(handle)) {
        drag.axis = unitAxis(k);
        const auto s = closestOnAxis(drag.centre, drag.axis, ray);
        if (!s)
            return false;
        drag.start = drag.centre + *s * drag.axis;
    } else if (isPlane(handle) || handle == GizmoHandle::MoveView) {
        drag.axis = handle == GizmoHandle::MoveView ? -glm::dvec3(camera.forward()) : unitAxis(k);
        const auto hit = hitPlane(drag.centre, drag.axis, ray);
        if (!hit)
            return false;
        drag.start = *hit;
    } else {
        drag.axis = handle == GizmoHandle::RotateView ? toEye : unitAxis(k);
        drag.screenAngle = handle == GizmoHandle::RotateView || std::abs(glm::dot(drag.axis, toEye)) < kEdgeOnCosine;
        if (!drag.screenAngle) {
            const auto hit = hitPlane(drag.centre, drag.axis, ray);
            glm::dvec3 v = hit ? *hit - drag.centre : glm::dvec3(0.0);
            v -= drag.axis * glm::dot(drag.axis, v);
            if (glm::length(v) < 1e-9)
                drag.screenAngle = true;
            else
                drag.startU = glm::normalize(v);
        }
        // Seen from the side the axis points to, a positive turn is counter-clockwise on screen.
        drag.sign = glm::dot(drag.axis, toEye) >= 0.0 ? 1.0 : -1.0;
        drag.lastAngle = 0.0;
    }
    m_drag = drag;
    return true;
}

RigidDelta TransformGizmo::dragTo(const Camera& camera, const QPointF& mouse, bool snap) {
    if (!isDragging())
        return {};
    m_drag.mouse = mouse;
    const ViewRay ray = camera.unproject(static_cast<float>(mouse.x()), static_cast<float>(mouse.y()));
    RigidDelta delta;
    delta.pivot = m_drag.centre;
    const GizmoHandle h = m_drag.handle;
    if (isArrow(h)) {
        const auto s = closestOnAxis(m_drag.centre, m_drag.axis, ray);
        if (s) {
            double amount = *s - glm::dot(m_drag.start - m_drag.centre, m_drag.axis);
            if (snap)
                amount = snapTo(amount, kMoveStep);
            m_drag.amount = amount;
            delta.translation = amount * m_drag.axis; // exactly zero on the other two axes
        } else {
            delta.translation = m_drag.delta.translation;
        }
    } else if (isPlane(h) || h == GizmoHandle::MoveView) {
        const auto hit = hitPlane(m_drag.centre, m_drag.axis, ray);
        if (hit) {
            glm::dvec3 t = *hit - m_drag.start;
            const int k = axisOf(h);
            if (k >= 0)
                t[k] = 0.0; // stays in the plane exactly
            if (snap)
                for (int i = 0; i < 3; ++i)
                    t[i] = snapTo(t[i], kMoveStep);
            delta.translation = t;
            m_drag.amount = glm::length(t);
        } else {
            delta.translation = m_drag.delta.translation;
        }
    } else {
        double raw = 0.0;
        bool ok = true;
        if (m_drag.screenAngle) {
            const QPointF v = mouse - m_drag.centrePixel;
            const QPointF s = m_drag.startMouse - m_drag.centrePixel;
            raw = m_drag.sign * (std::atan2(-v.y(), v.x()) - std::atan2(-s.y(), s.x())); // screen y points down
        } else {
            const auto hit = hitPlane(m_drag.centre, m_drag.axis, ray);
            if (hit) {
                glm::dvec3 v = *hit - m_drag.centre;
                v -= m_drag.axis * glm::dot(m_drag.axis, v);
                raw = std::atan2(glm::dot(glm::cross(m_drag.startU, v), m_drag.axis), glm::dot(m_drag.startU, v));
            } else {
                ok = false;
            }
        }
        if (ok) {
            // Unwrap so that a drag can go round more than half a turn.
            const double turn = glm::two_pi<double>();
            raw += turn * std::round((m_drag.lastAngle - raw) / turn);
            m_drag.lastAngle = raw;
        }
        double angle = m_drag.lastAngle;
        if (snap)
            angle = snapTo(angle, glm::radians(kRotateStepDegrees));
        m_drag.amount = angle;
        if (angle != 0.0)
            delta.rotation = glm::angleAxis(angle, m_drag.axis);
    }
    m_drag.delta = delta;
    return delta;
}

void TransformGizmo::endDrag() {
    m_drag = DragState{};
}

QString TransformGizmo::dragText() const {
    if (!isDragging())
        return {};
    static const char* const kAxisNames[3] = {"X", "Y", "Z"};
    const GizmoHandle h = m_drag.handle;
    const int k = axisOf(h);
    if (isArrow(h))
        return QCoreApplication::translate("rl::TransformGizmo", "%1  %2 m")
            .arg(QLatin1String(kAxisNames[k]))
            .arg(m_drag.amount, 0, 'f', 3);
    if (isPlane(h) || h == GizmoHandle::MoveView) {
        const glm::dvec3 t = m_drag.delta.translation;
        return QCoreApplication::translate("rl::TransformGizmo", "Move  %1, %2, %3 m")
            .arg(t.x, 0, 'f', 3)
            .arg(t.y, 0, 'f', 3)
            .arg(t.z, 0, 'f', 3);
    }
    const QString axis =
        k >= 0 ? QLatin1String(kAxisNames[k]) : QCoreApplication::translate("rl::TransformGizmo", "View");
    return QCoreApplication::translate("rl::TransformGizmo", "%1  %2°")
        .arg(axis)
        .arg(glm::degrees(m_drag.amount), 0, 'f', 1);
}

} // namespace rl
