// Output of snow_accuracy. Numbers are printed with fixed formats so the
// markdown tables line up; every number in them comes from this run.
#include "bench/accuracy/report.hpp"

#include "ecs/staged_files.hpp"

#include <algorithm>
#include <cstdarg>
#include <cstdio>
#include <filesystem>
#include <span>
#include <string>

namespace snow::accuracy {

namespace {

/// A text file built in memory and written all or nothing by close()
/// (ecs/staged_files.hpp), so an interrupted study leaves the old file.
class OutFile {
  public:
    explicit OutFile(std::string path) : path_(std::move(path)) {}
    [[gnu::format(printf, 2, 3)]] void print(const char* fmt, ...) {
        va_list args, again;
        va_start(args, fmt);
        va_copy(again, args);
        const int n = std::vsnprintf(nullptr, 0, fmt, args);
        va_end(args);
        const std::size_t at = text_.size();
        text_.resize(at + static_cast<std::size_t>(std::max(n, 0)) + 1);
        std::vsnprintf(text_.data() + at, text_.size() - at, fmt, again);
        va_end(again);
        text_.pop_back(); // vsnprintf's terminating zero
    }
    void text(const std::string& s) { text_ += s; }
    /// Writes the file; throws FileWriteError naming it if that fails.
    void close() const { write_file(path_, std::as_bytes(std::span(text_))); }

  private:
    std::string path_, text_;
};

std::string name_of(Integrator i) {
    return std::string(integrator_name(i));
}

/// The enumerator's name in C++ (for the quality.hpp snippet).
const char* integrator_enum(Integrator i) {
    switch (i) {
    case Integrator::explicit_euler:
        return "explicit_euler";
    case Integrator::semi_implicit_euler:
        return "semi_implicit_euler";
    case Integrator::exponential:
        return "exponential";
    case Integrator::rk4:
        return "rk4";
    case Integrator::automatic:
        return "automatic";
    }
    return "explicit_euler";
}

/// "1/60" for the dts of the study (all 1/n).
std::string dt_text(float dt) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "1/%.0f", 1.0 / dt);
    return buf;
}

double mm(double metres) {
    return metres * 1.0e3;
}

bool on_front(const StudyResults& r, std::size_t i) {
    return std::find(r.front.begin(), r.front.end(), i) != r.front.end();
}

// ---------------------------------------------------------------- CSV / dat

void write_trajectory(const std::string& dir, const StudyResults& r) {
    OutFile csv(dir + "/trajectory.csv");
    csv.text("integrator,dt,steps_per_s,max_pos_error_m,rms_pos_error_m,max_vel_error_mps,"
             "stiff_share,ns_per_flake_tick,ns_per_flake_second\n");
    for (const TrajectoryRow& t : r.trajectory) {
        csv.print("%s,%.9g,%.0f,%.6e,%.6e,%.6e,%.4f,%.4f,%.2f\n", name_of(t.integrator).c_str(),
                  static_cast<double>(t.dt), 1.0 / t.dt, t.max_pos_error, t.rms_pos_error,
                  t.max_vel_error, t.stiff_share, t.ns_per_flake_tick,
                  t.ns_per_flake_tick / static_cast<double>(t.dt));
    }
    csv.close();
    // One gnuplot data block per integrator (blocks split by two blank lines).
    OutFile dat(dir + "/trajectory.dat");
    for (const Integrator i : r.trajectory_options.integrators) {
        dat.print("# %s: steps_per_s max_pos_error_m ns_per_flake_second\n", name_of(i).c_str());
        for (const TrajectoryRow& t : r.trajectory) {
            if (t.integrator == i) {
                dat.print("%.0f %.6e %.3f\n", 1.0 / t.dt, t.max_pos_error,
                          t.ns_per_flake_tick / static_cast<double>(t.dt));
            }
        }
        dat.text("\n\n");
    }
    dat.close();
}

