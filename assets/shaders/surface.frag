// surface.frag: settled snow, lit; bare cells are left to the mesh below.
in vec3 v_world;
in vec3 v_normal;
in float v_depth;
out vec4 frag_color;
uniform float min_depth; // metres of snow below which a fragment shows the bare top
void main() {
    if (v_depth < min_depth) {
        discard;
    }
    vec3 n = normalize(gl_FrontFacing ? v_normal : -v_normal);
    vec3 color = snow_color.rgb * irradiance(n, v_world);
#ifdef FOG
    color = apply_fog(color, v_world);
#endif
    frag_color = vec4(color, 1.0);
}
