#version 330 core
// Faceted shading: the face was lit once, at its triangle's last vertex (mesh.vert); every pixel takes that colour.
// Under llvmpipe the per-pixel normal from screen-space derivatives cost a third of the 5,000-box frame.
flat in vec3 vColour;

out vec4 fragColour;

void main() {
    fragColour = vec4(vColour, 1.0);
}
