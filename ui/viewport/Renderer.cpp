#include "viewport/Renderer.h"

#include <QDebug>
#include <QElapsedTimer>
#include <QFile>
#include <QImage>
#include <QOpenGLShaderProgram>

#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <array>
#include <cstddef>
#include <ctime>
#include <limits>
#include <unordered_set>

// Q_INIT_RESOURCE must be used outside any namespace. It makes sure the shaders' resource is linked in even when
// rl_ui is a static library (the linker would otherwise drop the unreferenced resource object).
static void initShaderResources() {
    Q_INIT_RESOURCE(shaders);
}

namespace rl {

namespace {

constexpr GLuint kPositionLocation = 0;
constexpr GLuint kModelLocation = 2; // four vec4 columns: 2, 3, 4, 5
constexpr GLuint kColourFlagsLocation = 6;
constexpr GLuint kSlotLocation = 1;         // the batch: the vertex's instance slot, as a float (exact below 2^24)
constexpr GLuint kCentreRadiusLocation = 7; // the batch: the mesh's centre and radius, for the outline
constexpr GLuint kNormalLocation = 8;       // the face normal, used where the vertex is a triangle's last (flat)

// With more selected instances in the batch than this, the outline passes draw the whole batch (the vertex shader
// drops the unselected instances) instead of one draw per selected mesh: selecting all of 5,000 unique boxes would
// otherwise cost 10,000 draw calls a frame.
constexpr int kBatchOutlineAbove = 16;

#ifndef GL_TEXTURE_BUFFER
#define GL_TEXTURE_BUFFER 0x8C2A
#endif
#ifndef GL_RGBA32F
#define GL_RGBA32F 0x8814
#endif

// llvmpipe (Mesa's software GL) shades a draw's vertices and bins its triangles into screen tiles on the calling
// thread, and its rasteriser threads start on a frame's triangles only when they are flushed. A flush every few
// thousand triangles lets them draw one part while this thread bins the next. Measured on the 5,000-box scrub
// (tst_bakeplayback, 2 cores, median frame change to frame on screen): 17.2-19.1 ms in one draw, 14.3-15.7 ms in
// parts of a 1/8 and 14.0-14.8 ms in parts of 1/16 of its 60,000 triangles. A GPU driver takes a flush in its stride.
constexpr int kTrianglesPerFlush = 4096;

// A mesh with fewer instances than this goes into the batch; one with more is drawn instanced, which stores its
// vertices once instead of once per instance.
constexpr int kBatchBelowInstances = 16;
// The batch holds at most this many vertices (16 bytes each); further meshes are drawn instanced.
constexpr size_t kBatchMaxVertices = size_t(4) << 20;

// A mesh is closed when every directed edge (a, b) appears once and its twin (b, a) appears too: then each back
// face is hidden behind a front face and culling them halves the triangles llvmpipe has to set up and bin.
bool isClosed(const ViewportMesh& mesh) {
    if (mesh.triangles.empty())
        return false;
    std::unordered_set<uint64_t> edges;
    edges.reserve(mesh.triangles.size() * 3);
    auto key = [](uint32_t a, uint32_t b) { return (static_cast<uint64_t>(a) << 32) | b; };
    for (const auto& t : mesh.triangles)
        for (int k = 0; k < 3; ++k)
            if (!edges.insert(key(t[k], t[(k + 1) % 3])).second)
                return false;
    for (uint64_t e : edges)
        if (!edges.contains(key(static_cast<uint32_t>(e & 0xffffffffu), static_cast<uint32_t>(e >> 32))))
            return false;
    return true;
}

std::unique_ptr<QOpenGLShaderProgram> buildProgram(const char* vertexPath, const char* fragmentPath) {
    auto program = std::make_unique<QOpenGLShaderProgram>();
    if (!program->addShaderFromSourceFile(QOpenGLShader::Vertex, QString::fromLatin1(vertexPath)) ||
        !program->addShaderFromSourceFile(QOpenGLShader::Fragment, QString::fromLatin1(fragmentPath)) ||
        !program->link()) {
        qWarning() << "rl::Renderer: shader" << vertexPath << fragmentPath << "failed:" << program->log();
        return nullptr;
    }
    return program;
}

double processCpuMs() {
    timespec t{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return static_cast<double>(t.tv_sec) * 1e3 + static_cast<double>(t.tv_nsec) * 1e-6;
}

// The batch's programs: the instanced vertex shader compiled with RL_BATCHED defined, so that both paths share
// their code.
std::unique_ptr<QOpenGLShaderProgram> buildBatchProgram(const char* vertexPath, const char* fragmentPath) {
    QFile vertexFile(QString::fromLatin1(vertexPath));
    if (!vertexFile.open(QIODevice::ReadOnly)) {
        qWarning() << "rl::Renderer: cannot read" << vertexPath;
        return nullptr;
    }
    QByteArray source = vertexFile.readAll();
    const qsizetype versionEnd = source.indexOf('\n') + 1; // the #version line must stay first
    source.insert(versionEnd, "#define RL_BATCHED 1\n");
    auto program = std::make_unique<QOpenGLShaderProgram>();
    if (!program->addShaderFromSourceCode(QOpenGLShader::Vertex, source) ||
        !program->addShaderFromSourceFile(QOpenGLShader::Fragment, QString::fromLatin1(fragmentPath)) ||
        !program->link()) {
        qWarning() << "rl::Renderer: batched shader" << vertexPath << "failed:" << program->log();
        return nullptr;
    }
    return program;
}

void setUniform(QOpenGLShaderProgram& program, const char* name, const glm::mat4& m) {
    program.setUniformValue(name, QMatrix4x4(glm::value_ptr(m)).transposed()); // glm is column-major
}
void setUniform(QOpenGLShaderProgram& program, const char* name, const glm::vec3& v) {
    program.setUniformValue(name, QVector3D(v.x, v.y, v.z));
}

} // namespace

Renderer::Renderer() = default;

Renderer::~Renderer() {
    // GL objects must have been released with the context current (Viewport's cleanup); only CPU data is left.
}

bool Renderer::initialize() {
    initShaderResources();
    initializeOpenGLFunctions();
    m_meshProgram = buildProgram(":/shaders/mesh.vert", ":/shaders/mesh.frag");
    m_outlineProgram = buildProgram(":/shaders/outline.vert", ":/shaders/flat.frag");
    m_backgroundProgram = buildProgram(":/shaders/background.vert", ":/shaders/background.frag");
    m_gridProgram = buildProgram(":/shaders/grid.vert", ":/shaders/grid.frag");
    m_overlayProgram = buildProgram(":/shaders/overlay.vert", ":/shaders/overlay.frag");
    m_batchProgram = buildBatchProgram(":/shaders/mesh.vert", ":/shaders/mesh.frag");
    m_batchOutlineProgram = buildBatchProgram(":/shaders/outline.vert", ":/shaders/flat.frag");
    if (!m_meshProgram || !m_outlineProgram || !m_backgroundProgram || !m_gridProgram || !m_overlayProgram ||
        !m_batchProgram || !m_batchOutlineProgram) {
        // Leave nothing half-built: the widget then shows nothing rather than drawing with missing programs.
        m_meshProgram.reset();
        m_batchProgram.reset();
        m_batchOutlineProgram.reset();
        m_outlineProgram.reset();
        m_backgroundProgram.reset();
        m_gridProgram.reset();
        m_overlayProgram.reset();
        return false;
    }
    glGenVertexArrays(1, &m_emptyVao);
    glGenBuffers(1, &m_instanceBuffer);
    glGenTextures(1, &m_instanceTexture);
    glGenBuffers(1, &m_selectionBuffer);
    m_instanceBufferCapacity = 0;
    m_selectionBufferCapacity = 0;
    glGenTextures(kOverlaySlots, m_overlayTextures);
    std::fill(std::begin(m_overlayKeys), std::end(m_overlayKeys), 0);
    // A new context has none of the old buffers: upload everything again.
    m_meshesDirty = true;
    m_instancesDirty = true;
    m_selectionDirty = true;
    m_initialized = true;
    return true;
}

void Renderer::release() {
    if (!m_initialized)
        return;
    releaseMeshes();
    releaseStaticLayer();
    glDeleteBuffers(1, &m_instanceBuffer);
    glDeleteTextures(1, &m_instanceTexture);
    m_instanceTexture = 0;
    glDeleteBuffers(1, &m_selectionBuffer);
    m_selectionBuffer = 0;
    m_selectionBufferCapacity = 0;
    glDeleteVertexArrays(1, &m_emptyVao);
    glDeleteTextures(kOverlaySlots, m_overlayTextures);
    std::fill(std::begin(m_overlayTextures), std::end(m_overlayTextures), 0u);
    std::fill(std::begin(m_overlayKeys), std::end(m_overlayKeys), 0);
    m_instanceBuffer = 0;
    m_emptyVao = 0;
    m_instanceBufferCapacity = 0;
    m_meshProgram.reset();
    m_batchProgram.reset();
    m_batchOutlineProgram.reset();
    m_outlineProgram.reset();
    m_backgroundProgram.reset();
    m_gridProgram.reset();
    m_overlayProgram.reset();
    m_initialized = false;
}

void Renderer::releaseMeshes() {
    for (MeshGl& gl : m_meshGl) {
        glDeleteVertexArrays(1, &gl.vao);
        glDeleteBuffers(1, &gl.vertexBuffer);
        glDeleteBuffers(1, &gl.indexBuffer);
    }
    m_meshGl.clear();
    if (m_batchVao)
        glDeleteVertexArrays(1, &m_batchVao);
    if (m_batchVertexBuffer)
        glDeleteBuffers(1, &m_batchVertexBuffer);
    if (m_batchIndexBuffer)
        glDeleteBuffers(1, &m_batchIndexBuffer);
    m_batchVao = m_batchVertexBuffer = m_batchIndexBuffer = 0;
    m_batchClosedIndices = m_batchOpenIndices = 0;
}

void Renderer::setScene(const ViewportScene& scene) {
    anchorsChanged();
    m_meshes = scene.meshes;
    m_ranges.assign(m_meshes.size(), MeshRange{});
    for (size_t m = 0; m < m_meshes.size(); ++m) {
        const Bounds b = m_meshes[m].bounds();
        m_ranges[m].centre = b.isEmpty() ? glm::vec3(0.0f) : b.centre();
        m_ranges[m].radius = b.isEmpty() ? 0.0f : 0.5f * glm::length(b.size());
        m_ranges[m].closed = isClosed(m_meshes[m]);
    }
    // Group instances by mesh (a counting sort) so that each mesh's instances are one contiguous range.
    const int meshCount = static_cast<int>(m_meshes.size());
    for (const ViewportInstance& inst : scene.instances)
        if (inst.meshIndex >= 0 && inst.meshIndex < meshCount)
            ++m_ranges[inst.meshIndex].instanceCount;
    int first = 0;
    size_t batchVertices = 0;
    for (size_t m = 0; m < m_ranges.size(); ++m) {
        MeshRange& range = m_ranges[m];
        range.firstInstance = first;
        first += range.instanceCount;
        const size_t vertices = m_meshes[m].vertices.size() * static_cast<size_t>(range.instanceCount);
        range.batched = range.instanceCount > 0 && range.instanceCount < kBatchBelowInstances &&
                        !m_meshes[m].triangles.empty() && batchVertices + vertices <= kBatchMaxVertices;
        if (range.batched)
            batchVertices += vertices;
    }
    m_instances.assign(first, InstanceData{});
    m_slotOfInstance.assign(scene.instances.size(), -1);
    std::vector<int> next(m_ranges.size());
    for (size_t m = 0; m < m_ranges.size(); ++m)
        next[m] = m_ranges[m].firstInstance;
    for (size_t i = 0; i < scene.instances.size(); ++i) {
        const int mesh = scene.instances[i].meshIndex;
        if (mesh >= 0 && mesh < meshCount)
            m_slotOfInstance[i] = next[mesh]++;
    }
    m_meshesDirty = true;
    setInstanceAttributes(scene);
}

void Renderer::setInstanceAttributes(const ViewportScene& scene) {
    const size_t count = std::min(scene.instances.size(), m_slotOfInstance.size());
    for (size_t i = 0; i < count; ++i) {
        const int slot = m_slotOfInstance[i];
        if (slot < 0)
            continue;
        const ViewportInstance& inst = scene.instances[i];
        InstanceData& data = m_instances[slot];
        const glm::vec4 colourFlags(inst.colour, static_cast<float>(inst.flags));
        // An anchor that changes, or a body that becomes or stops being one, changes the static layer.
        const bool wasAnchor = data.flags() & kInstanceAnchor;
        if ((wasAnchor || (inst.flags & kInstanceAnchor)) &&
            (data.model != inst.model || data.colourFlags != colourFlags))
            anchorsChanged();
        data.model = inst.model;
        data.colourFlags = colourFlags;
    }
    m_instancesDirty = true;
    gatherSelection();
}

void Renderer::gatherSelection() {
    // The outline passes draw only these copies, so a few selected bodies among 5,000 cost a few instances.
    m_selectedSlots.clear();
    m_selectedInBatch = 0;
    m_selectedRanges.assign(m_ranges.size(), SelectionRange{});
    for (size_t m = 0; m < m_ranges.size(); ++m) {
        m_selectedRanges[m].first = static_cast<int>(m_selectedSlots.size());
        const MeshRange& range = m_ranges[m];
        for (int slot = range.firstInstance; slot < range.firstInstance + range.instanceCount; ++slot) {
            const uint32_t flags = m_instances[slot].flags();
            if ((flags & kInstanceSelected) && !(flags & kInstanceHidden))
                m_selectedSlots.push_back(slot);
        }
        m_selectedRanges[m].count = static_cast<int>(m_selectedSlots.size()) - m_selectedRanges[m].first;
        if (range.batched)
            m_selectedInBatch += m_selectedRanges[m].count;
    }
    m_selected.resize(m_selectedSlots.size());
    for (size_t k = 0; k < m_selectedSlots.size(); ++k)
        m_selected[k] = m_instances[m_selectedSlots[k]];
    m_selectionDirty = true;
}

void Renderer::setTransforms(std::span<const glm::mat4> models) {
    const size_t count = std::min(models.size(), m_slotOfInstance.size());
    for (size_t i = 0; i < count; ++i) {
        const int slot = m_slotOfInstance[i];
        if (slot < 0)
            continue;
        InstanceData& data = m_instances[slot];
        if ((data.flags() & kInstanceAnchor) && data.model != models[i])
            anchorsChanged();
        data.model = models[i];
    }
    m_instancesDirty = true;
    for (size_t k = 0; k < m_selectedSlots.size(); ++k)
        m_selected[k].model = m_instances[m_selectedSlots[k]].model;
    m_selectionDirty = m_selectionDirty || !m_selectedSlots.empty();
}

void Renderer::setInstanceTransforms(const ViewportScene& scene, std::span<const int> instances) {
    for (int i : instances) {
        if (i < 0 || i >= static_cast<int>(m_slotOfInstance.size()) || i >= static_cast<int>(scene.instances.size()))
            continue;
        const int slot = m_slotOfInstance[i];
        if (slot >= 0) {
            if (m_instances[slot].flags() & kInstanceAnchor)
                anchorsChanged();
            m_instances[slot].model = scene.instances[i].model;
            m_partialFirst = std::min(m_partialFirst, slot);
            m_partialLast = std::max(m_partialLast, slot);
        }
    }
    // Only these slots changed: unless a full upload is pending anyway, render() uploads just their range.
    m_partialDirty = !m_instancesDirty;
    for (size_t k = 0; k < m_selectedSlots.size(); ++k)
        m_selected[k].model = m_instances[m_selectedSlots[k]].model;
    m_selectionDirty = m_selectionDirty || !m_selectedSlots.empty();
}

void Renderer::uploadMeshes() {
    releaseMeshes();
    m_meshGl.resize(m_meshes.size());
    std::vector<FlatShadedMesh> flatMeshes;
    flatMeshes.reserve(m_meshes.size());
    for (size_t m = 0; m < m_meshes.size(); ++m) {
        MeshGl& gl = m_meshGl[m];
        const FlatShadedMesh& flat = flatMeshes.emplace_back(flatShaded(m_meshes[m]));
        gl.indexCount = static_cast<int>(flat.triangles.size() * 3);
        glGenVertexArrays(1, &gl.vao);
        glGenBuffers(1, &gl.vertexBuffer);
        glGenBuffers(1, &gl.indexBuffer);
        glBindVertexArray(gl.vao);
        glBindBuffer(GL_ARRAY_BUFFER, gl.vertexBuffer);
        glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(flat.vertices.size() * sizeof(FlatShadedVertex)),
                     flat.vertices.data(), GL_STATIC_DRAW);
        glEnableVertexAttribArray(kPositionLocation);
        glVertexAttribPointer(kPositionLocation, 3, GL_FLOAT, GL_FALSE, sizeof(FlatShadedVertex), nullptr);
        glEnableVertexAttribArray(kNormalLocation);
        glVertexAttribPointer(kNormalLocation, 3, GL_FLOAT, GL_FALSE, sizeof(FlatShadedVertex),
                              reinterpret_cast<const void*>(offsetof(FlatShadedVertex, normal)));
        glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, gl.indexBuffer);
        glBufferData(GL_ELEMENT_ARRAY_BUFFER, static_cast<GLsizeiptr>(flat.triangles.size() * 3 * sizeof(uint32_t)),
                     flat.triangles.data(), GL_STATIC_DRAW);
        for (GLuint column = 0; column < 4; ++column) {
            glEnableVertexAttribArray(kModelLocation + column);
            glVertexAttribDivisor(kModelLocation + column, 1);
        }
        glEnableVertexAttribArray(kColourFlagsLocation);
        glVertexAttribDivisor(kColourFlagsLocation, 1);
    }
    glBindVertexArray(0);
    buildBatch(flatMeshes);
    m_meshesDirty = false;
}