void scene_row(OutFile& f, const ScenePoint& p) {
    const SceneKnobs& k = p.knobs;
    f.print("%s,%.0f,%s,%g,%u,%u,%llu,%.4f,%.2f,%.5f,%.5f,%.5f,%.5f,%.4f,%.5f,%.5f,%.5f,%.5f,"
            "%.4f,%.4f,%.4f,%.4f,%.4f,%.2f",
            dt_text(k.dt).c_str(), 1.0 / k.dt, name_of(k.integrator).c_str(),
            static_cast<double>(k.cell_scale), k.smoothing, k.occlusion,
            static_cast<unsigned long long>(p.ticks), p.cpu_ms_per_tick, p.cpu_ms_per_second(),
            p.error.rel_l1, mm(p.error.l1), mm(p.error.linf), mm(p.error.centroid_shift),
            p.error.volume_ratio, p.fine_error.rel_l1, p.cell_error.rel_l1, p.paired.rel_l1,
            mm(p.paired.centroid_shift), p.settled_share, p.airborne_share, p.bounds_share,
            p.sphere_share, p.bare_share, p.smoothing_per_tick);
    for (std::size_t i = 0; i < p.rel_l1_by_seed.size(); ++i) {
        f.print("%s%.5f", i == 0 ? "," : ";", p.rel_l1_by_seed[i]);
    }
}

constexpr const char* scene_header =
    "dt,steps_per_s,integrator,cell_scale,smoothing,occlusion,ticks,cpu_ms_per_tick,"
    "cpu_ms_per_sim_s,rel_l1,l1_mm,linf_mm,centroid_shift_mm,volume_ratio,fine_rel_l1,"
    "cell_rel_l1,paired_rel_l1,paired_centroid_shift_mm,settled_share,airborne_share,"
    "removed_bounds_share,removed_sphere_share,removed_bare_share,smoothing_iter_per_tick,"
    "rel_l1_by_seed";

void write_scene(const std::string& dir, const StudyResults& r) {
    const SceneStudy& s = r.scene;
    OutFile csv(dir + "/scene.csv");
    csv.print("role,%s,on_front\n", scene_header);
    for (const ScenePoint& p : s.floor) {
        csv.text("floor,");
        scene_row(csv, p);
        csv.text(",0\n");
    }
    for (std::size_t i = 0; i < s.points.size(); ++i) {
        csv.text("study,");
        scene_row(csv, s.points[i]);
        csv.print(",%d\n", on_front(r, i) ? 1 : 0);
    }
    csv.close();
    // gnuplot blocks: 0 dt, 1 integrators, 2 cell, 3 smoothing, 4 occlusion,
    // 5 grid, 6 front, 7 presets. Columns: ms/tick, ms per simulated s,
    // rel L1, steps per s, label.
    OutFile dat(dir + "/scene.dat");
    const auto block = [&](const char* name, const std::vector<std::size_t>& idx,
                           const std::vector<std::string_view>& labels) {
        dat.print("# %s: cpu_ms_per_tick cpu_ms_per_sim_s rel_l1 steps_per_s label\n", name);
        for (std::size_t n = 0; n < idx.size(); ++n) {
            const ScenePoint& p = s.points[idx[n]];
            dat.print("%.5f %.3f %.5f %.0f %s\n", p.cpu_ms_per_tick, p.cpu_ms_per_second(),
                      p.error.rel_l1, 1.0 / p.knobs.dt,
                      n < labels.size() ? std::string(labels[n]).c_str() : "-");
        }
        dat.text("\n\n");
    };
    block("dt", s.dt_sweep, {});
    block("integrator", s.integrator_sweep, {});
    block("cell", s.cell_sweep, {});
    block("smoothing", s.smoothing_sweep, {});
    block("occlusion", s.occlusion_sweep, {});
    block("grid", s.grid, {});
    block("front", r.front, {});
    std::vector<std::size_t> picks;
    std::vector<std::string_view> names;
    for (const PresetPick& p : r.presets) {
        picks.push_back(p.point);
        names.push_back(p.rule.name);
    }
    block("presets", picks, names);
    dat.close();
    OutFile gp(dir + "/floor.gp");
    gp.print("noise_floor = %.6f\nfloor_min = %.6f\nfloor_max = %.6f\n", s.floor_rel_l1(),
             s.floor_rel_l1_min(), s.floor_rel_l1_max());
    for (const PresetRule& rule : preset_rules) {
        gp.print("tol_%s = %.4f\n", std::string(rule.name).c_str(), rule.tolerance);
    }
    gp.close();
}

