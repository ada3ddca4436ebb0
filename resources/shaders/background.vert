#version 330 core
// A full-screen triangle from gl_VertexID alone (no vertex buffer): covers the viewport with one primitive.
out float vHeight;

void main() {
    vec2 p = vec2((gl_VertexID == 1) ? 3.0 : -1.0, (gl_VertexID == 2) ? 3.0 : -1.0);
    vHeight = 0.5 * (p.y + 1.0);
    gl_Position = vec4(p, 1.0, 1.0);
}