void Renderer::buildBatch(const std::vector<FlatShadedMesh>& flatMeshes) {
    // Vertices in shape coordinates with their instance's slot; the vertex shader takes the model matrix and the
    // colour from the instance buffer (as a buffer texture), so playback still uploads only the instances.
    struct BatchVertex {
        glm::vec3 position;
        float slot;
        glm::vec4 centreRadius; // the mesh's box centre and half diagonal, for the outline (see outline.vert)
        glm::vec3 normal;       // see flatShaded()
    };
    std::vector<BatchVertex> vertices;
    std::vector<uint32_t> closedIndices, openIndices;
    for (size_t m = 0; m < m_meshes.size() && m < m_ranges.size(); ++m) {
        const MeshRange& range = m_ranges[m];
        if (!range.batched)
            continue;
        const FlatShadedMesh& mesh = flatMeshes[m];
        std::vector<uint32_t>& indices = range.closed ? closedIndices : openIndices;
        for (int slot = range.firstInstance; slot < range.firstInstance + range.instanceCount; ++slot) {
            const auto base = static_cast<uint32_t>(vertices.size());
            for (const FlatShadedVertex& v : mesh.vertices)
                vertices.push_back(
                    {v.position, static_cast<float>(slot), glm::vec4(range.centre, range.radius), v.normal});
            for (const auto& t : mesh.triangles)
                for (uint32_t k : t)
                    indices.push_back(base + k);
        }
    }
    m_batchClosedIndices = static_cast<int>(closedIndices.size());
    m_batchOpenIndices = static_cast<int>(openIndices.size());
    if (vertices.empty())
        return;
    closedIndices.insert(closedIndices.end(), openIndices.begin(), openIndices.end());
    glGenVertexArrays(1, &m_batchVao);
    glGenBuffers(1, &m_batchVertexBuffer);
    glGenBuffers(1, &m_batchIndexBuffer);
    glBindVertexArray(m_batchVao);
    glBindBuffer(GL_ARRAY_BUFFER, m_batchVertexBuffer);
    glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(vertices.size() * sizeof(BatchVertex)), vertices.data(),
                 GL_STATIC_DRAW);
    glEnableVertexAttribArray(kPositionLocation);
    glVertexAttribPointer(kPositionLocation, 3, GL_FLOAT, GL_FALSE, sizeof(BatchVertex), nullptr);
    glEnableVertexAttribArray(kSlotLocation);
    glVertexAttribPointer(kSlotLocation, 1, GL_FLOAT, GL_FALSE, sizeof(BatchVertex),
                          reinterpret_cast<const void*>(offsetof(BatchVertex, slot)));
    glEnableVertexAttribArray(kCentreRadiusLocation);
    glVertexAttribPointer(kCentreRadiusLocation, 4, GL_FLOAT, GL_FALSE, sizeof(BatchVertex),
                          reinterpret_cast<const void*>(offsetof(BatchVertex, centreRadius)));
    glEnableVertexAttribArray(kNormalLocation);
    glVertexAttribPointer(kNormalLocation, 3, GL_FLOAT, GL_FALSE, sizeof(BatchVertex),
                          reinterpret_cast<const void*>(offsetof(BatchVertex, normal)));
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, m_batchIndexBuffer);
    glBufferData(GL_ELEMENT_ARRAY_BUFFER, static_cast<GLsizeiptr>(closedIndices.size() * sizeof(uint32_t)),
                 closedIndices.data(), GL_STATIC_DRAW);
    glBindVertexArray(0);
    glBindBuffer(GL_ARRAY_BUFFER, 0);
}