// ---------------------------------------------------------------- markdown

/// "| a | b |" header with right-aligned numeric columns after the first `text_cols`.
void table_head(OutFile& md, const std::vector<std::string>& cols, std::size_t text_cols) {
    md.text("|");
    for (const std::string& c : cols) {
        md.print(" %s |", c.c_str());
    }
    md.text("\n|");
    for (std::size_t i = 0; i < cols.size(); ++i) {
        md.text(i < text_cols ? "---|" : "---:|");
    }
    md.text("\n");
}

std::vector<std::string> dt_columns(const std::string& first, const std::vector<float>& dts) {
    std::vector<std::string> cols{first};
    for (const float dt : dts) {
        cols.push_back("dt " + dt_text(dt));
    }
    return cols;
}

void trajectory_tables(OutFile& md, const StudyResults& r) {
    const TrajectoryOptions& o = r.trajectory_options;
    md.print("### Trajectory error\n\n"
             "Largest position error (mm) over %u flakes and %.0f s against "
             "`integrate::exact_at`. The flakes start at rest (as spilled snow does) in a steady "
             "%.1f m/s wind, with terminal speeds in still air spread over %.1f–%.1f m/s "
             "(k/m = %.1f–%.1f 1/s, the village emitter's range). In brackets: share of "
             "flake-ticks the stiffness guard of `integrate.cpp` moved to the exact update.\n\n",
             o.flakes, static_cast<double>(o.seconds), static_cast<double>(o.wind.x),
             static_cast<double>(o.fall_min), static_cast<double>(o.fall_max), 9.81 / o.fall_max,
             9.81 / o.fall_min);
    table_head(md, dt_columns("integrator", o.dts), 1);
    for (const Integrator i : o.integrators) {
        md.print("| %s |", name_of(i).c_str());
        for (const TrajectoryRow& t : r.trajectory) {
            if (t.integrator != i) {
                continue;
            }
            md.print(" %.3g", mm(t.max_pos_error));
            if (t.stiff_share > 0.0) {
                md.print(" (%.0f%%)", 100.0 * t.stiff_share);
            }
            md.text(" |");
        }
        md.text("\n");
    }
    md.print("\n### Cost of the integrate pass\n\n"
             "CPU ns per flake-tick of `integrate_system` (SoA, one thread): %u flakes "
             "prefilled with `prefill_flakes` and the k/m spread above, fastest of %d repeats "
             "of %u ticks; last column: a pool of %u flakes (larger than the caches) at dt %s.\n\n",
             o.timing_flakes, o.timing_repeats, o.timing_ticks, r.large_pool_flakes,
             dt_text(r.large_pool_dt).c_str());
    std::vector<std::string> cols = dt_columns("integrator", o.dts);
    cols.push_back(std::to_string(r.large_pool_flakes) + " flakes");
    table_head(md, cols, 1);
    for (std::size_t n = 0; n < o.integrators.size(); ++n) {
        const Integrator i = o.integrators[n];
        md.print("| %s |", name_of(i).c_str());
        for (const TrajectoryRow& t : r.trajectory) {
            if (t.integrator == i) {
                md.print(" %.2f |", t.ns_per_flake_tick);
            }
        }
        md.print(" %.2f |\n", r.large_pool_ns[n]);
    }
    md.text("\n![trajectory error versus steps per second and versus cost, per integrator]"
            "(img/accuracy_integrators.png)\n\n");
}

