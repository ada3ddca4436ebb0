#version 330 core
// Grid lines every 1 m and, stronger, every 10 m; the X axis red and the Z axis blue as in Blender.
// Lines fade out where they would be denser than a few pixels (no moire) and with distance from the eye.
// One fwidth() serves every line family: under llvmpipe the grid covers much of the screen, so it is kept lean.
in vec3 vWorld;

uniform vec3 uEye;
uniform float uFadeDistance; // metres from the eye where the grid has vanished

out vec4 fragColour;

// Coverage (0..1) of lines every `spacing` metres, about widthPixels wide; metresPerPixel from fwidth(xz).
float lines(vec2 xz, vec2 metresPerPixel, float spacing, float widthPixels) {
    vec2 c = xz / spacing;
    vec2 w = max(metresPerPixel / spacing, vec2(1e-6));
    vec2 distancePixels = abs(fract(c - 0.5) - 0.5) / w;
    float d = min(distancePixels.x, distancePixels.y);
    float coverage = 1.0 - smoothstep(0.5 * widthPixels - 0.5, 0.5 * widthPixels + 0.5, d);
    // Cells narrower than about 4 pixels would alias: fade them out as they shrink.
    return coverage * (1.0 - smoothstep(0.12, 0.30, max(w.x, w.y)));
}

void main() {
    vec2 xz = vWorld.xz;
    vec2 metresPerPixel = fwidth(xz);
    float minor = lines(xz, metresPerPixel, 1.0, 1.0);
    float major = lines(xz, metresPerPixel, 10.0, 1.6);
    // Distance in pixels to the X axis (the line z = 0) and to the Z axis (x = 0).
    vec2 axisPixels = abs(xz) / max(metresPerPixel, vec2(1e-6));
    float xAxis = 1.0 - smoothstep(0.5, 1.5, axisPixels.y);
    float zAxis = 1.0 - smoothstep(0.5, 1.5, axisPixels.x);
    float fade = 1.0 - smoothstep(0.35 * uFadeDistance, uFadeDistance, distance(uEye, vWorld));

    vec4 colour = vec4(0.42, 0.42, 0.42, 0.45 * minor);
    colour = mix(colour, vec4(0.50, 0.50, 0.50, 0.75), major);
    colour = mix(colour, vec4(0.85, 0.25, 0.28, 0.9), xAxis);
    colour = mix(colour, vec4(0.25, 0.45, 0.90, 0.9), zAxis);
    // No discard: it would stop llvmpipe from rejecting hidden grid pixels by depth before shading them.
    fragColour = vec4(colour.rgb, colour.a * fade);
}
