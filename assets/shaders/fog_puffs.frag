// fog_puffs.frag: Gaussian and Gabor fog puffs of [PE] with analytic line
// integrals: render/passes/fog_puffs.cpp's formulas in float. Drawn with sky.vert over
// the finished frame: transparency 0.5^(optical depth eye → surface).
// PUFF_PROBE: one fragment per test segment instead (shader_puff_optical_depths).
out vec4 frag_color;

const float PUFF_PI = 3.14159265358979;
uniform int puff_count;
uniform vec4 puff_shape[32];    // xyz: centre, w: sigma (m)
uniform vec4 puff_wave[32];     // xyz: Gabor wave vector (rad/m; 0 = Gaussian), w: phase
uniform float puff_density[32]; // halvings per metre at the centre

// erf(x), Abramowitz & Stegun 7.1.26 (|error| < 1.5e-7): GLSL has none.
float puff_erf(float x) {
    float t = 1.0 / (1.0 + 0.3275911 * abs(x));
    float poly = ((((1.061405429 * t - 1.453152027) * t + 1.421413741) * t - 0.284496736) * t +
                  0.254829592) * t;
    return sign(x) * (1.0 - poly * exp(-x * x));
}

float puff_sinc(float u) {
    return abs(u) < 1e-3 ? 1.0 - u * u / 6.0 : sin(u) / u;
}

// e^(−y²)·erf(x + iy), Abramowitz & Stegun 7.1.29 with e^(−y²) folded into
// every term so none overflows (render/passes/fog_puffs.cpp scaled_complex_erf). The
// series' exponentials come from two geometric recurrences, not one exp each.
vec2 puff_erf_scaled(float x, float y_signed) {
    float y = abs(y_signed); // F(x, −y) = conj(F(x, y))
    float ey = exp(-y * y);
    float ex = exp(-x * x);
    float u = x * y;
    vec2 w = vec2(puff_erf(x) * ey + ex * ey * y * sin(u) * puff_sinc(u) / PUFF_PI,
                  ex * ey * y * puff_sinc(2.0 * u) / PUFF_PI);
    // With e^(−x²) < 1.2e-7 (float resolution) the series adds nothing.
    if (x * x <= 16.0) {
        float c2 = cos(2.0 * u);
        float s2 = sin(2.0 * u);
        // Terms matter while e^(−(n/2 − y)²) is above float resolution: n = 2y ± 8.
        int first = max(1, int(2.0 * y) - 8);
        int last = int(ceil(2.0 * y)) + 8;
        float h = 0.5 * float(first);
        float plus = exp(-(h - y) * (h - y));  // e^(−y²)·e^(−n²/4)·e^(+ny)
        float minus = exp(-(h + y) * (h + y)); // e^(−y²)·e^(−n²/4)·e^(−ny)
        float plus_ratio = exp(-(h - y) - 0.25); // to the next n; shrinks by e^(−1/2)
        float minus_ratio = exp(-(h + y) - 0.25);
        vec2 sum = vec2(0.0);
        for (int n = first; n <= last; ++n) {
            float ch = 0.5 * (plus + minus);
            float sh = 0.5 * (plus - minus);
            float e = sqrt(plus * minus); // e^(−y²)·e^(−n²/4)
            float fn = float(n);
            float denom = fn * fn + 4.0 * x * x;
            sum += vec2(2.0 * x * e - 2.0 * x * ch * c2 + fn * sh * s2,
                        2.0 * x * ch * s2 + fn * sh * c2) / denom;
            plus *= plus_ratio;
            minus *= minus_ratio;
            plus_ratio *= 0.60653066; // e^(−1/2)
            minus_ratio *= 0.60653066;
        }
        w += (2.0 / PUFF_PI) * ex * sum;
    }
    return y_signed < 0.0 ? vec2(w.x, -w.y) : w;
}

// ∫ density of puff i along a + s·dir, 0 ≤ s ≤ len: a Gaussian in s [PE],
// times (1 + cos(κs + θ))/2 for a Gabor puff.
float puff_line_integral(int i, vec3 a, vec3 dir, float len) {
    float sigma = puff_shape[i].w;
    vec3 q = a - puff_shape[i].xyz;
    float along = dot(q, dir);
    vec3 perp = q - along * dir;
    float inv = 1.0 / (sigma * sqrt(2.0));
    float envelope = exp(-dot(perp, perp) * inv * inv);
    if (envelope < 1e-6) {
        return 0.0; // the ray passes more than 5.3 sigma from the centre
    }
    float t0 = along * inv;
    float t1 = (along + len) * inv;
    float scale = puff_density[i] * envelope * (sqrt(PUFF_PI) / 2.0) / inv;
    float gauss = puff_erf(t1) - puff_erf(t0);
    vec3 k = puff_wave[i].xyz;
    if (k == vec3(0.0)) {
        return scale * gauss;
    }
    float beta = dot(k, dir) * sigma / sqrt(2.0);
    float theta = dot(k, perp) + puff_wave[i].w;
    vec2 delta = puff_erf_scaled(t1, -beta) - puff_erf_scaled(t0, -beta);
    float wave = cos(theta) * delta.x - sin(theta) * delta.y; // Re(e^(iθ)·delta)
    return scale * 0.5 * (gauss + wave);
}

float puffs_optical_depth(vec3 a, vec3 b) {
    vec3 ab = b - a;
    float len = length(ab);
    if (len <= 0.0) {
        return 0.0;
    }
    float depth = 0.0;
    for (int i = 0; i < puff_count; ++i) {
        depth += puff_line_integral(i, a, ab / len, len);
    }
    return depth;
}

#ifdef PUFF_PROBE
uniform sampler2D probe_segments; // texel (i, 0): start of segment i, (i, 1): its end
void main() {
    int i = int(gl_FragCoord.x);
    vec3 a = texelFetch(probe_segments, ivec2(i, 0), 0).xyz;
    vec3 b = texelFetch(probe_segments, ivec2(i, 1), 0).xyz;
    frag_color = vec4(puffs_optical_depth(a, b), 0.0, 0.0, 1.0);
}
#else
in vec2 v_ndc;
uniform sampler2D scene_depth; // depth of the opaque scene
void main() {
    float depth = texelFetch(scene_depth, ivec2(gl_FragCoord.xy), 0).r;
    vec4 q = inv_view_proj * vec4(v_ndc, depth * 2.0 - 1.0, 1.0);
    float transparency = exp2(-puffs_optical_depth(camera_pos.xyz, q.xyz / q.w)); // 0.5^depth
    if (transparency >= 1.0) {
        discard;
    }
    frag_color = vec4(fog_color.rgb, 1.0 - transparency);
}
#endif
