// Far-field spectral snow [LZ]: the volume is real, periodic, band
// limited with power ∝ 1/|ω| and on the dispersion surface; the pass draws it
// only beyond the particles and only for worlds that declare it.
#include "render/passes/spectral_volume.hpp"
#include "render/renderer_internals.hpp"
#include "systems/api/simulation_internals.hpp"
#include "systems/flakes/flake_pool.hpp"
#include "tests/render/render_fixture.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

namespace snow::test {
namespace {

SpectralSnow small_layer() {
    SpectralSnow s;
    s.size_xy = 64;
    s.size_t = 32;
    s.band_low = 4.0f;
    s.band_high = 16.0f;
    return s;
}

/// Signed frequency of bin i on an axis of n samples.
int signed_frequency(std::size_t i, std::size_t n) {
    return i < n / 2 ? static_cast<int>(i) : static_cast<int>(i) - static_cast<int>(n);
}

TEST(SpectralVolume, TemporalFrequencyFollowsTheDispersionRelation) {
    EXPECT_EQ(spectral_temporal_frequency(0, 5, 8.0), 8);  // straight down: fastest
    EXPECT_EQ(spectral_temporal_frequency(5, 0, 8.0), 0);  // horizontal stripes do not move
    EXPECT_EQ(spectral_temporal_frequency(3, 4, 10.0), 8); // c·ky/|k| = 10·4/5
    for (int kx = -6; kx <= 6; ++kx) {
        for (int ky = -6; ky <= 6; ++ky) {
            if (kx != 0 || ky != 0) {
                EXPECT_EQ(spectral_temporal_frequency(-kx, -ky, 7.3),
                          -spectral_temporal_frequency(kx, ky, 7.3));
            }
        }
    }
}

TEST(SpectralVolume, SpectrumIsConjugateSymmetricAndTheVolumeRealToRoundOff) {
    const SpectralSnow s = small_layer();
    const std::vector<Complex> spectrum = spectral_spectrum(s, 5);
    const std::size_t n = s.size_xy, nt = s.size_t;
    std::size_t nonzero = 0;
    for (std::size_t t = 0; t < nt; ++t) {
        for (std::size_t y = 0; y < n; ++y) {
            for (std::size_t x = 0; x < n; ++x) {
                const Complex v = spectrum[x + n * (y + n * t)];
                const Complex mirror =
                    spectrum[(n - x) % n + n * ((n - y) % n + n * ((nt - t) % nt))];
                EXPECT_EQ(v, std::conj(mirror));
                nonzero += v != Complex(0.0) ? 1u : 0u;
            }
        }
    }
    EXPECT_GT(nonzero, 500u);
    std::vector<Complex> volume = spectrum;
    fft_3d(volume, n, n, nt, FftDirection::inverse);
    double max_real = 0.0, max_imag = 0.0;
    for (const Complex& c : volume) {
        max_real = std::max(max_real, std::abs(c.real()));
        max_imag = std::max(max_imag, std::abs(c.imag()));
    }
    EXPECT_GT(max_real, 0.0);
    EXPECT_LT(max_imag, 1e-13 * max_real);
    EXPECT_LT(build_spectral_volume(s, 5).imaginary_ratio, 1e-13);
}

TEST(SpectralVolume, AlphaIsRescaledToZeroOneAndDeterministic) {
    const SpectralSnow s = small_layer();
    const SpectralVolume a = build_spectral_volume(s, 9);
    ASSERT_EQ(a.alpha.size(), std::size_t{64} * 64 * 32);
    EXPECT_EQ(*std::min_element(a.alpha.begin(), a.alpha.end()), 0.0f);
    EXPECT_EQ(*std::max_element(a.alpha.begin(), a.alpha.end()), 1.0f);
    EXPECT_EQ(build_spectral_volume(s, 9).alpha, a.alpha);
    EXPECT_NE(build_spectral_volume(s, 10).alpha, a.alpha);
    // A band with no integer frequency in it: no snow rather than NaN.
    SpectralSnow empty = s;
    empty.band_low = 4.01f;
    empty.band_high = 4.05f;
    const SpectralVolume none = build_spectral_volume(empty, 9);
    EXPECT_TRUE(
        std::all_of(none.alpha.begin(), none.alpha.end(), [](float v) { return v == 0.0f; }));
}

TEST(SpectralVolume, TemporalSpectrumOfAlphaLiesOnTheDispersionSurface) {
    const SpectralSnow s = small_layer();
    const SpectralVolume v = build_spectral_volume(s, 3);
    const std::size_t n = v.size_xy, nt = v.size_t;
    std::vector<Complex> f(v.alpha.begin(), v.alpha.end());
    fft_3d(f, n, n, nt, FftDirection::forward);
    const double c_max = spectral_c_max(s);
    double on = 0.0, off = 0.0;
    double min_power_k = 1e300, max_power_k = 0.0; // power·|k| per spatial bin
    for (std::size_t y = 0; y < n; ++y) {
        for (std::size_t x = 0; x < n; ++x) {
            const int kx = signed_frequency(x, n), ky = signed_frequency(y, n);
            if (kx == 0 && ky == 0) {
                continue; // the rescaling's offset
            }
            const double k = std::hypot(kx, ky);
            const bool in_band = k >= s.band_low && k <= s.band_high &&
                                 std::abs(kx) < static_cast<int>(n / 2) &&
                                 std::abs(ky) < static_cast<int>(n / 2);
            // The "small range of constants c" of [LZ]: kt between the rounded ends.
            const int lo_c =
                spectral_temporal_frequency(kx, ky, c_max * (1.0 - spectral_speed_spread));
            const int hi_c = spectral_temporal_frequency(kx, ky, c_max);
            double bin_power = 0.0;
            for (std::size_t t = 0; t < nt; ++t) {
                const int kt = signed_frequency(t, nt);
                const double p = std::norm(f[x + n * (y + n * t)]);
                const bool allowed =
                    in_band && kt >= std::min(lo_c, hi_c) && kt <= std::max(lo_c, hi_c);
                (allowed ? on : off) += p;
                bin_power += p;
            }
            int peaks = 0; // above the float round-off of α
            for (std::size_t t = 0; t < nt; ++t) {
                peaks += std::norm(f[x + n * (y + n * t)]) > 1e-9 * bin_power ? 1 : 0;
            }
            if (in_band) {
                EXPECT_EQ(peaks, 1)
                    << "one temporal frequency per spatial one: " << kx << "," << ky;
                min_power_k = std::min(min_power_k, bin_power * k);
                max_power_k = std::max(max_power_k, bin_power * k);
            }
        }
    }
    EXPECT_GT(on, 0.0);
    EXPECT_LT(off, 1e-10 * on) << "energy off the dispersion surface or outside the band";
    EXPECT_LT(max_power_k / min_power_k, 1.0 + 1e-4) << "power is not ∝ 1/|ω|";
}

TEST(SpectralVolume, SnowFallsDownTheYAxis) {
    // y points up (the pass maps elevation onto it): frame t + 1 at height y
    // resembles frame t higher up, at y + dy with dy > 0.
    const SpectralVolume v = build_spectral_volume(small_layer(), 4);
    const std::size_t n = v.size_xy, nt = v.size_t;
    const auto at = [&](std::size_t x, int y, std::size_t t) { // y wraps
        const auto row = static_cast<std::size_t>((y + static_cast<int>(n)) % static_cast<int>(n));
        return static_cast<double>(v.alpha[x + n * (row + n * (t % nt))]) - 0.5;
    };
    int best = 0;
    double best_c = -1e300, c_up = 0.0, c_down = 0.0;
    for (int dy = -6; dy <= 6; ++dy) {
        double c = 0.0;
        for (std::size_t t = 0; t < nt; ++t) {
            for (int y = 0; y < static_cast<int>(n); ++y) {
                for (std::size_t x = 0; x < n; ++x) {
                    c += at(x, y, t + 1) * at(x, y + dy, t);
                }
            }
        }
        if (c > best_c) {
            best_c = c;
            best = dy;
        }
        c_up += dy == 2 ? c : 0.0;
        c_down += dy == -2 ? c : 0.0;
    }
    EXPECT_GT(best, 0);
    EXPECT_GT(c_up, 2.0 * std::abs(c_down));
}

/// Mean |α(next) − α(i)| over each plane of neighbour pairs along one axis of
/// a volume `len` samples long on that axis (the first `len` of its samples):
/// planes 0 … len − 2 are interior, plane len − 1 wraps around to 0.
std::vector<double> plane_steps(const SpectralVolume& v, int axis, std::size_t len) {
    const std::size_t n = v.size_xy;
    const std::size_t dims[3] = {n, n, v.size_t};
    const std::size_t strides[3] = {1, n, n * n};
    std::vector<double> sums(len, 0.0);
    std::vector<std::size_t> counts(len, 0);
    for (std::size_t i = 0; i < v.alpha.size(); ++i) {
        const std::size_t pos = (i / strides[axis]) % dims[axis];
        if (pos >= len) {
            continue;
        }
        const std::size_t next = pos + 1 < len ? i + strides[axis] : i - pos * strides[axis];
        sums[pos] += std::abs(static_cast<double>(v.alpha[next]) - v.alpha[i]);
        ++counts[pos];
    }
    for (std::size_t p = 0; p < len; ++p) {
        sums[p] /= static_cast<double>(counts[p]);
    }
    return sums;
}

/// True when the wrap-around plane's mean step lies within the interior planes' range.
bool wrap_looks_interior(const std::vector<double>& steps) {
    const auto [lo, hi] = std::minmax_element(steps.begin(), steps.end() - 1);
    return steps.back() >= *lo && steps.back() <= *hi;
}

TEST(SpectralVolume, TilesAndLoopsWithoutASeam) {
    const SpectralVolume v = build_spectral_volume(small_layer(), 21);
    const std::size_t dims[3] = {v.size_xy, v.size_xy, v.size_t};
    for (int axis = 0; axis < 3; ++axis) {
        // Periodic: the step across the edge is just another step.
        const std::vector<double> steps = plane_steps(v, axis, dims[axis]);
        EXPECT_TRUE(wrap_looks_interior(steps))
            << "axis " << axis << ": wrap " << steps.back() << ", first interior " << steps[0];
        // The check can fail: a crop of the volume, tiled, has a seam.
        const std::vector<double> cropped = plane_steps(v, axis, dims[axis] * 3 / 4);
        EXPECT_FALSE(wrap_looks_interior(cropped)) << "axis " << axis;
    }
}

TEST(SpectralMapping, WholeTilesAroundAndLoopFollowsSpeed) {
    SpectralSnow s;
    const SpectralMapping a = spectral_mapping(s, 50.0f, 480, 1.0f);
    // 480 px over 50°: ≈ 515 px per radian, 128-texel tiles → 2π·515/128 ≈ 25.
    EXPECT_EQ(a.tiles_around, 25);
    s.speed = 2.0f;
    const SpectralMapping b = spectral_mapping(s, 50.0f, 480, 1.0f);
    EXPECT_NEAR(b.loop_seconds, 0.5 * a.loop_seconds, 1e-9 * a.loop_seconds);
    const SpectralMapping c = spectral_mapping(s, 50.0f, 480, 2.0f);
    EXPECT_NEAR(c.loop_seconds, 0.25 * a.loop_seconds, 1e-9 * a.loop_seconds);
    // The nearest band falls like a particle at start_distance: speed·v/d rad/s.
    const double tile = 2.0 * 3.141592653589793 / a.tiles_around;
    const double band_low_rad_per_s =
        spectral_c_max(SpectralSnow{}) / SpectralSnow{}.band_low * tile / a.loop_seconds;
    EXPECT_NEAR(band_low_rad_per_s, 1.0 / SpectralSnow{}.start_distance, 1e-9);
}

/// The fixture scene with a spectral layer that starts at `start` metres.
void add_layer(FixtureScene& scene, float start) {
    SpectralSnow s = small_layer();
    s.opacity = 0.7f;
    s.start_distance = start;
    scene.visuals.spectral = s;
}

TEST(RenderSpectral, PassesExistOnlyForWorldsThatDeclareTheEffects) {
    FixtureScene scene;
    build_fixture(scene);
    auto context = headless_context();
    Renderer renderer(*context);
    render_world(renderer, scene.world, scene.visuals, scene.camera);
    const std::vector<std::string> builtin = {"sky", "meshes", "snow_surfaces", "flakes"};
    EXPECT_EQ(renderer.pass_names(), builtin);
    for (const std::string& v : renderer.compiled_variants()) {
        EXPECT_EQ(v.find("spectral"), std::string::npos) << v;
        EXPECT_EQ(v.find("puff"), std::string::npos) << v;
    }

    add_layer(scene, 10.0f);
    Fog fog;
    fog.puffs.push_back(FogPuff{{0.0f, 1.0f, 0.0f}, 1.0f, 0.5f, {}, 0.0f});
    scene.visuals.fog = fog;
    render_world(renderer, scene.world, scene.visuals, scene.camera);
    const std::vector<std::string> effects = {"sky",           "meshes", "snow_surfaces",
                                              "spectral_snow", "flakes", "fog_puffs"};
    EXPECT_EQ(renderer.pass_names(), effects);
    for (const PassTiming& p : renderer.timings().passes) {
        EXPECT_TRUE(p.ran) << p.name;
    }
    std::size_t spectral_variants = 0, puff_variants = 0;
    for (const std::string& v : renderer.compiled_variants()) {
        spectral_variants += v.find("spectral_snow.frag") != std::string::npos ? 1u : 0u;
        puff_variants += v.find("fog_puffs.frag") != std::string::npos ? 1u : 0u;
    }
    EXPECT_EQ(spectral_variants, 1u);
    EXPECT_EQ(puff_variants, 1u);

    // The effects removed again: their passes stay in the list but skip.
    scene.visuals.spectral.reset();
    scene.visuals.fog.reset();
    render_world(renderer, scene.world, scene.visuals, scene.camera);
    for (const PassTiming& p : renderer.timings().passes) {
        EXPECT_EQ(p.ran, p.name != "spectral_snow" && p.name != "fog_puffs" && p.name != "sky")
            << p.name;
    }
}

TEST(RenderSpectral, LayerCoversTheFarFieldAndLeavesNearSurfacesAlone) {
    FixtureScene plain;
    build_fixture(plain);
    FixtureScene snowy;
    build_fixture(snowy);
    add_layer(snowy, 10.0f);
    const Image a = render_image(plain.world, plain.visuals, plain.camera);
    const Image b = render_image(snowy.world, snowy.visuals, snowy.camera);
    // Near surfaces (the crate and the house, under 10 m away) stay as they were.
    for (const glm::vec3& p : {glm::vec3(2.0f, 0.35f, 0.6f), glm::vec3(-2.5f, 1.0f, 1.0f)}) {
        const glm::vec3 d = glm::abs(mean_color(a, to_pixel(plain.camera, p), 2) -
                                     mean_color(b, to_pixel(plain.camera, p), 2));
        EXPECT_LT(std::max({d.x, d.y, d.z}), 1.0f) << p.x;
    }
    // The sky (top rows) gets a textured veil of snow: it changes and varies.
    double changed = 0.0, mean = 0.0, mean2 = 0.0;
    int count = 0;
    for (int y = 0; y < 12; ++y) {
        for (int x = 0; x < a.width; ++x) {
            const double va = a.pixel(x, y)[0], vb = b.pixel(x, y)[0];
            changed += std::abs(vb - va);
            mean += vb;
            mean2 += vb * vb;
            ++count;
        }
    }
    mean /= count;
    const double stddev = std::sqrt(std::max(0.0, mean2 / count - mean * mean));
    EXPECT_GT(changed / count, 3.0);
    EXPECT_GT(stddev, 2.0) << "the far-field snow has no texture";
}

/// A ground 120 m wide that ends 40 m ahead of the camera, the sky above it.
struct HorizonScene {
    World world;
    SceneVisuals visuals;
    ViewCamera camera;
    float far_edge_z = -30.0f;
    HorizonScene() {
        MeshRenderable ground;
        ground.name = "ground";
        ground.positions = {{-60.0f, 0.0f, far_edge_z},
                            {60.0f, 0.0f, far_edge_z},
                            {60.0f, 0.0f, 12.0f},
                            {-60.0f, 0.0f, 12.0f}};
        ground.normals.assign(4, glm::vec3(0.0f, 1.0f, 0.0f));
        ground.indices = {0, 2, 1, 0, 3, 2};
        ground.color = {0.3f, 0.3f, 0.3f};
        visuals.meshes.push_back(std::move(ground));
        camera.position = {0.0f, 3.0f, 10.0f};
        camera.look_at({0.0f, 1.5f, far_edge_z});
    }
};

/// Mean over each image row of the layer's opacity: out = a·snow + (1 − a)·in,
/// solved per channel where the snow colour and the scene differ enough.
std::vector<double> layer_by_row(const Image& with, const Image& without) {
    const glm::vec3 snow = RenderSettings{}.snow_color * 255.0f;
    std::vector<double> rows(static_cast<std::size_t>(with.height), 0.0);
    for (int y = 0; y < with.height; ++y) {
        double sum = 0.0;
        int n = 0;
        for (int x = 0; x < with.width; ++x) {
            for (int k = 0; k < 3; ++k) {
                const double in = without.pixel(x, y)[k], contrast = snow[k] - in;
                if (std::abs(contrast) > 40.0) {
                    sum += (with.pixel(x, y)[k] - in) / contrast;
                    ++n;
                }
            }
        }
        rows[static_cast<std::size_t>(y)] = n > 0 ? sum / n : 0.0;
    }
    return rows;
}

TEST(RenderSpectral, FarFieldMeetsTheHorizonWithoutASeam) {
    // The layer over a surface D away has the weight 1 − (h/D)², h the
    // hand-over from the flakes (12 m: their lod_distance is nearer than the
    // start): over the ground's last rows, 40 m away, it is nearly what it is
    // over the sky just above them. Faded in from the start distance to twice
    // it instead (as before), the ground's last rows got 40 % of the sky's
    // opacity: a band where the streaks of the far field began.
    HorizonScene scene;
    RenderSettings dark_ground; // bare albedo: the white layer shows on it as on the sky
    dark_ground.mesh_snow = 0.0f;
    const Image without = render_image(scene.world, scene.visuals, scene.camera, dark_ground);
    SpectralSnow s = small_layer();
    s.start_distance = 25.0f;
    s.opacity = 0.6f;
    scene.visuals.spectral = s;
    const Image with = render_image(scene.world, scene.visuals, scene.camera, dark_ground);
    const std::vector<double> rows = layer_by_row(with, without);
    const int horizon = to_pixel(scene.camera, {0.0f, 0.0f, scene.far_edge_z}).y;
    ASSERT_GT(horizon, 40);
    ASSERT_LT(horizon, golden_height - 40);
    const auto mean = [&](int from, int to) {
        double sum = 0.0;
        for (int y = from; y <= to; ++y) {
            sum += rows[static_cast<std::size_t>(y)];
        }
        return sum / (to - from + 1);
    };
    const double sky = mean(horizon - 30, horizon - 3);
    const double above = mean(horizon - 5, horizon - 3), below = mean(horizon + 3, horizon + 5);
    ASSERT_GT(sky, 0.1) << "the layer veils the sky";
    EXPECT_LT(std::abs(above - below) / sky, 0.2)
        << "the layer jumps at the horizon: " << above << " above, " << below << " below";
    // Down the ground toward the camera it thins out steadily, gone by 12 m.
    const int near_row = to_pixel(scene.camera, {0.0f, 0.0f, 0.0f}).y; // 10 m away
    EXPECT_LT(std::abs(rows[static_cast<std::size_t>(near_row)]), 0.01);
    for (int y = horizon + 3; y < near_row; ++y) {
        EXPECT_LT(
            std::abs(rows[static_cast<std::size_t>(y + 1)] - rows[static_cast<std::size_t>(y)]),
            0.1 * sky)
            << "a step between rows " << y << " and " << y + 1;
    }
}

/// `count` flakes at fixed quasi-random places in the box lo..hi (golden-ratio
/// sequences), diameters from size_lo to size_hi.
void scatter_flakes(World& world, int count, const glm::vec3& lo, const glm::vec3& hi,
                    float size_lo, float size_hi) {
    FlakePool& pool = world.set_resource<FlakePool>();
    pool.reset(static_cast<std::uint32_t>(count));
    const auto at = [](int i, double step) { return static_cast<float>(std::fmod(i * step, 1.0)); };
    for (int i = 0; i < count; ++i) {
        std::uint32_t slot = 0;
        ASSERT_TRUE(pool.acquire(slot));
        pool.px[slot] = lo.x + (hi.x - lo.x) * at(i, 0.6180339887);
        pool.py[slot] = lo.y + (hi.y - lo.y) * at(i, 0.7548776662);
        pool.pz[slot] = lo.z + (hi.z - lo.z) * at(i, 0.5698402910);
        pool.size[slot] = size_lo + (size_hi - size_lo) * at(i, 0.3819660113);
        pool.mass_units[slot] = 1;
    }
}

TEST(RenderSpectral, FlakesHandOverToTheLayerBeyondTheHandOverDistance) {
    // 4000 flakes 30 m ahead: all drawn without the layer (no level of
    // detail), a share (h/d)² = (12/30)² = 16 % with it, h the hand-over.
    World world;
    scatter_flakes(world, 4000, {-3.0f, 2.0f, -20.0f}, {3.0f, 4.0f, -20.0f}, 0.01f, 0.01f);
    ViewCamera camera;
    camera.position = {0.0f, 3.0f, 10.0f};
    camera.look_at({0.0f, 3.0f, -20.0f});
    RenderSettings settings;
    settings.flake_lod = FlakeLod::never;
    auto context = headless_context();
    Renderer renderer(*context, settings);
    SceneVisuals visuals;
    render_world(renderer, world, visuals, camera);
    EXPECT_EQ(renderer.timings().flakes_drawn, 4000u);
    SpectralSnow s = small_layer();
    s.start_distance = 25.0f;
    visuals.spectral = s;
    render_world(renderer, world, visuals, camera);
    EXPECT_NEAR(renderer.timings().flakes_drawn, 4000.0 * (12.0 / 30.0) * (12.0 / 30.0), 60.0);
    // A start of 0 puts the layer everywhere and leaves the flakes alone.
    visuals.spectral->start_distance = 0.0f;
    render_world(renderer, world, visuals, camera);
    EXPECT_EQ(renderer.timings().flakes_drawn, 4000u);
}

TEST(RenderGolden, FarFieldTakesOverFromTheFlakesAtTheHorizon) {
    // The horizon scene in falling snow: 3000 flakes out to the ground's far
    // edge, thinned beyond the 12 m hand-over as the far-field layer takes
    // over, on the ground as on the sky (compare with the horizon test above).
    HorizonScene scene;
    scatter_flakes(scene.world, 3000, {-15.0f, 0.2f, -30.0f}, {15.0f, 8.2f, 8.0f}, 0.012f, 0.024f);
    SpectralSnow s = small_layer();
    s.start_distance = 25.0f;
    scene.visuals.spectral = s;
    RenderSettings dark_ground; // bare albedo, so the white snow shows on the ground too
    dark_ground.mesh_snow = 0.0f;
    EXPECT_TRUE(matches_golden(render_image(scene.world, scene.visuals, scene.camera, dark_ground),
                               "far_field_horizon"));
}

TEST(RenderSpectral, AnimatesWithTheSimulationClock) {
    FixtureScene scene;
    build_fixture(scene);
    add_layer(scene, 10.0f);
    scene.world.set_resource<SimConfig>();
    scene.world.set_resource<SimClock>();
    const Image t0 = render_image(scene.world, scene.visuals, scene.camera);
    scene.world.resource<SimClock>().tick = 30;
    const Image t1 = render_image(scene.world, scene.visuals, scene.camera);
    EXPECT_GT(compare_images(t0, t1).pixels_over, 100u);
}

TEST(RenderGolden, FixtureWithSpectralSnow) {
    FixtureScene scene;
    build_fixture(scene);
    add_layer(scene, 10.0f);
    EXPECT_TRUE(
        matches_golden(render_image(scene.world, scene.visuals, scene.camera), "scene_spectral"));
}

TEST(RenderPerf, DISABLED_SpectralVolumeBuildAndPass) {
    // Cost table of docs/effects.md: the one-off volume build and the pass at 640×480.
    for (const std::uint32_t size : {64u, 128u}) {
        SpectralSnow s;
        s.size_xy = size;
        s.size_t = size / 2;
        const auto t0 = std::chrono::steady_clock::now();
        const SpectralVolume v = build_spectral_volume(s, 1);
        const double ms =
            std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0)
                .count();
        std::printf("spectral volume %ux%ux%u: build %.1f ms (FFT + rescale, no upload)\n", size,
                    size, size / 2, ms);
        EXPECT_EQ(v.alpha.size(), std::size_t{size} * size * (size / 2));
    }
    FixtureScene scene;
    build_fixture(scene);
    scene.visuals.spectral = SpectralSnow{};
    auto context = headless_context(640, 480);
    RenderSettings settings;
    settings.timing_mode = true;
    Renderer renderer(*context, settings);
    std::vector<double> pass_ms, frame_ms;
    for (int i = 0; i < 16; ++i) {
        render_world(renderer, scene.world, scene.visuals, scene.camera);
        if (i == 0) {
            continue; // the first frame builds the volume
        }
        for (const PassTiming& p : renderer.timings().passes) {
            if (p.name == "spectral_snow") {
                pass_ms.push_back(p.cpu_ms);
            }
        }
        frame_ms.push_back(renderer.timings().frame_ms);
    }
    std::sort(pass_ms.begin(), pass_ms.end());
    std::sort(frame_ms.begin(), frame_ms.end());
    std::printf("spectral_snow pass at 640x480 (128x128x64): median %.2f ms, frame %.2f ms\n",
                pass_ms[pass_ms.size() / 2], frame_ms[frame_ms.size() / 2]);
}

} // namespace
} // namespace snow::test
