#version 450 core
in vec3 vColour;
layout(location = 0) out vec4 fragColour;
void main() {
    fragColour = vec4(vColour, 1.0);
}
