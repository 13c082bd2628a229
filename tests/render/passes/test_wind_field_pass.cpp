// The wind field drawn as arrows (snow_game's V key): a line per arrow and
// two for its head, at most a few thousand segments, blue where the air is
// still and red where it is fastest; drawn only when asked for and only for
// a world with a field, and it reads the field without changing it.
#include "render/passes/wind_arrows.hpp"
#include "render/renderer_internals.hpp"
#include "systems/api/simulation_internals.hpp"
#include "tests/render/render_fixture.hpp"
#include "tests/support/steady_field.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <string>
#include <vector>

namespace snow::test {
namespace {

/// A 2 m box in a 24 m × 8 m × 12 m yard under a steady 2 m/s wind through a
/// 48 × 8 × 24 field (or none), after 4 simulated seconds.
std::unique_ptr<Simulation> box_in_wind(bool field) {
    SimConfig cfg;
    cfg.bounds = {{-6.0f, 0.0f, -6.0f}, {18.0f, 8.0f, 6.0f}};
    auto sim = std::make_unique<Simulation>(cfg);
    sim->add_box({{0.0f, 0.0f, -1.0f}, {2.0f, 2.0f, 1.0f}});
    if (field) {
        blow_steadily_through_field(*sim, 2.0f, {48, 8, 24, 4});
    }
    sim->run(240);
    return sim;
}

ViewCamera above_the_yard() {
    ViewCamera c;
    c.position = {6.0f, 22.0f, 16.0f};
    c.look_at({6.0f, 0.0f, 0.0f});
    return c;
}

struct Drawn {
    Image image;
    std::vector<std::string> passes;
    bool arrows_ran = false;
};

Drawn draw(const Simulation& sim, bool show) {
    auto context = headless_context();
    RenderSettings settings;
    settings.show_wind_field = show;
    Renderer renderer(*context, settings);
    renderer.render(sim, SceneVisuals{}, above_the_yard());
    Drawn d{renderer.read_pixels(), renderer.pass_names()};
    for (const PassTiming& p : renderer.timings().passes) {
        d.arrows_ran = d.arrows_ran || (p.name == "wind_field" && p.ran);
    }
    return d;
}

TEST(RenderWindField, ArrowsAreDrawnOnlyWhenAskedFor) {
    auto sim = box_in_wind(true);
    const std::uint64_t hash = sim->state_hash();
    const Drawn off = draw(*sim, false);
    const Drawn on = draw(*sim, true);
    EXPECT_EQ(std::count(off.passes.begin(), off.passes.end(), "wind_field"), 0);
    EXPECT_TRUE(on.arrows_ran);
    const ImageComparison c = compare_images(off.image, on.image);
    EXPECT_GT(c.pixels_over, 1000u) << "the arrows cover visible pixels";
    EXPECT_EQ(sim->state_hash(), hash) << "drawing reads the field only";
}

TEST(RenderWindField, AWorldWithoutAFieldDrawsNoArrows) {
    auto sim = box_in_wind(false);
    const Drawn off = draw(*sim, false);
    const Drawn on = draw(*sim, true);
    EXPECT_FALSE(on.arrows_ran);
    EXPECT_EQ(std::count(on.passes.begin(), on.passes.end(), "wind_field"), 0);
    EXPECT_EQ(compare_images(off.image, on.image).pixels_over, 0u);
}

TEST(RenderWindField, ArrowsAreFewAndColouredBySpeed) {
    auto sim = box_in_wind(true);
    WindArrows a;
    wind_arrows(world_of(*sim).resource<WindField>(), a);
    EXPECT_GT(a.arrows, 100u);
    EXPECT_LE(a.arrows, wind_arrows_across * wind_arrow_layers * wind_arrows_across);
    EXPECT_EQ(a.vertices.size(), std::size_t{a.arrows} * wind_arrow_segments * 2 * 6);
    // The free stream is the fastest air but for the speed-up over the box.
    EXPECT_GT(a.max_speed, 1.9f);
    EXPECT_LT(a.max_speed, 3.0f);
    // Blue for still air, red for the fastest, and the ramp in between.
    EXPECT_GT(wind_speed_color(0.0f).b, 0.9f);
    EXPECT_LT(wind_speed_color(0.0f).r, 0.2f);
    EXPECT_GT(wind_speed_color(1.0f).r, 0.9f);
    EXPECT_LT(wind_speed_color(1.0f).b, 0.2f);
    // Every arrow's colour is the ramp's at its speed: the reddest ones are
    // the longest.
    float longest_red = 0.0f, longest_blue = 0.0f;
    for (std::size_t v = 0; v < a.vertices.size(); v += wind_arrow_segments * 12) {
        const float* p = &a.vertices[v];
        const float dx = p[6] - p[0], dy = p[7] - p[1], dz = p[8] - p[2];
        const float length = std::sqrt(dx * dx + dy * dy + dz * dz);
        (p[3] > p[5] ? longest_red : longest_blue) =
            std::max(p[3] > p[5] ? longest_red : longest_blue, length);
    }
    EXPECT_GT(longest_red, longest_blue);
}

} // namespace
} // namespace snow::test
