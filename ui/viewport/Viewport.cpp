#include "viewport/Viewport.h"

#include "viewport/Overlays.h"

#include <QCoreApplication>
#include <QCursor>
#include <QDropEvent>
#include <QElapsedTimer>
#include <QKeyEvent>
#include <QMouseEvent>
#include <QOpenGLContext>
#include <QOpenGLFramebufferObject>
#include <QOpenGLFunctions>
#include <QPainter>
#include <QSurfaceFormat>
#include <QVBoxLayout>
#include <QWheelEvent>
#include <QWindow>

#include <glm/gtc/constants.hpp>

#include <cmath>
#include <memory>

namespace rl {

namespace {
// A press that moves less than this is a click; more on the left button starts a box selection.
constexpr int kClickSlopPixels = 4;
// One wheel notch (120 eighths of a degree) brings the camera 15% closer; touchpads send fractions of a notch.
constexpr float kZoomPerNotch = 0.85f;
constexpr float kZoomPerDragPixel = 1.005f; // Ctrl+middle drag: 140 px down doubles the distance
} // namespace

// The native window the frames are swapped to. It takes no focus and draws nothing itself: input goes to the
// Viewport widget, as if the widget had received it, and expose events ask the widget for a frame.
class ViewportWindow : public QWindow {
public:
    explicit ViewportWindow(Viewport* owner) : m_owner(owner) {
        setSurfaceType(QSurface::OpenGLSurface);
        // A press on a window that accepts focus would activate it (xcb), and keys would then bypass the widgets'
        // focus and shortcuts. The widget takes the focus on a press instead (see event()).
        setFlag(Qt::WindowDoesNotAcceptFocus);
    }

protected:
    void exposeEvent(QExposeEvent*) override {
        if (isExposed())
            m_owner->renderNow();
    }

