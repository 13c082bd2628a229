#include "game/play/session_report.hpp"
#include "systems/api/simulation_internals.hpp"

#include "game/play/snow_readout.hpp"

#include <algorithm>
#include <cmath>
#include <cstdarg>
#include <cstdio>

namespace snow {

namespace {

/// printf into a string (the lines are the ones snow_game always printed).
[[gnu::format(printf, 1, 2)]] std::string text_of(const char* fmt, ...) {
    va_list args;
    va_start(args, fmt);
    va_list again;
    va_copy(again, args);
    const int n = std::vsnprintf(nullptr, 0, fmt, args);
    va_end(args);
    std::string text(static_cast<std::size_t>(std::max(n, 0)), '\0');
    std::vsnprintf(text.data(), text.size() + 1, fmt, again);
    va_end(again);
    return text;
}

double simulated_seconds(const GameSession& session) {
    const Simulation& sim = session.sim();
    return static_cast<double>(sim.tick_count() - session.start_tick()) *
           static_cast<double>(sim.config().dt);
}

} // namespace

std::string clock_text(double seconds) {
    const auto s = static_cast<long long>(std::lround(seconds));
    return text_of("%lld:%02lld", s / 60, s % 60);
}

std::string moment_label(const GameSession& session) {
    std::string label = "t " + clock_text(simulated_seconds(session));
    if (const SnowSurface* g = ground_surface(world_of(session.sim()))) {
        label += text_of("  %.1f cm", 100.0 * mean_depth(*g));
    }
    return label;
}

std::string progress_line(const GameSession& session, std::uint64_t frame, std::uint64_t frames,
                          double render_ms) {
    const Simulation& sim = session.sim();
    return text_of(
        "snow_game: frame %llu/%llu, tick %llu (%s simulated, %s), %u flakes, "
        "settled %llu units, %.1f ms/frame render\n",
        static_cast<unsigned long long>(frame + 1), static_cast<unsigned long long>(frames),
        static_cast<unsigned long long>(sim.tick_count()),
        clock_text(simulated_seconds(session)).c_str(), moment_label(session).c_str(),
        flake_pool(sim).alive, static_cast<unsigned long long>(sim.mass().settled), render_ms);
}

std::string session_report(const GameSession& session, std::uint64_t frames) {
    const Simulation& sim = session.sim();
    const MassReport m = sim.mass();
    std::string report = text_of(
        "snow_game: done after %llu frames, tick %llu; mass units spawned %llu = airborne "
        "%llu + settled %llu + carried %llu + removed %llu\n",
        static_cast<unsigned long long>(frames), static_cast<unsigned long long>(sim.tick_count()),
        static_cast<unsigned long long>(m.spawned), static_cast<unsigned long long>(m.airborne),
        static_cast<unsigned long long>(m.settled), static_cast<unsigned long long>(m.carried),
        static_cast<unsigned long long>(m.removed));
    const Walker* walker = session.walker();
    if (walker && walker->alive(sim)) {
        const TrailReport t = walker->trail(sim);
        report +=
            text_of("snow_game: player walked %.2f m from (%.2f, %.2f) to (%.2f, %.2f); snow on "
                    "its trail %.2f mm, 1 m beside it %.2f mm (%zu samples)\n",
                    static_cast<double>(t.walked), static_cast<double>(t.from.x),
                    static_cast<double>(t.from.y), static_cast<double>(t.to.x),
                    static_cast<double>(t.to.y), 1000.0 * t.on_trail, 1000.0 * t.beside, t.samples);
    }
    return report;
}

} // namespace snow
