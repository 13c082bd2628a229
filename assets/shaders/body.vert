// body.vert: a moving body (sphere, upright capsule, box) at its pose. The
// unit shape is scaled, and a capsule's two hemispheres (side +1 / -1) are
// pulled apart by its core's half height; the normals stay as they are.
layout(location = 0) in vec3 a_position;
layout(location = 1) in vec3 a_normal;
layout(location = 2) in float a_side;
uniform vec3 center;
uniform vec3 scale;
uniform float half_height;
out vec3 v_world;
out vec3 v_normal;
void main() {
    v_world = center + a_position * scale + vec3(0.0, a_side * half_height, 0.0);
    v_normal = a_normal;
    gl_Position = view_proj * vec4(v_world, 1.0);
}
