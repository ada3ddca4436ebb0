#version 330 core
// One uniform colour: the selection outline.
uniform vec4 uColour;
out vec4 fragColour;

void main() { fragColour = uColour; }
