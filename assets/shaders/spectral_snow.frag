// spectral_snow.frag: far-field snow of [LZ] composited over the scene
// behind the particle flakes, I = I_snow·α + (1 − α)·I_background. Drawn with
// spectral_snow.vert (one screen-covering triangle) and alpha blending.
in vec2 v_ndc;
out vec4 frag_color;
uniform sampler3D spectral_volume; // α(x, y, t): periodic in x, y and t
uniform sampler2D scene_depth;     // depth of the opaque scene drawn so far
uniform vec4 spectral_view;        // x: tiles per radian, y: wind shear, z: loop phase, w: opacity
uniform vec2 spectral_fade;        // x: hand-over distance h from the flakes, y: where it is fogged

void main() {
    float depth = texelFetch(scene_depth, ivec2(gl_FragCoord.xy), 0).r;
    vec4 q = inv_view_proj * vec4(v_ndc, depth * 2.0 - 1.0, 1.0);
    vec3 ray = q.xyz / q.w - camera_pos.xyz;
    float d = length(ray);
    vec3 dir = ray / max(d, 1e-6);
    // The share of the snow in front of the surface behind the pixel that the
    // flakes no longer draw: beyond h they are kept with probability (h/d)²
    // (render/passes/far_field.hpp), so 1 − (h/d)², continuous in d: no seam where
    // the layer starts nor at the horizon. Faded toward zenith and nadir,
    // where azimuth degenerates.
    float kept = spectral_fade.x / max(d, spectral_fade.x);
    float fade = (1.0 - kept * kept) * (1.0 - smoothstep(0.75, 0.95, abs(dir.y)));
    if (fade <= 0.0) {
        discard;
    }
    // Tile coordinates from the view direction (azimuth across, elevation up),
    // so distant snow stays put when the camera turns; y up: the volume's snow
    // falls down. The wind shears the columns: flakes drift as they fall.
    vec2 uv = vec2(atan(dir.x, -dir.z), asin(clamp(dir.y, -1.0, 1.0))) * spectral_view.x;
    uv.x += spectral_view.y * uv.y;
    float alpha = texture(spectral_volume, vec3(uv, spectral_view.z)).r;
    // [LZ] composites a constant snow intensity; the fog in front of the
    // layer's full-strength depth still veils it.
    vec3 color = snow_color.rgb;
#ifdef FOG
    color = apply_fog(color, camera_pos.xyz + dir * min(d, spectral_fade.y));
#endif
    frag_color = vec4(color, spectral_view.w * alpha * fade);
}
