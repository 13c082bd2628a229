// surface.frag: settled snow, lit and fogged per sample by surface.vert and
// laid over the scene below by its incline [SKY], fading where it thins
// below min_depth to the bare top (a sharp rim where the depth crosses it).
in vec4 v_color;
in float v_depth;
out vec4 frag_color;
uniform float min_depth; // metres of snow below which the bare top shows
void main() {
    frag_color = vec4(v_color.rgb, v_color.a * smoothstep(min_depth, 2.0 * min_depth, v_depth));
}
