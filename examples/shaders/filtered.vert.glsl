// filtered.vert.glsl — texfilter example: one triangle that covers the whole viewport, built from
// gl_VertexIndex (no vertex buffer). The fragment shader does all the work.
#version 450

void main()
{
    // Vertices (-1,-1), (3,-1), (-1,3): the part inside the viewport is the full screen.
    vec2 corner = vec2((gl_VertexIndex << 1) & 2, gl_VertexIndex & 2);
    gl_Position = vec4(2.0 * corner - 1.0, 0.0, 1.0);
}
