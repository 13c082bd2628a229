// surface.vert: one tile of a SnowSurface as a displaced heightfield over its
// bare top [WF §6]. No vertex buffer: with n = side², id < n is the grid
// sample (id % side, id / side), n + id its copy hung a little below the bare
// top (tile seams; on the grid's border exactly to it, facing out), 2n + id
// its copy hung to the bare top (the cut where the bare top jumps like an
// edge; render/passes/surface_tiles.hpp). Heights come from the cell texture, so a
// changed tile re-uploads only its texels.
layout(location = 0) in ivec2 a_tile; // per instance: the tile's first cell (x, z)
uniform sampler2D surface_cells;      // per cell: r = snow top, g = bare top (m)
uniform ivec4 surface_grid;           // x, y: cells (nx, nz); z: cells between samples; w: side
uniform vec3 surface_place;           // x0, z0, cell edge (m)
// Lit and fogged per sample (the interpolation is finer than the lighting
// varies; llvmpipe is fill bound); a: the incline dot(N, up) of the snow top,
// how much it hides the scene below it, as in the mesh shading [SKY].
out vec4 v_color;
out float v_depth; // snow depth (m), faded out per fragment as it thins to nothing
#ifdef SUN
out vec3 v_world; // shaded per fragment (surface.frag)
out vec3 v_normal;
out float v_hollow; // how far the snow lies below its surroundings (m)
#endif

// A bare top rising faster than this between two samples is an edge (eaves, a
// box's rim, a sphere's side), not a slope: normals and the seam skirts' depth
// do not difference across it, and the renderer leaves out the quads that
// bridge it. Equal to surface_edge_slope (render/passes/surface_tiles.hpp).
const float edge_slope = 2.0;

vec2 cell(ivec2 c) {
    return texelFetch(surface_cells, c, 0).rg;
}

// Snow top and bare top (r, g) of the sample in cell c. A border sample sits
// on the grid's border, half a cell out from its cell's centre: its heights
// continue the slope from the next cell inward (unless an edge lies between),
// so a sloped surface keeps its slope and normals right up to the border.
vec2 sample_at(ivec2 c) {
    vec2 h = cell(c);
    ivec2 last = surface_grid.xy - 1;
    ivec2 inward = ivec2(c.x == 0 ? 1 : (c.x == last.x ? -1 : 0),
                         c.y == 0 ? 1 : (c.y == last.y ? -1 : 0));
    inward *= ivec2(greaterThan(last, ivec2(0))); // a grid one cell wide has no inward cell
    vec2 out_h = h;
    if (inward.x != 0) {
        vec2 n = cell(c + ivec2(inward.x, 0));
        out_h += abs(n.g - h.g) <= edge_slope * surface_place.z ? 0.5 * (h - n) : vec2(0.0);
    }
    if (inward.y != 0) {
        vec2 n = cell(c + ivec2(0, inward.y));
        out_h += abs(n.g - h.g) <= edge_slope * surface_place.z ? 0.5 * (h - n) : vec2(0.0);
    }
    return out_h;
}

// Position, in cells from the grid origin, of the sample in cell u of an axis
// of n cells: the cell's centre, the outermost pulled out to the border.
float place(int u, int n) {
    return u <= 0 ? 0.0 : (u >= n - 1 ? float(n) : float(u) + 0.5);
}

// Snow-top gradient along one axis from the samples below (lo, at plo) and above
// (hi, at phi) the sample h at p, one-sided where the base jumps like an edge;
// y: the steepest side that is not an edge; z: the way down an edge (−1, 0, 1).
vec3 gradient(vec2 h, float p, vec2 lo, float plo, vec2 hi, float phi) {
    float cell_m = surface_place.z;
    bool use_lo = p > plo && abs(lo.g - h.g) <= edge_slope * (p - plo) * cell_m;
    bool use_hi = phi > p && abs(hi.g - h.g) <= edge_slope * (phi - p) * cell_m;
    float down = (!use_hi && phi > p && hi.g < h.g ? 1.0 : 0.0) -
                 (!use_lo && p > plo && lo.g < h.g ? 1.0 : 0.0);
    float a = use_lo ? plo : p;
    float b = use_hi ? phi : p;
    float ya = use_lo ? lo.r : h.r;
    float yb = use_hi ? hi.r : h.r;
    float along = b > a ? (yb - ya) / ((b - a) * cell_m) : 0.0;
    float steep = max(use_lo ? abs(h.r - lo.r) / ((p - plo) * cell_m) : 0.0,
                      use_hi ? abs(hi.r - h.r) / ((phi - p) * cell_m) : 0.0);
    return vec3(along, steep, down);
}

