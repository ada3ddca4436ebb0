#version 330 core
// Bodies. Instanced: one draw per unique mesh, the model matrix and colour/flags come per instance (divisor 1).
// Batched (RL_BATCHED, defined by the renderer): meshes with few instances are merged into one vertex buffer whose
// vertices carry their instance's slot, and the instance data is read from the instance buffer as a buffer
// texture, five RGBA32F texels per instance (the four model columns, then colour and flags).
layout(location = 0) in vec3 aPosition;
layout(location = 8) in vec3 aNormal; // shape coordinates; the face normal where this vertex ends a triangle
#ifdef RL_BATCHED
layout(location = 1) in float aSlot;
uniform samplerBuffer uInstances;
#else
layout(location = 2) in vec4 aModel0;
layout(location = 3) in vec4 aModel1;
layout(location = 4) in vec4 aModel2;
layout(location = 5) in vec4 aModel3;
layout(location = 6) in vec4 aColourFlags; // rgb colour, a = flags as a float (exact below 2^24)
#endif

uniform mat4 uViewProjection;
uniform vec3 uEye;
uniform vec3 uKeyDirection; // unit, towards the key light (it follows the camera: above, left, behind)
uniform int uLayer;         // 0: every body; 1: anchors only (the static layer); 2: all but the anchors

// Lit colour of the face, taken from the triangle's last (provoking) vertex: the renderer turns every triangle to end
// on a vertex that carries its face normal, so the whole face gets one colour (Blender's faceted look).
flat out vec3 vColour;

const uint kAnchor = 1u;
const uint kSelected = 2u;
const uint kSleeping = 4u;
const uint kHidden = 8u;

void main() {
#ifdef RL_BATCHED
    int base = 5 * int(aSlot + 0.5);
    vec4 aColourFlags = texelFetch(uInstances, base + 4);
#endif
    uint flags = uint(aColourFlags.a + 0.5);
    bool anchor = (flags & kAnchor) != 0u;
    if ((flags & kHidden) != 0u || (uLayer == 1 && !anchor) || (uLayer == 2 && anchor)) {
        gl_Position = vec4(0.0, 0.0, 2.0, 1.0); // outside the clip volume: the triangle is dropped
        vColour = vec3(0.0);
        return;
    }
#ifdef RL_BATCHED
    mat4 model = mat4(texelFetch(uInstances, base), texelFetch(uInstances, base + 1), texelFetch(uInstances, base + 2),
                      texelFetch(uInstances, base + 3));
#else
    mat4 model = mat4(aModel0, aModel1, aModel2, aModel3);
#endif
    vec4 world = model * vec4(aPosition, 1.0);
    gl_Position = uViewProjection * world;

    // Anchors are a neutral grey whatever their colour so that static geometry never looks like a dynamic body.
    vec3 colour = anchor ? vec3(0.50, 0.50, 0.52) : aColourFlags.rgb;
    // Sleeping bodies are washed out a little; selected ones take an orange tint on top of the outline.
    if ((flags & kSleeping) != 0u)
        colour = mix(colour, vec3(dot(colour, vec3(0.299, 0.587, 0.114))), 0.5) * 0.85;
    if ((flags & kSelected) != 0u)
        colour = mix(colour, vec3(1.0, 0.55, 0.10), 0.35);

    // Models are rigid (rotation and translation), so the normal turns with the model's upper 3x3.
    vec3 n = normalize(mat3(model) * aNormal);
    // Two-sided: a flat anchor (a Blender plane) is lit from whichever side the camera sees. The triangle is
    // planar, so the side seen from this vertex is the side seen from all of it.
    if (dot(n, uEye - world.xyz) < 0.0)
        n = -n;
    // Hemisphere light: cool sky from above, warm dark bounce from below, so side faces differ from top faces.
    vec3 sky = vec3(0.66, 0.69, 0.75);
    vec3 ground = vec3(0.30, 0.28, 0.27);
    vec3 hemisphere = mix(ground, sky, 0.5 + 0.5 * n.y);
    float lambert = max(dot(n, uKeyDirection), 0.0);
    vec3 light = 0.06 + 0.50 * hemisphere + 0.50 * lambert * vec3(1.0, 0.98, 0.95);
    vColour = colour * light;
}
