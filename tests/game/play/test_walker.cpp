// The walk mode's player on its own (no window): it walks through the
// facade and leaves a trench, stands on the ground, stops at walls, pushes
// and makes a snowball; the snow readout, the time scale's frame budget, the
// key scripts and the contact sheet.
#include "game/play/contact_sheet.hpp"
#include "game/play/game_input.hpp"
#include "game/play/snow_readout.hpp"
#include "game/play/time_scale.hpp"
#include "game/play/walker.hpp"
#include "systems/api/simulation_internals.hpp"
#include "tests/support/even_snow.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

namespace snow {
namespace {

constexpr float cell = 0.1f;
/// 4000 units on 10 cm cells: 2.7 cm of snow at the default air temperature's
/// fresh density (75 kg/m³ at −5 °C [HP98]; SnowyYard::fresh_depth).
constexpr std::uint32_t depth_units = 4000;

/// A 10 m ground surface with 2.7 cm of snow and a 1 m high box (a wall) at x > 2.
struct SnowyYard {
    Simulation sim;
    SurfaceId ground;
    SnowyYard() : sim(config()) {
        SurfaceDef d;
        d.x0 = d.z0 = -5.0f;
        d.size_x = d.size_z = 10.0f;
        d.cell = cell;
        d.spills = false;
        ground = sim.add_surface(d);
        test::snow_every_cell(sim, ground, depth_units);
        // A wall as a box with a surface on its top: its bare top is 1 m up.
        const Aabb wall{{2.0f, 0.0f, -5.0f}, {3.0f, 1.0f, 5.0f}};
        SurfaceDef top;
        top.x0 = 2.0f;
        top.z0 = -5.0f;
        top.size_x = 1.0f;
        top.size_z = 10.0f;
        top.cell = cell;
        top.base_y = 1.0f;
        sim.add_surface(top, sim.add_box(wall));
    }
    static SimConfig config() {
        SimConfig c;
        c.seed = 4;
        c.bounds = {{-6.0f, -1.0f, -6.0f}, {6.0f, 4.0f, 6.0f}};
        c.max_flakes = 1000;
        return c;
    }
    /// The untouched snow's depth (m): depth_units at the ground's unit height.
    [[nodiscard]] double fresh_depth() const {
        return depth_units * double{snow_surface(sim, ground).unit_height};
    }
    float depth(float x, float z) const {
        const auto c = snow_column(world_of(sim), x, z);
        EXPECT_TRUE(c.has_value()) << x << ", " << z;
        return c ? c->depth : -1.0f;
    }
    void walk(Walker& w, const glm::vec2& direction, int ticks) {
        for (int t = 0; t < ticks; ++t) {
            w.before_tick(sim, direction);
            sim.tick();
            ASSERT_TRUE(sim.mass().balanced()) << "tick " << t;
        }
    }
};

TEST(Walker, WalksThroughTheFacadeAndLeavesATrench) {
    SnowyYard y;
    Walker w(y.sim, {-2.0f, 5.0f, 0.0f});
    y.walk(w, {0.0f, 0.0f}, 1);
    // It stands on the bare ground, its flat soles on it.
    const float lowest = body_of(y.sim, w.body()).position.y - 0.25f - 0.6f;
    EXPECT_NEAR(lowest, 0.0f, 1.0e-6f);
    const std::uint64_t settled = y.sim.mass().settled;
    y.walk(w, {1.0f, 0.0f}, 150); // 1.4 m/s for 2.5 s: 3.5 m along +x
    const glm::vec3 p = body_of(y.sim, w.body()).position;
    EXPECT_NEAR(p.x, -2.0f + 3.5f, 0.02f);
    EXPECT_NEAR(p.z, 0.0f, 1.0e-4f);
    EXPECT_EQ(y.sim.mass().settled, settled) << "snow pushed aside, none lost";
    for (const float x : {-1.5f, -1.0f, -0.5f, 0.0f, 0.5f}) {
        EXPECT_LT(y.depth(x, 0.0f), 0.25f * y.depth(x, 1.0f)) << "trench floor at x " << x;
        // As wide as the capsule: cleared to within a cell of its 0.25 m radius.
        EXPECT_LT(y.depth(x, 0.15f), 0.25f * y.depth(x, 1.0f)) << "trench side at x " << x;
        EXPECT_LT(y.depth(x, -0.15f), 0.25f * y.depth(x, 1.0f)) << "trench side at x " << x;
        EXPECT_NEAR(y.depth(x, 1.0f), y.fresh_depth(), 0.002) << "untouched 1 m beside it";
    }
    const TrailReport t = w.trail(y.sim);
    EXPECT_NEAR(t.walked, 3.5f, 0.05f);
    EXPECT_GT(t.samples, 8u);
    EXPECT_LT(t.on_trail, 0.25f * t.beside);
    EXPECT_NEAR(w.eye(y.sim).y, w.depth_under(y.sim) + 1.6f, 1.0e-4f);
    EXPECT_LT(w.depth_under(y.sim), w.depth_ahead(y.sim, {0.0f, 1.0f}));
}

TEST(Walker, StopsAtAWallAndSlidesAlongIt) {
    SnowyYard y;
    Walker w(y.sim, {1.0f, 0.0f, 0.0f});
    y.walk(w, {1.0f, 0.0f}, 120); // towards the 1 m wall at x = 2
    const float x = body_of(y.sim, w.body()).position.x;
    EXPECT_LT(x, 2.0f - 0.25f) << "its front stops at the wall";
    EXPECT_GT(x, 2.0f - 0.25f - 0.03f);
    const glm::vec2 diagonal = glm::normalize(glm::vec2(1.0f, 1.0f));
    y.walk(w, diagonal, 60); // into the wall at 45°: only the z part moves
    const glm::vec3 p = body_of(y.sim, w.body()).position;
    EXPECT_EQ(p.x, x);
    EXPECT_NEAR(p.z, 1.4f * diagonal.y, 0.03f);
}

/// A snowy roof on a box from `low` to `high` over x in [-1, 1], z in [-1, 1].
SurfaceId add_roof(SnowyYard& y, float low, float high) {
    SurfaceDef top;
    top.x0 = top.z0 = -1.0f;
    top.size_x = top.size_z = 2.0f;
    top.cell = cell;
    top.base_y = high;
    top.spills = false;
    const SurfaceId roof =
        y.sim.add_surface(top, y.sim.add_box({{-1.0f, low, -1.0f}, {1.0f, high, 1.0f}}));
    test::snow_every_cell(y.sim, roof, depth_units);
    return roof;
}

TEST(Walker, WalksUnderARoofAndLeavesItsSnowAlone) {
    SnowyYard y;
    const SurfaceId roof = add_roof(y, 2.0f, 2.15f); // a porch: higher than the 1.7 m player
    const Vector<std::uint32_t> roof_snow = snow_surface(y.sim, roof).snow;
    Walker w(y.sim, {-2.0f, 0.0f, 0.0f});
    y.walk(w, {1.0f, 0.0f}, 60); // to x = -0.6, under the roof
    EXPECT_NEAR(w.eye(y.sim).y, w.depth_under(y.sim) + 1.6f, 1.0e-4f) << "on the ground";
    y.walk(w, {1.0f, 0.0f}, 90); // out the other side, to x = 1.5
    const glm::vec3 p = body_of(y.sim, w.body()).position;
    EXPECT_NEAR(p.x, 1.5f, 0.02f);
    EXPECT_NEAR(p.y, 0.85f, 1.0e-4f) << "its soles on the ground all the way";
    EXPECT_EQ(snow_surface(y.sim, roof).snow, roof_snow);
    const auto under = snow_column(world_of(y.sim), 0.0f, 0.0f, 0.5f); // the ground, not the roof
    ASSERT_TRUE(under);
    EXPECT_EQ(under->base, 0.0f);
    EXPECT_LT(under->depth, 0.25f * y.depth(0.0f, 1.5f)) << "its trench under the roof";
}

TEST(Walker, ALowBeamStopsIt) {
    SnowyYard y;
    add_roof(y, 1.0f, 1.2f); // lower than its head
    Walker w(y.sim, {-2.0f, 0.0f, 0.0f});
    y.walk(w, {1.0f, 0.0f}, 90);
    EXPECT_LT(body_of(y.sim, w.body()).position.x, -1.0f - 0.25f + 0.03f);
}

TEST(Walker, StaysOnTheSnowAndInsideTheGround) {
    SnowyYard y;
    Walker w(y.sim, {40.0f, 0.0f, -40.0f}); // placed 1 m inside the ground's corner
    const glm::vec3 start = body_of(y.sim, w.body()).position;
    EXPECT_FLOAT_EQ(start.x, 4.0f);
    EXPECT_FLOAT_EQ(start.z, -4.0f);
    y.walk(w, {0.0f, -1.0f}, 120); // off the edge of the snow: it stops there
    EXPECT_GT(body_of(y.sim, w.body()).position.z, -5.0f);
}

TEST(Walker, MakesPushesAndRollsASnowball) {
    SnowyYard y;
    Walker w(y.sim, {-2.0f, 0.0f, 0.0f});
    y.walk(w, {0.0f, 0.0f}, 1);
    const glm::vec2 east{1.0f, 0.0f};
    EXPECT_EQ(w.push_snowball(y.sim, east).rfind("snowball made", 0), 0u);
    EXPECT_EQ(world_of(y.sim).count<Body>(), 2u);
    y.walk(w, {0.0f, 0.0f}, 1);
    const BodyId ball = [&] {
        BodyId found;
        world_of(y.sim).each<Body>([&](Entity e, const Body& b) {
            if (b.snowball) {
                found = id_of<BodyId>(e);
            }
        });
        return found;
    }();
    ASSERT_FALSE(ball.is_null());
    const float x0 = body_of(y.sim, ball).position.x;
    EXPECT_NEAR(x0, -2.0f + 0.25f + 0.2f + 0.3f, 1.0e-4f);
    EXPECT_EQ(w.push_snowball(y.sim, east).rfind("snowball pushed", 0), 0u);
    y.walk(w, {0.0f, 0.0f}, 60); // it rolls on, slowing, and picks the snow up
    const Body& b = body_of(y.sim, ball);
    EXPECT_GT(b.position.x, x0 + 1.0f);
    EXPECT_LT(glm::length(b.velocity), 2.0f);
    EXPECT_GT(b.carried, 0u);
    EXPECT_GT(b.radius, 0.2f);
    EXPECT_TRUE(y.sim.mass().balanced());
    y.walk(w, {0.0f, 0.0f}, 600); // friction stops it, or the wall at x = 2 does
    EXPECT_EQ(body_of(y.sim, ball).velocity, glm::vec3(0.0f));
    EXPECT_LT(body_of(y.sim, ball).position.x, 2.0f);
    EXPECT_NE(w.push_snowball(y.sim, east).find("away: walk up to it"), std::string::npos);
}

TEST(Walker, ResetKeepsTheBodyAndStartsTheTrailAgain) {
    SnowyYard y;
    Walker w(y.sim, {-2.0f, 0.0f, 0.0f});
    const auto start = save_snapshot(y.sim);
    y.walk(w, {1.0f, 0.0f}, 60);
    EXPECT_GT(w.trail(y.sim).walked, 1.0f);
    restore_snapshot(y.sim, *start);
    ASSERT_TRUE(w.alive(y.sim));
    w.restart(y.sim);
    EXPECT_EQ(w.trail(y.sim).walked, 0.0f);
}

TEST(SnowReadout, ColumnIsTheHighestBareTopAndItsSnow) {
    SnowyYard y;
    const auto ground = snow_column(world_of(y.sim), 0.0f, 0.0f);
    ASSERT_TRUE(ground);
    EXPECT_FLOAT_EQ(ground->base, 0.0f);
    EXPECT_NEAR(ground->depth, y.fresh_depth(), 1.0e-6);
    const auto wall = snow_column(world_of(y.sim), 2.5f, 0.0f);
    ASSERT_TRUE(wall);
    EXPECT_NEAR(wall->base, 1.0f, 1.0e-4f); // the wall's top, above the ground's cell
    EXPECT_FALSE(snow_column(world_of(y.sim), 7.0f, 0.0f));
    const SnowSurface* g = ground_surface(world_of(y.sim));
    ASSERT_NE(g, nullptr);
    EXPECT_EQ(g->nx, 100u); // the ground, not the wall's top
    EXPECT_NEAR(mean_depth(*g), y.fresh_depth(), 1.0e-9);
}

TEST(TimeScale, CyclesAndStopsGrowingPastTheFrameBudget) {
    TimeScale t(0.02);
    EXPECT_EQ(t.factor(), 1u);
    EXPECT_EQ(t.ticks(2), 2u);
    t.cycle();
    t.cycle();
    EXPECT_EQ(t.factor(), 16u);
    EXPECT_EQ(t.ticks(2), 32u);
    t.took(32, 0.01); // within the budget: no cap
    EXPECT_EQ(t.ticks(2), 32u);
    t.cycle();
    EXPECT_EQ(t.ticks(2), 128u);
    t.took(128, 0.08); // 4 times the budget: a quarter fits
    EXPECT_EQ(t.cap(), 32u);
    EXPECT_EQ(t.ticks(2), 32u);
    EXPECT_TRUE(t.capped(2));
    t.took(32, 0.005); // quick again: the cap grows back a quarter at a time
    EXPECT_EQ(t.cap(), 41u);
    t.cycle();
    EXPECT_EQ(t.factor(), 1u);
    EXPECT_FALSE(t.capped(2));
    EXPECT_TRUE(t.set(4));
    EXPECT_FALSE(t.set(8));
    EXPECT_EQ(t.factor(), 4u);
}

TEST(KeyScript, PressesAndHolds) {
    const KeyScript k = parse_key_script("0:W:30,10:B,12:T,40:D,50:ESC");
    ASSERT_EQ(k.presses.size(), 3u);
    EXPECT_EQ(k.presses[0].frame, 10u);
    EXPECT_EQ(k.presses[0].action, Action::push_snowball);
    EXPECT_EQ(k.presses[1].action, Action::time_scale);
    EXPECT_EQ(k.presses[2].action, Action::quit);
    EXPECT_TRUE(k.held(MoveKey::forward, 0));
    EXPECT_TRUE(k.held(MoveKey::forward, 29));
    EXPECT_FALSE(k.held(MoveKey::forward, 30));
    EXPECT_TRUE(k.held(MoveKey::right, 40));
    EXPECT_FALSE(k.held(MoveKey::right, 41));
    EXPECT_FALSE(k.held(MoveKey::left, 40));
}

TEST(KeyScript, VTogglesTheWindFieldArrowsAndIsInTheHelp) {
    const KeyScript k = parse_key_script("5:V");
    ASSERT_EQ(k.presses.size(), 1u);
    EXPECT_EQ(k.presses[0].action, Action::toggle_wind);
    const auto& help = key_help();
    EXPECT_TRUE(std::any_of(help.begin(), help.end(), [](const KeyHelp& h) {
        return std::string(h.key) == "V" && std::string(h.what).find("wind") != std::string::npos;
    }));
}

TEST(KeyScript, BadItemsNameTheProblem) {
    const auto message = [](const char* text) {
        try {
            (void)parse_key_script(text);
        } catch (const std::invalid_argument& e) {
            return std::string(e.what());
        }
        return std::string("no error");
    };
    EXPECT_NE(message("").find("names no key"), std::string::npos);
    EXPECT_NE(message("10").find("'10' names no key"), std::string::npos);
    EXPECT_NE(message("10:").find("'10:' names no key"), std::string::npos);
    EXPECT_NE(message("5:P,,7:N").find("'' names no key"), std::string::npos);
    EXPECT_NE(message("3:Z").find("unknown key 'Z'"), std::string::npos);
    EXPECT_NE(message("x:P").find("frame number"), std::string::npos);
    EXPECT_NE(message("1:W:0").find("frames >= 1"), std::string::npos);
    EXPECT_NE(message("1:P:5").find("only W A S D are held"), std::string::npos);
}

TEST(ContactSheet, EvenlySpacedLabelledMomentsInRows) {
    ContactSheet sheet(120, 8, 4, 2);
    std::vector<std::uint64_t> moments;
    for (std::uint64_t f = 0; f < 120; ++f) {
        if (sheet.wants(f)) {
            moments.push_back(f);
        }
    }
    EXPECT_EQ(moments, (std::vector<std::uint64_t>{0, 17, 34, 51, 68, 85, 102, 119}));
    Image frame;
    frame.width = 64;
    frame.height = 40;
    frame.rgba.assign(64 * 40 * 4, 0);
    for (std::size_t i = 0; i < frame.rgba.size(); i += 4) {
        frame.rgba[i] = 100; // a dark red frame
        frame.rgba[i + 3] = 255;
    }
    for (std::size_t k = 0; k < moments.size(); ++k) {
        sheet.add(frame, "t 1:05");
    }
    const Image s = sheet.compose();
    EXPECT_EQ(s.width, 4 * 32 + 5 * 4);
    EXPECT_EQ(s.height, 2 * 20 + 3 * 4);
    EXPECT_EQ(s.pixel(0, 0)[0], 24);              // the background between tiles
    EXPECT_EQ(s.pixel(4 + 31, 4 + 19)[0], 100);   // a tile's corner, shrunk unchanged
    EXPECT_EQ(s.pixel(4 + 4 + 2, 4 + 4)[1], 250); // the label's first stroke ('t', 2 px scale)
    EXPECT_EQ(s.pixel(4 + 4, 4 + 4)[1], 0);       // beside it the tile shows
}

TEST(ContactSheet, FewerFramesThanMoments) {
    ContactSheet sheet(3, 8, 4, 1);
    EXPECT_TRUE(sheet.wants(0) && sheet.wants(1) && sheet.wants(2));
    EXPECT_FALSE(sheet.wants(3));
}

} // namespace
} // namespace snow
