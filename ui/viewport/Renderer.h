// Instanced OpenGL 3.3 renderer of the viewport: background, bodies (one instanced draw per mesh with many instances,
// one batch for all meshes with few), selection outline and ground grid. It keeps CPU copies and uploads lazily in
// render(), so setters work before the GL context exists.
#pragma once

#include "viewport/Camera.h"
#include "viewport/ViewportScene.h"

#include <QElapsedTimer>
#include <QOpenGLExtraFunctions>

#include <glm/glm.hpp>

#include <limits>
#include <memory>
#include <span>
#include <vector>

class QImage;
class QOpenGLShaderProgram;

namespace rl {

struct RenderOptions {
    bool grid = true;
    float outlineWidthPixels = 2.0f;
    glm::vec4 outlineColour{1.0f, 0.56f, 0.12f, 1.0f}; // orange, as selection is in Blender
    glm::vec3 backgroundTop{0.275f, 0.275f, 0.285f};
    glm::vec3 backgroundBottom{0.165f, 0.165f, 0.172f};
};

class Renderer : protected QOpenGLExtraFunctions {
public:
    Renderer();
    ~Renderer();
    Renderer(const Renderer&) = delete;
    Renderer& operator=(const Renderer&) = delete;

    // Both need the viewport's context current. initialize() may follow release() (a new context).
    bool initialize();
    void release();
    bool isInitialized() const { return m_initialized; }

    // Meshes and instances changed: everything is re-uploaded on the next render().
    void setScene(const ViewportScene& scene);
    // Colours or flags changed (selection, sleeping): only the instance buffer is re-uploaded.
    void setInstanceAttributes(const ViewportScene& scene);
    // Playback: new model matrices in instance order; only the instance buffer is re-uploaded.
    void setTransforms(std::span<const glm::mat4> models);
    // A few instances moved (a gizmo drag): their models are taken from the scene, the rest is left alone.
    void setInstanceTransforms(const ViewportScene& scene, std::span<const int> instances);

    // Draws into the bound framebuffer. pixelWidth/Height are device pixels.
    void render(const Camera& camera, int pixelWidth, int pixelHeight, const RenderOptions& options);

    // Blends a premultiplied image over the frame with its top-left at (x, y) device pixels: the axis indicator,
    // painted with QPainter into a QImage because QPainter on the GL widget itself costs far more per frame.
    // Each slot keeps its own texture, re-uploaded only when that slot's image cacheKey() changes: slot 0 is the
    // owner's overlay painter, 1 the axis indicator, 2 the transform gizmo, 3 the box selection's rectangle.
    static constexpr int kOverlaySlots = 4;
    void drawOverlay(const QImage& image, int x, int y, int pixelWidth, int pixelHeight, int slot = 0);

    int drawCallsLastFrame() const { return m_drawCalls; }

    // Profiling: with it on, render() waits for the GL after each phase (glFinish) and records each phase's wall
    // time, so that the figures say where a frame's time goes. Off by default: the waits cost pipelining.
    // StaticLayer is the copy of the cached static layer; a frame that rebuilds it books the build under Clear,
    // Background, Bodies and Grid.
    enum Phase { Upload, Clear, Background, Bodies, Grid, Outline, StaticLayer, PhaseCount };
    void setProfiling(bool on) { m_profiling = on; }
    bool profiling() const { return m_profiling; }
    double phaseMs(Phase phase) const { return m_phaseMs[phase]; }
    // Process CPU time of the phase (this thread and llvmpipe's): less sensitive to a busy machine than wall time.
    double phaseCpuMs(Phase phase) const { return m_phaseCpuMs[phase]; }

    // The static layer: background, anchors and grid. While none of it changes (camera, viewport size, grid and
    // background options, the anchors' poses and looks), it is kept in an offscreen framebuffer, and a frame copies
    // it and draws only the moving bodies over it: a scrub or a playback frame skips the background and the grid,
    // which cost a quarter of a 5,000-box frame under llvmpipe. The layer is built on the second frame in a row
    // with the same static content, so orbiting does not pay for building it. Every frame draws the layers in
    // the same order, cached or not: the grid shows over anchors and under every moving body.
    void setStaticLayerCaching(bool on) { m_staticCaching = on; }
    int staticLayerBuilds() const { return m_staticBuilds; }
    bool lastFrameUsedStaticLayer() const { return m_lastFrameCached; }

private:
    // What the static layer depends on; a cached layer is used only for a frame with an equal key.
    struct StaticKey {
        glm::mat4 viewProjection{0.0f};
        glm::vec3 eye{0.0f};
        float distance = 0.0f; // the camera's, which sets how far the grid reaches
        int width = 0;
        int height = 0;
        bool grid = false;
        glm::vec3 backgroundTop{0.0f};
        glm::vec3 backgroundBottom{0.0f};
        uint64_t generation = 0; // of the anchors' poses and looks, see m_staticGeneration
        bool operator==(const StaticKey&) const = default;
    };

    // 80 bytes per instance: the model matrix and the colour with the flags in the fourth component.
    struct InstanceData {
        glm::mat4 model;
        glm::vec4 colourFlags;
        uint32_t flags() const { return static_cast<uint32_t>(colourFlags.a); }
    };
    struct MeshRange {
        int firstInstance = 0; // into the instance buffer, which is grouped by mesh
        int instanceCount = 0;
        glm::vec3 centre{0.0f}; // of the mesh's box, shape coordinates: the outline grows away from it
        float radius = 0.0f;    // half the box diagonal
        bool closed = false;    // watertight and consistently wound: back faces can be culled
        bool batched = false;   // drawn in the merged batch rather than by its own instanced draw
    };
    struct MeshGl {
        unsigned vao = 0;
        unsigned vertexBuffer = 0;
        unsigned indexBuffer = 0;
        int indexCount = 0;
    };