const std::vector<std::string> scene_columns{
    "dt",           "integrator",    "cell ×",  "smoothing", "occlusion", "ms/tick",
    "ms per sim s", "rel L1",        "÷ floor", "L1 (mm)",   "L∞ (mm)",   "centroid (mm)",
    "rel L1 0.5 m", "paired rel L1", "settled", "iter/tick"};

void scene_line(OutFile& md, const ScenePoint& p, double floor) {
    const SceneKnobs& k = p.knobs;
    md.print("| %s | %s | %.2f | %u | %u | %.3f | %.1f | %.3f | %.2f | %.3f | %.3f | %.0f | "
             "%.3f | %.3f | %.1f%% | %.2f |\n",
             dt_text(k.dt).c_str(), name_of(k.integrator).c_str(),
             static_cast<double>(k.cell_scale), k.smoothing, k.occlusion, p.cpu_ms_per_tick,
             p.cpu_ms_per_second(), p.error.rel_l1, floor > 0.0 ? p.error.rel_l1 / floor : 0.0,
             mm(p.error.l1), mm(p.error.linf), mm(p.error.centroid_shift), p.fine_error.rel_l1,
             p.paired.rel_l1, 100.0 * p.settled_share, p.smoothing_per_tick);
}

void scene_table(OutFile& md, const SceneStudy& s, const char* title,
                 const std::vector<std::size_t>& idx) {
    md.print("#### %s\n\n", title);
    table_head(md, scene_columns, 2);
    for (const std::size_t i : idx) {
        scene_line(md, s.points[i], s.floor_rel_l1());
    }
    md.text("\n");
}

/// Error and cost range over one sweep; the spread in units of the noise floor.
void sensitivity_line(OutFile& md, const SceneStudy& s, const char* knob,
                      const std::vector<std::size_t>& idx) {
    if (idx.empty()) {
        return;
    }
    double lo = 1e30, hi = 0.0, plo = 1e30, phi = 0.0, cost_lo = 1e30, cost_hi = 0.0;
    for (const std::size_t i : idx) {
        const ScenePoint& p = s.points[i];
        lo = std::min(lo, p.error.rel_l1);
        hi = std::max(hi, p.error.rel_l1);
        plo = std::min(plo, p.paired.rel_l1);
        phi = std::max(phi, p.paired.rel_l1);
        cost_lo = std::min(cost_lo, p.cpu_ms_per_second());
        cost_hi = std::max(cost_hi, p.cpu_ms_per_second());
    }
    const double floor = s.floor_rel_l1();
    md.print("| %s | %.3f – %.3f | %.2f | %.3f – %.3f | %.1f – %.1f |\n", knob, lo, hi,
             floor > 0.0 ? (hi - lo) / floor : 0.0, plo, phi, cost_lo, cost_hi);
}

void mass_table(OutFile& md, const SceneStudy& s) {
    md.text("#### Where the snow went (dt sweep)\n\n"
            "Shares of the spawned snow mass at the end of the snowfall.\n\n");
    table_head(md,
               {"dt", "integrator", "settled", "airborne", "left the bounds", "hit a sphere",
                "hit bare geometry"},
               2);
    for (const ScenePoint& p : s.floor) {
        md.print("| %s (reference knobs) | %s | %.1f%% | %.1f%% | %.1f%% | %.1f%% | %.1f%% |\n",
                 dt_text(p.knobs.dt).c_str(), name_of(p.knobs.integrator).c_str(),
                 100.0 * p.settled_share, 100.0 * p.airborne_share, 100.0 * p.bounds_share,
                 100.0 * p.sphere_share, 100.0 * p.bare_share);
    }
    for (const std::size_t i : s.dt_sweep) {
        const ScenePoint& p = s.points[i];
        md.print("| %s | %s | %.1f%% | %.1f%% | %.1f%% | %.1f%% | %.1f%% |\n",
                 dt_text(p.knobs.dt).c_str(), name_of(p.knobs.integrator).c_str(),
                 100.0 * p.settled_share, 100.0 * p.airborne_share, 100.0 * p.bounds_share,
                 100.0 * p.sphere_share, 100.0 * p.bare_share);
    }
    md.text("\n");
}

