// The editor's 3D viewport widget: draws a ViewportScene with the instanced Renderer, drives an orbit Camera with
// Blender's mouse and keys, and hosts the move/rotate gizmo. It reports picks, box selections and finished
// transforms; the owner decides what is selected and turns a transform into an undo step.
//
// It draws into a native child window (ViewportWindow, in a window container), not as a QOpenGLWidget. A
// QOpenGLWidget's frame reaches the screen through its top-level window, which draws the whole window again and
// swaps it. Under llvmpipe, for a 1280x800 editor window, that cost 11-15 ms per frame, and only 2.5-3.5 ms for a
// native window of the viewport's size (clear-only frames, measured in one program on this machine). The child
// window takes no keyboard focus: its input is handed to this widget, which keeps the focus and the shortcuts.
#pragma once

#include "viewport/Camera.h"
#include "viewport/Gizmo.h"
#include "viewport/Renderer.h"
#include "viewport/ViewportScene.h"

#include <QImage>
#include <QList>
#include <QPoint>
#include <QRect>
#include <QWidget>

#include <functional>
#include <memory>
#include <optional>
#include <span>
#include <utility>
#include <vector>

class QOpenGLContext;
class QWindow;
class QPainter;

namespace rl {

class ViewportWindow;

class Viewport : public QWidget {
    Q_OBJECT
public:
    // Maps a world ray to the instance it hits first, or -1. The owner wires it to the core's ray cast.
    using PickFunction = std::function<int(const ViewRay&)>;

    explicit Viewport(QWidget* parent = nullptr);
    ~Viewport() override;

    // The whole scene changed (bodies added, removed, re-meshed).
    void setScene(ViewportScene scene);
    const ViewportScene& scene() const { return m_scene; }
    // Playback: one model matrix per instance, in instance order. Cheap: only the instance buffer is re-uploaded.
    void setTransforms(std::span<const glm::mat4> models);
    // Sets the selected flag on exactly these instances (the owner's selection, after selectionChanged).
    void setSelection(const QList<int>& instances);
    QList<int> selection() const;
    // Replaces one instance's colour and flags (sleeping, hidden, anchor) without touching the meshes.
    void setInstanceAppearance(int instance, const glm::vec3& colour, uint32_t flags);

    // Draws a frame soon: once, however often it is asked before the event loop runs (QWidget::update() paints the
    // widget, which is hidden under the child window, so it is not the way to ask).
    void requestRender();
    // Renders a frame into an offscreen framebuffer of the viewport's size and returns it, alpha included.
    QImage grabFramebuffer();
    // The GL context of the viewport, current on its window (created on first use); false if GL is unavailable.
    bool makeCurrent();
    void doneCurrent();
    QOpenGLContext* context() const { return m_context.get(); }
    // The native window the frames are swapped to (tests send it input as the window system would).
    QWindow* nativeWindow() const;

    // Multisampling of the viewport's framebuffer; takes effect only before the widget is first shown. The default
    // is 0 whatever the application's default format says. Measured under llvmpipe, process CPU time per 5,000-box
    // frame at 1280x800: 77 ms without MSAA, 193 ms with 4x in both the default format and the viewport, 129 ms with
    // 4x in the default format only (the window's own surface), so the application should ask for 0 samples too.
    void setSamples(int samples);

    // Draws over the 3D frame with QPainter in widget (logical) pixels: the simulation overlays. Called from paintGL
    // only when set; call update() after the painter's data changed. An empty function removes it.
    using OverlayPainter = std::function<void(QPainter&, const Camera&, const QSize&)>;
    void setOverlayPainter(OverlayPainter painter);

    // Without a pick function, clicks pick by the instances' world boxes (ViewportScene::pickBounds).
    void setPickFunction(PickFunction pick) { m_pick = std::move(pick); }

    Camera& camera() { return m_camera; }
    const Camera& camera() const { return m_camera; }
    void frameAll(); // Home
    // The bodies of the scene, leaving out a ground that dwarfs them (ViewportScene::contentBounds()); everything
    // where that leaves nothing. Opening a scene or a bake frames this.
    void frameContents();
    void frameSelection(); // F or numpad '.'; everything when nothing is selected

    const RenderOptions& renderOptions() const { return m_options; }
    void setRenderOptions(const RenderOptions& options);
    void setGridVisible(bool visible);
    void setAxisGizmoVisible(bool visible);

    // Transform tools (Q select, W move, E rotate). With Move or Rotate and a selection, the gizmo sits at the centre
    // of the selection's box; a left drag on a handle previews the motion on the selected instances and ends with
    // transformFinished (the owner turns it into one undo step). Ctrl snaps; Escape or the right button cancels.
    void setTool(GizmoTool tool);
    GizmoTool tool() const { return m_tool; }
    // Centre of the selected instances' world box; empty without a selection.
    std::optional<glm::vec3> selectionCentre() const { return m_selectionCentre; }
    // Widget pixel of a handle that a press there would grab; empty when the gizmo or that handle is not shown.
    std::optional<QPointF> gizmoHandlePosition(GizmoHandle handle);
    GizmoHandle hoveredHandle() const { return m_hoveredHandle; }
    bool isTransforming() const { return m_drag == Drag::Gizmo || m_drag == Drag::Modal; }
    // Blender's G and R: moves in the view plane, or turns about the view axis, with the mouse until a left click
    // (or Enter) confirms and Escape or the right button cancels. Needs a selection.
    bool startModalTransform(GizmoTool tool);
    void cancelTransform();

