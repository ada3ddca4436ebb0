#version 330 core
// A screen-aligned textured rectangle (the axis indicator), placed in NDC by uRect = (x0, y0, x1, y1).
uniform vec4 uRect;
out vec2 vUv;

void main() {
    vec2 corner = vec2((gl_VertexID & 1) != 0 ? 1.0 : 0.0, (gl_VertexID & 2) != 0 ? 1.0 : 0.0);
    // QImage rows run top to bottom, GL's v runs bottom to top.
    vUv = vec2(corner.x, 1.0 - corner.y);
    gl_Position = vec4(mix(uRect.xy, uRect.zw, corner), 0.0, 1.0);
}
