#include "render_fixture.hpp"

#include "render/renderer_internals.hpp"
#include "systems/flakes/flake_pool.hpp"
#include "systems/sky/occlusion.hpp"

#include <glm/geometric.hpp>
#include <glm/mat4x4.hpp>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>

namespace snow::test {

namespace {

float fract(double v) {
    return static_cast<float>(v - std::floor(v));
}

MeshRenderable ground_mesh(float half, const glm::vec3& color) {
    MeshRenderable m;
    m.name = "ground";
    m.positions = {
        {-half, 0.0f, -half}, {half, 0.0f, -half}, {half, 0.0f, half}, {-half, 0.0f, half}};
    m.normals.assign(4, glm::vec3(0.0f, 1.0f, 0.0f));
    m.indices = {0, 2, 1, 0, 3, 2};
    m.color = color;
    return m;
}

/// Snow units for a depth in metres.
std::uint32_t units(float depth) {
    return static_cast<std::uint32_t>(std::lround(std::max(depth, 0.0f) / fixture_unit_height));
}

/// Highest box top over (x, z), or the ground (0) — what the sky camera sees.
float top_at(const std::vector<Aabb>& boxes, float x, float z) {
    float top = 0.0f;
    for (const Aabb& b : boxes) {
        if (x >= b.min.x && x <= b.max.x && z >= b.min.z && z <= b.max.z) {
            top = std::max(top, b.max.y);
        }
    }
    return top;
}

} // namespace

std::unique_ptr<OsMesaContext> headless_context(int width, int height) {
    setenv("MESA_SHADER_CACHE_DISABLE", "true", 0); // deterministic, no files written
    return std::make_unique<OsMesaContext>(width, height);
}

SnowSurface flat_surface(float x0, float z0, float size_x, float size_z, float cell, float base_y) {
    SnowSurface s;
    s.x0 = x0;
    s.z0 = z0;
    s.cell = cell;
    s.nx = static_cast<std::uint32_t>(std::lround(size_x / cell));
    s.nz = static_cast<std::uint32_t>(std::lround(size_z / cell));
    s.unit_height = fixture_unit_height;
    s.base_level.assign(static_cast<std::size_t>(s.nx) * s.nz,
                        std::llround(base_y / s.unit_height));
    s.snow.assign(s.base_level.size(), 0);
    return s;
}

MeshRenderable box_mesh(const Aabb& b, const glm::vec3& color) {
    MeshRenderable m;
    m.name = "box";
    m.color = color;
    const glm::vec3 lo = b.min, hi = b.max;
    // Each face: outward normal and its 4 corners counter-clockwise seen from outside.
    const struct {
        glm::vec3 n;
        glm::vec3 c[4];
    } faces[6] = {
        {{1, 0, 0},
         {{hi.x, lo.y, hi.z}, {hi.x, lo.y, lo.z}, {hi.x, hi.y, lo.z}, {hi.x, hi.y, hi.z}}},
        {{-1, 0, 0},
         {{lo.x, lo.y, lo.z}, {lo.x, lo.y, hi.z}, {lo.x, hi.y, hi.z}, {lo.x, hi.y, lo.z}}},
        {{0, 1, 0},
         {{lo.x, hi.y, hi.z}, {hi.x, hi.y, hi.z}, {hi.x, hi.y, lo.z}, {lo.x, hi.y, lo.z}}},
        {{0, -1, 0},
         {{lo.x, lo.y, lo.z}, {hi.x, lo.y, lo.z}, {hi.x, lo.y, hi.z}, {lo.x, lo.y, hi.z}}},
        {{0, 0, 1},
         {{lo.x, lo.y, hi.z}, {hi.x, lo.y, hi.z}, {hi.x, hi.y, hi.z}, {lo.x, hi.y, hi.z}}},
        {{0, 0, -1},
         {{hi.x, lo.y, lo.z}, {lo.x, lo.y, lo.z}, {lo.x, hi.y, lo.z}, {hi.x, hi.y, lo.z}}},
    };
    for (const auto& f : faces) {
        const auto base = static_cast<std::uint32_t>(m.positions.size());
        for (const glm::vec3& c : f.c) {
            m.positions.push_back(c);
            m.normals.push_back(f.n);
        }
        m.indices.insert(m.indices.end(), {base, base + 1, base + 2, base, base + 2, base + 3});
    }
    return m;
}

void build_fixture(FixtureScene& s) {
    World& w = s.world;
    s.house_box = {{-4.0f, 0.0f, -2.0f}, {-1.0f, 2.0f, 1.0f}};
    s.shelter_roof_box = {{0.5f, 2.0f, -1.5f}, {3.5f, 2.15f, 1.5f}};
    s.crate_box = {{1.4f, 0.0f, -0.6f}, {2.6f, 0.7f, 0.6f}};

    std::vector<MeshRenderable>& meshes = s.visuals.meshes;
    meshes.push_back(ground_mesh(12.0f, {0.32f, 0.30f, 0.26f}));
    meshes.push_back(box_mesh(s.house_box, {0.55f, 0.25f, 0.20f}));
    meshes.push_back(box_mesh(s.shelter_roof_box, {0.40f, 0.40f, 0.45f}));
    std::vector<Aabb> boxes = {s.house_box, s.shelter_roof_box, s.crate_box};
    for (const float px : {0.55f, 3.35f}) {
        for (const float pz : {-1.45f, 1.35f}) {
            const Aabb post{{px, 0.0f, pz}, {px + 0.1f, 2.0f, pz + 0.1f}};
            meshes.push_back(box_mesh(post, {0.25f, 0.2f, 0.15f}));
            boxes.push_back(post);
        }
    }
    meshes.push_back(box_mesh(s.crate_box, {0.45f, 0.30f, 0.15f}));

    // Ground snow: gentle waves, none under the house or the shelter roof.
    SnowSurface ground = flat_surface(-6.0f, -6.0f, 12.0f, 12.0f, 0.25f, 0.0f);
    for (std::uint32_t iz = 0; iz < ground.nz; ++iz) {
        for (std::uint32_t ix = 0; ix < ground.nx; ++ix) {
            const float x = ground.x0 + (static_cast<float>(ix) + 0.5f) * ground.cell;
            const float z = ground.z0 + (static_cast<float>(iz) + 0.5f) * ground.cell;
            const bool covered = top_at(boxes, x, z) > 0.0f;
            const float depth = 0.05f + 0.035f * std::sin(0.9f * x) * std::cos(0.7f * z);
            ground.snow[ground.index(ix, iz)] = covered ? 0u : units(depth);
        }
    }
    s.ground_surface = w.create();
    w.add<SnowSurface>(s.ground_surface, std::move(ground));

    // House roof: a dome of snow, thickest in the middle.
    SnowSurface roof = flat_surface(-4.0f, -2.0f, 3.0f, 3.0f, 0.1f, 2.0f);
    for (std::uint32_t iz = 0; iz < roof.nz; ++iz) {
        for (std::uint32_t ix = 0; ix < roof.nx; ++ix) {
            const float u = (static_cast<float>(ix) + 0.5f) / static_cast<float>(roof.nx) - 0.5f;
            const float v = (static_cast<float>(iz) + 0.5f) / static_cast<float>(roof.nz) - 0.5f;
            roof.snow[roof.index(ix, iz)] = units(0.16f - 0.4f * (u * u + v * v));
        }
    }
    s.house_roof = w.create();
    w.add<SnowSurface>(s.house_roof, std::move(roof));

    // Three coloured point lights as in [WF §5]: white above the house,
    // blue toward the camera, yellow to the right.
    s.visuals.lights = {PointLight{{-2.5f, 7.0f, 0.0f}, {1.0f, 1.0f, 1.0f}, 1.0f},
                        PointLight{{-1.0f, 3.0f, 7.0f}, {0.45f, 0.55f, 1.0f}, 0.7f},
                        PointLight{{7.0f, 3.5f, 1.0f}, {1.0f, 0.85f, 0.45f}, 0.7f}};

    // The sky camera's map [SKY], rasterised from the boxes above.
    OcclusionMap& map = w.set_resource<OcclusionMap>();
    map.x0 = -6.0f;
    map.z0 = -6.0f;
    map.texel = 0.1f;
    map.width = map.height = 120;
    map.top_y.resize(static_cast<std::size_t>(map.width) * map.height);
    for (std::uint32_t j = 0; j < map.height; ++j) {
        for (std::uint32_t i = 0; i < map.width; ++i) {
            map.top_y[j * map.width + i] =
                top_at(boxes, map.x0 + (static_cast<float>(i) + 0.5f) * map.texel,
                       map.z0 + (static_cast<float>(j) + 0.5f) * map.texel);
        }
    }
    map.version = 1;

    // Flakes at fixed quasi-random positions (golden-ratio sequences).
    FlakePool& pool = w.set_resource<FlakePool>();
    pool.reset(2000);
    for (int i = 0; i < 700; ++i) {
        std::uint32_t slot = 0;
        if (!pool.acquire(slot)) {
            break;
        }
        pool.px[slot] = -6.0f + 12.0f * fract(i * 0.6180339887);
        pool.py[slot] = 0.3f + 5.5f * fract(i * 0.7548776662);
        pool.pz[slot] = -6.0f + 12.0f * fract(i * 0.5698402910);
        pool.size[slot] = 0.012f + 0.012f * fract(i * 0.3819660113);
        pool.mass_units[slot] = 1;
    }

    CameraDef& def = s.visuals.camera;
    def.position = {1.5f, 3.4f, 8.5f};
    def.target = {0.0f, 0.9f, 0.0f};
    def.fov_y_deg = 50.0f;
    s.camera = ViewCamera::from_def(def);
}

Image render_image(const World& world, const SceneVisuals& visuals, const ViewCamera& camera,
                   const RenderSettings& settings) {
    auto context = headless_context();
    Renderer renderer(*context, settings);
    render_world(renderer, world, visuals, camera);
    return renderer.read_pixels();
}

glm::ivec2 to_pixel(const ViewCamera& camera, const glm::vec3& p) {
    const glm::mat4 vp =
        camera.projection(static_cast<float>(golden_width) / golden_height) * camera.view();
    const glm::vec4 c = vp * glm::vec4(p, 1.0f);
    const float x = (c.x / c.w * 0.5f + 0.5f) * golden_width;
    const float y = (1.0f - (c.y / c.w * 0.5f + 0.5f)) * golden_height;
    return {static_cast<int>(std::floor(x)), static_cast<int>(std::floor(y))};
}

glm::vec3 mean_color(const Image& image, glm::ivec2 px, int r) {
    glm::vec3 sum(0.0f);
    int n = 0;
    for (int y = std::max(0, px.y - r); y <= std::min(image.height - 1, px.y + r); ++y) {
        for (int x = std::max(0, px.x - r); x <= std::min(image.width - 1, px.x + r); ++x) {
            const std::uint8_t* p = image.pixel(x, y);
            sum += glm::vec3(p[0], p[1], p[2]);
            ++n;
        }
    }
    return n > 0 ? sum / static_cast<float>(n) : sum;
}

ImageComparison compare_images(const Image& a, const Image& b) {
    ImageComparison c;
    c.diff = a;
    for (std::size_t i = 0; i + 3 < a.rgba.size() && i + 3 < b.rgba.size(); i += 4) {
        int d = 0;
        for (std::size_t k = 0; k < 3; ++k) {
            const int dk = std::abs(int(a.rgba[i + k]) - int(b.rgba[i + k]));
            d = std::max(d, dk);
            c.diff.rgba[i + k] = static_cast<std::uint8_t>(std::min(255, 8 * dk));
        }
        c.diff.rgba[i + 3] = 255;
        c.worst = std::max(c.worst, d);
        c.pixels_over += d > golden_tolerance ? 1u : 0u;
    }
    return c;
}

bool close_enough(const ImageComparison& c, const Image& a) {
    return c.pixels_over * 1000 <= (a.rgba.size() / 4) * 2;
}

::testing::AssertionResult matches_golden(const Image& actual, const std::string& name) {
    namespace fs = std::filesystem;
    const fs::path golden = fs::path(SNOW_SOURCE_DIR) / "assets" / "golden" / (name + ".png");
    const char* update = std::getenv("SNOW_UPDATE_GOLDEN");
    if (update != nullptr && std::string(update) == "1") {
        write_png(golden, actual);
        std::printf("updated golden image %s\n", golden.c_str());
        return ::testing::AssertionSuccess();
    }
    if (!fs::exists(golden)) {
        return ::testing::AssertionFailure()
               << "golden image " << golden << " is missing; run with SNOW_UPDATE_GOLDEN=1";
    }
    const Image expected = read_png(golden);
    if (expected.width != actual.width || expected.height != actual.height) {
        return ::testing::AssertionFailure()
               << name << ": size " << actual.width << "x" << actual.height << " vs golden "
               << expected.width << "x" << expected.height;
    }
    const ImageComparison c = compare_images(actual, expected);
    if (close_enough(c, actual)) {
        return ::testing::AssertionSuccess();
    }
    const fs::path out_dir = fs::path(SNOW_BINARY_DIR) / "golden_out";
    fs::create_directories(out_dir);
    const fs::path actual_path = out_dir / (name + ".actual.png");
    const fs::path diff_path = out_dir / (name + ".diff.png");
    write_png(actual_path, actual);
    write_png(diff_path, c.diff);
    return ::testing::AssertionFailure()
           << name << ": " << c.pixels_over << " of " << actual.rgba.size() / 4
           << " pixels differ by more than " << golden_tolerance << " (worst " << c.worst
           << ")\n  golden: " << golden << "\n  actual: " << actual_path
           << "\n  diff (x8): " << diff_path
           << "\n  if the change is intended, rerun with SNOW_UPDATE_GOLDEN=1";
}

} // namespace snow::test
