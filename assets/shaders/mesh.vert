// mesh.vert: world-space scene meshes; with TEXTURE, their base colour
// texture's coordinates too.
layout(location = 0) in vec3 a_position;
layout(location = 1) in vec3 a_normal;
out vec3 v_world;
out vec3 v_normal;
#ifdef TEXTURE
layout(location = 2) in vec2 a_texcoord;
out vec2 v_texcoord;
#endif
void main() {
    v_world = a_position;
    v_normal = a_normal;
#ifdef TEXTURE
    v_texcoord = a_texcoord;
#endif
    gl_Position = view_proj * vec4(a_position, 1.0);
}
