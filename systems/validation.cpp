// validate() for every user-facing settings struct, in one place (Box2D's
// def-struct habit): each struct's field table, then the rules that relate
// fields. The facade and the scene loader both call these.
#include "systems/validation.hpp"

#include "systems/settings_fields.hpp"

#include <bit>
#include <string>

namespace snow {

namespace {

/// The corners of `box` finite and min <= max on every axis ("prefix.max.x", ...).
void check_box(Invalid& e, std::string_view prefix, const Aabb& box) {
    check_fields(e, prefix, aabb_fields, box);
    static constexpr std::string_view lo[] = {"min.x", "min.y", "min.z"};
    static constexpr std::string_view hi[] = {"max.x", "max.y", "max.z"};
    for (int a = 0; a < 3; ++a) {
        check::ordered(e, prefix, lo[a], box.min[a], hi[a], box.max[a]);
    }
}

} // namespace

Invalid validate(const SimConfig& c) {
    Invalid e = check_fields("simulation", sim_config_fields, c);
    check_box(e, "simulation.bounds", c.bounds);
    if (integrator_name(c.integrator) == "unknown") {
        check::fail(e, "simulation.integrator", "one of " + integrator_choices(),
                    static_cast<double>(c.integrator));
    }
    return e;
}

Invalid validate(const Emitter& m) {
    Invalid e = check_fields("emitter", emitter_fields, m);
    check::ordered(e, "emitter", "mass_min_g", m.mass_min_g, "mass_max_g", m.mass_max_g);
    check::ordered(e, "emitter", "size_min", m.size_min, "size_max", m.size_max);
    check::ordered(e, "emitter", "fall_speed_min", m.fall_speed_min, "fall_speed_max",
                   m.fall_speed_max);
    return e;
}

Invalid validate(const Aabb& box) {
    Invalid e;
    check_box(e, "box", box);
    return e;
}

Invalid validate(const FlakeSpec& f) {
    return check_fields("flake", flake_fields, f);
}

Invalid validate(const Wind& w) {
    return check_fields("wind", wind_fields, w);
}

Invalid validate(const Fog& f) {
    Invalid e = check_fields("fog", fog_fields, f);
    check::ordered(e, "fog", "layer_bottom", f.layer_bottom, "layer_top", f.layer_top);
    for (std::size_t i = 0; i < f.puffs.size() && e.empty(); ++i) {
        check_fields(e, "fog.puffs[" + std::to_string(i) + "]", fog_puff_fields, f.puffs[i]);
    }
    return e;
}

Invalid validate(const SpectralSnow& s) {
    Invalid e = check_fields("spectral", spectral_fields, s);
    for (const auto& [field, size] :
         {std::pair{"spectral.size_xy", s.size_xy}, std::pair{"spectral.size_t", s.size_t}}) {
        if (!std::has_single_bit(size)) {
            check::fail(e, field, "a power of two", size);
        }
    }
    check::ordered(e, "spectral", "band_low", s.band_low, "band_high", s.band_high);
    // The band must fit the volume: at most its Nyquist frequency [LZ].
    check::number(e, "spectral.band_high", up_to(s.size_xy / 2.0), s.band_high);
    return e;
}

Invalid validate(const OcclusionCamera& cam) {
    return check_fields("occlusion", occlusion_fields, cam);
}

Invalid validate(const BodyMotion& m) {
    Invalid e;
    if (m.waypoints.empty()) {
        e = {"motion.waypoints", "must hold at least one point (got none)"};
    }
    for (std::size_t i = 0; i < m.waypoints.size() && e.empty(); ++i) {
        check::finite3(e, "motion.waypoints[" + std::to_string(i) + "]", m.waypoints[i]);
    }
    check_fields(e, "motion", motion_fields, m);
    return e;
}

Invalid validate(const BodyDef& d) {
    Invalid e;
    if (d.shape != BodyShape::sphere && d.shape != BodyShape::box &&
        d.shape != BodyShape::capsule) {
        check::fail(e, "body.shape", "sphere, box or capsule", static_cast<double>(d.shape));
    }
    check_fields(e, "body", body_fields, d);
    if (d.shape == BodyShape::box) {
        check_fields(e, "body", box_body_fields, d);
    } else if (d.shape == BodyShape::sphere) {
        check_fields(e, "body", sphere_body_fields, d);
    } else if (d.shape == BodyShape::capsule) {
        check_fields(e, "body", capsule_body_fields, d);
    }
    if (e.empty() && d.snowball && d.shape != BodyShape::sphere) {
        e = {"body.snowball", "needs shape sphere"};
    }
    if (e.empty() && !d.motion.waypoints.empty()) {
        e = validate(d.motion);
    }
    return e;
}

Invalid validate(const WindFieldDef& d) {
    Invalid e = check_fields("wind.field", wind_field_fields, d);
    const std::uint64_t cells = std::uint64_t{d.cells_x} * d.cells_y * d.cells_z;
    check::number(e, "wind.field.cells (total)", up_to(max_wind_field_cells),
                  static_cast<double>(cells));
    return e;
}

Invalid validate(const WindTransportDef& t) {
    return check_fields("wind.field.transport", wind_transport_fields, t);
}

Invalid validate(const SurfaceDef& def) {
    Invalid e = check_fields("surface", surface_fields, def);
    if (e.empty() && def.slide_depth > 0.0f) {
        if (def.slope_x == 0.0f && def.slope_z == 0.0f) {
            e = {"surface.slide_depth",
                 "needs a tilted surface (slope_x or slope_z), got a flat one"};
        } else if (!def.spills) {
            e = {"surface.slide_depth", "needs a surface that spills (spills is false)"};
        }
    }
    return e;
}

Invalid validate(const CoverDef& def) {
    Invalid e = check_fields("cover", cover_fields, def);
    check::ordered(e, "cover", "min.x", def.min_x, "max.x", def.max_x, true);
    check::ordered(e, "cover", "min.z", def.min_z, "max.z", def.max_z, true);
    return e;
}

} // namespace snow