#ifdef SUN
// How far the snow top h.r of cell c lies below the mean of the tops
// hollow_cells away in the eight compass directions: the depth of a trench or
// a footprint (a slope's tops cancel in opposite pairs). A top across an edge
// of the bare top counts as level with h.
const int hollow_cells = 3;
float hollow(ivec2 c, vec2 h) {
    ivec2 last = surface_grid.xy - 1;
    float limit = edge_slope * float(hollow_cells) * surface_place.z;
    float sum = 0.0;
    for (int i = 0; i < 8; ++i) {
        float a = float(i) * (PI / 4.0);
        ivec2 o = ivec2(round(vec2(cos(a), sin(a)) * float(hollow_cells)));
        vec2 t = cell(clamp(c + o, ivec2(0), last));
        sum += abs(t.g - h.g) <= limit ? t.r : h.r;
    }
    return max(sum / 8.0 - h.r, 0.0);
}
#endif

void main() {
    int side = surface_grid.w;
    int step = surface_grid.z;
    int copy = gl_VertexID / (side * side); // 0 grid, 1 seam skirt, 2 edge cut
    int id = gl_VertexID - copy * side * side;
    ivec2 last = surface_grid.xy - 1;
    ivec2 c = min(a_tile + ivec2(id % side, id / side) * step, last);
    vec2 h = sample_at(c);
    vec2 p = vec2(place(c.x, surface_grid.x), place(c.y, surface_grid.y));
    int xl = max(c.x - step, 0), xh = min(c.x + step, last.x);
    int zl = max(c.y - step, 0), zh = min(c.y + step, last.y);
    vec3 gx = gradient(h, p.x, sample_at(ivec2(xl, c.y)), place(xl, surface_grid.x),
                       sample_at(ivec2(xh, c.y)), place(xh, surface_grid.x));
    vec3 gz = gradient(h, p.y, sample_at(ivec2(c.x, zl)), place(zl, surface_grid.y),
                       sample_at(ivec2(c.x, zh)), place(zh, surface_grid.y));
    vec3 n = normalize(vec3(-gx.x, 1.0, -gz.x));
    float y = h.r;
    vec3 normal = n;
    vec3 out_dir = vec3(0.0);
    if (copy == 1) {
        // A tile seam hangs below the bare top by about what the surface can
        // stray between samples on a smooth slope (the slope times the
        // spacing), which hides the cracks where a neighbour of another level
        // meets it. The grid's border hangs exactly to the bare top, facing
        // out: no crack under the snow's edge.
        bvec4 border = bvec4(c.x == 0, c.x == last.x, c.y == 0, c.y == last.y);
        float stray = (1.25 * max(gx.y, gz.y) + 0.1) * float(step) * surface_place.z + 0.002;
        y = any(border) ? h.g : h.g - stray;
        out_dir = vec3(float(border.y) - float(border.x), 0.0, float(border.w) - float(border.z));
    } else if (copy == 2) {
        y = h.g; // the snow's side at an edge, facing down it
        out_dir = vec3(gx.z, 0.0, gz.z);
    }
    if (dot(out_dir, out_dir) > 0.0) {
        normal = normalize(out_dir);
    }
    vec3 world = vec3(surface_place.x + p.x * surface_place.z, y,
                      surface_place.y + p.y * surface_place.z);
#ifdef SUN
    v_world = world;
    v_normal = normal;
    v_hollow = hollow(c, cell(c));
    vec3 color = vec3(0.0);
#else
    float shadow;
    vec3 color = shade(vec3(0.0), 1.0, normal, world, 0.0, shadow);
#ifdef FOG
    color = apply_fog(color, world);
#endif
#endif
    v_color = vec4(color, clamp(n.y, 0.0, 1.0));
    v_depth = h.r - h.g;
    gl_Position = view_proj * vec4(world, 1.0);
}