std::string seed_list(const std::vector<std::uint64_t>& seeds) {
    std::string out;
    for (const std::uint64_t s : seeds) {
        out += (out.empty() ? "" : ", ") + std::to_string(s);
    }
    return out;
}

void scene_tables(OutFile& md, const StudyResults& r) {
    const SceneStudy& s = r.scene;
    const SceneStudyOptions& o = r.scene_options;
    md.print("### Setup of this run\n\n"
             "- Scene `%s`, %.0f s of snowfall per run (whole ticks), one thread.\n"
             "- Reference: mean depth field of %zu runs (seeds %s) with dt %s, %s, cells × "
             "%.2f (%.3f m), %u smoothing iterations, occlusion %u: %.3f CPU ms/tick, "
             "%.2f kg settled on average.\n"
             "- Studied settings: each run with seeds %s; errors are the means over the "
             "seeds, costs (ms/tick) the fastest seed's run.\n"
             "- Wind: %s.\n"
             "- Main error (rel L1, L1, L∞, centroid): blocks of %.2f m; also rel L1 over "
             "blocks of %.2f m; paired rel L1: blocks of the main size, against the run with "
             "the same dt and seed and the reference's other knobs.\n\n",
             o.scene.substr(o.scene.find_last_of('/') + 1).c_str(), static_cast<double>(o.seconds),
             o.reference_seeds.size(), seed_list(o.reference_seeds).c_str(),
             dt_text(o.reference.dt).c_str(), name_of(o.reference.integrator).c_str(),
             static_cast<double>(o.reference.cell_scale), s.base_cell * o.reference.cell_scale,
             o.reference.smoothing, o.reference.occlusion, s.reference_ms_per_tick,
             s.reference_settled_kg, seed_list(o.seeds).c_str(),
             o.steady_wind ? "steady at the scene's base wind (random walk off)"
                           : "the scene's own, random walk included",
             static_cast<double>(o.block), static_cast<double>(o.fine_block));
    md.print("### Noise floor\n\n"
             "Single runs with the reference's own knobs (seeds %s): all their error is "
             "sampling noise. rel L1 mean **%.3f** (%.3f – %.3f).\n\n",
             seed_list(o.floor_seeds).c_str(), s.floor_rel_l1(), s.floor_rel_l1_min(),
             s.floor_rel_l1_max());
    table_head(md, scene_columns, 2);
    double t_lo = 1e30, t_hi = 0.0;
    for (const ScenePoint& p : s.floor) {
        scene_line(md, p, s.floor_rel_l1());
        t_lo = std::min(t_lo, p.cpu_ms_per_tick);
        t_hi = std::max(t_hi, p.cpu_ms_per_tick);
    }
    md.print("\nTiming noise: these runs do the same work up to their random flakes and took "
             "%.3f – %.3f CPU ms/tick (%.0f%% apart).\n",
             t_lo, t_hi, t_lo > 0.0 ? 100.0 * (t_hi - t_lo) / t_lo : 0.0);
    const WindCheck& w = s.wind;
    md.print("\n### The wind's random walk\n\n"
             "The same floor measurement at the scene's own knobs (dt %s, %s, cells × %.2f, "
             "occlusion %u), once with a steady wind and once with the scene's random walk "
             "(keyed by seed and tick, so every seed and every dt blows differently):\n\n",
             dt_text(o.baseline.dt).c_str(), name_of(o.baseline.integrator).c_str(),
             static_cast<double>(o.baseline.cell_scale), o.baseline.occlusion);
    table_head(md, {"wind", "noise floor rel L1", "settled share over the runs"}, 1);
    md.print("| steady | %.3f | %.1f%% – %.1f%% |\n| random walk | %.3f | %.1f%% – %.1f%% |\n\n",
             w.rel_l1_steady, 100.0 * w.settled_min_steady, 100.0 * w.settled_max_steady,
             w.rel_l1_walk, 100.0 * w.settled_min_walk, 100.0 * w.settled_max_walk);
    md.text("\n### Which knobs matter\n\n"
            "Range of the errors over each one-knob sweep (other knobs at the scene's own "
            "settings). Spread ÷ floor well below 1 is lost in the sampling noise; paired "
            "rel L1 has no sampling noise but cannot see dt.\n\n");
    table_head(md, {"knob", "rel L1", "spread ÷ floor", "paired rel L1", "ms per sim s"}, 1);
    sensitivity_line(md, s, "dt", s.dt_sweep);
    sensitivity_line(md, s, "integrator", s.integrator_sweep);
    sensitivity_line(md, s, "cell size", s.cell_sweep);
    sensitivity_line(md, s, "smoothing iterations", s.smoothing_sweep);
    sensitivity_line(md, s, "occlusion resolution", s.occlusion_sweep);
    md.text("\n### Sweeps\n\n");
    scene_table(md, s, "dt (the scene's integrator)", s.dt_sweep);
    mass_table(md, s);
    scene_table(md, s, "Integrator at each dt", s.integrator_sweep);
    scene_table(md, s, "Surface cell size (× the scene's cells)", s.cell_sweep);
    scene_table(md, s, "Smoothing iterations per tick (cap)", s.smoothing_sweep);
    scene_table(md, s, "Occlusion map resolution", s.occlusion_sweep);
    md.text("### Pareto front\n\n"
            "Over all studied settings (sweeps and the dt × cell × occlusion grid): a setting "
            "is on the front when every cheaper one (CPU ms per simulated second) has a "
            "larger rel L1.\n\n");
    scene_table(md, s, "Front, cheapest first", r.front);
    md.text("![depth error versus CPU ms per simulated second](img/accuracy_scene.png)\n\n"
            "![depth error versus CPU ms per tick](img/accuracy_scene_tick.png)\n\n");
}

