// surface.frag: settled snow laid over the scene below by its incline [SKY],
// fading where it thins below min_depth to the bare top (a sharp rim where
// the depth crosses it). Lit and fogged per sample by surface.vert, or, with
// a sun, here per fragment: its shadows, detail normals, the blue inside
// hollows and the glints (shade() in common.glsl) are finer than the samples.
in vec4 v_color;
in float v_depth;
#ifdef SUN
in vec3 v_world;
in vec3 v_normal;
in float v_hollow;
#endif
out vec4 frag_color;
uniform float min_depth; // metres of snow below which the bare top shows

void main() {
    float alpha = v_color.a * smoothstep(min_depth, 2.0 * min_depth, v_depth);
#ifdef SUN
    float shadow;
    vec3 color = shade(vec3(0.0), 1.0, normalize(v_normal), v_world, v_hollow, shadow);
#ifdef FOG
    color = apply_fog(color, v_world);
#endif
#else
    float shadow = 0.0;
    vec3 color = v_color.rgb;
#endif
    frag_color = frame_output(color, alpha, 1.0, shadow);
}