void Renderer::drawBatch(bool outlinePass) {
    if (!m_batchVao || m_batchClosedIndices + m_batchOpenIndices == 0)
        return;
    glActiveTexture(GL_TEXTURE1);
    glBindTexture(GL_TEXTURE_BUFFER, m_instanceTexture);
    glTexBuffer(GL_TEXTURE_BUFFER, GL_RGBA32F, m_instanceBuffer);
    (outlinePass ? m_batchOutlineProgram : m_batchProgram)->setUniformValue("uInstances", 1);
    glBindVertexArray(m_batchVao);
    if (outlinePass) {
        // Never culled: pushing vertices sideways can turn a silhouette face around.
        glDisable(GL_CULL_FACE);
        glDrawElements(GL_TRIANGLES, m_batchClosedIndices + m_batchOpenIndices, GL_UNSIGNED_INT, nullptr);
        ++m_drawCalls;
    } else if (m_batchClosedIndices > 0) {
        glEnable(GL_CULL_FACE);
        // Drawn in parts, each handed to llvmpipe's rasteriser as soon as it is binned (see kTrianglesPerFlush).
        const int triangles = m_batchClosedIndices / 3;
        for (int begin = 0; begin < triangles; begin += kTrianglesPerFlush) {
            const int count = std::min(kTrianglesPerFlush, triangles - begin);
            glDrawElements(GL_TRIANGLES, 3 * count, GL_UNSIGNED_INT,
                           reinterpret_cast<const void*>(static_cast<size_t>(begin) * 3 * sizeof(uint32_t)));
            ++m_drawCalls;
            drewTriangles(count);
        }
    }
    if (m_batchOpenIndices > 0 && !outlinePass) {
        glDisable(GL_CULL_FACE);
        glDrawElements(GL_TRIANGLES, m_batchOpenIndices, GL_UNSIGNED_INT,
                       reinterpret_cast<const void*>(static_cast<size_t>(m_batchClosedIndices) * sizeof(uint32_t)));
        ++m_drawCalls;
    }
    glDisable(GL_CULL_FACE);
    glBindVertexArray(0);
    glBindTexture(GL_TEXTURE_BUFFER, 0);
    glActiveTexture(GL_TEXTURE0);
}

