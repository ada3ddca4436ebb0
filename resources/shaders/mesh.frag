#version 330 core
// Faceted shading: the face was lit once, at its triangle's last vertex (mesh.vert); every pixel takes that colour.
// Under llvmpipe, drawing 5,000 boxes took 11.5-12 ms with a per-pixel normal from screen-space derivatives and
// 7.2-9.5 ms with a flat colour (two runs each).
flat in vec3 vColour;

out vec4 fragColour;

void main() {
    fragColour = vec4(vColour, 1.0);
}
