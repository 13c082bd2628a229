#include "game/run/run_report.hpp"
#include "systems/api/simulation_internals.hpp"

#include "game/export/surface_list.hpp"
#include "systems/core/units.hpp"

#include <nlohmann/json.hpp>

#include <cstdio>
#include <sstream>

namespace snow {

std::string hash_hex(std::uint64_t h) {
    char buf[17];
    std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(h));
    return buf;
}

std::string run_report_json(const Simulation& sim, const RunInfo& info) {
    const SimConfig& cfg = sim.config();
    const MassReport m = sim.mass();
    const SimCounters& c = sim.counters();
    nlohmann::ordered_json j;
    j["scene"] = info.scene;
    j["seed"] = cfg.seed;
    j["ticks"] = info.ticks;
    j["dt"] = cfg.dt;
    j["threads"] = cfg.threads;
    j["integrator"] = std::string(integrator_name(cfg.integrator));
    j["state_hash"] = hash_hex(sim.state_hash());
    j["mass"] = {{"unit_kg", unit_kg},      {"spawned", m.spawned}, {"airborne", m.airborne},
                 {"settled", m.settled},    {"carried", m.carried}, {"removed", m.removed},
                 {"balanced", m.balanced()}};
    j["flakes"] = {{"alive", flake_pool(sim).alive},
                   {"max_alive", flake_pool(sim).max_alive},
                   {"capacity", flake_pool(sim).capacity()}};
    j["nonfinite"] = sim.nonfinite_count();
    j["counters"] = {{"landed", c.landed},
                     {"rolled", c.rolled},
                     {"stiff_flake_ticks", c.stiff_flake_ticks},
                     {"smoothing_iterations", c.smoothing_iterations},
                     {"spilled_units", c.spilled_units},
                     {"occlusion_refreshes", c.occlusion_refreshes}};
    auto systems = nlohmann::ordered_json::array();
    for (const SystemStats& s : schedule_of(sim).stats()) {
        systems.push_back(
            {{"name", s.name},
             {"calls", s.calls},
             {"skipped", s.skipped},
             {"total_ms", s.total_ms},
             {"ms_per_call", s.calls ? s.total_ms / static_cast<double>(s.calls) : 0.0}});
    }
    j["systems"] = systems;
    auto surfaces = nlohmann::ordered_json::array();
    for (const NamedSurface& ns : named_surfaces(sim)) {
        const SurfaceStats st = surface_stats(*ns.surface);
        surfaces.push_back({{"name", ns.name},
                            {"kind", kind_name(ns.kind)},
                            {"cells", st.cells},
                            {"settled_units", st.settled_units},
                            {"mean_depth_m", st.mean_depth_m},
                            {"max_depth_m", st.max_depth_m}});
    }
    j["surfaces"] = surfaces;
    j["wall_ms"] = info.wall_ms;
    return j.dump(2);
}

std::string run_report_text(const Simulation& sim, const RunInfo& info) {
    const SimConfig& cfg = sim.config();
    const MassReport m = sim.mass();
    std::ostringstream os;
    os << "scene      " << info.scene << "\n"
       << "ticks      " << info.ticks << " (dt " << cfg.dt << " s, seed " << cfg.seed << ", "
       << cfg.threads << " thread(s), integrator " << integrator_name(cfg.integrator) << ")\n"
       << "state hash " << hash_hex(sim.state_hash()) << "\n"
       << "mass units spawned " << m.spawned << " = airborne " << m.airborne << " + settled "
       << m.settled << " + carried " << m.carried << " + removed " << m.removed
       << (m.balanced() ? "  (exact)" : "  (MISMATCH)") << "\n"
       << "flakes     alive " << flake_pool(sim).alive << ", max alive "
       << flake_pool(sim).max_alive << "\n"
       << "nonfinite  " << sim.nonfinite_count() << "\n"
       << "wall       " << info.wall_ms << " ms\n"
       << "system           calls    skipped   total ms   ms/call\n";
    for (const SystemStats& s : schedule_of(sim).stats()) {
        char line[160];
        std::snprintf(line, sizeof line, "%-14s %8llu %10llu %10.2f %9.4f\n", s.name.c_str(),
                      static_cast<unsigned long long>(s.calls),
                      static_cast<unsigned long long>(s.skipped), s.total_ms,
                      s.calls ? s.total_ms / static_cast<double>(s.calls) : 0.0);
        os << line;
    }
    os << "surface           cells    settled units  mean depth mm  max depth mm\n";
    for (const NamedSurface& ns : named_surfaces(sim)) {
        const SurfaceStats st = surface_stats(*ns.surface);
        char line[160];
        std::snprintf(line, sizeof line, "%-14s %9llu %16llu %14.3f %13.3f\n", ns.name.c_str(),
                      static_cast<unsigned long long>(st.cells),
                      static_cast<unsigned long long>(st.settled_units), st.mean_depth_m * 1e3,
                      st.max_depth_m * 1e3);
        os << line;
    }
    return os.str();
}

} // namespace snow
