// glTF base colour textures: a textured quad draws the texture's colours
// times the base colour factor where they lie, and every bad texture input
// (a missing or non-PNG image, a texcoord accessor of the wrong type or
// count, a dangling index) is one error naming the field, exit status 2.
#include "tests/game/scene/scene_test_files.hpp"
#include "tests/render/render_fixture.hpp"
#include "tests/support/run_app.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <array>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

namespace snow::test {
namespace {

using nlohmann::json;

/// The texture's four 2 x 2 blocks, top left first: sampled at a block's
/// centre, linear filtering reads that block's colour alone.
const std::array<glm::vec3, 4> block_colors{
    {{200, 40, 40}, {40, 160, 60}, {30, 60, 200}, {190, 190, 120}}};
constexpr float factor = 0.8f; ///< the material's baseColorFactor (grey)

std::vector<unsigned char> texture_png() {
    Image image;
    image.width = image.height = 4;
    image.rgba.resize(4 * 4 * 4);
    for (int y = 0; y < 4; ++y) {
        for (int x = 0; x < 4; ++x) {
            const glm::vec3 c = block_colors[static_cast<std::size_t>((y / 2) * 2 + x / 2)];
            const std::array<std::uint8_t, 4> px{static_cast<std::uint8_t>(c.r),
                                                 static_cast<std::uint8_t>(c.g),
                                                 static_cast<std::uint8_t>(c.b), 255};
            std::memcpy(image.rgba.data() + (y * 4 + x) * 4, px.data(), 4);
        }
    }
    const std::vector<std::uint8_t> png = encode_png(image);
    return {png.begin(), png.end()};
}

/// A 2 x 2 m quad at y = 0 facing up; texcoord (0, 0) at (-1, -1), so the
/// image's top left block lies at x < 0, z < 0 and its top right at x > 0.
json textured_quad(const std::string& image_uri) {
    const std::vector<float> xyz{-1, 0, -1, 1, 0, -1, 1, 0, 1, -1, 0, 1};
    const std::vector<float> normals{0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1, 0};
    const std::vector<float> uv{0, 0, 1, 0, 1, 1, 0, 1};
    std::vector<unsigned char> bytes = mesh_bytes(xyz, quad_indices);
    const auto append = [&](const std::vector<float>& v) {
        const std::size_t at = bytes.size();
        bytes.resize(at + v.size() * 4);
        std::memcpy(bytes.data() + at, v.data(), v.size() * 4);
    };
    append(normals); // at 60
    append(uv);      // at 108
    json doc = json::parse(R"({
      "asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}],
      "nodes": [{"name": "quad", "mesh": 0}],
      "meshes": [{"primitives": [{"attributes": {"POSITION": 0, "NORMAL": 2, "TEXCOORD_0": 3},
                                  "indices": 1, "material": 0}]}],
      "materials": [{"pbrMetallicRoughness": {"baseColorFactor": [0.8, 0.8, 0.8, 1],
                                              "baseColorTexture": {"index": 0}}}],
      "textures": [{"source": 0}],
      "accessors": [
        {"bufferView": 0, "componentType": 5126, "count": 4, "type": "VEC3"},
        {"bufferView": 1, "componentType": 5123, "count": 6, "type": "SCALAR"},
        {"bufferView": 2, "componentType": 5126, "count": 4, "type": "VEC3"},
        {"bufferView": 3, "componentType": 5126, "count": 4, "type": "VEC2"}],
      "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 48},
                      {"buffer": 0, "byteOffset": 48, "byteLength": 12},
                      {"buffer": 0, "byteOffset": 60, "byteLength": 48},
                      {"buffer": 0, "byteOffset": 108, "byteLength": 32}]})");
    doc["buffers"] =
        json::array({{{"byteLength", bytes.size()},
                      {"uri", "data:application/octet-stream;base64," + base64(bytes)}}});
    doc["images"] = json::array({{{"uri", image_uri}}});
    return doc;
}

std::string png_data_uri(const std::vector<unsigned char>& png) {
    return "data:image/png;base64," + base64(png);
}

