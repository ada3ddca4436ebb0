#version 330 core
// Selected instances only, pushed outwards in screen space from the instance's centre by uWidthPixels:
// drawn where the stencil does not already hold the object, this leaves a constant-width outline.
// Batched (RL_BATCHED): the whole batch is drawn, instance data come from the instance buffer (see mesh.vert) and
// the mesh's centre and radius per vertex; the unselected instances are dropped here.
layout(location = 0) in vec3 aPosition;
#ifdef RL_BATCHED
layout(location = 1) in float aSlot;
layout(location = 7) in vec4 aCentreRadius;
uniform samplerBuffer uInstances;
#else
layout(location = 2) in vec4 aModel0;
layout(location = 3) in vec4 aModel1;
layout(location = 4) in vec4 aModel2;
layout(location = 5) in vec4 aModel3;
layout(location = 6) in vec4 aColourFlags;
uniform vec3 uMeshCentre;    // centre of the mesh's box in shape coordinates
uniform float uMeshRadius;   // half the box diagonal, shape coordinates
#endif

uniform mat4 uViewProjection;
uniform vec3 uEye;
uniform vec2 uViewportSize;  // pixels
uniform float uWidthPixels;  // 0 for the stencil mask pass

const uint kSelected = 2u;
const uint kHidden = 8u;

void main() {
#ifdef RL_BATCHED
    int base = 5 * int(aSlot + 0.5);
    vec4 aColourFlags = texelFetch(uInstances, base + 4);
    uint flags = uint(aColourFlags.a + 0.5);
    if ((flags & kSelected) == 0u) {
        gl_Position = vec4(0.0, 0.0, 2.0, 1.0); // not selected: dropped before any other work
        return;
    }
    mat4 model = mat4(texelFetch(uInstances, base), texelFetch(uInstances, base + 1), texelFetch(uInstances, base + 2),
                      texelFetch(uInstances, base + 3));
    vec3 uMeshCentre = aCentreRadius.xyz;
    float uMeshRadius = aCentreRadius.w;
#else
    uint flags = uint(aColourFlags.a + 0.5);
    mat4 model = mat4(aModel0, aModel1, aModel2, aModel3);
#endif
    vec4 clip = uViewProjection * model * vec4(aPosition, 1.0);
    vec4 centreWorld = model * vec4(uMeshCentre, 1.0);
    vec4 centre = uViewProjection * centreWorld;
    if ((flags & kSelected) == 0u || (flags & kHidden) != 0u || centre.w <= 0.0 || clip.w <= 0.0) {
        gl_Position = vec4(0.0, 0.0, 2.0, 1.0); // outside the clip volume: dropped
        return;
    }
    vec2 away = clip.xy / clip.w - centre.xy / centre.w;
    if (dot(away, away) > 1e-12)
        clip.xy += normalize(away * uViewportSize) * (2.0 * uWidthPixels / uViewportSize) * clip.w;

    // The ring takes the depth of the object's nearest possible point (its bounding sphere towards the eye):
    // anything in front of the whole object hides it, the ground just behind the silhouette does not.
    float scale = max(length(model[0].xyz), max(length(model[1].xyz), length(model[2].xyz)));
    vec3 towardsEye = uEye - centreWorld.xyz;
    float eyeDistance = length(towardsEye);
    float reach = min(uMeshRadius * scale, 0.99 * eyeDistance);
    vec4 nearest = uViewProjection * vec4(centreWorld.xyz + towardsEye / max(eyeDistance, 1e-6) * reach, 1.0);
    float ndcDepth = clamp(nearest.z / nearest.w, -1.0, 1.0);
    clip.z = ndcDepth * clip.w;
    gl_Position = clip;
}
