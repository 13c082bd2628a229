// common.glsl: prepended to every stage after "#version" and the variant
// #defines (FOG + one of FOG_EXPONENTIAL / FOG_HALF_LIFE / FOG_LAYERED,
// OCCLUSION). Mirrors render/gl/frame_block.hpp (std140).

layout(std140) uniform Frame {
    mat4 view_proj;
    mat4 inv_view_proj;
    vec4 camera_pos;   // xyz
    vec4 lens;         // x: pixels per metre at 1 m distance, y: near, z: far
    vec4 ambient;      // rgb
    vec4 sky;          // rgb
    vec4 sun;          // xyz: direction to the sun, w: intensity (0 when point lights exist)
    vec4 snow_color;   // rgb, w: how white exposed, sky-facing meshes get
    vec4 fog_color;    // rgb, w: density (1/m, exponential) or 1/D (half-life)
    vec4 fog_layer;    // x: bottom, y: top, z: table texels
    vec4 occlusion;    // xy: map origin (x0, z0), z: 1/texel, w: tolerance (m)
    vec4 occlusion_shear; // xy: (shear_x, shear_z): p lies in the texel of p.xz + shear * p.y
    vec4 flake;        // x: min px, y: max px, z: base alpha, w: 1/fade distance
    vec4 light_params; // x: falloff k in 1/(1 + k d^2)
    ivec4 counts;      // x: point lights, yz: occlusion map size
    vec4 light_pos[8]; // xyz, w: intensity
    vec4 light_color[8];
};

// Diffuse light arriving at p with normal n: ambient, the point lights
// ([WF §5]: three coloured lights) with a soft 1/(1 + k d^2) falloff, the sun.
vec3 irradiance(vec3 n, vec3 p) {
    // Hemispheric sky light: an overcast sky lights what faces up the most.
    vec3 light = ambient.rgb + sky.rgb * (0.35 * (0.5 + 0.5 * n.y)) +
                 sun.w * max(dot(n, sun.xyz), 0.0) * vec3(1.0);
    for (int i = 0; i < counts.x; ++i) {
        vec3 to_light = light_pos[i].xyz - p;
        float dist2 = max(dot(to_light, to_light), 1e-8);
        float lambert = max(dot(n, to_light * inversesqrt(dist2)), 0.0);
        light += light_color[i].rgb * (light_pos[i].w * lambert / (1.0 + light_params.x * dist2));
    }
    return light;
}

#ifdef FOG
#if defined(FOG_EXPONENTIAL)
// [SKY]: fogFactor = e^(-density * z), z taken as the distance to the eye
float fog_transmittance(vec3 p) {
    return exp(-fog_color.w * distance(p, camera_pos.xyz));
}
#elif defined(FOG_HALF_LIFE)
// [PE]: light is halved every D metres, 0.5^(d/D)
float fog_transmittance(vec3 p) {
    return exp2(-distance(p, camera_pos.xyz) * fog_color.w);
}
#elif defined(FOG_LAYERED)
// [PE] layered mist: texel i holds (E(y_i), density(y_i)), E the integral
// of the density from below the layer; interpolated exactly with texelFetch.
uniform sampler1D fog_table;
vec2 fog_lookup(float y) {
    float last = fog_layer.z - 1.0;
    float t = clamp((y - fog_layer.x) / (fog_layer.y - fog_layer.x), 0.0, 1.0) * last;
    int i = min(int(t), int(last) - 1);
    return mix(texelFetch(fog_table, i, 0).rg, texelFetch(fog_table, i + 1, 0).rg, t - float(i));
}
float fog_transmittance(vec3 p) {
    vec3 a = camera_pos.xyz;
    float d = distance(p, a);
    float dy = p.y - a.y;
    // (E(yB) - E(yA)) / cos(theta), cos(theta) = |dy| / d; a level ray reads the density.
    float depth = abs(dy) > 1e-3 ? abs(fog_lookup(p.y).r - fog_lookup(a.y).r) * (d / abs(dy))
                                 : fog_lookup(0.5 * (a.y + p.y)).g * d;
    return exp2(-depth); // 0.5^density
}
#endif
vec3 apply_fog(vec3 color, vec3 p) {
    return mix(fog_color.rgb, color, fog_transmittance(p));
}
#endif
