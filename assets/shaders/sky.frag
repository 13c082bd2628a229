// sky.frag: the sky seen through the fog out to the far plane.
in vec2 v_ndc;
out vec4 frag_color;
void main() {
    vec4 far_point = inv_view_proj * vec4(v_ndc, 1.0, 1.0);
    vec3 dir = normalize(far_point.xyz / far_point.w - camera_pos.xyz);
    vec3 color = sky.rgb;
#ifdef FOG
    color = apply_fog(color, camera_pos.xyz + dir * lens.z);
#endif
    frag_color = vec4(color, 1.0);
}
