// The settings tables drive validate(): for every bounded row of every table
// validate() rejects a value just past a bound (and NaN) naming the row's
// field, the table accepts the bound itself, and messages say which bound
// was broken.
#include "render/visual_rules.hpp"
#include "systems/api/validation.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>
#include <vector>

namespace snow {
namespace {

/// A value for one field and whether its row must accept it.
template <typename V>
struct Probe {
    V value;
    bool accepted;
};

/// Values at and just past the bounds of `r`, for a float field.
std::vector<Probe<float>> probes(const Range& r, float) {
    constexpr float inf = std::numeric_limits<float>::infinity();
    std::vector<Probe<float>> p = {{std::numeric_limits<float>::quiet_NaN(), false}};
    if (std::isfinite(r.min)) {
        const auto lo = static_cast<float>(r.min);
        p.push_back({r.min_exclusive ? lo : std::nextafter(lo, -inf), false});
        p.push_back({r.min_exclusive ? std::nextafter(lo, inf) : lo, true});
    }
    if (std::isfinite(r.max)) {
        const auto hi = static_cast<float>(r.max);
        p.push_back({r.max_exclusive ? hi : std::nextafter(hi, inf), false});
        p.push_back({r.max_exclusive ? std::nextafter(hi, -inf) : hi, true});
    }
    return p;
}

/// Values at and just past the bounds of `r`, for an integer field.
std::vector<Probe<std::uint32_t>> probes(const Range& r, std::uint32_t) {
    std::vector<Probe<std::uint32_t>> p;
    if (r.min >= 1.0) {
        const auto lo = static_cast<std::uint32_t>(r.min);
        p.push_back({lo - 1, false});
        p.push_back({lo, true});
    }
    if (std::isfinite(r.max)) {
        const auto hi = static_cast<std::uint32_t>(r.max);
        p.push_back({hi + 1, false});
        p.push_back({hi, true});
    }
    return p;
}

/// Runs every probe of every row of `table` on a copy of `valid` (whose part
/// `part(w)` the table describes) and checks what validate() says.
template <typename T, std::size_t N, typename Whole, typename Part>
int expect_rows_checked(const FieldRule<T> (&table)[N], const std::string& prefix,
                        const Whole& valid, Part part) {
    EXPECT_TRUE(validate(valid).empty()) << validate(valid).text();
    int probed = 0;
    for (const FieldRule<T>& row : table) {
        std::visit(
            [&](auto member) {
                using V = std::remove_cvref_t<decltype(part(std::declval<Whole&>()).*member)>;
                if constexpr (std::is_same_v<V, float> || std::is_same_v<V, std::uint32_t> ||
                              std::is_same_v<V, glm::vec3>) {
                    using Scalar = std::conditional_t<std::is_same_v<V, glm::vec3>, float, V>;
                    const std::string field = prefix + "." + std::string(row.name) +
                                              (std::is_same_v<V, glm::vec3> ? ".x" : "");
                    for (const auto& [value, accepted] : probes(row.range, Scalar{})) {
                        Whole w = valid;
                        if constexpr (std::is_same_v<V, glm::vec3>) {
                            (part(w).*member).x = value;
                        } else {
                            part(w).*member = value;
                        }
                        SCOPED_TRACE(field + " = " + std::to_string(value));
                        if (accepted) { // by the table (a rule relating fields may still object)
                            Invalid v;
                            check_fields(v, prefix, table, part(w));
                            EXPECT_TRUE(v.empty()) << v.text();
                        } else {
                            EXPECT_EQ(validate(w).field, field) << validate(w).text();
                        }
                        ++probed;
                    }
                }
            },
            row.member);
    }
    return probed;
}

template <typename Whole, std::size_t N, typename T>
int expect_rows_checked(const FieldRule<T> (&table)[N], const std::string& prefix,
                        const Whole& valid) {
    return expect_rows_checked(table, prefix, valid, [](Whole& w) -> Whole& { return w; });
}

TEST(FieldRules, EveryBoundedRowIsCheckedByValidate) {
    int probed = 0;
    probed += expect_rows_checked(sim_config_fields, "simulation", SimConfig{});
    probed += expect_rows_checked(emitter_fields, "emitter", Emitter{});
    probed += expect_rows_checked(flake_fields, "flake", FlakeSpec{});
    probed += expect_rows_checked(wind_fields, "wind", Wind{});
    probed += expect_rows_checked(wind_field_fields, "wind.field", WindFieldDef{});
    probed += expect_rows_checked(fog_fields, "fog", Fog{});
    Fog puffed;
    puffed.puffs.emplace_back();
    probed += expect_rows_checked(fog_puff_fields, "fog.puffs[0]", puffed,
                                  [](Fog& f) -> FogPuff& { return f.puffs[0]; });
    probed += expect_rows_checked(occlusion_fields, "occlusion", OcclusionCamera{});
    probed += expect_rows_checked(spectral_fields, "spectral", SpectralSnow{});
    probed += expect_rows_checked(surface_fields, "surface", SurfaceDef{});
    probed += expect_rows_checked(cover_fields, "cover", CoverDef{});
    probed += expect_rows_checked(motion_fields, "motion", BodyMotion{{glm::vec3(0.0f)}});
    probed += expect_rows_checked(aabb_fields, "box", Aabb{});
    BodyDef body;
    probed += expect_rows_checked(body_fields, "body", body);
    probed += expect_rows_checked(sphere_body_fields, "body", body);
    body.shape = BodyShape::capsule;
    probed += expect_rows_checked(capsule_body_fields, "body", body);
    body.shape = BodyShape::box;
    probed += expect_rows_checked(box_body_fields, "body", body);
    EXPECT_GT(probed, 150);
}

TEST(FieldRules, MessagesNameTheBrokenBound) {
    EXPECT_EQ(range_problem(positive, 0.0), "must be > 0 (got 0)");
    EXPECT_EQ(range_problem(between(0, 1.0e8), -1.0), "must be >= 0 (got -1)");
    EXPECT_EQ(range_problem(between(0, 1.0e8), 2.0e8), "must be <= 100000000 (got 2e+08)");
    EXPECT_EQ(range_problem(non_negative, std::nan("")), "must be finite (got nan)");
    EXPECT_EQ(range_problem(at_least(1), 1.0), "");
    Emitter e;
    e.rate = -1.0f;
    EXPECT_EQ(validate(e).text(), "emitter.rate must be >= 0 (got -1)");
    e.rate = 2.0e8f;
    EXPECT_EQ(validate(e).text(), "emitter.rate must be <= 100000000 (got 2e+08)");
    Wind w;
    w.base.y = 300.0f;
    EXPECT_EQ(validate(w).text(), "wind.base.y must be <= 200 (got 300)");
    SimConfig c;
    c.bounds.max.y = c.bounds.min.y - 1.0f;
    EXPECT_EQ(validate(c).text(),
              "simulation.bounds.max.y must be >= simulation.bounds.min.y (-1) (got -2)");
    CoverDef cover;
    cover.max_z = cover.min_z;
    EXPECT_EQ(validate(cover).text(), "cover.max.z must be > cover.min.z (-1) (got -1)");
}

TEST(FieldRules, CrossFieldRulesHold) {
    Emitter e;
    e.size_min = 0.5f;
    e.size_max = 0.25f;
    EXPECT_EQ(validate(e).field, "emitter.size_max");
    SpectralSnow s;
    s.size_xy = 96; // in range, not a power of two
    EXPECT_EQ(validate(s).text(), "spectral.size_xy must be a power of two (got 96)");
    s = {};
    s.band_high = s.size_xy / 2.0f + 1.0f; // above the volume's Nyquist frequency
    EXPECT_EQ(validate(s).field, "spectral.band_high");
    WindFieldDef d;
    d.cells_x = d.cells_y = d.cells_z = 257;
    EXPECT_EQ(validate(d).field, "wind.field.cells (total)");
    BodyDef b;
    b.shape = BodyShape::box;
    b.snowball = true;
    EXPECT_EQ(validate(b).field, "body.snowball");
}

} // namespace
} // namespace snow
