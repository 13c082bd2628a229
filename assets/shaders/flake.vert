// flake.vert: one point sprite per flake [ZCL], sized by perspective.
layout(location = 0) in vec4 a_flake; // xyz: position, w: drawn diameter (m)
out vec4 v_color;
void main() {
    vec3 p = a_flake.xyz;
    gl_Position = view_proj * vec4(p, 1.0);
    float px = a_flake.w * lens.x / max(gl_Position.w, 1e-3); // projected diameter
    float size = clamp(px, flake.x, flake.y);
    gl_PointSize = size;
    // A sprite enlarged to the minimum size keeps its true coverage; farther
    // flakes fade further ([SKY]: "further points are more translucent").
    float coverage = min(1.0, (px * px) / (size * size));
    float alpha = flake.z * coverage * exp(-distance(p, camera_pos.xyz) * flake.w);
    // Ice scatters light from every side: flakes stay bright away from the lamps.
    vec3 color = snow_color.rgb * min(vec3(0.75) + 0.5 * irradiance(vec3(0.0, 1.0, 0.0), p), vec3(1.0));
#ifdef FOG
    color = apply_fog(color, p);
#endif
    v_color = vec4(color, alpha);
}
