// Shader programs: errors carry the driver's info log; every built-in variant compiles.
#include "render/gl/shader.hpp"
#include "render/gl/shader_error.hpp"
#include "render/gl/shader_sources.hpp"
#include "tests/render/render_fixture.hpp"

#include <gtest/gtest.h>

namespace snow::test {
namespace {

const std::string vertex_ok = "#version 330 core\nvoid main() { gl_Position = vec4(0.0); }\n";

std::string error_of(const std::string& vs, const std::string& fs) {
    try {
        Program p("probe", vs, fs);
    } catch (const ShaderError& e) {
        return e.what();
    }
    return {};
}

TEST(RenderShader, CompileErrorCarriesTheInfoLog) {
    auto context = headless_context();
    const std::string msg = error_of(
        vertex_ok, "#version 330 core\nout vec4 c;\nvoid main() { c = undefined_fn(1.0); }\n");
    ASSERT_FALSE(msg.empty()) << "the broken shader compiled";
    EXPECT_NE(msg.find("'probe'"), std::string::npos) << msg;
    EXPECT_NE(msg.find("fragment"), std::string::npos) << msg;
    EXPECT_NE(msg.find("undefined_fn"), std::string::npos) << "driver log missing: " << msg;
}

TEST(RenderShader, LinkErrorCarriesTheInfoLog) {
    auto context = headless_context();
    // Compiles on its own, but a program needs a main() in every stage.
    const std::string msg =
        error_of(vertex_ok, "#version 330 core\nout vec4 c;\nvoid helper() { c = vec4(1.0); }\n");
    ASSERT_FALSE(msg.empty()) << "a fragment stage without main() linked";
    EXPECT_NE(msg.find("link"), std::string::npos) << msg;
    EXPECT_NE(msg.find("main"), std::string::npos) << "driver log missing: " << msg;
}

TEST(RenderShader, UnknownEmbeddedShaderIsAnError) {
    EXPECT_THROW((void)shader_source("no_such.frag"), RenderError);
    EXPECT_NE(shader_source("common.glsl").find("uniform Frame"), std::string_view::npos);
}

TEST(RenderShader, EveryBuiltInVariantCompiles) {
    auto context = headless_context();
    ProgramCache cache;
    const std::vector<std::vector<std::string>> fogs = {
        {}, {"FOG", "FOG_EXPONENTIAL"}, {"FOG", "FOG_HALF_LIFE"}, {"FOG", "FOG_LAYERED"}};
    for (const auto& fog : fogs) {
        for (const char* stage : {"sky", "surface", "flake"}) {
            EXPECT_NO_THROW(
                (void)cache.get(std::string(stage) + ".vert", std::string(stage) + ".frag", fog));
        }
        std::vector<std::string> occ = fog;
        occ.emplace_back("OCCLUSION");
        EXPECT_NO_THROW((void)cache.get("mesh.vert", "mesh.frag", fog));
        EXPECT_NO_THROW((void)cache.get("mesh.vert", "mesh.frag", occ));
    }
    EXPECT_EQ(cache.variants().size(), 4u * 5u);
}

} // namespace
} // namespace snow::test
