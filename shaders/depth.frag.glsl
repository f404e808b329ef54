#version 450 core
// Depth-only: the rasteriser writes gl_FragCoord.z into the depth attachment.
void main() {}
