// Flakes as point sprites ([ZCL], [SKY]): selection (alive, frustum, level of
// detail), drawing, far flakes fainter.
#include "render/passes/flake_selection.hpp"
#include "render/renderer_internals.hpp"
#include "systems/flakes/flake_pool.hpp"
#include "tests/render/render_fixture.hpp"

#include <gtest/gtest.h>

#include <cstdio>

namespace snow::test {
namespace {

ViewCamera looking_down_minus_z() {
    ViewCamera c;
    c.position = {0.0f, 0.0f, 0.0f};
    c.yaw = 0.0f;
    c.pitch = 0.0f;
    return c;
}

FlakeSelection selection_for(const ViewCamera& c) {
    FlakeSelection s;
    s.view_proj = c.projection(4.0f / 3.0f) * c.view();
    s.eye = c.position;
    s.size_scale = 1.0f;
    return s;
}

std::uint32_t add_flake(FlakePool& pool, glm::vec3 p, float size = 0.02f) {
    std::uint32_t slot = 0;
    EXPECT_TRUE(pool.acquire(slot));
    pool.px[slot] = p.x;
    pool.py[slot] = p.y;
    pool.pz[slot] = p.z;
    pool.size[slot] = size;
    pool.mass_units[slot] = 1;
    return slot;
}

TEST(RenderFlakes, SelectionKeepsAliveFlakesInsideTheFrustumOnly) {
    FlakePool pool;
    pool.reset(8);
    add_flake(pool, {0.0f, 0.0f, -5.0f}, 0.03f);        // in view
    add_flake(pool, {0.0f, 0.0f, 5.0f});                // behind the eye
    add_flake(pool, {50.0f, 0.0f, -5.0f});              // far to the right
    pool.release(add_flake(pool, {0.0f, 0.5f, -5.0f})); // dead
    add_flake(pool, {0.0f, 0.0f, -500.0f});             // past the far plane
    std::vector<float> out(4 * pool.capacity());
    FlakeSelection sel = selection_for(looking_down_minus_z());
    sel.size_scale = 2.0f;
    ASSERT_EQ(select_flakes(pool, sel, out), 1u);
    EXPECT_EQ(out[2], -5.0f);
    EXPECT_FLOAT_EQ(out[3], 0.06f); // drawn diameter = size × scale
}

TEST(RenderFlakes, LevelOfDetailThinsOnlyFarFlakesAndIsStable) {
    FlakePool pool;
    pool.reset(20000);
    for (int i = 0; i < 10000; ++i) {
        add_flake(pool, {0.0f, 0.0f, -5.0f}); // near: all kept
    }
    for (int i = 0; i < 10000; ++i) {
        add_flake(pool, {0.0f, 0.0f, -40.0f}); // at 2 × lod distance: ~1/4 kept
    }
    std::vector<float> out(4 * pool.capacity());
    FlakeSelection sel = selection_for(looking_down_minus_z());
    sel.lod = true;
    sel.lod_distance = 20.0f;
    const std::uint32_t kept = select_flakes(pool, sel, out);
    const std::vector<float> first(out.begin(), out.begin() + 4 * kept);
    EXPECT_GT(kept, 10000u + 2300u);
    EXPECT_LT(kept, 10000u + 2700u);
    ASSERT_EQ(select_flakes(pool, sel, out), kept);
    EXPECT_TRUE(std::equal(first.begin(), first.end(), out.begin())) << "same flakes every frame";
    sel.lod = false;
    EXPECT_EQ(select_flakes(pool, sel, out), 20000u);
}

TEST(RenderFlakes, SelectionKeepsSlotOrderWhateverTheMixOfKeptAndSkipped) {
    // Slots alive or freed, in view or behind the eye, in a fixed irregular
    // mix over several blocks and a count that is no multiple of 16: the
    // output is exactly the kept flakes' records, in slot order.
    constexpr std::uint32_t n = 5003;
    FlakePool pool;
    pool.reset(n);
    std::vector<float> expected;
    std::vector<std::uint32_t> freed_slots;
    std::uint32_t h = 12345u;
    for (std::uint32_t i = 0; i < n; ++i) {
        h = h * 1664525u + 1013904223u;
        const bool in_view = (h >> 28) % 3 != 0;
        const bool freed = (h >> 24) % 5 == 0;
        const float x = 0.001f * static_cast<float>(i % 997), size = 0.01f + 1.0e-6f * i;
        const glm::vec3 p{x, 0.0f, in_view ? -5.0f : 5.0f};
        const std::uint32_t slot = add_flake(pool, p, size);
        if (freed) {
            freed_slots.push_back(slot);
        } else if (in_view) {
            expected.insert(expected.end(), {p.x, p.y, p.z, size * 1.5f});
        }
    }
    for (const std::uint32_t slot : freed_slots) {
        pool.release(slot); // after all are placed: a freed slot is the next one handed out
    }
    std::vector<float> out(4 * pool.capacity());
    FlakeSelection sel = selection_for(looking_down_minus_z());
    sel.size_scale = 1.5f;
    const std::uint32_t kept = select_flakes(pool, sel, out);
    ASSERT_EQ(4 * kept, expected.size());
    EXPECT_TRUE(std::equal(expected.begin(), expected.end(), out.begin()));
}

/// Brightest channel value anywhere in the image.
int peak(const Image& img) {
    int m = 0;
    for (std::size_t i = 0; i < img.rgba.size(); i += 4) {
        m = std::max({m, int(img.rgba[i]), int(img.rgba[i + 1]), int(img.rgba[i + 2])});
    }
    return m;
}

/// Peak brightness of one flake at `p` over a black sky.
int flake_peak(const glm::vec3& p, float size) {
    World w;
    SceneVisuals visuals;
    visuals.environment = Environment{{0.1f, 0.1f, 0.1f}, {0.0f, 0.0f, 0.0f}};
    FlakePool& pool = w.set_resource<FlakePool>();
    pool.reset(4);
    if (size > 0.0f) {
        add_flake(pool, p, size);
    }
    RenderSettings settings;
    settings.flake_scale = 1.0f;
    settings.flake_lod = FlakeLod::never;
    return peak(render_image(w, visuals, looking_down_minus_z(), settings));
}

TEST(RenderFlakes, SpritesShowAndFarOnesAreMoreTranslucent) {
    EXPECT_EQ(flake_peak({0.0f, 0.0f, -4.0f}, 0.0f), 0) << "no flakes: black sky";
    // Same projected size (diameter ∝ distance), so only the distance fade differs.
    const int near = flake_peak({0.0f, 0.0f, -4.0f}, 0.1f);
    const int far = flake_peak({0.0f, 0.0f, -32.0f}, 0.8f);
    EXPECT_GT(near, 100);
    EXPECT_GT(far, 20);
    EXPECT_GT(near, far + far / 2);
}

TEST(RenderFlakes, PassRunsOnlyWithAliveFlakes) {
    World w;
    const SceneVisuals visuals;
    auto context = headless_context();
    Renderer renderer(*context);
    render_world(renderer, w, visuals, looking_down_minus_z());
    const auto flakes_ran = [&] {
        for (const PassTiming& p : renderer.timings().passes) {
            if (p.name == "flakes") {
                return p.ran;
            }
        }
        return false;
    };
    EXPECT_FALSE(flakes_ran());
    FlakePool& pool = w.set_resource<FlakePool>();
    pool.reset(4);
    render_world(renderer, w, visuals, looking_down_minus_z());
    EXPECT_FALSE(flakes_ran()) << "an empty pool draws nothing";
    add_flake(pool, {0.0f, 0.0f, -3.0f});
    render_world(renderer, w, visuals, looking_down_minus_z());
    EXPECT_TRUE(flakes_ran());
    EXPECT_EQ(renderer.timings().flakes_drawn, 1u);
    EXPECT_EQ(renderer.timings().flakes_alive, 1u);
}

} // namespace
} // namespace snow::test
