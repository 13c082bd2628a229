// common.glsl: prepended to every stage after "#version" and the variant
// #defines (FOG + one of FOG_EXPONENTIAL / FOG_HALF_LIFE / FOG_LAYERED,
// OCCLUSION, SUN, SUN_SHADOWS). Mirrors render/gl/frame_block.hpp (std140).

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
    vec4 sun_color;    // rgb: a Sun's colour x intensity, w: exposure
    vec4 view_forward; // xyz: the camera's forward axis
    vec4 cascade_far;  // xyz: view depth where each shadow cascade ends
    vec4 cascade_texel; // xyz: metres per shadow texel, w: 1 / texels of a cascade
    vec4 snow_detail;  // x: detail normals, y: sparkle (1 on, 0 off)
    ivec4 counts;      // x: point lights, yz: occlusion map size, w: output (0 colour, 1 snow, 2 shadow)
    vec4 light_pos[8]; // xyz, w: intensity
    vec4 light_color[8];
    mat4 sun_atlas[3]; // world -> (u, v, depth) in the shadow atlas, per cascade
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

// How open p (normal n) is to the sky: the sky map's test [SKY], shared by
// the meshes and the moving bodies (which the map does not hold).
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

#ifdef SUN
#ifdef SUN_SHADOWS
uniform sampler2DShadow sun_shadow_map; // the cascades side by side [CSM]
// How much of the sun reaches p [WIL]: the cascade holding p's view depth
// [PSSM], 3x3 taps of the hardware's 2x2-filtered compare [PCF]. p is pushed
// out along n (normal offset [NOS]) by 1.5 texels, up to 4 where the sun
// grazes the face, so lit faces (and coarse spheres' smooth normals near
// their terminator) do not shadow themselves; taps stay inside the
// cascade's third of the atlas.
float sun_visibility(vec3 p, vec3 n) {
    float depth = dot(p - camera_pos.xyz, view_forward.xyz);
    int c = depth < cascade_far.x ? 0 : (depth < cascade_far.y ? 1 : 2);
    if (depth >= cascade_far.z) {
        return 1.0; // past the shadow distance: lit
    }
    float grazing = 1.0 - clamp(dot(n, sun.xyz), 0.0, 1.0);
    vec4 s = sun_atlas[c] * vec4(p + n * ((1.5 + 2.5 * grazing) * cascade_texel[c]), 1.0);
    vec2 texel = vec2(cascade_texel.w / 3.0, cascade_texel.w);
    float lo = float(c) / 3.0 + 1.5 * texel.x;
    float hi = float(c + 1) / 3.0 - 1.5 * texel.x;
    float sum = 0.0;
    for (int y = -1; y <= 1; ++y) {
        for (int x = -1; x <= 1; ++x) {
            vec2 uv = s.xy + vec2(x, y) * texel;
            sum += texture(sun_shadow_map, vec3(clamp(uv.x, lo, hi), uv.y, min(s.z, 1.0)));
        }
    }
    return sum / 9.0;
}
#else
float sun_visibility(vec3 p, vec3 n) { return 1.0; }
#endif

const float PI = 3.14159265;
// Fresh snow reflects about 90 % of visible light [WAR]; snow_color tints it.
const float snow_albedo = 0.9;
const float snow_roughness = 0.6; // a rough, grainy surface
const float snow_f0 = 0.02;       // ice's Fresnel reflectance at normal incidence (n = 1.31)
// Snow scatters light under its surface past the terminator: wrapped
// diffuse, max(0, (N.L + w) / (1 + w)) [GREEN].
const float snow_wrap = 0.2;

// GGX microfacet specular [GGX] with Smith-Schlick visibility (k = (r+1)^2/8)
// and Schlick's Fresnel [KAR], times N.L: radiance per unit sun irradiance.
float ggx_specular(vec3 n, vec3 v, vec3 l) {
    vec3 h = normalize(v + l);
    float nl = max(dot(n, l), 0.0), nv = max(dot(n, v), 1e-4);
    float nh = max(dot(n, h), 0.0), vh = max(dot(v, h), 0.0);
    float a2 = pow(snow_roughness, 4.0);
    float d = nh * nh * (a2 - 1.0) + 1.0;
    float k = (snow_roughness + 1.0) * (snow_roughness + 1.0) / 8.0;
    float g = nv / (nv * (1.0 - k) + k) * nl / (nl * (1.0 - k) + k);
    float f = snow_f0 + (1.0 - snow_f0) * pow(1.0 - vh, 5.0);
    return a2 / (PI * d * d) * g * f / (4.0 * nv * max(nl, 1e-4)) * nl;
}