    struct SelectionRange {
        int first = 0; // into m_selected
        int count = 0;
    };

    void uploadMeshes();
    void buildBatch(const std::vector<FlatShadedMesh>& flatMeshes); // flatShaded() of each of m_meshes
    void drawBatch(bool outlinePass);
    // Counts the triangles drawn since the last flush and flushes once there are kTrianglesPerFlush of them.
    void drewTriangles(size_t triangles);
    void uploadInstances(unsigned buffer, size_t& capacity, const std::vector<InstanceData>& data);
    void gatherSelection();
    void drawMeshes(QOpenGLShaderProgram& program, bool outlinePass);
    void releaseMeshes();
    // Layer 0: every body; 1: anchors only; 2: every body but the anchors (the vertex shader drops the others).
    void drawBodies(const glm::mat4& viewProjection, const glm::vec3& eye, const glm::vec3& light, int layer);
    // Clear, background, anchors and grid into the bound framebuffer.
    void drawStaticLayer(const StaticKey& key, const RenderOptions& options, const glm::vec3& light);
    // (Re)creates the offscreen framebuffer at the key's size and draws the static layer into it, then binds
    // `target` again; false when the framebuffer cannot be made complete (the frame then draws the layer itself).
    bool buildStaticLayer(const StaticKey& key, const RenderOptions& options, const glm::vec3& light, unsigned target);
    // Profiling only: finishes the GL work of the phase that just ended and books its wall and CPU time. A phase may
    // come more than once in a frame (the anchors and the moving bodies): its times add up.
    void endPhase(Phase phase);
    void releaseStaticLayer();
    // An anchor's pose or look changed: the cached layer is stale.
    void anchorsChanged() { ++m_staticGeneration; }

    bool m_initialized = false;
    std::unique_ptr<QOpenGLShaderProgram> m_meshProgram;
    std::unique_ptr<QOpenGLShaderProgram> m_batchProgram; // mesh.vert with RL_BATCHED: instances from a buffer texture
    std::unique_ptr<QOpenGLShaderProgram> m_outlineProgram;
    std::unique_ptr<QOpenGLShaderProgram> m_batchOutlineProgram; // outline.vert with RL_BATCHED
    std::unique_ptr<QOpenGLShaderProgram> m_backgroundProgram;
    std::unique_ptr<QOpenGLShaderProgram> m_gridProgram;
    std::unique_ptr<QOpenGLShaderProgram> m_overlayProgram;
    unsigned m_overlayTextures[kOverlaySlots] = {};
    qint64 m_overlayKeys[kOverlaySlots] = {}; // cacheKey() of the image in each texture
    unsigned m_emptyVao = 0;                  // core profile needs a bound VAO even for attribute-less draws
    unsigned m_instanceBuffer = 0;
    size_t m_instanceBufferCapacity = 0;
    unsigned m_instanceTexture = 0; // buffer texture over m_instanceBuffer, read by the batch's vertex shader

    // The batch: meshes with few instances (a scene of 5,000 boxes of different sizes has 5,000 meshes of one
    // instance each) are copied once per instance into one vertex buffer whose vertices carry their instance's
    // slot, and drawn with two draws (closed meshes culled, open ones two-sided). Under llvmpipe each draw call
    // costs several microseconds of validation and vertex setup, so 5,000 draws of 8 vertices took ~20 ms.
    unsigned m_batchVao = 0;
    unsigned m_batchVertexBuffer = 0;
    unsigned m_batchIndexBuffer = 0;
    int m_batchClosedIndices = 0; // the closed meshes' triangles come first in the index buffer
    int m_batchOpenIndices = 0;
    size_t m_trianglesSinceFlush = 0;

    int m_selectedInBatch = 0; // selected instances of batched meshes: many are outlined with the whole batch
    bool m_outlineWithBatch = false;

    std::vector<ViewportMesh> m_meshes;
    std::vector<MeshRange> m_ranges;
    std::vector<MeshGl> m_meshGl;          // GL objects of m_meshes, rebuilt on upload
    std::vector<InstanceData> m_instances; // grouped by mesh
    std::vector<int> m_slotOfInstance;     // instance index -> position in m_instances, -1 when not drawn
    bool m_meshesDirty = false;
    bool m_instancesDirty = false;
    bool m_partialDirty = false; // only slots m_partialFirst..m_partialLast changed (setInstanceTransforms)
    int m_partialFirst = std::numeric_limits<int>::max();
    int m_partialLast = -1;
    std::vector<InstanceData> m_selected; // copies of the selected instances, grouped by mesh, for the outline
    std::vector<int> m_selectedSlots;     // where each copy comes from in m_instances
    std::vector<SelectionRange> m_selectedRanges;
    unsigned m_selectionBuffer = 0;
    size_t m_selectionBufferCapacity = 0;
    bool m_selectionDirty = false;
    int m_drawCalls = 0;

    bool m_staticCaching = true;
    bool m_staticSupported = true; // false once copying the layer failed (formats the blit cannot convert)
    bool m_staticValid = false;
    bool m_lastFrameCached = false;
    int m_staticBuilds = 0;
    uint64_t m_staticGeneration = 1;
    StaticKey m_staticKey;    // of the cached layer
    StaticKey m_lastFrameKey; // of the last frame drawn
    unsigned m_staticFbo = 0;
    unsigned m_staticColour = 0; // renderbuffers
    unsigned m_staticDepth = 0;

    bool m_profiling = false;
    QElapsedTimer m_phaseTimer;
    double m_phaseCpuStart = 0.0;
    double m_phaseMs[PhaseCount] = {};
    double m_phaseCpuMs[PhaseCount] = {};
};

} // namespace rl
