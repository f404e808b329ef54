#version 450 core
// --debug-view light-frusta: world-space line vertices with a colour each.
layout(location = 0) in vec3 aPosition;
layout(location = 1) in vec3 aColour;
layout(location = 0) uniform mat4 uClipFromWorld;
out vec3 vColour;
void main() {
    vColour = aColour;
    gl_Position = uClipFromWorld * vec4(aPosition, 1.0);
}
