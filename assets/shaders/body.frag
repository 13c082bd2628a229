// body.frag: a moving body, lit like the scene's meshes but never whitened by
// the sky map (the map holds only static geometry, [SKY]).
in vec3 v_world;
in vec3 v_normal;
out vec4 frag_color;
uniform vec3 albedo;
void main() {
    vec3 n = normalize(v_normal);
    float shadow;
    vec3 color = shade(albedo, 0.0, n, v_world, 0.0, shadow);
#ifdef FOG
    color = apply_fog(color, v_world);
#endif
    frag_color = frame_output(color, 1.0, 0.0, shadow);
}