void Renderer::uploadInstances(unsigned buffer, size_t& capacity, const std::vector<InstanceData>& data) {
    glBindBuffer(GL_ARRAY_BUFFER, buffer);
    const size_t bytes = data.size() * sizeof(InstanceData);
    // Re-allocate when growing or when far too big; otherwise overwrite in place.
    if (bytes > capacity || bytes < capacity / 4) {
        glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(bytes), data.data(), GL_DYNAMIC_DRAW);
        capacity = bytes;
    } else if (bytes > 0) {
        glBufferSubData(GL_ARRAY_BUFFER, 0, static_cast<GLsizeiptr>(bytes), data.data());
    }
    glBindBuffer(GL_ARRAY_BUFFER, 0);
}

void Renderer::drewTriangles(size_t triangles) {
    m_trianglesSinceFlush += triangles;
    if (m_trianglesSinceFlush >= static_cast<size_t>(kTrianglesPerFlush)) {
        glFlush();
        m_trianglesSinceFlush = 0;
    }
}

void Renderer::drawMeshes(QOpenGLShaderProgram& program, bool outlinePass) {
    constexpr GLsizei stride = sizeof(InstanceData);
    for (size_t m = 0; m < m_meshGl.size() && m < m_ranges.size(); ++m) {
        const MeshRange& range = m_ranges[m];
        const MeshGl& gl = m_meshGl[m];
        const int first = outlinePass ? m_selectedRanges[m].first : range.firstInstance;
        const int instanceCount = outlinePass ? m_selectedRanges[m].count : range.instanceCount;
        if (instanceCount == 0 || gl.indexCount == 0 || (range.batched && (!outlinePass || m_outlineWithBatch)))
            continue;
        if (outlinePass) {
            setUniform(program, "uMeshCentre", range.centre);
            program.setUniformValue("uMeshRadius", range.radius);
        }
        // Open meshes (a flat anchor) are two-sided; closed ones show only their front faces anyway.
        // The outline pass pushes vertices sideways, which can turn a silhouette face around: never cull there.
        if (range.closed && !outlinePass)
            glEnable(GL_CULL_FACE);
        else
            glDisable(GL_CULL_FACE);
        glBindVertexArray(gl.vao);
        glBindBuffer(GL_ARRAY_BUFFER, outlinePass ? m_selectionBuffer : m_instanceBuffer);
        // Many instances go in parts of about kTrianglesPerFlush triangles.
        const int meshTriangles = gl.indexCount / 3;
        const int perPart = outlinePass ? instanceCount : std::max(1, kTrianglesPerFlush / std::max(1, meshTriangles));
        for (int part = 0; part < instanceCount; part += perPart) {
            // The instance attributes start at this part: GL 3.3 has no base-instance draw.
            const auto base = static_cast<size_t>(first + part) * stride;
            for (GLuint column = 0; column < 4; ++column)
                glVertexAttribPointer(kModelLocation + column, 4, GL_FLOAT, GL_FALSE, stride,
                                      reinterpret_cast<const void*>(base + column * sizeof(glm::vec4)));
            glVertexAttribPointer(kColourFlagsLocation, 4, GL_FLOAT, GL_FALSE, stride,
                                  reinterpret_cast<const void*>(base + offsetof(InstanceData, colourFlags)));
            const int count = std::min(perPart, instanceCount - part);
            glDrawElementsInstanced(GL_TRIANGLES, gl.indexCount, GL_UNSIGNED_INT, nullptr, count);
            ++m_drawCalls;
            if (!outlinePass)
                drewTriangles(static_cast<size_t>(count) * static_cast<size_t>(meshTriangles));
        }
    }
    glBindVertexArray(0);
    glBindBuffer(GL_ARRAY_BUFFER, 0);
    glDisable(GL_CULL_FACE);
}