    // Frame time: wall time of paintGL (scene, outline, grid, overlays). With measurement on, paintGL ends with
    // glFinish so that the figure includes the rasterisation, which llvmpipe otherwise finishes later.
    void setFrameTimeMeasurement(bool on) { m_measureFrameTime = on; }
    bool frameTimeMeasurement() const { return m_measureFrameTime; }
    double lastFrameMs() const { return m_lastFrameMs; }
    double averageFrameMs() const { return m_averageFrameMs; } // exponential average over about 20 frames
    int drawCallsLastFrame() const { return m_renderer.drawCallsLastFrame(); }
    // Where a frame's time goes: with profiling on, paintGL waits for the GL after each phase (see Renderer) and
    // after the overlays (the simulation overlays, the axis indicator and the transform gizmo).
    void setProfiling(bool on) { m_renderer.setProfiling(on); }
    double phaseMs(Renderer::Phase phase) const { return m_renderer.phaseMs(phase); }
    double phaseCpuMs(Renderer::Phase phase) const { return m_renderer.phaseCpuMs(phase); }
    double overlaysMs() const { return m_overlaysMs; }
    bool isRendererReady() const { return m_renderer.isInitialized(); }
    // The static layer (background, anchors, grid) is drawn once and reused while it does not change (Renderer).
    void setStaticLayerCaching(bool on) {
        m_renderer.setStaticLayerCaching(on);
        requestRender();
    }
    int staticLayerBuilds() const { return m_renderer.staticLayerBuilds(); }
    bool lastFrameUsedStaticLayer() const { return m_renderer.lastFrameUsedStaticLayer(); }

    QSize minimumSizeHint() const override { return {160, 120}; }
    QSize sizeHint() const override { return {800, 600}; }

signals:
    // A click (one instance or none) or a box selection (many). extend: Ctrl or Shift was held, so the owner adds
    // to (or toggles in) its selection instead of replacing it. A plain click on nothing clears: ({}, false).
    void selectionChanged(const QList<int>& instances, bool extend);
    void frameRendered(double milliseconds);
    // A frame was swapped to the viewport's window: it is on screen.
    void frameSwapped();
    void cameraChanged();
    void toolChanged(rl::GizmoTool tool);
    // A gizmo drag or modal transform: started, previewed, and either finished with the motion to apply to these
    // instances (the selection when it started) or cancelled (the preview is undone).
    void transformStarted();
    void transformFinished(const QList<int>& instances, const rl::RigidDelta& delta);
    void transformCancelled();

protected:
    void paintEvent(QPaintEvent* event) override;
    void resizeEvent(QResizeEvent* event) override;

    void mousePressEvent(QMouseEvent* event) override;
    void mouseMoveEvent(QMouseEvent* event) override;
    void mouseReleaseEvent(QMouseEvent* event) override;
    void wheelEvent(QWheelEvent* event) override;
    void keyPressEvent(QKeyEvent* event) override;
    void keyReleaseEvent(QKeyEvent* event) override;
    void leaveEvent(QEvent* event) override;

private:
    // Frames `box`, or everything where it is empty.
    void frameBounds(const Bounds& box);
    enum class Drag { None, Orbit, Pan, Zoom, PendingClick, BoxSelect, Gizmo, Modal };
    friend class ViewportWindow; // renders on expose

    void renderNow();
    void initializeGL();
    void paintGL();
    void paintBoxSelection();
    // Paints an overlay with QPainter (in widget coordinates) into `image`, sized to `bounds` and filled with `fill`
    // first, and draws it over the frame in the renderer's overlay slot `slot`.
    void drawPaintedOverlay(QImage& image, const QRect& bounds, int slot, const QColor& fill,
                            const std::function<void(QPainter&)>& paint);
    void cleanup();
    void clickSelect(const QPoint& position, bool extend);
    void boxSelect(const QRect& rectangle, bool extend);
    void cameraMoved();
    void updateGizmoImage();
    void updateSelectionCentre();
    bool layoutGizmo();
    void paintTransformGizmo();
    void beginTransform();
    void previewTransform(const QPointF& mouse, bool snap);
    void finishTransform();
    void restoreTransformStart();

    ViewportScene m_scene;
    Renderer m_renderer;
    Camera m_camera;
    RenderOptions m_options;
    PickFunction m_pick;
    bool m_axisGizmo = true;
    QImage m_gizmoImage;
    OverlayPainter m_overlayPainter;
    QImage m_overlayImage;
    glm::vec3 m_gizmoForward{0.0f};     // camera direction the image was painted for
    ViewportWindow* m_window = nullptr; // owned by its container, a child widget
    std::unique_ptr<QOpenGLContext> m_context;
    bool m_renderPending = false;
    bool m_glFailed = false;
    QImage m_bandImage; // the box selection's rectangle, drawn over the frame

    Drag m_drag = Drag::None;
    QPoint m_pressPosition;
    QPoint m_lastPosition;
    bool m_extendSelection = false;

    GizmoTool m_tool = GizmoTool::Select;
    GizmoTool m_modalTool = GizmoTool::Move; // what G (Move) or R (Rotate) started
    TransformGizmo m_gizmo;
    std::vector<Bounds> m_meshBounds; // shape coordinates, per mesh of m_scene
    std::optional<glm::vec3> m_selectionCentre;
    GizmoHandle m_hoveredHandle = GizmoHandle::None;
    QImage m_transformImage;
    std::vector<std::pair<int, glm::mat4>> m_transformStart; // selected instances and their models at the press
    std::vector<int> m_transformInstances;
    RigidDelta m_transformDelta;
    QPointF m_modalLastMouse;

    bool m_measureFrameTime = true;
    double m_lastFrameMs = 0.0;
    double m_averageFrameMs = 0.0;
    double m_overlaysMs = 0.0;
};

} // namespace rl