void preset_table(OutFile& md, const StudyResults& r) {
    const SceneStudy& s = r.scene;
    md.print("### Presets\n\n"
             "Noise floor (rel L1) %.3f. Allowed trajectory error: half the preset's finest "
             "surface cell. Costs within %.0f%% of the cheapest qualifying one count as equal "
             "(the more accurate wins).\n\n",
             s.floor_rel_l1(), 100.0 * (preset_cost_tie - 1.0));
    table_head(md,
               {"preset", "allowed rel L1", "allowed dt", "allowed cells", "dt", "cell ×",
                "smoothing", "occlusion", "ms/tick", "ms per sim s", "rel L1", "integrator",
                "allowed drift (mm)", "drift (mm)"},
               4);
    for (const PresetPick& p : r.presets) {
        const ScenePoint& pt = s.points[p.point];
        const SceneKnobs& k = pt.knobs;
        md.print("| %s | %.3f (%.2f× floor) | ≤ %s | %s | %s | %.2f | %u | %u | %.3f | %.1f | "
                 "%.3f | %s | %.0f | %.3g |\n",
                 std::string(p.rule.name).c_str(), p.max_error, p.rule.tolerance,
                 dt_text(p.rule.max_dt).c_str(),
                 p.rule.min_cell_scale > 0.0f ? "scene's or coarser" : "any", dt_text(k.dt).c_str(),
                 static_cast<double>(k.cell_scale), k.smoothing, k.occlusion, pt.cpu_ms_per_tick,
                 pt.cpu_ms_per_second(), pt.error.rel_l1, name_of(p.integrator).c_str(),
                 mm(p.max_drift), mm(p.drift));
    }
    md.text("\nIn game/play/quality.hpp (dt, integrator, cell_scale, occlusion_resolution):\n\n"
            "```cpp\n");
    for (const PresetPick& p : r.presets) {
        const SceneKnobs& k = s.points[p.point].knobs;
        md.print("{\"%s\", 1.0f / %.1ff, Integrator::%s, %.1ff, %u, ...},\n",
                 std::string(p.rule.name).c_str(), 1.0 / k.dt, integrator_enum(p.integrator),
                 static_cast<double>(k.cell_scale), k.occlusion);
    }
    md.text("```\n\n");
    for (std::size_t n = 0; n < r.presets.size(); ++n) {
        const PresetPick& p = r.presets[n];
        if (n > 0 && r.presets[n - 1].front == p.front) {
            continue; // same candidates as the preset before
        }
        std::string title = "Front of the candidates for " + std::string(p.rule.name);
        for (std::size_t m = n + 1; m < r.presets.size() && r.presets[m].front == p.front; ++m) {
            title += ", " + std::string(r.presets[m].rule.name);
        }
        scene_table(md, s, title.c_str(), p.front);
    }
}