// The filmic curve of [ACES] (Narkowicz's fit) after the exposure: bright
// sunlit snow rolls off towards white instead of clipping.
vec3 filmic(vec3 x) {
    x *= sun_color.w;
    return clamp(x * (2.51 * x + 0.03) / (x * (2.43 * x + 0.59) + 0.14), 0.0, 1.0);
}

// Three random words from three [PCG3D] (Jarzynski & Olano's pcg3d).
uvec3 pcg3d(uvec3 v) {
    v = v * 1664525u + 1013904223u;
    v.x += v.y * v.z;
    v.y += v.z * v.x;
    v.z += v.x * v.y;
    v ^= v >> 16u;
    v.x += v.y * v.z;
    v.y += v.z * v.x;
    v.z += v.x * v.y;
    return v;
}

vec3 unit_random(uvec3 k) {
    return vec3(k >> 8u) * (1.0 / 16777216.0); // [0, 1)
}

// Gradient of value noise over the plane, quintic-smoothed, taken
// analytically [IQN]; `seed` picks one of many independent fields.
vec2 noise_gradient(vec2 x, uint seed) {
    vec2 i = floor(x);
    vec2 f = x - i;
    vec2 u = f * f * f * (f * (f * 6.0 - 15.0) + 10.0);
    vec2 du = 30.0 * f * f * (f * (f - 2.0) + 1.0);
    uvec3 k = uvec3(ivec3(ivec2(i), 0)) + uvec3(0u, 0u, seed);
    float a = unit_random(pcg3d(k)).x;
    float b = unit_random(pcg3d(k + uvec3(1u, 0u, 0u))).x;
    float c = unit_random(pcg3d(k + uvec3(0u, 1u, 0u))).x;
    float d = unit_random(pcg3d(k + uvec3(1u, 1u, 0u))).x;
    float e = a - b - c + d;
    return du * vec2(b - a + e * u.y, c - a + e * u.x);
}

// Snow's small relief the height field is too coarse for: two octaves of
// slopes over world x/z (they stay on the snow as the camera moves), each
// faded out as its wavelength nears a few pixels [TMPA] so it cannot alias.
// `footprint`: metres one pixel covers at p; `amount`: how much of it to tilt.
vec3 detail_normal(vec3 n, vec3 p, float footprint, float amount) {
    const vec2 wavelength = vec2(0.9, 0.23); // m
    const vec2 slope = vec2(1.0, 0.55);
    const mat2 turn = mat2(0.8, 0.6, -0.6, 0.8); // the octaves' grids do not line up
    vec2 g = slope.x * smoothstep(3.0, 8.0, wavelength.x / footprint) *
                 noise_gradient(p.xz / wavelength.x, 1u) +
             slope.y * smoothstep(3.0, 8.0, wavelength.y / footprint) *
                 (noise_gradient(turn * p.xz / wavelength.y, 2u) * turn);
    vec3 t = vec3(g.x, 0.0, g.y);
    t -= n * dot(n, t); // along the surface
    return normalize(n - amount * t);
}

// Light that reaches the floor of a hollow has come through snow: ice
// absorbs red most and blue least [WAR], so the floor of a trench or a
// footprint turns bluer the deeper it is (Beer-Lambert over the depth,
// coefficients per metre).
vec3 subsurface_tint(float depth) {
    return exp(-depth * vec3(5.0, 2.2, 0.9));
}