void Renderer::drawBodies(const glm::mat4& viewProjection, const glm::vec3& eye, const glm::vec3& light, int layer) {
    for (QOpenGLShaderProgram* program : {m_meshProgram.get(), m_batchProgram.get()}) {
        program->bind();
        setUniform(*program, "uViewProjection", viewProjection);
        setUniform(*program, "uEye", eye);
        setUniform(*program, "uKeyDirection", light);
        program->setUniformValue("uLayer", layer);
        if (program == m_batchProgram.get())
            drawBatch(false);
        else
            drawMeshes(*program, false);
    }
}

void Renderer::drawStaticLayer(const StaticKey& key, const RenderOptions& options, const glm::vec3& light) {
    // No colour clear: the background covers every pixel.
    glClearDepthf(1.0f);
    glClearStencil(0);
    glClear(GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
    endPhase(Clear);

    // Background gradient, behind everything and without touching depth.
    glDisable(GL_DEPTH_TEST);
    m_backgroundProgram->bind();
    setUniform(*m_backgroundProgram, "uTop", options.backgroundTop);
    setUniform(*m_backgroundProgram, "uBottom", options.backgroundBottom);
    glBindVertexArray(m_emptyVao);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    ++m_drawCalls;
    // The rasteriser paints the background while this thread shades the bodies' vertices.
    glFlush();
    m_trianglesSinceFlush = 0;
    endPhase(Background);

    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    drawBodies(key.viewProjection, key.eye, light, 1);
    endPhase(Bodies);

    // Ground grid: blended, depth-tested but not written, and pulled slightly forward so that it shows on a floor
    // whose top face lies in the plane y = 0.
    if (options.grid) {
        glEnable(GL_BLEND);
        // The destination alpha stays 1: a grabbed frame keeps its alpha, and a grid line must not turn it
        // translucent.
        glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ZERO, GL_ONE);
        glDepthMask(GL_FALSE);
        glDepthFunc(GL_LEQUAL);
        glEnable(GL_POLYGON_OFFSET_FILL);
        glPolygonOffset(-1.0f, -4.0f);
        const float fadeDistance = std::max(25.0f, 6.0f * key.distance);
        m_gridProgram->bind();
        setUniform(*m_gridProgram, "uViewProjection", key.viewProjection);
        setUniform(*m_gridProgram, "uEye", key.eye);
        m_gridProgram->setUniformValue("uFadeDistance", fadeDistance);
        m_gridProgram->setUniformValue("uCentre", QVector2D(key.eye.x, key.eye.z));
        m_gridProgram->setUniformValue("uExtent", fadeDistance);
        glBindVertexArray(m_emptyVao);
        glDrawArrays(GL_TRIANGLE_STRIP, 0, 4);
        ++m_drawCalls;
        glDisable(GL_POLYGON_OFFSET_FILL);
        glDisable(GL_BLEND);
        glDepthMask(GL_TRUE);
    }
    endPhase(Grid);
}

