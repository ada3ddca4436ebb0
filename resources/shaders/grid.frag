#version 330 core
// Grid lines every 1 m and, stronger, every 10 m; the X axis red and the Z axis blue as in Blender.
// Lines fade out where they would be denser than a few pixels (no moire) and with distance from the eye.
in vec3 vWorld;

uniform vec3 uEye;
uniform float uFadeDistance; // metres from the eye where the grid has vanished

out vec4 fragColour;

// Coverage (0..1) of lines every `spacing` metres, about widthPixels wide.
float lines(vec2 coord, float spacing, float widthPixels) {
    vec2 c = coord / spacing;
    vec2 w = fwidth(c);
    vec2 distancePixels = abs(fract(c - 0.5) - 0.5) / max(w, vec2(1e-6));
    float d = min(distancePixels.x, distancePixels.y);
    float coverage = 1.0 - smoothstep(0.5 * widthPixels - 0.5, 0.5 * widthPixels + 0.5, d);
    // Cells narrower than about 4 pixels would alias: fade them out as they shrink.
    float density = max(w.x, w.y);
    return coverage * (1.0 - smoothstep(0.12, 0.30, density));
}

float axisLine(float coord, float widthPixels) {
    float d = abs(coord) / max(fwidth(coord), 1e-6);
    return 1.0 - smoothstep(0.5 * widthPixels - 0.5, 0.5 * widthPixels + 0.5, d);
}

void main() {
    vec2 xz = vWorld.xz;
    float minor = lines(xz, 1.0, 1.0);
    float major = lines(xz, 10.0, 1.6);
    float fade = 1.0 - smoothstep(0.35 * uFadeDistance, uFadeDistance, distance(uEye, vWorld));

    vec4 colour = vec4(0.42, 0.42, 0.42, 0.45 * minor);
    colour = mix(colour, vec4(0.50, 0.50, 0.50, 0.75), major);
    float xAxis = axisLine(vWorld.z, 2.0); // the line z = 0 is the X axis
    float zAxis = axisLine(vWorld.x, 2.0);
    colour = mix(colour, vec4(0.85, 0.25, 0.28, 0.9), xAxis);
    colour = mix(colour, vec4(0.25, 0.45, 0.90, 0.9), zAxis);
    // No discard: it would stop llvmpipe from rejecting hidden grid pixels by depth before shading them.
    fragColour = vec4(colour.rgb, colour.a * fade);
}