void write_wind_field(const std::string& dir, const StudyResults& r) {
    const WindFieldStudy& w = r.wind;
    OutFile csv(dir + "/wind_field.csv");
    csv.text("role,cells_x,cells_y,cells_z,update_every,sample_every,cpu_ms_per_tick,"
             "field_ms_per_tick,wind_rel_l1,lee_speed,free_speed,lee_units\n");
    const auto row = [&](const char* role, const WindFieldPoint& p) {
        csv.print("%s,%u,%u,%u,%u,%u,%.5f,%.5f,%.5f,%.4f,%.4f,%llu\n", role, p.knobs.cells(0),
                  p.knobs.cells(1), p.knobs.cells(2), p.knobs.update_every, p.knobs.sample_every,
                  p.cpu_ms_per_tick, p.field_ms_per_tick, p.wind_rel_l1, p.lee_speed, p.free_speed,
                  static_cast<unsigned long long>(p.lee_units));
    };
    row("reference", w.reference);
    for (const WindFieldPoint& p : w.points) {
        row("study", p);
    }
    csv.close();
    // gnuplot blocks: 0 cells, 1 update_every. Columns: field ms per
    // simulated s, wind rel L1, label.
    OutFile dat(dir + "/wind_field.dat");
    const auto block = [&](const char* name, const std::vector<std::size_t>& idx, bool cells) {
        dat.print("# %s: field_ms_per_sim_s wind_rel_l1 label\n", name);
        for (const std::size_t i : idx) {
            const WindFieldPoint& p = w.points[i];
            if (cells) {
                dat.print("%.4f %.5f %ux%ux%u\n", p.field_ms_per_second(w.dt), p.wind_rel_l1,
                          p.knobs.cells(0), p.knobs.cells(1), p.knobs.cells(2));
            } else {
                dat.print("%.4f %.5f every_%u\n", p.field_ms_per_second(w.dt), p.wind_rel_l1,
                          p.knobs.update_every);
            }
        }
        dat.text("\n\n");
    };
    block("cells", w.cell_sweep, true);
    block("update_every", w.update_sweep, false);
    dat.close();
}

void wind_field_line(OutFile& md, const WindFieldPoint& p, float dt) {
    md.print("| %u × %u × %u | %u | %llu | %.3f | %.2f | %.3f | %.3f | %.2f | %.2f |\n",
             p.knobs.cells(0), p.knobs.cells(1), p.knobs.cells(2), p.knobs.update_every,
             static_cast<unsigned long long>(p.knobs.total_cells()), p.field_ms_per_tick,
             p.field_ms_per_second(dt), p.cpu_ms_per_tick, p.wind_rel_l1,
             p.free_speed > 0.0 ? p.lee_speed / p.free_speed : 0.0, p.lee_units_ratio);
}

