// wind_field.vert: the wind field's arrows, one coloured line vertex each.
layout(location = 0) in vec3 a_position;
layout(location = 1) in vec3 a_color;
out vec3 v_color;
void main() {
    gl_Position = view_proj * vec4(a_position, 1.0);
    v_color = a_color;
}
