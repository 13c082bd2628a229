// snow_game's session (game/play/game_session.hpp) played through its input, no
// window and no GL: each key does to the simulation, the camera, the player
// and the clock what the game's help says it does.
#include "systems/api/simulation_internals.hpp"
#include "systems/flakes/snowfall.hpp"
#include "tests/game/play/game_play.hpp"

#include <gtest/gtest.h>

#include <GLFW/glfw3.h>

#include <cmath>
#include <vector>

namespace snow {
namespace {

using test::GamePlay;
using test::quick_game;

std::vector<Emitter> emitters(const Simulation& sim) {
    std::vector<Emitter> all;
    world_of(sim).each<Emitter>([&](Entity, const Emitter& e) { all.push_back(e); });
    return all;
}

glm::vec3 player_position(const GamePlay& g) {
    const Walker* w = g.session->walker();
    EXPECT_NE(w, nullptr);
    return w ? body_of(g.sim(), w->body()).position : glm::vec3(NAN);
}

TEST(GameSession, SnowfallKeysScaleEverySnowfallAndTheRateCarriesIt) {
    GamePlay g(quick_game());
    const std::vector<Emitter> before = emitters(g.sim());
    ASSERT_FALSE(before.empty());
    const glm::vec3 size = g.sim().config().bounds.size();
    const double area = static_cast<double>(size.x) * size.z;
    g.press(GLFW_KEY_EQUAL);
    const std::vector<Emitter> more = emitters(g.sim());
    ASSERT_EQ(more.size(), before.size());
    for (std::size_t i = 0; i < before.size(); ++i) {
        EXPECT_FLOAT_EQ(more[i].snowfall_kg_m2_h, before[i].snowfall_kg_m2_h * 1.5f) << i;
        EXPECT_GE(more[i].rate, before[i].rate) << i;
        EXPECT_GE(more[i].rate, min_parcel_rate(more[i], area)) << i;
    }
    EXPECT_NE(g.session->message().find("snowfall"), std::string::npos) << g.session->message();
    EXPECT_NE(g.session->message().find("kg/m²/h"), std::string::npos) << g.session->message();
    g.press(GLFW_KEY_MINUS);
    const std::vector<Emitter> less = emitters(g.sim());
    for (std::size_t i = 0; i < before.size(); ++i) {
        EXPECT_FLOAT_EQ(less[i].snowfall_kg_m2_h, before[i].snowfall_kg_m2_h) << i;
    }
}

TEST(GameSession, SnowfallOptionSetsEveryEmitter) {
    GameOptions o = quick_game();
    o.snowfall = 120.0f;
    GamePlay g(o);
    const glm::vec3 size = g.sim().config().bounds.size();
    for (const Emitter& e : emitters(g.sim())) {
        EXPECT_EQ(e.snowfall_kg_m2_h, 120.0f);
        EXPECT_GE(e.rate, min_parcel_rate(e, static_cast<double>(size.x) * size.z));
    }
}

TEST(GameSession, CameraKeyCyclesWalkFlyOrbit) {
    GamePlay g(quick_game());
    EXPECT_EQ(g.session->camera().mode(), CameraMode::walk); // the village has snow ground
    for (const CameraMode m : {CameraMode::fly, CameraMode::orbit, CameraMode::walk}) {
        g.press(GLFW_KEY_O);
        EXPECT_EQ(g.session->camera().mode(), m);
        EXPECT_EQ(g.session->message(), std::string(camera_mode_name(m)) + " camera");
    }
}

TEST(GameSession, CameraKeySkipsWalkWithoutSnowGround) {
    GamePlay g(quick_game("testdata/plain.gltf"));
    EXPECT_EQ(g.session->camera().mode(), CameraMode::fly);
    g.press(GLFW_KEY_O);
    EXPECT_EQ(g.session->camera().mode(), CameraMode::orbit);
    g.press(GLFW_KEY_O);
    EXPECT_EQ(g.session->camera().mode(), CameraMode::fly);
    EXPECT_EQ(g.session->walker(), nullptr);
}

TEST(GameSession, TimeScaleKeyStepsTicksPerFrame1_4_16_64) {
    GamePlay g(quick_game(), "1:T,2:T,3:T,4:T");
    std::uint64_t tick = g.sim().tick_count();
    for (const std::uint64_t factor : {1u, 4u, 16u, 64u, 1u}) {
        g.play();
        EXPECT_EQ(g.session->time_scale().factor(), factor);
        EXPECT_EQ(g.session->ticks_last_frame(), factor); // low quality: one tick a frame
        EXPECT_EQ(g.sim().tick_count(), tick + factor);
        tick = g.sim().tick_count();
    }
}

TEST(GameSession, PauseStopsTheClockAndStepRunsOneTick) {
    GamePlay g(quick_game(), "0:P,2:N,3:N,4:P");
    g.play();
    const std::uint64_t paused_at = g.sim().tick_count();
    EXPECT_TRUE(g.session->paused());
    EXPECT_EQ(g.session->message(), "paused at tick " + std::to_string(paused_at));
    g.play();
    EXPECT_EQ(g.sim().tick_count(), paused_at);
    EXPECT_EQ(g.session->ticks_last_frame(), 0u);
    g.play(2);
    EXPECT_EQ(g.sim().tick_count(), paused_at + 2);
    EXPECT_EQ(g.session->message(), "stepped to tick " + std::to_string(paused_at + 2));
    g.play();
    EXPECT_FALSE(g.session->paused());
    EXPECT_EQ(g.sim().tick_count(), paused_at + 3);
}

TEST(GameSession, HeldForwardWalksThePlayer) {
    GamePlay g(quick_game(), "0:W:30");
    const glm::vec3 start = player_position(g);
    g.play(30); // 30 ticks of 1/30 s at 1.4 m/s
    const glm::vec3 end = player_position(g);
    EXPECT_NEAR(glm::length(glm::vec2(end.x - start.x, end.z - start.z)), 1.4f, 0.05f);
    // The walk camera is the player's eye.
    EXPECT_EQ(g.session->camera().camera().position, g.session->walker()->eye(g.sim()));
}

TEST(GameSession, WalkOnceAtStartsTheScenesWalkAtItsFrame) {
    GameOptions o = quick_game();
    o.walk_once_at = 3;
    GamePlay g(o);
    const auto ground_distance = [&](const glm::vec3& a, const glm::vec3& b) {
        return glm::length(glm::vec2(a.x - b.x, a.z - b.z));
    };
    const glm::vec3 start = player_position(g);
    g.play(3);
    EXPECT_EQ(ground_distance(player_position(g), start), 0.0f) << "it waits at its path's start";
    g.play();
    EXPECT_EQ(g.session->message(), "the walker sets off, once round its path");
    g.play(10);
    EXPECT_GT(ground_distance(player_position(g), start), 0.3f);
}

TEST(GameSession, ResetRestoresTheSavedState) {
    GamePlay g(quick_game(), "0:W:10,10:P,11:R");
    const std::uint64_t start_tick = g.sim().tick_count();
    const MassReport start_mass = g.sim().mass();
    const glm::vec3 start = player_position(g);
    g.play(11);
    EXPECT_EQ(g.sim().tick_count(), start_tick + 10);
    EXPECT_NE(player_position(g), start);
    g.play(); // R, while paused: no tick after it
    EXPECT_EQ(g.sim().tick_count(), start_tick);
    EXPECT_EQ(g.session->start_tick(), start_tick);
    EXPECT_EQ(g.sim().mass().spawned, start_mass.spawned);
    EXPECT_EQ(g.sim().mass().settled, start_mass.settled);
    EXPECT_EQ(player_position(g), start);
    EXPECT_EQ(g.session->message(), "reset to tick " + std::to_string(start_tick));
}

TEST(GameSession, ResetAfterASnowballGoesOnFromTheStart) {
    // B adds the snowball's body after the start was saved; R once stopped
    // the game there ("snapshot belongs to a different scene (body count)").
    GamePlay g(quick_game(), "0:B,3:P,4:R,5:P");
    const std::uint64_t start_tick = g.sim().tick_count();
    const MassReport start_mass = g.sim().mass();
    const std::size_t start_bodies = world_of(g.sim()).count<Body>();
    const glm::vec3 start = player_position(g);
    g.play();
    EXPECT_EQ(g.session->message().rfind("snowball made ahead", 0), 0u) << g.session->message();
    EXPECT_EQ(world_of(g.sim()).count<Body>(), start_bodies + 1);
    g.play(3); // on to P: the snowball rolls with the world for three ticks
    EXPECT_EQ(g.sim().tick_count(), start_tick + 3);
    g.play(); // R, while paused: no tick after it
    EXPECT_FALSE(g.session->quit());
    EXPECT_EQ(g.session->message(), "reset to tick " + std::to_string(start_tick));
    EXPECT_EQ(g.sim().tick_count(), start_tick);
    EXPECT_EQ(world_of(g.sim()).count<Body>(), start_bodies) << "the snowball is gone";
    const MassReport mass = g.sim().mass();
    EXPECT_EQ(mass.spawned, start_mass.spawned);
    EXPECT_EQ(mass.airborne, start_mass.airborne);
    EXPECT_EQ(mass.settled, start_mass.settled);
    EXPECT_EQ(mass.carried, start_mass.carried);
    EXPECT_EQ(mass.removed, start_mass.removed);
    EXPECT_EQ(player_position(g), start);
    g.play(); // P again: the session goes on from the start
    EXPECT_FALSE(g.session->paused());
    EXPECT_EQ(g.sim().tick_count(), start_tick + 1);
    EXPECT_TRUE(g.sim().mass().balanced());
}

TEST(GameSession, ResetAfterTheWalkCameraCameLaterKeepsAPlayer) {
    // The player made when O reaches the walk camera is not in the start either.
    GameOptions o = quick_game();
    o.camera = CameraMode::fly;
    GamePlay g(o, "0:O,1:O,2:R");
    const std::uint64_t start_tick = g.sim().tick_count();
    EXPECT_EQ(g.session->walker(), nullptr);
    g.play(2); // orbit, then walk: the player is added
    ASSERT_NE(g.session->walker(), nullptr);
    g.play(); // R
    EXPECT_FALSE(g.session->quit());
    EXPECT_EQ(g.session->message(), "reset to tick " + std::to_string(start_tick));
    EXPECT_EQ(g.session->camera().mode(), CameraMode::walk);
    ASSERT_NE(g.session->walker(), nullptr) << "a new player where the camera stands";
    EXPECT_TRUE(g.session->walker()->alive(g.sim()));
}

TEST(GameSession, FogKeyTogglesTheScenesFog) {
    GamePlay g(quick_game());
    ASSERT_TRUE(g.session->visuals().fog.has_value());
    g.press(GLFW_KEY_F);
    EXPECT_FALSE(g.session->visuals().fog.has_value());
    EXPECT_EQ(g.session->message(), "fog off");
    g.press(GLFW_KEY_F);
    EXPECT_TRUE(g.session->visuals().fog.has_value());
}

TEST(GameSession, ArrowKeysTurnAndScaleTheWind) {
    GamePlay g(quick_game());
    const glm::vec3 base = world_of(g.sim()).resource<Wind>().base;
    g.press(GLFW_KEY_UP);
    EXPECT_NEAR(glm::length(world_of(g.sim()).resource<Wind>().base), 1.25f * glm::length(base),
                1e-5f);
    g.press(GLFW_KEY_DOWN);
    g.press(GLFW_KEY_LEFT);
    const glm::vec3 turned = world_of(g.sim()).resource<Wind>().base;
    EXPECT_NEAR(glm::length(turned), glm::length(base), 1e-5f);
    // 15° counter-clockwise seen from above (+y): the angle between them, and its sense.
    EXPECT_NEAR(std::acos(glm::dot(turned, base) / glm::dot(base, base)), 0.2618f, 1e-3f);
    EXPECT_GT(base.z * turned.x - base.x * turned.z, 0.0f);
}

TEST(GameSession, WindFieldKeyTogglesTheArrowsWhereTheSceneHasAField) {
    GamePlay village(quick_game());
    village.press(GLFW_KEY_V);
    EXPECT_FALSE(village.session->show_wind_field());
    EXPECT_EQ(village.session->message(), "this scene declares no wind field");
    GamePlay effects(quick_game("scenes/village_effects.gltf"));
    effects.press(GLFW_KEY_V);
    EXPECT_TRUE(effects.session->show_wind_field());
    effects.press(GLFW_KEY_V);
    EXPECT_FALSE(effects.session->show_wind_field());
}

TEST(GameSession, QualityKeyReloadsWithTheNextPreset) {
    GamePlay g(quick_game());
    EXPECT_FLOAT_EQ(g.sim().config().dt, 1.0f / 30.0f);
    g.press(GLFW_KEY_Q);
    EXPECT_EQ(g.session->quality(), 1u);
    EXPECT_FLOAT_EQ(g.sim().config().dt, 1.0f / 60.0f);
    EXPECT_EQ(g.session->message(), "quality medium");
    EXPECT_EQ(g.session->camera().mode(), CameraMode::walk) << "the camera is kept";
}

TEST(GameSession, SnowballKeyMakesOneInTheWalkCameraOnly) {
    GamePlay g(quick_game());
    g.press(GLFW_KEY_B);
    EXPECT_EQ(g.session->message().rfind("snowball made ahead", 0), 0u) << g.session->message();
    g.press(GLFW_KEY_O); // fly
    g.press(GLFW_KEY_B);
    EXPECT_EQ(g.session->message(), "snowballs are pushed in the walk camera (O)");
}

TEST(GameSession, ScreenshotIsAskedForInItsFrameOnly) {
    GamePlay g(quick_game(), "1:C");
    g.play();
    EXPECT_FALSE(g.session->screenshot_requested());
    g.play();
    EXPECT_TRUE(g.session->screenshot_requested());
    g.play();
    EXPECT_FALSE(g.session->screenshot_requested());
}

TEST(GameSession, HelpKeyTogglesTheKeyList) {
    GamePlay g(quick_game());
    EXPECT_FALSE(g.session->help());
    g.press(GLFW_KEY_H);
    EXPECT_TRUE(g.session->help());
}

TEST(GameSession, EscapeQuitsAndLaterPressesAreNotCarriedOut) {
    GamePlay g(quick_game(), "1:ESC,1:T");
    g.play();
    const std::uint64_t tick = g.sim().tick_count();
    g.play();
    EXPECT_TRUE(g.session->quit());
    EXPECT_EQ(g.session->time_scale().factor(), 1u);
    EXPECT_EQ(g.sim().tick_count(), tick) << "no ticks in the frame that quits";
}

TEST(GameSession, MouseLooksWithTheRightButtonAndDragsOnlyTheOrbit) {
    GamePlay g(quick_game());
    g.press(GLFW_KEY_O); // fly
    PlayerActions drag;
    drag.mouse = {100.0f, 0.0f};
    drag.drag_button = true;
    const float yaw = g.session->camera().camera().yaw;
    g.session->update(drag, g.frame++, std::nullopt);
    EXPECT_EQ(g.session->camera().camera().yaw, yaw) << "the left button drags the orbit only";
    PlayerActions look = drag;
    look.drag_button = false;
    look.look_button = true;
    g.session->update(look, g.frame++, std::nullopt);
    EXPECT_NE(g.session->camera().camera().yaw, yaw);
    g.press(GLFW_KEY_O); // orbit
    const float orbit_yaw = g.session->camera().camera().yaw;
    g.session->update(drag, g.frame++, std::nullopt);
    EXPECT_NE(g.session->camera().camera().yaw, orbit_yaw);
}

} // namespace
} // namespace snow
