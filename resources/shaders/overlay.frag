#version 330 core
// The overlay image is premultiplied (QImage::Format_RGBA8888_Premultiplied): blended with ONE, 1 - alpha.
in vec2 vUv;
uniform sampler2D uImage;
out vec4 fragColour;

void main() { fragColour = texture(uImage, vUv); }
