#version 330 core
// Bodies. Instanced: one draw per unique mesh, the model matrix and colour/flags come per instance (divisor 1).
// Batched (RL_BATCHED, defined by the renderer): meshes with few instances are merged into one vertex buffer whose
// vertices carry their instance's slot, and the instance data is read from the instance buffer as a buffer
// texture, five RGBA32F texels per instance (the four model columns, then colour and flags).
layout(location = 0) in vec3 aPosition;
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

out vec3 vWorld;
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
    if ((flags & kHidden) != 0u) {
        gl_Position = vec4(0.0, 0.0, 2.0, 1.0); // outside the clip volume: the triangle is dropped
        vWorld = vec3(0.0);
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
    vWorld = world.xyz;
    gl_Position = uViewProjection * world;

    // Anchors are a neutral grey whatever their colour so that static geometry never looks like a dynamic body.
    vec3 colour = (flags & kAnchor) != 0u ? vec3(0.50, 0.50, 0.52) : aColourFlags.rgb;
    // Sleeping bodies are washed out a little; selected ones take an orange tint on top of the outline.
    if ((flags & kSleeping) != 0u)
        colour = mix(colour, vec3(dot(colour, vec3(0.299, 0.587, 0.114))), 0.5) * 0.85;
    if ((flags & kSelected) != 0u)
        colour = mix(colour, vec3(1.0, 0.55, 0.10), 0.35);
    vColour = colour;
}
