// body.frag: a moving body, lit like the scene's meshes. The sky map holds
// only static geometry [SKY], so a body never shades itself out of it: where
// the map shows the body open to the sky, its upward parts (the snowball's
// crown, the walker's head and shoulders, a box's top) wear snow in the snow
// material of shade(), as the meshes do.
in vec3 v_world;
in vec3 v_normal;
out vec4 frag_color;
uniform vec3 albedo;
uniform float snow_amount; // RenderSettings::body_snow

void main() {
    vec3 n = normalize(v_normal);
    // Snow stays only where the face is less steep than snow's angle of
    // repose (45 degrees, n.y 0.71, as the simulation's piles): a cap with a
    // soft rim, not the meshes' linear incline, which would grey a sphere's sides.
    float lies = smoothstep(0.6, 0.8, n.y);
    float cover = lies * sky_exposure(v_world, n) * snow_amount;
    float shadow;
    vec3 color = shade(albedo, cover, n, v_world, 0.0, shadow);
#ifdef FOG
    color = apply_fog(color, v_world);
#endif
    frag_color = frame_output(color, 1.0, cover, shadow);
}