    bool event(QEvent* event) override {
        switch (event->type()) {
        case QEvent::MouseButtonPress:
        case QEvent::MouseButtonDblClick:
            if (m_owner->focusPolicy() & Qt::ClickFocus)
                m_owner->setFocus(Qt::MouseFocusReason);
            [[fallthrough]];
        case QEvent::MouseButtonRelease:
        case QEvent::MouseMove:
        case QEvent::Wheel:
        case QEvent::KeyPress:
        case QEvent::KeyRelease:
        case QEvent::Enter:
        case QEvent::Leave:
        // A drag that the window system delivers here (Qt's own xcb drag sources target the deepest window) goes
        // to the widgets, which pass it up to the main window: dropping a scene on the viewport opens it.
        case QEvent::DragEnter:
        case QEvent::DragMove:
        case QEvent::DragLeave:
        case QEvent::Drop: {
            // The window fills the widget, so positions relative to the window are relative to the widget too.
            std::unique_ptr<QEvent> copy(event->clone());
            QCoreApplication::sendEvent(m_owner, copy.get());
            event->setAccepted(copy->isAccepted());
            if (event->type() == QEvent::DragEnter || event->type() == QEvent::DragMove ||
                event->type() == QEvent::Drop)
                static_cast<QDropEvent*>(event)->setDropAction(static_cast<QDropEvent*>(copy.get())->dropAction());
            return true;
        }
        default:
            return QWindow::event(event);
        }
    }

private:
    Viewport* m_owner;
};

Viewport::Viewport(QWidget* parent) : QWidget(parent) {
    // The outline needs a stencil buffer and the shaders need 3.3 core; keep what the application asked for
    // otherwise (it should set the same as the default format before creating QApplication).
    QSurfaceFormat format = QSurfaceFormat::defaultFormat();
    format.setDepthBufferSize(std::max(format.depthBufferSize(), 24));
    format.setStencilBufferSize(std::max(format.stencilBufferSize(), 8));
    if (format.version() < qMakePair(3, 3)) {
        format.setVersion(3, 3);
        format.setProfile(QSurfaceFormat::CoreProfile);
    }
    format.setSamples(0);
    m_window = new ViewportWindow(this);
    m_window->setFormat(format);
    QWidget* container = QWidget::createWindowContainer(m_window, this);
    container->setFocusPolicy(Qt::NoFocus);
    container->setAttribute(Qt::WA_OpaquePaintEvent);
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(container);
    // Nothing of the widget itself shows: the window covers it.
    setAttribute(Qt::WA_OpaquePaintEvent);
    setAttribute(Qt::WA_NoSystemBackground);
    setFocusPolicy(Qt::StrongFocus);
    setMouseTracking(true); // the gizmo highlights the handle under the cursor
    m_camera.setViewportSize(width(), height());
}

Viewport::~Viewport() {
    cleanup();
}

void Viewport::cleanup() {
    // GL objects die with the context current.
    if (m_renderer.isInitialized() && makeCurrent()) {
        m_renderer.release();
        doneCurrent();
    }
}

bool Viewport::makeCurrent() {
    if (m_glFailed)
        return false;
    if (!m_context) {
        if (!m_window->handle())
            m_window->create();
        m_context = std::make_unique<QOpenGLContext>();
        m_context->setFormat(m_window->requestedFormat());
        if (!m_context->create()) {
            qWarning("rl::Viewport: no OpenGL context could be created; the viewport stays empty");
            m_context.reset();
            m_glFailed = true;
            return false;
        }
    }
    if (!m_context->makeCurrent(m_window))
        return false;
    if (!m_renderer.isInitialized())
        initializeGL();
    return true;
}

QWindow* Viewport::nativeWindow() const {
    return m_window;
}

void Viewport::doneCurrent() {
    if (m_context)
        m_context->doneCurrent();
}

void Viewport::initializeGL() {
    if (!m_renderer.initialize())
        return;
    // The renderer keeps CPU copies; hand it the scene again so that it uploads everything.
    m_renderer.setScene(m_scene);
}

void Viewport::requestRender() {
    if (m_renderPending)
        return;
    m_renderPending = true;
    QMetaObject::invokeMethod(this, &Viewport::renderNow, Qt::QueuedConnection);
}

void Viewport::renderNow() {
    m_renderPending = false;
    // A window that is not on screen is drawn when it is exposed.
    if (!m_window->isExposed() || !makeCurrent())
        return;
    paintGL();
    m_context->swapBuffers(m_window);
    emit frameSwapped();
}

QImage Viewport::grabFramebuffer() {
    if (!makeCurrent())
        return {};
    const qreal ratio = devicePixelRatioF();
    const QSize pixels(std::max(1, static_cast<int>(std::lround(width() * ratio))),
                       std::max(1, static_cast<int>(std::lround(height() * ratio))));
    QOpenGLFramebufferObject target(pixels, QOpenGLFramebufferObject::CombinedDepthStencil);
    target.bind();
    paintGL();
    QImage image = target.toImage(); // premultiplied ARGB, the alpha as drawn
    target.release();
    image.setDevicePixelRatio(ratio);
    return image;
}

void Viewport::paintEvent(QPaintEvent*) {
    // Qt repaints the widget when it is shown or uncovered; the window's expose draws it, this keeps it current.
    requestRender();
}

void Viewport::resizeEvent(QResizeEvent* event) {
    // Camera works in logical pixels, as mouse events do; only the aspect matters to the projection.
    m_camera.setViewportSize(width(), height());
    QWidget::resizeEvent(event);
}

void Viewport::paintGL() {
    QElapsedTimer timer;
    timer.start();
    const qreal ratio = devicePixelRatioF();
    m_renderer.render(m_camera, static_cast<int>(std::lround(width() * ratio)),
                      static_cast<int>(std::lround(height() * ratio)), m_options);
    const qint64 sceneDone = timer.nsecsElapsed();

    if (m_overlayPainter) {
        const QSize pixels(static_cast<int>(std::lround(width() * ratio)),
                           static_cast<int>(std::lround(height() * ratio)));
        if (m_overlayImage.size() != pixels) {
            m_overlayImage = QImage(pixels, QImage::Format_RGBA8888_Premultiplied);
            m_overlayImage.setDevicePixelRatio(ratio);
        }
        m_overlayImage.fill(Qt::transparent);
        {
            QPainter painter(&m_overlayImage);
            painter.setRenderHint(QPainter::Antialiasing);
            m_overlayPainter(painter, m_camera, size());
        }
        m_renderer.drawOverlay(m_overlayImage, 0, 0, pixels.width(), pixels.height(), 0);
    }
    if (m_axisGizmo) {
        updateGizmoImage();
        const int margin = static_cast<int>(std::lround(6 * ratio));
        m_renderer.drawOverlay(
            m_gizmoImage, margin, static_cast<int>(std::lround(height() * ratio)) - margin - m_gizmoImage.height(),
            static_cast<int>(std::lround(width() * ratio)), static_cast<int>(std::lround(height() * ratio)), 1);
    }
    paintTransformGizmo();
    paintBoxSelection();
    if (m_measureFrameTime || m_renderer.profiling())
        m_context->functions()->glFinish();
    m_overlaysMs = static_cast<double>(timer.nsecsElapsed() - sceneDone) * 1e-6;

    m_lastFrameMs = static_cast<double>(timer.nsecsElapsed()) * 1e-6;
    m_averageFrameMs = m_averageFrameMs == 0.0 ? m_lastFrameMs : 0.95 * m_averageFrameMs + 0.05 * m_lastFrameMs;
    emit frameRendered(m_lastFrameMs);
}

void Viewport::paintBoxSelection() {
    if (m_drag != Drag::BoxSelect)
        return;
    const QRect band = QRect(m_pressPosition, m_lastPosition).normalized().intersected(rect());
    // Blender's box select: a faint fill inside a dashed outline.
    drawPaintedOverlay(m_bandImage, band, 3, QColor(255, 255, 255, 28), [&](QPainter& painter) {
        QPen pen(QColor(255, 255, 255, 220), 1.0, Qt::DashLine);
        pen.setCosmetic(true);
        painter.setPen(pen);
        painter.drawRect(QRectF(band).adjusted(0.5, 0.5, -0.5, -0.5));
    });
}

void Viewport::drawPaintedOverlay(QImage& image, const QRect& bounds, int slot, const QColor& fill,
                                  const std::function<void(QPainter&)>& paint) {
    if (bounds.isEmpty())
        return;
    const qreal ratio = devicePixelRatioF();
    const QSize pixels(static_cast<int>(std::lround(bounds.width() * ratio)),
                       static_cast<int>(std::lround(bounds.height() * ratio)));
    if (image.size() != pixels) {
        image = QImage(pixels, QImage::Format_RGBA8888_Premultiplied);
        image.setDevicePixelRatio(ratio);
    }
    image.fill(fill);
    {
        QPainter painter(&image);
        painter.translate(-bounds.topLeft()); // the painter works in widget coordinates
        paint(painter);
    }
    m_renderer.drawOverlay(
        image, static_cast<int>(std::lround(bounds.x() * ratio)), static_cast<int>(std::lround(bounds.y() * ratio)),
        static_cast<int>(std::lround(width() * ratio)), static_cast<int>(std::lround(height() * ratio)), slot);
}

void Viewport::setOverlayPainter(OverlayPainter painter) {
    m_overlayPainter = std::move(painter);
    if (!m_overlayPainter)
        m_overlayImage = QImage();
    requestRender();
}

void Viewport::updateGizmoImage() {
    // Repainted only when the view direction changes; panning and zooming reuse the uploaded texture.
    const qreal ratio = devicePixelRatioF();
    constexpr int kSide = 88; // logical pixels: radius 30 plus room for the labels and the backdrop
    const QSize pixels(static_cast<int>(std::lround(kSide * ratio)), static_cast<int>(std::lround(kSide * ratio)));
    if (m_gizmoImage.size() == pixels && m_gizmoForward == m_camera.forward())
        return;
    m_gizmoImage = QImage(pixels, QImage::Format_RGBA8888_Premultiplied);
    m_gizmoImage.setDevicePixelRatio(ratio);
    m_gizmoImage.fill(Qt::transparent);
    QPainter painter(&m_gizmoImage);
    paintAxisGizmo(painter, m_camera, QPointF(0.5 * kSide, 0.5 * kSide), 30.0f);
    m_gizmoForward = m_camera.forward();
}

void Viewport::setScene(ViewportScene scene) {
    if (isTransforming()) {
        // The scene under the drag is gone (an undo, a reload): the preview goes with it.
        m_gizmo.endDrag();
        m_drag = Drag::None;
        m_transformStart.clear();
        emit transformCancelled();
    }
    m_scene = std::move(scene);
    m_meshBounds.clear();
    m_meshBounds.reserve(m_scene.meshes.size());
    for (const ViewportMesh& mesh : m_scene.meshes)
        m_meshBounds.push_back(mesh.bounds());
    m_renderer.setScene(m_scene);
    updateSelectionCentre();
    requestRender();
}

void Viewport::setTransforms(std::span<const glm::mat4> models) {
    const size_t count = std::min(models.size(), m_scene.instances.size());
    for (size_t i = 0; i < count; ++i)
        m_scene.instances[i].model = models[i];
    m_renderer.setTransforms(models.first(count));
    updateSelectionCentre();
    requestRender();
}

void Viewport::setSelection(const QList<int>& instances) {
    for (ViewportInstance& inst : m_scene.instances)
        inst.flags &= ~kInstanceSelected;
    for (int i : instances)
        if (i >= 0 && i < static_cast<int>(m_scene.instances.size()))
            m_scene.instances[i].flags |= kInstanceSelected;
    m_renderer.setInstanceAttributes(m_scene);
    updateSelectionCentre();
    requestRender();
}

QList<int> Viewport::selection() const {
    QList<int> selected;
    for (int i = 0; i < static_cast<int>(m_scene.instances.size()); ++i)
        if (m_scene.instances[i].flags & kInstanceSelected)
            selected.append(i);
    return selected;
}

void Viewport::setInstanceAppearance(int instance, const glm::vec3& colour, uint32_t flags) {
    if (instance < 0 || instance >= static_cast<int>(m_scene.instances.size()))
        return;
    m_scene.instances[instance].colour = colour;
    m_scene.instances[instance].flags = flags;
    m_renderer.setInstanceAttributes(m_scene);
    requestRender();
}

void Viewport::frameAll() {
    Bounds all = m_scene.bounds();
    if (all.isEmpty()) {
        all.extend(glm::vec3(-5.0f, 0.0f, -5.0f)); // an empty scene shows a patch of the grid
        all.extend(glm::vec3(5.0f, 0.0f, 5.0f));
    }
    frameBounds(all);
}

void Viewport::frameContents() {
    frameBounds(m_scene.contentBounds());
}

void Viewport::frameSelection() {
    frameBounds(m_scene.bounds(true));
}

void Viewport::frameBounds(const Bounds& box) {
    if (box.isEmpty()) {
        frameAll();
        return;
    }
    m_camera.setViewportSize(width(), height()); // framing may come before the first resizeGL
    m_camera.frame(box);
    cameraMoved();
}

void Viewport::setSamples(int samples) {
    QSurfaceFormat f = m_window->requestedFormat();
    f.setSamples(samples);
    m_window->setFormat(f);
}

void Viewport::setRenderOptions(const RenderOptions& options) {
    m_options = options;
    requestRender();
}

void Viewport::setGridVisible(bool visible) {
    m_options.grid = visible;
    requestRender();
}

void Viewport::setAxisGizmoVisible(bool visible) {
    m_axisGizmo = visible;
    requestRender();
}

void Viewport::cameraMoved() {
    emit cameraChanged();
    requestRender();
}

void Viewport::mousePressEvent(QMouseEvent* event) {
    const QPoint position = event->position().toPoint();
    m_pressPosition = position;
    m_lastPosition = position;
    const Qt::KeyboardModifiers mods = event->modifiers();
    if (isTransforming()) {
        // Right button cancels (Blender); a left click confirms a modal transform.
        if (event->button() == Qt::RightButton)
            cancelTransform();
        else if (m_drag == Drag::Modal && event->button() == Qt::LeftButton)
            finishTransform();
        event->accept();
        return;
    }
    if (event->button() == Qt::LeftButton && !(mods & Qt::AltModifier) && layoutGizmo()) {
        const GizmoHandle handle = m_gizmo.hitTest(event->position());
        if (handle != GizmoHandle::None && m_gizmo.beginDrag(handle, m_camera, event->position())) {
            m_drag = Drag::Gizmo;
            beginTransform();
            event->accept();
            return;
        }
    }
    if (event->button() == Qt::MiddleButton) {
        m_drag = (mods & Qt::ShiftModifier) ? Drag::Pan : (mods & Qt::ControlModifier) ? Drag::Zoom : Drag::Orbit;
    } else if (event->button() == Qt::LeftButton && (mods & Qt::AltModifier)) {
        // Alt+left emulates the middle button for mice and touchpads without one.
        m_drag = (mods & Qt::ShiftModifier) ? Drag::Pan : (mods & Qt::ControlModifier) ? Drag::Zoom : Drag::Orbit;
    } else if (event->button() == Qt::LeftButton) {
        m_drag = Drag::PendingClick;
        m_extendSelection = (mods & (Qt::ControlModifier | Qt::ShiftModifier)) != 0;
    } else {
        QWidget::mousePressEvent(event);
        return;
    }
    event->accept();
}

void Viewport::mouseMoveEvent(QMouseEvent* event) {
    const QPoint position = event->position().toPoint();
    const QPoint delta = position - m_lastPosition;
    switch (m_drag) {
    case Drag::Orbit:
        m_camera.orbit(static_cast<float>(delta.x()), static_cast<float>(delta.y()));
        cameraMoved();
        break;
    case Drag::Pan:
        m_camera.pan(static_cast<float>(delta.x()), static_cast<float>(delta.y()));
        cameraMoved();
        break;
    case Drag::Zoom:
        m_camera.zoom(std::pow(kZoomPerDragPixel, static_cast<float>(delta.y())));
        cameraMoved();
        break;
    case Drag::PendingClick:
        if ((position - m_pressPosition).manhattanLength() > kClickSlopPixels) {
            m_drag = Drag::BoxSelect;
            requestRender(); // paintBoxSelection draws the rectangle from the press to m_lastPosition
        }
        break;
    case Drag::BoxSelect:
        requestRender();
        break;
    case Drag::Gizmo:
    case Drag::Modal:
        m_modalLastMouse = event->position();
        previewTransform(event->position(), event->modifiers() & Qt::ControlModifier);
        break;
    case Drag::None: {
        const GizmoHandle hovered = layoutGizmo() ? m_gizmo.hitTest(event->position()) : GizmoHandle::None;
        if (hovered != m_hoveredHandle) {
            m_hoveredHandle = hovered;
            requestRender();
        }
        QWidget::mouseMoveEvent(event);
        return;
    }
    }
    m_lastPosition = position;
    event->accept();
}

void Viewport::mouseReleaseEvent(QMouseEvent* event) {
    const QPoint position = event->position().toPoint();
    const Drag drag = m_drag;
    m_drag = Drag::None;
    if (drag == Drag::PendingClick) {
        clickSelect(position, m_extendSelection);
    } else if (drag == Drag::Gizmo) {
        if (event->button() == Qt::LeftButton) {
            previewTransform(event->position(), event->modifiers() & Qt::ControlModifier);
            m_drag = Drag::Gizmo; // finishTransform ends it
            finishTransform();
        } else {
            m_drag = drag; // another button's release does not end the drag
        }
    } else if (drag == Drag::Modal) {
        m_drag = drag; // a modal transform ends with a click, Enter or Escape
    } else if (drag == Drag::BoxSelect) {
        m_lastPosition = position;
        requestRender();
        boxSelect(QRect(m_pressPosition, position).normalized(), m_extendSelection);
    } else if (drag == Drag::None) {
        QWidget::mouseReleaseEvent(event);
        return;
    }
    event->accept();
}

void Viewport::wheelEvent(QWheelEvent* event) {
    const float notches = static_cast<float>(event->angleDelta().y()) / 120.0f;
    if (notches == 0.0f) {
        event->ignore();
        return;
    }
    m_camera.zoom(std::pow(kZoomPerNotch, notches));
    cameraMoved();
    event->accept();
}

void Viewport::keyPressEvent(QKeyEvent* event) {
    const bool keypad = event->modifiers() & Qt::KeypadModifier;
    const bool opposite = event->modifiers() & Qt::ControlModifier;
    int key = event->key();
    // With Num Lock off the keypad sends navigation keys: map them back to the digits Blender's views use.
    if (keypad) {
        switch (key) {
        case Qt::Key_End:
            key = Qt::Key_1;
            break;
        case Qt::Key_PageDown:
            key = Qt::Key_3;
            break;
        case Qt::Key_Home:
            key = Qt::Key_7;
            break;
        case Qt::Key_Delete:
            key = Qt::Key_Period;
            break;
        default:
            break;
        }
    }
    const float half = glm::half_pi<float>();
    if (isTransforming()) {
        if (key == Qt::Key_Escape) {
            cancelTransform();
        } else if (m_drag == Drag::Modal && (key == Qt::Key_Return || key == Qt::Key_Enter)) {
            finishTransform();
        } else if (key == Qt::Key_Control) {
            previewTransform(m_modalLastMouse, true); // snapping follows Ctrl without waiting for a mouse move
        }
        event->accept(); // no camera keys or shortcuts in the middle of a transform
        return;
    }
    if (key == Qt::Key_Escape && m_drag == Drag::BoxSelect) {
        m_drag = Drag::None;
        requestRender();
    } else if (key == Qt::Key_F || key == Qt::Key_Period) {
        frameSelection();
    } else if (key == Qt::Key_Home) {
        frameAll();
    } else if (keypad && key == Qt::Key_1) { // Blender's numpad views; Ctrl looks from the opposite side
        m_camera.setYaw(opposite ? glm::pi<float>() : 0.0f);
        m_camera.setPitch(0.0f);
        cameraMoved();
    } else if (keypad && key == Qt::Key_3) {
        m_camera.setYaw(opposite ? -half : half);
        m_camera.setPitch(0.0f);
        cameraMoved();
    } else if (keypad && key == Qt::Key_7) {
        m_camera.setYaw(0.0f);
        m_camera.setPitch(opposite ? -half : half); // clamped just short of the pole
        cameraMoved();
    } else {
        QWidget::keyPressEvent(event);
        return;
    }
    event->accept();
}

void Viewport::keyReleaseEvent(QKeyEvent* event) {
    if (isTransforming() && event->key() == Qt::Key_Control) {
        previewTransform(m_modalLastMouse, false);
        event->accept();
        return;
    }
    QWidget::keyReleaseEvent(event);
}

void Viewport::leaveEvent(QEvent* event) {
    if (m_hoveredHandle != GizmoHandle::None) {
        m_hoveredHandle = GizmoHandle::None;
        requestRender();
    }
    QWidget::leaveEvent(event);
}

void Viewport::setTool(GizmoTool tool) {
    if (tool == m_tool)
        return;
    if (isTransforming())
        cancelTransform();
    m_tool = tool;
    m_hoveredHandle = GizmoHandle::None;
    emit toolChanged(tool);
    requestRender();
}

void Viewport::updateSelectionCentre() {
    Bounds box;
    for (const ViewportInstance& inst : m_scene.instances) {
        if (!(inst.flags & kInstanceSelected) || (inst.flags & kInstanceHidden))
            continue;
        if (inst.meshIndex < 0 || inst.meshIndex >= static_cast<int>(m_meshBounds.size()))
            continue;
        const Bounds& local = m_meshBounds[inst.meshIndex];
        if (local.isEmpty())
            continue;
        for (int corner = 0; corner < 8; ++corner) {
            const glm::vec3 p((corner & 1) ? local.max.x : local.min.x, (corner & 2) ? local.max.y : local.min.y,
                              (corner & 4) ? local.max.z : local.min.z);
            box.extend(glm::vec3(inst.model * glm::vec4(p, 1.0f)));
        }
    }
    m_selectionCentre = box.isEmpty() ? std::nullopt : std::optional<glm::vec3>(box.centre());
}

bool Viewport::layoutGizmo() {
    // The camera's viewport size may lag behind a resize that has not been painted yet.
    m_camera.setViewportSize(width(), height());
    const GizmoTool tool = m_drag == Drag::Modal ? m_modalTool : m_tool;
    m_gizmo.setTool(m_selectionCentre ? tool : GizmoTool::Select);
    m_gizmo.layout(m_camera, m_selectionCentre.value_or(glm::vec3(0.0f)));
    return m_gizmo.isVisible();
}

std::optional<QPointF> Viewport::gizmoHandlePosition(GizmoHandle handle) {
    if (!layoutGizmo())
        return std::nullopt;
    return m_gizmo.handlePoint(handle);
}

void Viewport::paintTransformGizmo() {
    if (!layoutGizmo())
        return;
    // Painted into an image just big enough for the gizmo, so a frame uploads a few hundred kilobytes at most.
    const QRect bounds = m_gizmo.paintBounds().toAlignedRect().intersected(rect());
    drawPaintedOverlay(m_transformImage, bounds, 2, Qt::transparent,
                       [&](QPainter& painter) { m_gizmo.paint(painter, m_hoveredHandle); });
}

void Viewport::beginTransform() {
    m_transformStart.clear();
    m_transformInstances.clear();
    for (int i = 0; i < static_cast<int>(m_scene.instances.size()); ++i)
        if (m_scene.instances[i].flags & kInstanceSelected) {
            m_transformStart.emplace_back(i, m_scene.instances[i].model);
            m_transformInstances.push_back(i);
        }
    m_transformDelta = RigidDelta{};
    m_transformDelta.pivot = glm::dvec3(m_selectionCentre.value_or(glm::vec3(0.0f)));
    m_hoveredHandle = GizmoHandle::None;
    emit transformStarted();
    requestRender();
}

void Viewport::previewTransform(const QPointF& mouse, bool snap) {
    if (!isTransforming())
        return;
    m_modalLastMouse = mouse;
    m_transformDelta = m_gizmo.dragTo(m_camera, mouse, snap);
    // Only the moved instances change; the renderer re-uploads its instance buffer once, in paintGL.
    const glm::mat4 motion = m_transformDelta.matrix();
    for (const auto& [instance, model] : m_transformStart)
        m_scene.instances[instance].model = motion * model;
    m_renderer.setInstanceTransforms(m_scene, m_transformInstances);
    // The gizmo follows a move; a rotation turns about a fixed centre.
    const glm::vec3 pivot(m_transformDelta.pivot);
    m_selectionCentre = pivot + glm::vec3(m_transformDelta.translation);
    requestRender();
}

void Viewport::finishTransform() {
    const QList<int> instances(m_transformInstances.begin(), m_transformInstances.end());
    const RigidDelta delta = m_transformDelta;
    m_gizmo.endDrag();
    m_drag = Drag::None;
    m_transformStart.clear();
    updateSelectionCentre();
    requestRender();
    if (!delta.isIdentity())
        emit transformFinished(instances, delta);
    else
        emit transformCancelled();
}

void Viewport::restoreTransformStart() {
    for (const auto& [instance, model] : m_transformStart)
        m_scene.instances[instance].model = model;
    m_renderer.setInstanceTransforms(m_scene, m_transformInstances);
}

void Viewport::cancelTransform() {
    if (!isTransforming())
        return;
    restoreTransformStart();
    m_gizmo.endDrag();
    m_drag = Drag::None;
    m_transformStart.clear();
    updateSelectionCentre();
    requestRender();
    emit transformCancelled();
}

bool Viewport::startModalTransform(GizmoTool tool) {
    if (isTransforming() || m_drag != Drag::None || tool == GizmoTool::Select || !m_selectionCentre)
        return false;
    QPointF mouse = mapFromGlobal(QCursor::pos());
    if (!rect().contains(mouse.toPoint()))
        mouse = QPointF(0.5 * width(), 0.5 * height());
    m_modalTool = tool;
    m_drag = Drag::Modal;
    if (!layoutGizmo()) {
        m_drag = Drag::None;
        return false;
    }
    const GizmoHandle handle = tool == GizmoTool::Move ? GizmoHandle::MoveView : GizmoHandle::RotateView;
    if (!m_gizmo.beginDrag(handle, m_camera, mouse)) {
        m_drag = Drag::None;
        return false;
    }
    m_modalLastMouse = mouse;
    setFocus(Qt::OtherFocusReason);
    beginTransform();
    return true;
}

void Viewport::clickSelect(const QPoint& position, bool extend) {
    const ViewRay ray = m_camera.unproject(static_cast<float>(position.x()), static_cast<float>(position.y()));
    const int hit = m_pick ? m_pick(ray) : m_scene.pickBounds(ray);
    if (hit >= 0)
        emit selectionChanged({hit}, extend);
    else if (!extend)
        emit selectionChanged({}, false);
}

void Viewport::boxSelect(const QRect& rectangle, bool extend) {
    // An instance is inside when its centre projects into the rectangle and lies within the clip range.
    QList<int> inside;
    for (int i = 0; i < static_cast<int>(m_scene.instances.size()); ++i) {
        if (m_scene.instances[i].flags & kInstanceHidden)
            continue;
        const Bounds b = m_scene.instanceBounds(i);
        if (b.isEmpty())
            continue;
        const glm::vec3 p = m_camera.project(b.centre());
        if (p.z < -1.0f || p.z > 1.0f)
            continue;
        if (rectangle.contains(QPoint(static_cast<int>(std::floor(p.x)), static_cast<int>(std::floor(p.y)))))
            inside.append(i);
    }
    if (!inside.isEmpty() || !extend)
        emit selectionChanged(inside, extend);
}

} // namespace rl
