// The viewport's transform gizmo: move arrows, plane squares and a view-plane disc, or three rotation rings and a
// view ring, laid out in screen space at a constant size, hit-tested, painted with QPainter and dragged.
#pragma once

#include "viewport/Camera.h"

#include <QPointF>
#include <QPolygonF>
#include <QRectF>
#include <QString>

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

#include <array>
#include <optional>
#include <vector>

class QPainter;

namespace rl {

// Q: select only, W: move, E: rotate (Blender's tool keys).
enum class GizmoTool { Select, Move, Rotate };

enum class GizmoHandle {
    None,
    MoveX,
    MoveY,
    MoveZ,
    MoveYZ, // the plane squares are named by the plane they move in
    MoveXZ,
    MoveXY,
    MoveView, // the disc at the centre: moves in the plane facing the camera
    RotateX,
    RotateY,
    RotateZ,
    RotateView, // the outer ring: turns about the view direction
};

// A rigid motion about a pivot: x' = pivot + rotation * (x - pivot) + translation.
struct RigidDelta {
    glm::dvec3 pivot{0.0};
    glm::dquat rotation{1.0, 0.0, 0.0, 0.0};
    glm::dvec3 translation{0.0};

    bool isIdentity() const;
    // Moves a body pose (the position of its shape frame and its orientation). Without rotation the translation is
    // added exactly, so the axes a move leaves alone keep every bit.
    void applyToPose(glm::dvec3& position, glm::dquat& orientation) const;
    glm::mat4 matrix() const; // the same motion as a float matrix, for the live preview
};

class TransformGizmo {
public:
    // Screen sizes in logical pixels; the gizmo keeps them at every zoom level, as Blender's does.
    static constexpr float kArrowPixels = 96.0f;
    static constexpr float kRingPixels = 84.0f;
    static constexpr float kViewRingPixels = 100.0f;
    static constexpr float kHitPixels = 7.0f;
    // Ctrl while dragging: moves go in 0.1 m steps (per axis), rotations in 15 degree steps.
    static constexpr double kMoveStep = 0.1;
    static constexpr double kRotateStepDegrees = 15.0;

    void setTool(GizmoTool tool) { m_tool = tool; }
    GizmoTool tool() const { return m_tool; }

    // Projects the handles for this camera with the gizmo's centre at `centre` (world). Nothing is shown when the
    // tool is Select or the centre is behind the camera.
    void layout(const Camera& camera, const glm::vec3& centre);
    bool isVisible() const { return m_visible; }
    glm::vec3 centre() const { return m_centre; }

    // The handle under a widget pixel, the nearest one within kHitPixels; None elsewhere.
    GizmoHandle hitTest(const QPointF& point) const;
    // A pixel where hitTest answers this handle with the widest margin (tests press there); empty when the handle
    // is not shown in this view (an arrow pointing at the camera, a plane seen edge-on).
    std::optional<QPointF> handlePoint(GizmoHandle handle) const;
    // Everything paint() may touch, in widget pixels.
    QRectF paintBounds() const;
    // Draws in widget pixels. `hovered` is drawn highlighted; during a drag only the dragged handle is drawn.
    void paint(QPainter& painter, GizmoHandle hovered) const;

    // Dragging: begin on a handle, then each mouse position gives the motion since the press.
    bool beginDrag(GizmoHandle handle, const Camera& camera, const QPointF& mouse);
    RigidDelta dragTo(const Camera& camera, const QPointF& mouse, bool snap);
    void endDrag();
    bool isDragging() const { return m_drag.handle != GizmoHandle::None; }
    GizmoHandle dragHandle() const { return m_drag.handle; }
    // What the drag did so far, for the label next to the gizmo ("X 0.300 m", "Z 45.0°").
    QString dragText() const;

private:
    struct Shape {
        GizmoHandle handle = GizmoHandle::None;
        bool shown = false;
        QPolygonF line;          // arrows and rings: the polyline that is hit-tested and stroked
        std::vector<bool> front; // rings: whether each point faces the camera
        QPolygonF area;          // arrow heads and plane squares: filled and hit when inside
        float depth = 0.0f;      // view depth of the handle's middle, for painting far ones first
    };
    struct DragState {
        GizmoHandle handle = GizmoHandle::None;
        glm::dvec3 centre{0.0};
        glm::dvec3 axis{0.0};     // move axis, plane normal or rotation axis (unit, world)
        glm::dvec3 start{0.0};    // move: where the press hit the axis or plane
        glm::dvec3 startU{0.0};   // rotate in the plane: unit vector from the centre towards the press
        bool screenAngle = false; // rotate by the angle around the centre on screen (rings seen edge-on)
        double sign = 1.0;
        double lastAngle = 0.0; // unwrapped, radians
        QPointF centrePixel;
        QPointF mouse;
        QPointF startMouse;
        RigidDelta delta;
        double amount = 0.0; // signed distance or angle shown by dragText
    };

    const Shape& shape(GizmoHandle handle) const { return m_shapes[static_cast<size_t>(handle)]; }
    Shape& shape(GizmoHandle handle) { return m_shapes[static_cast<size_t>(handle)]; }
    double distanceTo(const Shape& s, const QPointF& point) const;

    GizmoTool m_tool = GizmoTool::Select;
    bool m_visible = false;
    Camera m_camera; // the view of the last layout
    glm::vec3 m_centre{0.0f};
    QPointF m_centrePixel;
    float m_worldPerPixel = 0.0f;
    glm::vec3 m_forward{0.0f, 0.0f, -1.0f};
    std::array<Shape, 12> m_shapes;
    DragState m_drag;
};

} // namespace rl
