// Images: PNG round trip, errors naming the path, screenshots right side up.
#include "render/renderer_internals.hpp"
#include "render_fixture.hpp"
#include <snow/error.hpp>

#include <gtest/gtest.h>

#include <filesystem>

namespace snow::test {
namespace {

TEST(RenderImage, PngRoundTripIsExact) {
    Image img;
    img.width = 5;
    img.height = 3;
    for (int i = 0; i < 5 * 3 * 4; ++i) {
        img.rgba.push_back(static_cast<std::uint8_t>(i * 17));
    }
    const auto path = std::filesystem::path(SNOW_BINARY_DIR) / "render_roundtrip.png";
    write_png(path, img);
    const Image back = read_png(path);
    EXPECT_EQ(back.width, 5);
    EXPECT_EQ(back.height, 3);
    EXPECT_EQ(back.rgba, img.rgba);
    std::filesystem::remove(path);
}

TEST(RenderImage, FileErrorsNameThePath) {
    Image img;
    img.width = 1;
    img.height = 1;
    img.rgba = {1, 2, 3, 4};
    try {
        write_png("/nonexistent_dir/x.png", img);
        FAIL() << "writing into a missing directory succeeded";
    } catch (const RenderError& e) {
        EXPECT_NE(std::string(e.what()).find("/nonexistent_dir/x.png"), std::string::npos);
    }
    EXPECT_THROW((void)read_png("/nonexistent_dir/y.png"), RenderError);
    img.rgba.pop_back();
    EXPECT_THROW(write_png(std::filesystem::path(SNOW_BINARY_DIR) / "bad.png", img), RenderError);
}

TEST(RenderImage, ScreenshotIsRightSideUp) {
    // Sky above, a dark ground plane below the horizon: row 0 must be sky.
    const World w;
    SceneVisuals visuals;
    visuals.environment = Environment{{0.2f, 0.2f, 0.2f}, {0.0f, 0.0f, 1.0f}};
    MeshRenderable ground;
    ground.positions = {{-50, 0, -50}, {50, 0, -50}, {50, 0, 50}, {-50, 0, 50}};
    ground.normals.assign(4, {0.0f, 1.0f, 0.0f});
    ground.indices = {0, 2, 1, 0, 3, 2};
    ground.color = {1.0f, 0.0f, 0.0f};
    visuals.meshes.push_back(ground);
    ViewCamera cam;
    cam.position = {0.0f, 1.0f, 0.0f};
    RenderSettings settings;
    settings.mesh_snow = 0.0f;
    const Image img = render_image(w, visuals, cam, settings);
    const std::uint8_t* top = img.pixel(golden_width / 2, 0);
    const std::uint8_t* bottom = img.pixel(golden_width / 2, golden_height - 1);
    EXPECT_EQ(top[2], 255);
    EXPECT_EQ(top[0], 0);
    EXPECT_GT(bottom[0], 100);
    EXPECT_EQ(bottom[2], 0);
}

} // namespace
} // namespace snow::test
