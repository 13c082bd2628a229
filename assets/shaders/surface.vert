// surface.vert: snow heightfields and their aprons [WF §6].
layout(location = 0) in vec3 a_position;
layout(location = 1) in vec3 a_normal;
layout(location = 2) in float a_depth;
out vec3 v_world;
out vec3 v_normal;
out float v_depth;
void main() {
    v_world = a_position;
    v_normal = a_normal;
    v_depth = a_depth;
    gl_Position = view_proj * vec4(a_position, 1.0);
}