/// The flakes' sample interval: it changes what flakes feel, not the field,
/// so its error is in the snow they leave, against sampling every tick.
void sample_table(OutFile& md, const WindFieldStudy& w) {
    md.text("#### Sample interval (cells and update_every at the baseline)\n\n"
            "Each flake samples the field every `sample_every` ticks, half a hold ahead of "
            "itself at its velocity, and holds the sample in between. Errors are against the "
            "first row (the same field, sampled every tick). The snowfall is chaotic: even "
            "sample_every 2 moves every flake's path a little, and the second row's error is "
            "that alone; what grows beyond it with the interval is the hold's.\n\n");
    table_head(md,
               {"sample_every", "tick CPU ms", "settled depth rel L1 (1 m blocks)",
                "centroid shift (m)", "lee snow ÷ every tick"},
               1);
    for (const std::size_t i : w.sample_sweep) {
        const WindFieldPoint& p = w.points[i];
        md.print("| %u | %.3f | %.4f | %.4f | %.3f |\n", p.knobs.sample_every, p.cpu_ms_per_tick,
                 p.depth_vs_first.rel_l1, p.depth_vs_first.centroid_shift, p.lee_units_vs_first);
    }
    md.text("\n");
}

void wind_field_tables(OutFile& md, const StudyResults& r) {
    const WindFieldStudy& w = r.wind;
    const WindFieldStudyOptions& o = r.wind_options;
    const WindFieldPoint& ref = w.reference;
    md.print("### Setup of this run\n\n- Scene `%s` with a field declared on load, seed %llu, "
             "%.0f s per run (the scene's snowfall and wind, walk included: the same seed "
             "blows the same gusts in every run), one thread; time means over the %.0f s after "
             "a %.0f s warm-up, sampled every 4 ticks.\n",
             std::filesystem::path(o.scene).filename().c_str(),
             static_cast<unsigned long long>(o.seed), static_cast<double>(o.seconds),
             static_cast<double>(o.seconds - o.warmup), static_cast<double>(o.warmup));
    md.print("- Reference: %u × %u × %u cells, update_every %u, sample_every %u: field %.3f "
             "ms/tick, tick %.3f CPU ms; lee / free stream %.2f, %llu units in the lee strip.\n"
             "- The baseline the sweeps vary one knob of: the defaults (update_every %u, "
             "sample_every %u).\n\n",
             ref.knobs.cells(0), ref.knobs.cells(1), ref.knobs.cells(2), ref.knobs.update_every,
             ref.knobs.sample_every, ref.field_ms_per_tick, ref.cpu_ms_per_tick,
             ref.free_speed > 0.0 ? ref.lee_speed / ref.free_speed : 0.0,
             static_cast<unsigned long long>(ref.lee_units), o.baseline.update_every,
             o.baseline.sample_every);
    const std::vector<std::string> cols{"cells",         "update_every",       "total",
                                        "field ms/tick", "field ms per sim s", "tick CPU ms",
                                        "wind rel L1",   "lee / free",         "lee snow ÷ ref"};
    md.text("#### Resolution (update_every at the baseline)\n\n");
    table_head(md, cols, 1);
    for (const std::size_t i : w.cell_sweep) {
        wind_field_line(md, w.points[i], w.dt);
    }
    md.text("\n#### Update interval (cells at the baseline)\n\n");
    table_head(md, cols, 1);
    for (const std::size_t i : w.update_sweep) {
        wind_field_line(md, w.points[i], w.dt);
    }
    md.text("\n![wind error versus field cost](img/accuracy_wind_field.png)\n\n");
    sample_table(md, w);
}

void write_markdown(const std::string& dir, const StudyResults& r) {
    OutFile md(dir + "/report.md");
    md.text("## Results\n\n");
    preset_table(md, r);
    md.text("## Integrators\n\n");
    trajectory_tables(md, r);
    md.text("## Scene level\n\n");
    scene_tables(md, r);
    md.text("## Wind field\n\n");
    wind_field_tables(md, r);
    md.print("The study took %.0f s of wall time.\n", r.seconds_total);
    md.close();
}

} // namespace

void write_results(const std::string& dir, const StudyResults& r) {
    write_trajectory(dir, r);
    write_scene(dir, r);
    write_wind_field(dir, r);
    write_markdown(dir, r);
}

} // namespace snow::accuracy
