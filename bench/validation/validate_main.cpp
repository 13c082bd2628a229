// snow_validate: runs every probe of the validation table (issue #30) and
// writes it as Markdown; scripts/validate.sh puts it into docs/validation.md.
#include "bench/validation/validation.hpp"
#include "ecs/staged_files.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <exception>
#include <iostream>
#include <span>
#include <sstream>
#include <string>
#include <string_view>

namespace {

using namespace snow::validation;

constexpr const char* usage = R"(usage: snow_validate [--quick] [--out FILE]
  --out FILE   write the Markdown table there (default: standard output)
  --quick      seconds-long smoke run; its numbers are not for the table
  --help       this text
Exit status: 0 ok (whatever the rows say), 2 bad arguments or an --out FILE that
cannot be written, 1 failure.
)";

std::string value_text(double v) {
    if (std::isnan(v)) {
        return "none";
    }
    char text[32];
    std::snprintf(text, sizeof text, std::fabs(v) >= 10.0 ? "%.1f" : "%.3g", v);
    return text;
}

std::string with_unit(const std::string& v, const std::string& unit) {
    return unit.empty() ? v : v + " " + unit;
}

} // namespace

int main(int argc, char** argv) {
    Plan plan;
    std::string out;
    for (int i = 1; i < argc; ++i) {
        const std::string_view a = argv[i];
        if (a == "--quick") {
            plan.quick = true;
        } else if (a == "--out" && i + 1 < argc) {
            out = argv[++i];
        } else if (a == "--help") {
            std::fputs(usage, stdout);
            return 0;
        } else {
            std::fprintf(stderr, "snow_validate: unknown or incomplete argument '%s'\n%s", argv[i],
                         usage);
            return 2;
        }
    }
    const Probe probes[] = {
        {"fall speed and mass by size", flakes_by_size},
        {"fresh snow density", fresh_density_by_temperature},
        {"settled snow density", settled_density},
        {"pile flank angle", pile_flank_angle},
        {"roof load by pitch", roof_load_by_pitch},
        {"wind over the ground", ground_wind},
        {"saltation flux", saltation_flux},
        {"drifts at a porous fence", fence_drift_shape},
    };
    try {
        if (!out.empty()) {
            snow::check_file_writable(out); // before the probes, not after them
        }
        std::ostringstream table;
        table << "| quantity | published | scene | ours | band | in band |\n"
              << "|---|---|---|---|---|---|\n";
        int rows = 0, passed = 0;
        for (const Probe& probe : probes) {
            std::fprintf(stderr, "snow_validate: %s ...", probe.name);
            const auto t0 = std::chrono::steady_clock::now();
            for (const Row& r : probe.run(plan)) {
                table << "| " << r.quantity << " | " << r.published << " | " << r.scene << " | "
                      << with_unit(value_text(r.ours), r.unit) << " | "
                      << with_unit(value_text(r.low) + " – " + value_text(r.high), r.unit) << " | "
                      << (r.pass() ? "yes" : "**no**") << " |\n";
                ++rows;
                passed += r.pass() ? 1 : 0;
            }
            std::fprintf(
                stderr, " %.1f s\n",
                std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
        }
        table << "\n" << passed << " of " << rows << " rows in band.\n";
        if (out.empty()) {
            std::cout << table.str();
        } else {
            const std::string text = table.str();
            snow::write_file(out, std::as_bytes(std::span(text)));
        }
        std::fprintf(stderr, "snow_validate: %d of %d rows in band\n", passed, rows);
    } catch (const snow::FileWriteError& e) {
        std::fprintf(stderr, "snow_validate: --out: %s\n", e.what());
        return 2;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "\nsnow_validate: %s\n", e.what());
        return 1;
    }
    return 0;
}
