// mesh.frag: lit scene meshes, whitened where snow reaches them [SKY]:
// incline coefficient dot(N, up) times exposure to the sky from the occlusion map
// (a scene without one has no snow on its meshes). With TEXTURE the albedo
// is the base colour factor times the glTF base colour texture.
in vec3 v_world;
in vec3 v_normal;
out vec4 frag_color;
uniform vec3 albedo;
#ifdef TEXTURE
in vec2 v_texcoord;
uniform sampler2D base_color_texture;
#endif

void main() {
    vec3 n = normalize(gl_FrontFacing ? v_normal : -v_normal);
    float incline = clamp(n.y, 0.0, 1.0); // [SKY step 3]
    float cover = incline * sky_exposure(v_world, n) * snow_color.w;
    vec3 base = albedo;
#ifdef TEXTURE
    base *= texture(base_color_texture, v_texcoord).rgb;
#endif
    float shadow;
    vec3 color = shade(base, cover, n, v_world, 0.0, shadow);
#ifdef FOG
    color = apply_fog(color, v_world);
#endif
    frag_color = frame_output(color, 1.0, cover, shadow);
}
