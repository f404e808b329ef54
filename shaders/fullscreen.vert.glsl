#version 450 core
// One triangle covering the viewport (no vertex buffer: positions from gl_VertexID); at depth
// 0 with AT_NEAR, else at 0.5.
void main() {
    vec2 p = vec2((gl_VertexID << 1) & 2, gl_VertexID & 2);
#ifdef AT_NEAR
    gl_Position = vec4(p * 2.0 - 1.0, -1.0, 1.0);
#else
    gl_Position = vec4(p * 2.0 - 1.0, 0.0, 1.0);
#endif
}
