// snow_state_hash SCENE TICKS THREADS [INTEGRATOR]: prints the state hash
// after TICKS ticks on THREADS threads as 16 hex digits (as snow_run's
// report). SCENE is built in code (tests/scenes): busy_yard and field_yard
// are the scenes Determinism.PinnedHashHoldsInEveryBuild and
// WindField.PinnedHashHoldsInEveryBuild pin; stormy_yard has gusts, a wind
// field, wind transport, bodies, a cover and a tilted sky camera. INTEGRATOR
// (euler, semi_implicit, exponential, rk4, auto) replaces the scene's.
// scripts/check_aarch64.sh compares its x86-64 and aarch64 hashes.
// Exit status: 0 ok, 2 bad arguments, 1 any other failure (an error,
// unbalanced mass, a non-finite value).
#include "systems/core/sim_config.hpp"
#include "tests/scenes/sample_scenes.hpp"
#include "tests/support/share_work.hpp"

#include <charconv>
#include <cstdio>
#include <cstring>
#include <exception>
#include <memory>
#include <optional>
#include <string_view>

namespace {

template <typename T>
std::optional<T> parse_number(const char* text) {
    T value{};
    const char* end = text + std::strlen(text);
    const auto [last, error] = std::from_chars(text, end, value);
    if (error != std::errc{} || last != end) {
        return std::nullopt;
    }
    return value;
}

/// The scene `name` on `threads` threads; null for an unknown name.
std::unique_ptr<snow::Simulation> make_scene(std::string_view name, unsigned threads) {
    if (name == "busy_yard") {
        return snow::make_yard(snow::busy_yard(threads));
    }
    if (name == "field_yard") {
        snow::YardOptions o;
        o.threads = threads;
        auto sim = snow::make_yard(o);
        sim->set_wind_field(snow::WindFieldDef{});
        return sim;
    }
    if (name == "stormy_yard") {
        return snow::make_stormy_yard(threads);
    }
    return nullptr;
}

} // namespace

int main(int argc, char** argv) {
    const auto ticks = argc >= 4 ? parse_number<std::uint64_t>(argv[2]) : std::nullopt;
    const auto threads = argc >= 4 ? parse_number<unsigned>(argv[3]) : std::nullopt;
    const auto integrator =
        argc == 5 ? snow::parse_integrator(argv[4]) : std::optional<snow::Integrator>{};
    try {
        const auto sim = ticks && threads && *threads > 0 ? make_scene(argv[1], *threads) : nullptr;
        if (argc < 4 || argc > 5 || !sim || (argc == 5 && !integrator)) {
            std::fprintf(stderr,
                         "usage: snow_state_hash SCENE TICKS THREADS [INTEGRATOR]\n"
                         "  SCENE: busy_yard, field_yard or stormy_yard; THREADS >= 1\n"
                         "  INTEGRATOR: %s\n",
                         snow::integrator_choices().c_str());
            return 2;
        }
        if (integrator) {
            sim->set_integrator(*integrator);
        }
        // Small scenes too hand their passes to the pool, so 2 threads share the work.
        snow::test::share_work_at_any_size(*sim);
        sim->run(*ticks);
        std::printf("%016llx\n", static_cast<unsigned long long>(sim->state_hash()));
        return sim->mass().balanced() && sim->nonfinite_count() == 0 ? 0 : 1;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "snow_state_hash: %s\n", e.what());
        return 1;
    }
}
