// Context backends: OSMesa headless, the automatic fallback and why it fell
// back, switching contexts, and a GLFW window under Xvfb.
#include "render/context/glfw_context.hpp"
#include "render/renderer_internals.hpp"
#include "tests/render/render_fixture.hpp"
#include "tests/support/xvfb.hpp"
#include <snow/error.hpp>
#include <snow/render.hpp>

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <optional>
#include <string>

namespace snow::test {
namespace {

TEST(RenderContext, HeadlessGivesACoreContextOfTheRequestedSize) {
    ContextRequest req;
    req.backend = ContextBackend::headless;
    req.width = 200;
    req.height = 100;
    setenv("MESA_SHADER_CACHE_DISABLE", "true", 0);
    const auto context = make_context(req);
    EXPECT_EQ(context->name(), "osmesa");
    EXPECT_EQ(context->framebuffer_size(), glm::ivec2(200, 100));
    EXPECT_FALSE(context->should_close());
    EXPECT_NE(context->proc_address("glDrawArrays"), nullptr);
    Renderer renderer(*context);
    EXPECT_FALSE(renderer.gl_description().empty());
}

TEST(RenderContext, BadSizesAreRejected) {
    EXPECT_THROW(OsMesaContext(0, 10), RenderError);
    EXPECT_THROW(OsMesaContext(10, -1), RenderError);
    EXPECT_THROW(OsMesaContext(100000, 10), RenderError);
}

TEST(RenderContext, AutomaticFallsBackToHeadlessWithoutDisplay) {
    const ScopedEnv no_x11("DISPLAY", std::nullopt);
    const ScopedEnv no_wayland("WAYLAND_DISPLAY", std::nullopt);
    ContextRequest req;
    req.quiet = true;
    std::string why;
    const auto context = make_context(req, &why);
    EXPECT_EQ(context->name(), "osmesa");
    EXPECT_NE(why.find("DISPLAY"), std::string::npos) << why;

    req.backend = ContextBackend::window;
    EXPECT_THROW((void)make_context(req), RenderError) << "a window was asked for explicitly";
}

TEST(RenderContext, AutomaticFallsBackWhenTheDisplayIsUnreachable) {
    const ScopedEnv bad_display("DISPLAY", std::string(":4093"));
    const ScopedEnv no_wayland("WAYLAND_DISPLAY", std::nullopt);
    ContextRequest req;
    req.quiet = true;
    std::string why;
    const auto context = make_context(req, &why);
    EXPECT_EQ(context->name(), "osmesa");
    EXPECT_NE(why.find("glfwInit failed"), std::string::npos) << why;
}

TEST(RenderContext, SwitchingBetweenContextsReloadsEntryPoints) {
    FixtureScene scene;
    build_fixture(scene);
    auto a = headless_context();
    Renderer ra(*a);
    auto b = headless_context();
    Renderer rb(*b);
    a->make_current();
    render_world(ra, scene.world, scene.visuals, scene.camera);
    const Image ia = ra.read_pixels();
    b->make_current();
    render_world(rb, scene.world, scene.visuals, scene.camera);
    const Image ib = rb.read_pixels();
    EXPECT_EQ(compare_images(ia, ib).worst, 0);
    a->make_current(); // leave `a` current for its renderer's destruction
}

TEST(RenderContext, EglSurfacelessDrawsLikeOsMesa) {
    FixtureScene scene;
    build_fixture(scene);
    const Image osmesa = render_image(scene.world, scene.visuals, scene.camera);
    ContextRequest req;
    req.backend = ContextBackend::egl;
    req.width = golden_width;
    req.height = golden_height;
    std::unique_ptr<GlContext> context;
    try {
        context = make_context(req);
    } catch (const RenderError& e) {
        GTEST_SKIP() << "EGL backend unavailable here: " << e.what();
    }
    EXPECT_EQ(context->name(), "egl");
    EXPECT_NE(context->framebuffer(), 0u);
    Image egl;
    {
        Renderer renderer(*context);
        render_world(renderer, scene.world, scene.visuals, scene.camera);
        egl = renderer.read_pixels();
    }
    const ImageComparison c = compare_images(egl, osmesa);
    EXPECT_TRUE(close_enough(c, osmesa))
        << c.pixels_over << " pixels differ (worst " << c.worst << ") from the OSMesa image";
}

TEST(RenderContext, GlfwWindowUnderXvfbDrawsLikeHeadless) {
    const std::optional<std::string> binary = Xvfb::find();
    if (!binary) {
        GTEST_SKIP() << "Xvfb is not installed (apt-get install xvfb): window backend untested";
    }
    FixtureScene scene;
    build_fixture(scene);
    const Image headless = render_image(scene.world, scene.visuals, scene.camera);

    Xvfb server;
    std::string display, error;
    ASSERT_TRUE(server.start(*binary, display, error)) << error;
    const ScopedEnv use_display("DISPLAY", display);
    const ScopedEnv no_wayland("WAYLAND_DISPLAY", std::nullopt);
    ContextRequest req;
    req.backend = ContextBackend::automatic;
    req.width = golden_width;
    req.height = golden_height;
    req.vsync = false;
    std::string why;
    Image windowed;
    {
        const auto context = make_context(req, &why);
        ASSERT_EQ(context->name(), "glfw") << "fell back: " << why;
        EXPECT_TRUE(why.empty());
        ASSERT_EQ(context->framebuffer_size(), glm::ivec2(golden_width, golden_height));
        EXPECT_FALSE(context->should_close());
        Renderer renderer(*context);
        render_world(renderer, scene.world, scene.visuals, scene.camera);
        windowed = renderer.read_pixels();
        context->swap_buffers();
        context->poll_events();
    }
    const ImageComparison c = compare_images(windowed, headless);
    EXPECT_TRUE(close_enough(c, headless))
        << c.pixels_over << " pixels differ (worst " << c.worst << ") from the OSMesa image";
}

} // namespace
} // namespace snow::test