SceneLoadResult load(const json& doc) {
    return load_scene_memory(doc.dump(), "tex.gltf");
}

ViewCamera above_camera() {
    ViewCamera c;
    c.position = {0.0f, 2.6f, 1.6f};
    c.look_at({0.0f, 0.0f, 0.0f});
    return c;
}

/// The centre of the quad's block k (0: top left of the image, 3: bottom right).
glm::vec3 block_centre(std::size_t k) {
    return {k % 2 == 0 ? -0.5f : 0.5f, 0.0f, k < 2 ? -0.5f : 0.5f};
}

TEST(SceneTextures, TexturedQuadShowsTheTexturesColoursTimesTheFactor) {
    const SceneLoadResult r = load(textured_quad(png_data_uri(texture_png())));
    ASSERT_NE(r.sim, nullptr) << r.error;
    ASSERT_EQ(r.visuals.meshes.size(), 1u);
    const MeshRenderable& quad = r.visuals.meshes[0];
    ASSERT_NE(quad.texture, nullptr);
    EXPECT_EQ(quad.texture->width, 4);
    EXPECT_EQ(quad.texcoords.size(), 4u);

    // The same quad untextured, one mesh per block in the factor times its colour.
    SceneVisuals reference = r.visuals;
    reference.meshes.clear();
    for (std::size_t k = 0; k < 4; ++k) {
        const glm::vec3 c = block_centre(k);
        MeshRenderable m;
        m.name = "block";
        m.positions = {c + glm::vec3(-0.5f, 0.0f, -0.5f), c + glm::vec3(0.5f, 0.0f, -0.5f),
                       c + glm::vec3(0.5f, 0.0f, 0.5f), c + glm::vec3(-0.5f, 0.0f, 0.5f)};
        m.normals.assign(4, glm::vec3(0.0f, 1.0f, 0.0f));
        m.indices = {0, 2, 1, 0, 3, 2};
        m.color = factor * block_colors[k] / 255.0f;
        reference.meshes.push_back(std::move(m));
    }
    auto context = headless_context();
    Renderer renderer(*context);
    const ViewCamera camera = above_camera();
    renderer.render(*r.sim, r.visuals, camera);
    const Image textured = renderer.read_pixels();
    renderer.render(*r.sim, reference, camera);
    const Image plain = renderer.read_pixels();
    for (std::size_t k = 0; k < 4; ++k) {
        const glm::ivec2 px = to_pixel(camera, block_centre(k));
        const glm::vec3 t = mean_color(textured, px, 1);
        const glm::vec3 p = mean_color(plain, px, 1);
        std::printf("[ measure ] block %zu at (%d, %d): textured (%.1f, %.1f, %.1f), plain "
                    "(%.1f, %.1f, %.1f)\n",
                    k, px.x, px.y, t.x, t.y, t.z, p.x, p.y, p.z);
        for (int c = 0; c < 3; ++c) {
            EXPECT_NEAR(t[c], p[c], 2.0f) << "block " << k << ", channel " << c;
        }
    }
    // The blocks differ from each other: the texture, not one colour, is drawn.
    const glm::vec3 red = mean_color(textured, to_pixel(camera, block_centre(0)), 1);
    const glm::vec3 green = mean_color(textured, to_pixel(camera, block_centre(1)), 1);
    EXPECT_GT(red.x, red.y + 60.0f);
    EXPECT_GT(green.y, green.x + 60.0f);
}