bool Renderer::buildStaticLayer(const StaticKey& key, const RenderOptions& options, const glm::vec3& light,
                                unsigned target) {
    if (!m_staticFbo || m_staticKey.width != key.width || m_staticKey.height != key.height) {
        releaseStaticLayer();
        glGenFramebuffers(1, &m_staticFbo);
        glGenRenderbuffers(1, &m_staticColour);
        glGenRenderbuffers(1, &m_staticDepth);
        glBindRenderbuffer(GL_RENDERBUFFER, m_staticColour);
        glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, key.width, key.height);
        glBindRenderbuffer(GL_RENDERBUFFER, m_staticDepth);
        glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH24_STENCIL8, key.width, key.height);
        glBindRenderbuffer(GL_RENDERBUFFER, 0);
        glBindFramebuffer(GL_FRAMEBUFFER, m_staticFbo);
        glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, m_staticColour);
        glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_RENDERBUFFER, m_staticDepth);
        if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) {
            glBindFramebuffer(GL_FRAMEBUFFER, target);
            releaseStaticLayer();
            m_staticSupported = false;
            return false;
        }
    }
    glBindFramebuffer(GL_FRAMEBUFFER, m_staticFbo);
    drawStaticLayer(key, options, light);
    glBindFramebuffer(GL_FRAMEBUFFER, target);
    m_staticKey = key;
    m_staticValid = true;
    ++m_staticBuilds;
    return true;
}

