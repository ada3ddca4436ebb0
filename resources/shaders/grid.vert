#version 330 core
// The ground grid is one large quad on the XZ plane around the point the camera looks at; the lines are
// computed per pixel in grid.frag, so no line geometry is needed and lines stay one pixel wide at any zoom.
uniform mat4 uViewProjection;
uniform vec2 uCentre;   // XZ
uniform float uExtent;  // half size of the quad, metres

out vec3 vWorld;

void main() {
    vec2 corner = vec2((gl_VertexID & 1) != 0 ? 1.0 : -1.0, (gl_VertexID & 2) != 0 ? 1.0 : -1.0);
    vec2 xz = uCentre + corner * uExtent;
    vWorld = vec3(xz.x, 0.0, xz.y);
    gl_Position = uViewProjection * vec4(vWorld, 1.0);
}