TEST(SceneTextures, AnImageFileBesideTheSceneIsReadAndAMissingOneIsAnError) {
    TempDir dir;
    const std::vector<unsigned char> png = texture_png();
    dir.write(dir.scene_dir() / "wood.png", std::string(png.begin(), png.end()));
    const fs::path good = dir.scene_dir() / "good.gltf";
    dir.write(good, textured_quad("wood.png").dump());
    const SceneLoadResult ok = load_scene_file(good.string());
    ASSERT_NE(ok.sim, nullptr) << ok.error;
    ASSERT_NE(ok.visuals.meshes[0].texture, nullptr);
    EXPECT_EQ(ok.visuals.meshes[0].texture->rgba[0], 200); // the top left texel's red

    const fs::path bad = dir.scene_dir() / "bad.gltf";
    dir.write(bad, textured_quad("missing.png").dump());
    expect_error(load_scene_file(bad.string()),
                 {"bad.gltf: images[0].uri names 'missing.png', which is not a file inside the "
                  "scene's folder"});
    dir.write(bad, textured_quad("../wood.png").dump());
    expect_error(load_scene_file(bad.string()),
                 {"bad.gltf: images[0].uri must not leave the scene's folder"});
    expect_error(load(textured_quad("wood.png")),
                 {"tex.gltf: images[0].uri names an external file ('wood.png'), which a scene "
                  "loaded from memory may not"});
}

TEST(SceneTextures, AnImageThatIsNotAValidPngIsAnError) {
    const std::string gif = "GIF89a\x01\x00\x01\x00";
    expect_error(load(textured_quad(png_data_uri({gif.begin(), gif.end()}))),
                 {"tex.gltf: images[0].uri is not a PNG (its bytes do not start with the PNG "
                  "signature"});
    std::vector<unsigned char> cut = texture_png();
    cut.resize(40); // the signature and the header, no image data
    expect_error(load(textured_quad(png_data_uri(cut))),
                 {"tex.gltf: images[0].uri is not a valid PNG ("});
    // An image in a bufferView is named by its image.
    json doc = textured_quad("");
    doc["images"][0] = {{"bufferView", 0}}; // the positions' bytes
    expect_error(load(doc), {"tex.gltf: images[0] is not a PNG"});
}

TEST(SceneTextures, BadTexcoordsAndIndicesAreErrorsNamingTheField) {
    const std::string uri = png_data_uri(texture_png());
    json doc = textured_quad(uri);
    doc["accessors"][3]["type"] = "VEC3";
    expect_error(load(doc), {"tex.gltf: accessors[3].type must be VEC2 (got \"VEC3\")"});
    doc = textured_quad(uri);
    doc["accessors"][3]["count"] = 3;
    expect_error(load(doc), {"tex.gltf: meshes[0].primitives[0].attributes.TEXCOORD_0 must have "
                             "as many elements as POSITION (4, got 3)"});
    doc = textured_quad(uri);
    doc["accessors"][3]["componentType"] = 5123;
    expect_error(load(doc), {"tex.gltf: accessors[3].componentType must be 5126 (FLOAT)"});
    doc = textured_quad(uri);
    doc["meshes"][0]["primitives"][0]["attributes"].erase("TEXCOORD_0");
    expect_error(load(doc), {"tex.gltf: meshes[0].primitives[0].attributes needs TEXCOORD_0: "
                             "its material (materials[0]) has a baseColorTexture"});
    doc = textured_quad(uri);
    doc["materials"][0]["pbrMetallicRoughness"]["baseColorTexture"]["index"] = 5;
    expect_error(load(doc), {"tex.gltf: materials[0].pbrMetallicRoughness.baseColorTexture.index "
                             "must name one of the file's 1 textures (got 5)"});
    doc = textured_quad(uri);
    doc["materials"][0]["pbrMetallicRoughness"]["baseColorTexture"]["texCoord"] = 1;
    expect_error(load(doc), {"baseColorTexture.texCoord must be 0 (only TEXCOORD_0 is read"});
    doc = textured_quad(uri);
    doc["textures"][0].erase("source");
    expect_error(load(doc), {"tex.gltf: textures[0].source must name one of the file's 1 images"});
}

TEST(SceneTextures, SnowRunExitsWithStatus2OnABadTexture) {
    TempDir dir;
    const fs::path bad = dir.scene_dir() / "bad.gltf";
    dir.write(bad, textured_quad("missing.png").dump());
    const AppRun run = run_app("game/snow_run", "--scene " + bad.string() + " --ticks 1");
    EXPECT_EQ(run.status, 2) << run.out;
    EXPECT_NE(run.out.find("images[0].uri names 'missing.png'"), std::string::npos) << run.out;
}

} // namespace
} // namespace snow::test
