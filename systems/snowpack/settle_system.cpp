// settle: snow settles under its own weight (docs/references.md [And76]).
// Every SimConfig::settle_interval each cell's snow shrinks at Anderson's
// compaction rate (1976, as SNTHERM.89 writes it [Jor91]), the sum of
// destructive metamorphism and overburden creep:
//   CR = c1·e^(−c2·(T0 − T))·e^(−c3·max(0, ρ − ρd)) + σ / (η0·e^(c5·(T0 − T) + c6·ρ))
// with the cell's mean density ρ (its units over its levels), the air
// temperature T (at most 0 °C) and σ the weight over the middle of the
// cell's snow, half its load: a cell is one layer. Its volume goes
// V → V·e^(−CR·Δt). Levels are whole, so the fraction left over is rounded
// by a draw keyed by tick and cell: exact in the mean, the same for any
// thread count; settling never packs past max_packing times fresh density.
#include "ecs/rng.hpp"
#include "systems/api/systems.hpp"
#include "systems/core/random_streams.hpp"
#include "systems/core/sim_config.hpp"
#include "systems/core/units.hpp"
#include "systems/snowpack/snow_surface.hpp"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace snow {

namespace {

// Anderson 1976 [And76] with SNTHERM.89's SI values [Jor91].
constexpr double metamorphism_rate = 2.777e-6; ///< c1 (1/s): 1 %/h at 0 °C
constexpr double metamorphism_cold = 0.04;     ///< c2 (1/K)
constexpr double metamorphism_dense = 0.046;   ///< c3 (m³/kg)
constexpr double metamorphism_density = 150.0; ///< ρd (kg/m³): slower above it
constexpr double viscosity_base = 3.6e6;       ///< η0 (N·s/m²)
constexpr double viscosity_cold = 0.08;        ///< c5 (1/K)
constexpr double viscosity_dense = 0.021;      ///< c6 (m³/kg)

/// Ticks per settling step: the interval in whole ticks, at least one.
std::uint64_t settle_ticks(const SimConfig& c) {
    return static_cast<std::uint64_t>(std::max(1.0, std::round(double{c.settle_interval} / c.dt)));
}

} // namespace

void settle_system(World& w) {
    const SimConfig& config = w.resource<SimConfig>();
    const std::uint64_t tick = w.resource<SimClock>().tick;
    const std::uint64_t every = settle_ticks(config);
    if ((tick + 1) % every != 0) {
        return;
    }
    const double dt = static_cast<double>(every) * config.dt;
    const double fresh = fresh_snow_density(config);
    const double below_melt = -std::min(double{config.air_temperature}, 0.0); // T0 − T (K)
    const double metamorphism = metamorphism_rate * std::exp(-metamorphism_cold * below_melt);
    const double viscosity = viscosity_base * std::exp(viscosity_cold * below_melt);
    const double g = glm::length(config.gravity);
    auto& surfaces = w.pool<SnowSurface>().components();
    for (std::uint32_t k = 0; k < surfaces.size(); ++k) {
        SnowSurface& s = surfaces[k];
        const double weight_per_unit = unit_kg * g / (double{s.cell} * s.cell); // Pa
        for (std::size_t i = 0; i < s.cell_count(); ++i) {
            const std::uint32_t units = s.snow[i];
            if (units == 0) {
                continue;
            }
            const auto levels = static_cast<double>(s.depth_levels(i));
            const double rho = fresh * units / levels;
            const double rate =
                metamorphism *
                    std::exp(-metamorphism_dense * std::max(0.0, rho - metamorphism_density)) +
                0.5 * units * weight_per_unit / (viscosity * std::exp(viscosity_dense * rho));
            const double shrink = -levels * std::expm1(-rate * dt);
            const std::uint32_t packed = s.compacted.empty() ? 0 : s.compacted[i];
            const double draw = rng_uniform(
                {config.seed, tick, static_cast<std::uint32_t>(i), random_stream::settle}, k);
            const double room = max_compaction(units) - packed;
            const auto lost = static_cast<std::uint32_t>(std::min(room, std::floor(shrink + draw)));
            if (lost != 0) {
                s.compact(i, lost);
                s.mark_dirty(i);
            }
        }
    }
}

} // namespace snow
