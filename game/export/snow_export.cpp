#include "game/export/snow_export.hpp"

#include "game/export/glb_writer.hpp"
#include "game/export/png16.hpp"
#include "game/export/snow_mesh.hpp"
#include "game/export/surface_list.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <span>
#include <string>

namespace snow {

namespace {

constexpr const char* generator = "snow " SNOW_VERSION " (snow_run --export)";

/// A string's or a byte vector's bytes, as the file writer takes them.
template <typename Bytes>
std::span<const std::byte> bytes_of(const Bytes& b) {
    return std::as_bytes(std::span(b));
}

/// The shortest decimal that reads back as `f`: a 0.1f cell is written 0.1.
double decimal(float f) {
    char buf[32];
    const auto end = std::to_chars(buf, buf + sizeof buf, f).ptr;
    return std::strtod(std::string(buf, end).c_str(), nullptr);
}

} // namespace

void export_snow_glb(const Simulation& sim, const std::filesystem::path& file) {
    const std::vector<NamedSurface> surfaces = named_surfaces(sim);
    std::vector<SnowMesh> meshes;
    meshes.reserve(surfaces.size());
    std::vector<NamedMesh> named;
    for (const NamedSurface& s : surfaces) {
        meshes.push_back(build_snow_mesh(*s.surface));
        named.push_back({s.name, &meshes.back()});
    }
    std::vector<std::uint8_t> glb;
    try {
        glb = encode_glb(named, generator);
    } catch (const std::length_error& e) {
        throw FileWriteError("cannot write '" + file.string() + "': " + e.what());
    }
    write_file(file, bytes_of(glb));
}

std::vector<std::uint16_t> depth_mm(const SnowSurface& s) {
    std::vector<std::uint16_t> px(s.cell_count(), 0);
    for (std::size_t i = 0; i < px.size(); ++i) {
        if (!s.is_void(i)) {
            const double mm =
                std::round(static_cast<double>(s.depth_levels(i)) * s.unit_height * 1000.0);
            px[i] = static_cast<std::uint16_t>(std::min(mm, 65535.0));
        }
    }
    return px;
}

void export_snow_depth(const Simulation& sim, const std::filesystem::path& dir) {
    prepare_output_dir(dir);
    StagedFiles out;
    for (const NamedSurface& ns : named_surfaces(sim)) {
        const SnowSurface& s = *ns.surface;
        out.stage(dir / (ns.name + ".png"), bytes_of(encode_png_gray16(s.nx, s.nz, depth_mm(s))));
        const nlohmann::ordered_json meta = {{"name", ns.name},
                                             {"kind", kind_name(ns.kind)},
                                             {"origin", {decimal(s.x0), decimal(s.z0)}},
                                             {"cell", decimal(s.cell)},
                                             {"cells", {s.nx, s.nz}},
                                             {"depth_unit_m", 0.001}};
        out.stage(dir / (ns.name + ".json"), bytes_of(meta.dump(2) + "\n"));
    }
    out.commit();
}

} // namespace snow