void Renderer::releaseStaticLayer() {
    // Names of 0 are ignored by glDelete*.
    glDeleteFramebuffers(1, &m_staticFbo);
    const unsigned renderbuffers[] = {m_staticColour, m_staticDepth};
    glDeleteRenderbuffers(2, renderbuffers);
    m_staticFbo = m_staticColour = m_staticDepth = 0;
    m_staticValid = false;
}

void Renderer::endPhase(Phase phase) {
    if (!m_profiling)
        return;
    glFinish();
    m_phaseMs[phase] += static_cast<double>(m_phaseTimer.nsecsElapsed()) * 1e-6;
    const double cpu = processCpuMs();
    m_phaseCpuMs[phase] += cpu - m_phaseCpuStart;
    m_phaseCpuStart = cpu;
    m_phaseTimer.restart();
}

void Renderer::render(const Camera& camera, int pixelWidth, int pixelHeight, const RenderOptions& options) {
    m_drawCalls = 0;
    if (!m_initialized)
        return;
    if (m_profiling) {
        m_phaseTimer.start();
        m_phaseCpuStart = processCpuMs();
    }
    std::fill(std::begin(m_phaseMs), std::end(m_phaseMs), 0.0);
    std::fill(std::begin(m_phaseCpuMs), std::end(m_phaseCpuMs), 0.0);
    if (m_meshesDirty)
        uploadMeshes();
    if (m_instancesDirty) {
        uploadInstances(m_instanceBuffer, m_instanceBufferCapacity, m_instances);
        m_instancesDirty = false;
    } else if (m_partialDirty && m_partialFirst <= m_partialLast &&
               static_cast<size_t>(m_partialLast) < m_instances.size() &&
               m_instanceBufferCapacity >= m_instances.size() * sizeof(InstanceData)) {
        // A gizmo drag moves a few instances: a full 5,000-instance upload per frame would cost far more.
        glBindBuffer(GL_ARRAY_BUFFER, m_instanceBuffer);
        glBufferSubData(GL_ARRAY_BUFFER, static_cast<GLintptr>(m_partialFirst * sizeof(InstanceData)),
                        static_cast<GLsizeiptr>((m_partialLast - m_partialFirst + 1) * sizeof(InstanceData)),
                        m_instances.data() + m_partialFirst);
        glBindBuffer(GL_ARRAY_BUFFER, 0);
    }
    m_partialDirty = false;
    m_partialFirst = std::numeric_limits<int>::max();
    m_partialLast = -1;
    if (m_selectionDirty) {
        uploadInstances(m_selectionBuffer, m_selectionBufferCapacity, m_selected);
        m_selectionDirty = false;
    }
    endPhase(Upload);

    const glm::mat4 viewProjection = camera.viewProjection();
    const glm::vec3 eye = camera.eye();
    // The key light is nearly a headlight, a little above and to the left of the camera: every face the user can
    // see gets some of it (also from below the floor), and neighbouring faces of a box still get different shades.
    const glm::vec3 light = glm::normalize(-camera.forward() + 0.25f * camera.up() - 0.25f * camera.right());

    StaticKey key;
    key.viewProjection = viewProjection;
    key.eye = eye;
    key.distance = camera.distance();
    key.width = pixelWidth;
    key.height = pixelHeight;
    key.grid = options.grid;
    key.backgroundTop = options.backgroundTop;
    key.backgroundBottom = options.backgroundBottom;
    key.generation = m_staticGeneration;
    const bool sameAsLastFrame = key == m_lastFrameKey;
    m_lastFrameKey = key;

    // State is set in full every frame: QPainter overlays drawn after us leave theirs behind.
    GLint target = 0; // the framebuffer to draw into: the window's, or the one grabFramebuffer() bound
    glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &target);
    glViewport(0, 0, pixelWidth, pixelHeight);
    glDisable(GL_SCISSOR_TEST);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glDepthMask(GL_TRUE);
    glStencilMask(0xFF);
    glCullFace(GL_BACK);
    glFrontFace(GL_CCW);
    glDisable(GL_CULL_FACE); // drawMeshes enables it per closed mesh
    glDisable(GL_BLEND);
    glDisable(GL_STENCIL_TEST);
    glDisable(GL_POLYGON_OFFSET_FILL);

    bool cached = false;
    if (m_staticCaching && m_staticSupported) {
        const bool fresh = m_staticValid && key == m_staticKey;
        if (fresh || sameAsLastFrame)
            cached = fresh || buildStaticLayer(key, options, light, static_cast<GLuint>(target));
        if (cached) {
            for (int k = 0; k < 16 && glGetError() != GL_NO_ERROR; ++k) {
                // earlier errors are not the copy's (bounded: a lost context keeps reporting one)
            }
            glBindFramebuffer(GL_READ_FRAMEBUFFER, m_staticFbo);
            glBindFramebuffer(GL_DRAW_FRAMEBUFFER, static_cast<GLuint>(target));
            glBlitFramebuffer(0, 0, pixelWidth, pixelHeight, 0, 0, pixelWidth, pixelHeight,
                              GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT, GL_NEAREST);
            glBindFramebuffer(GL_FRAMEBUFFER, static_cast<GLuint>(target));
            if (glGetError() != GL_NO_ERROR) {
                // The blit needs equal depth-stencil formats; a window whose buffers differ draws every frame.
                qWarning("rl::Renderer: the static layer cannot be copied to this framebuffer; drawing it each frame");
                m_staticSupported = false;
                cached = false;
            }
        }
        endPhase(StaticLayer);
    }
    m_lastFrameCached = cached;
    if (!cached)
        drawStaticLayer(key, options, light);

    // The moving bodies, over the static layer.
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    drawBodies(viewProjection, eye, light, 2);
    endPhase(Bodies);

    // Selection outline. Pass 1 marks the selected objects in the stencil; pass 2 draws them pushed outwards in
    // screen space where the stencil is clear, which leaves a ring of constant width around each silhouette.
    if (!m_selected.empty() && options.outlineWidthPixels > 0.0f) {
        m_outlineWithBatch = m_selectedInBatch > kBatchOutlineAbove;
        const QVector2D viewportSize(static_cast<float>(pixelWidth), static_cast<float>(pixelHeight));
        const QVector4D colour(options.outlineColour.r, options.outlineColour.g, options.outlineColour.b,
                               options.outlineColour.a);
        auto outlineDraws = [&](float widthPixels) {
            for (QOpenGLShaderProgram* program : {m_outlineProgram.get(), m_batchOutlineProgram.get()}) {
                const bool batch = program == m_batchOutlineProgram.get();
                if (batch && !m_outlineWithBatch)
                    continue;
                program->bind();
                setUniform(*program, "uViewProjection", viewProjection);
                setUniform(*program, "uEye", eye);
                program->setUniformValue("uViewportSize", viewportSize);
                program->setUniformValue("uColour", colour);
                program->setUniformValue("uWidthPixels", widthPixels);
                if (batch)
                    drawBatch(true);
                else
                    drawMeshes(*program, true);
            }
        };
        glEnable(GL_STENCIL_TEST);
        glDisable(GL_DEPTH_TEST);
        glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
        glDepthMask(GL_FALSE);
        glStencilFunc(GL_ALWAYS, 1, 0xFF);
        glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
        outlineDraws(0.0f);

        // Depth-tested at the object's nearest depth (see outline.vert): occluders hide the outline, the floor
        // the object stands on does not.
        glEnable(GL_DEPTH_TEST);
        glDepthFunc(GL_LEQUAL);
        glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
        glStencilFunc(GL_NOTEQUAL, 1, 0xFF);
        glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
        outlineDraws(options.outlineWidthPixels);

        glDisable(GL_STENCIL_TEST);
        glDepthMask(GL_TRUE);
    }
    endPhase(Outline);

    glBindVertexArray(0);
    glUseProgram(0);
}

