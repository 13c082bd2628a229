// mesh.frag: lit scene meshes, whitened where snow reaches them [SKY]:
// incline coefficient dot(N, up) times exposure to the sky from the occlusion map
// (a scene without one has no snow on its meshes).
in vec3 v_world;
in vec3 v_normal;
out vec4 frag_color;
uniform vec3 albedo;

#ifdef OCCLUSION
uniform sampler2D occlusion_map; // r: highest geometry y per texel
float exposed(ivec2 t, float y) {
    if (any(lessThan(t, ivec2(0))) || any(greaterThanEqual(t, counts.yz))) {
        return 1.0; // outside the map nothing covers the sky
    }
    return y >= texelFetch(occlusion_map, t, 0).r ? 1.0 : 0.0;
}
// Like a shadow-map test [SKY step 2], filtered over the 4 nearest texels.
// The map holds heights at texel centres up to 1.5 texels away, which a slope
// (rise per metre, from the normal) lifts above the fragment: the tolerance
// grows with it, like a shadow map's slope-scaled bias, or sloped roofs stripe
// at every texel row.
float sky_exposure(vec3 p, vec3 n) {
    float slope = sqrt(max(1.0 - n.y * n.y, 0.0)) / max(n.y, 0.25);
    float y = p.y + occlusion.w + 1.5 * slope / occlusion.z;
    vec2 t = (p.xz + occlusion_shear.xy * p.y - occlusion.xy) * occlusion.z - 0.5;
    ivec2 i = ivec2(floor(t));
    vec2 f = t - vec2(i);
    float e00 = exposed(i, y);
    float e10 = exposed(i + ivec2(1, 0), y);
    float e01 = exposed(i + ivec2(0, 1), y);
    float e11 = exposed(i + ivec2(1, 1), y);
    return mix(mix(e00, e10, f.x), mix(e01, e11, f.x), f.y);
}
#else
// No sky map: the simulation tracks no snow on the meshes, so none is drawn.
float sky_exposure(vec3 p, vec3 n) { return 0.0; }
#endif

void main() {
    vec3 n = normalize(gl_FrontFacing ? v_normal : -v_normal);
    float incline = clamp(n.y, 0.0, 1.0); // [SKY step 3]
    float cover = incline * sky_exposure(v_world, n) * snow_color.w;
    float shadow;
    vec3 color = shade(albedo, cover, n, v_world, 0.0, shadow);
#ifdef FOG
    color = apply_fog(color, v_world);
#endif
    frag_color = frame_output(color, 1.0, cover, shadow);
}
