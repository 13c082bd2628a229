// glTF's own objects, one table each (glTF 2.0 §5). Unknown properties are
// ignored: the format has many the loader does not use, and extensions and
// extras may appear anywhere.
#include "game/scene/scene_document.hpp"

namespace snow {

namespace {

constexpr auto ignore = UnknownKeys::ignore;

constexpr Field<GltfBuffer> buffer_fields[] = {
    {"byteLength", &GltfBuffer::byte_length, {1.0}, true},
    {"uri", &GltfBuffer::uri},
};

constexpr Field<GltfBufferView> buffer_view_fields[] = {
    {"buffer", &GltfBufferView::buffer, {}, true},
    {"byteOffset", &GltfBufferView::byte_offset},
    {"byteLength", &GltfBufferView::byte_length, {1.0}, true},
    {"byteStride", &GltfBufferView::byte_stride, {4.0, 252.0}},
};

constexpr Field<GltfAccessor> accessor_fields[] = {
    {"bufferView", &GltfAccessor::buffer_view},
    {"byteOffset", &GltfAccessor::byte_offset},
    {"componentType", &GltfAccessor::component_type, {}, true},
    {"count", &GltfAccessor::count, {1.0}, true},
    {"type", &GltfAccessor::type, {}, true},
    {"normalized", &GltfAccessor::normalized},
    {"sparse", +[](const Json&, const std::string&, GltfAccessor& a) { a.sparse = true; }},
};

constexpr Field<GltfPrimitive> attribute_fields[] = {
    {"POSITION", &GltfPrimitive::position},
    {"NORMAL", &GltfPrimitive::normal},
    {"TEXCOORD_0", &GltfPrimitive::texcoord},
};

constexpr Field<GltfPrimitive> primitive_fields[] = {
    {"attributes",
     +[](const Json& j, const std::string& field, GltfPrimitive& p) {
         read_fields(j, field, attribute_fields, ignore, p);
     },
     {},
     true},
    {"indices", &GltfPrimitive::indices},
    {"material", &GltfPrimitive::material},
    {"mode", &GltfPrimitive::mode, {0.0, 6.0}},
};

constexpr Field<GltfMesh> mesh_fields[] = {
    {"primitives",
     +[](const Json& j, const std::string& field, GltfMesh& m) {
         m.primitives = read_list(j, field, primitive_fields, ignore);
         if (m.primitives.empty()) {
             scene_fail(field, "must not be empty");
         }
     },
     {},
     true},
};

constexpr Field<GltfMaterial> texture_info_fields[] = {
    {"index", &GltfMaterial::base_color_texture, {}, true},
    {"texCoord", &GltfMaterial::base_color_texcoord},
};

constexpr Field<GltfMaterial> pbr_fields[] = {
    {"baseColorFactor", &GltfMaterial::base_color, {0.0, 1.0}},
    {"baseColorTexture",
     +[](const Json& j, const std::string& field, GltfMaterial& m) {
         read_fields(j, field, texture_info_fields, ignore, m);
         if (m.base_color_texcoord != 0) {
             scene_fail(field + ".texCoord", "must be 0 (only TEXCOORD_0 is read; got " +
                                                 std::to_string(m.base_color_texcoord) + ")");
         }
     }},
};

constexpr Field<GltfMaterial> material_fields[] = {
    {"pbrMetallicRoughness",
     +[](const Json& j, const std::string& field, GltfMaterial& m) {
         read_fields(j, field, pbr_fields, ignore, m);
         if (m.base_color.size() != 4) {
             scene_fail(field + ".baseColorFactor",
                        "must have 4 numbers (got " + std::to_string(m.base_color.size()) + ")");
         }
     }},
};

constexpr Field<GltfTexture> texture_fields[] = {
    {"source", &GltfTexture::source},
};

constexpr Field<GltfImage> image_fields[] = {
    {"uri", &GltfImage::uri},
    {"bufferView", &GltfImage::buffer_view},
};

constexpr Field<GltfNode> node_fields[] = {
    {"name", &GltfNode::name},
    {"mesh", &GltfNode::mesh},
    {"children", &GltfNode::children},
    {"matrix", &GltfNode::matrix},
    {"translation", &GltfNode::translation},
    {"rotation", &GltfNode::rotation},
    {"scale", &GltfNode::scale},
};

constexpr Field<GltfScene> scene_fields[] = {
    {"name", &GltfScene::name},
    {"nodes", &GltfScene::nodes},
};

constexpr Field<GltfDocument> asset_fields[] = {
    {"version", &GltfDocument::version, {}, true},
};

constexpr Field<GltfDocument> document_fields[] = {
    {"asset",
     +[](const Json& j, const std::string& field, GltfDocument& d) {
         read_fields(j, field, asset_fields, ignore, d);
         if (d.version.rfind("2.", 0) != 0) {
             scene_fail(field + ".version", "must be \"2.0\" (only glTF 2 is supported; got " +
                                                in_quotes(d.version) + ")");
         }
     },
     {},
     true},
    {"extensionsRequired", &GltfDocument::required_extensions},
    {"scene", &GltfDocument::scene},
    {"scenes", &read_nested<&GltfDocument::scenes, scene_fields, ignore>},
    {"nodes", &read_nested<&GltfDocument::nodes, node_fields, ignore>},
    {"meshes", &read_nested<&GltfDocument::meshes, mesh_fields, ignore>},
    {"materials", &read_nested<&GltfDocument::materials, material_fields, ignore>},
    {"accessors", &read_nested<&GltfDocument::accessors, accessor_fields, ignore>},
    {"bufferViews", &read_nested<&GltfDocument::buffer_views, buffer_view_fields, ignore>},
    {"buffers", &read_nested<&GltfDocument::buffers, buffer_fields, ignore>},
    {"textures", &read_nested<&GltfDocument::textures, texture_fields, ignore>},
    {"images", &read_nested<&GltfDocument::images, image_fields, ignore>},
};

/// Extensions a file may require that change only how it looks, not its
/// geometry; the loader draws without them.
bool only_changes_looks(const std::string& extension) {
    return extension.starts_with("KHR_materials_") || extension == "KHR_texture_transform" ||
           extension == "KHR_texture_basisu" || extension == "EXT_texture_webp";
}

} // namespace

GltfDocument read_document(const Json& doc, std::vector<std::string>& warnings) {
    if (!doc.is_object()) {
        throw SceneError("not a glTF file (got " + json_type_name(doc) + ", not an object)");
    }
    if (!doc.contains("asset")) {
        throw SceneError("not a glTF file (no \"asset\" object)");
    }
    GltfDocument d;
    read_fields(doc, "", document_fields, ignore, d);
    for (std::size_t i = 0; i < d.required_extensions.size(); ++i) {
        const std::string& e = d.required_extensions[i];
        const std::string field = "extensionsRequired[" + std::to_string(i) + "]";
        if (only_changes_looks(e)) {
            warnings.push_back(field + " " + in_quotes(e) +
                               " is not supported; the scene is drawn without it");
        } else if (e != "KHR_lights_punctual") {
            scene_fail(field, "is " + in_quotes(e) +
                                  ", which the loader does not support (it changes geometry or "
                                  "buffers: compression, quantization, instancing)");
        }
    }
    return d;
}

} // namespace snow
