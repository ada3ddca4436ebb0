#version 330 core
// Faceted shading: the face normal comes from screen-space derivatives of the world position, so every triangle
// is flat (Blender's faceted look) without duplicating vertices per face.
in vec3 vWorld;
flat in vec3 vColour;

uniform vec3 uEye;
uniform vec3 uKeyDirection; // unit, towards the key light (it follows the camera: above, left, behind)

out vec4 fragColour;

void main() {
    vec3 n = normalize(cross(dFdx(vWorld), dFdy(vWorld)));
    // Two-sided: a flat anchor (a Blender plane) is lit from whichever side the camera sees.
    if (dot(n, uEye - vWorld) < 0.0)
        n = -n;
    // Hemisphere light: cool sky from above, warm dark bounce from below, so side faces differ from top faces.
    vec3 sky = vec3(0.66, 0.69, 0.75);
    vec3 ground = vec3(0.30, 0.28, 0.27);
    vec3 hemisphere = mix(ground, sky, 0.5 + 0.5 * n.y);
    float lambert = max(dot(n, uKeyDirection), 0.0);
    vec3 light = 0.06 + 0.50 * hemisphere + 0.50 * lambert * vec3(1.0, 0.98, 0.95);
    fragColour = vec4(vColour * light, 1.0);
}
