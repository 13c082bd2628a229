// spectral_snow.vert: sky.vert's screen-covering triangle, but at the NDC depth
// of the layer's start, so the depth test drops every pixel whose surface is
// nearer than the far-field snow before the fragment shader runs.
uniform float layer_ndc_depth;
out vec2 v_ndc;
void main() {
    vec2 corner = vec2(float((gl_VertexID << 1) & 2), float(gl_VertexID & 2));
    v_ndc = corner * 2.0 - 1.0;
    gl_Position = vec4(v_ndc, layer_ndc_depth, 1.0);
}