// Glints after [BW15] [WB16]: a jittered 3D grid anchored in the world holds
// one glint per cell, a sphere of radius glint_radius cells around a random
// point, with a random facet normal about n; it shines where its facet
// reflects the sun into the eye (h: the half vector). Each glint is a
// Gaussian of its own radius convolved with the pixel's (half a footprint),
// its energy kept, so a glint about a pixel wide moves smoothly across
// pixels instead of popping; cells scale by powers of two with the footprint
// (two levels blended), so a glint stays one to two pixels wide at every
// distance, and the 8 cells nearest p hold every glint that reaches it.
const float glint_radius = 0.25;
float glints(vec3 n, vec3 p, vec3 h, float footprint, float level) {
    float cell = exp2(level);
    float r = glint_radius * cell;
    float s2 = r * r + 0.25 * footprint * footprint;
    float reach2 = 0.25 * cell * cell; // a half cell: the 8 nearest cells cover it
    ivec3 base = ivec3(floor(p / cell - 0.5));
    uint salt = uint(int(level) + 64) * 0x9E3779B9u;
    float sum = 0.0;
    for (int i = 0; i < 8; ++i) {
        ivec3 c = base + ivec3(i & 1, (i >> 1) & 1, i >> 2);
        uvec3 k = pcg3d(uvec3(c) ^ uvec3(salt));
        vec3 d = p - (vec3(c) + unit_random(k)) * cell;
        vec3 facet = normalize(n + 0.6 * (2.0 * unit_random(pcg3d(k)) - 1.0));
        float mirror = smoothstep(0.94, 0.975, dot(facet, h)); // within 20°, full by 13°
        float window = max(1.0 - dot(d, d) / reach2, 0.0);
        sum += mirror * exp(-0.5 * dot(d, d) / s2) * (r * r / s2) * window * window;
    }
    return sum;
}

// The glints' radiance at p: a peak of 3 after the exposure (flat sunlit
// snow: 1.1; the sum stays below the curve's white), faint in the shadow.
vec3 sparkle(vec3 n, vec3 p, vec3 v, float footprint, float visible) {
    float level = log2(footprint / glint_radius);
    float lo = floor(level);
    vec3 h = normalize(v + sun.xyz);
    float g = mix(glints(n, p, h, footprint, lo), glints(n, p, h, footprint, lo + 1.0), level - lo);
    vec3 hue = sun_color.rgb / max(dot(sun_color.rgb, vec3(0.2126, 0.7152, 0.0722)), 1e-6);
    return (3.0 / max(sun_color.w, 1e-6)) * g * mix(0.1, 1.0, visible) * hue;
}

// Radiance before the curve of a surface of colour `base` (its snow share
// `snow`) at p facing n, which sees `visible` of the sun: the ambient and
// lamps, the sun's wrapped diffuse and, for the snow, GGX specular.
vec3 sunlit(vec3 base, float snow, vec3 n, vec3 p, float visible) {
    vec3 l = sun.xyz;
    float w = snow_wrap * snow;
    float diffuse = max((dot(n, l) + w) / (1.0 + w), 0.0);
    float specular = snow * ggx_specular(n, normalize(camera_pos.xyz - p), l);
    return base * (irradiance(n, p) + sun_color.rgb * diffuse * visible) +
           sun_color.rgb * specular * visible;
}
#endif

// A surface of colour `albedo`, covered by snow to the amount `snow`, at p
// facing n, `hollow` metres below the snow around it (snow surfaces; 0
// elsewhere). Without a sun: the diffuse irradiance of ambient, sky and
// lamps. With one: sunlit() held back by the sun's shadow, under the filmic
// curve (the sky-coloured hemisphere turns shade blue), its snow with detail
// normals, the blue of hollows and glints. `shadow`: the share of the sun
// the shadow maps hold back (0 without a sun).
vec3 shade(vec3 albedo, float snow, vec3 n, vec3 p, float hollow, out float shadow) {
#ifdef SUN
    float visible = sun_visibility(p, n);
    shadow = 1.0 - visible;
    vec3 v = normalize(camera_pos.xyz - p);
    // Metres a pixel covers on the surface; stretched where it is seen edge on.
    float footprint = distance(camera_pos.xyz, p) / (lens.x * max(dot(n, v), 0.25));
    // Switched off (snow_detail) or without snow, the detail costs nothing.
    vec3 detail = snow_detail.x > 0.0 && snow > 0.0 ? detail_normal(n, p, footprint, snow) : n;
    vec3 base = mix(albedo, snow_color.rgb * snow_albedo * subsurface_tint(hollow), snow);
    vec3 glints = snow_detail.y > 0.0 && snow > 0.0
                      ? snow * sparkle(detail, p, v, footprint, visible)
                      : vec3(0.0);
    return filmic(sunlit(base, snow, detail, p, visible) + glints);
#else
    shadow = 0.0;
    return mix(albedo, snow_color.rgb, snow) * irradiance(n, p);
#endif
}

// What a surface's fragment writes: its colour, or one of the masks
// (RenderOutput) as grey, with the same alpha so that blended snow masks too.
vec4 frame_output(vec3 color, float alpha, float snow, float shadow) {
    vec3 value = counts.w == 1 ? vec3(snow) : (counts.w == 2 ? vec3(shadow) : color);
    return vec4(value, alpha);
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