void Renderer::drawOverlay(const QImage& image, int x, int y, int pixelWidth, int pixelHeight, int slot) {
    if (!m_initialized || image.isNull() || pixelWidth <= 0 || pixelHeight <= 0 || slot < 0 || slot >= kOverlaySlots)
        return;
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, m_overlayTextures[slot]);
    if (image.cacheKey() != m_overlayKeys[slot]) {
        const QImage rgba = image.convertToFormat(QImage::Format_RGBA8888_Premultiplied);
        glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
        glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, rgba.width(), rgba.height(), 0, GL_RGBA, GL_UNSIGNED_BYTE,
                     rgba.constBits());
        // Drawn 1:1 in device pixels, so nearest sampling keeps the QPainter antialiasing exactly as painted.
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
        m_overlayKeys[slot] = image.cacheKey();
    }
    const float x0 = 2.0f * static_cast<float>(x) / static_cast<float>(pixelWidth) - 1.0f;
    const float y1 = 1.0f - 2.0f * static_cast<float>(y) / static_cast<float>(pixelHeight);
    const float x1 = x0 + 2.0f * static_cast<float>(image.width()) / static_cast<float>(pixelWidth);
    const float y0 = y1 - 2.0f * static_cast<float>(image.height()) / static_cast<float>(pixelHeight);
    glViewport(0, 0, pixelWidth, pixelHeight);
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_STENCIL_TEST);
    glEnable(GL_BLEND);
    glBlendFunc(GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
    m_overlayProgram->bind();
    m_overlayProgram->setUniformValue("uRect", QVector4D(x0, y0, x1, y1));
    m_overlayProgram->setUniformValue("uImage", 0);
    glBindVertexArray(m_emptyVao);
    glDrawArrays(GL_TRIANGLE_STRIP, 0, 4);
    ++m_drawCalls;
    glBindVertexArray(0);
    glBindTexture(GL_TEXTURE_2D, 0);
    glDisable(GL_BLEND);
    glUseProgram(0);
}

} // namespace rl
