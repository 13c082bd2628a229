#include "game/app/cli_args.hpp"

#include "systems/core/sim_config.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <optional>
#include <string>

namespace snow::cli {

std::uint64_t parse_uint(std::string_view flag, std::string_view text, std::uint64_t min,
                         std::uint64_t max) {
    std::uint64_t v = 0;
    const auto* end = text.data() + text.size();
    const auto [ptr, ec] = std::from_chars(text.data(), end, v);
    if (text.empty() || ec != std::errc{} || ptr != end) {
        throw UsageError{std::string(flag) + ": expected a whole number, got '" +
                         std::string(text) + "'"};
    }
    if (v < min || v > max) {
        throw UsageError{std::string(flag) + ": must be in [" + std::to_string(min) + ", " +
                         std::to_string(max) + "], got " + std::string(text)};
    }
    return v;
}

namespace {

/// `text` read whole as a number (any finite or infinite value); nullopt if it is not one.
std::optional<double> whole_number(const std::string& text) {
    std::size_t used = 0;
    double v = 0.0;
    try {
        v = std::stod(text, &used);
    } catch (const std::exception&) {
        return std::nullopt;
    }
    return used == text.size() ? std::optional<double>(v) : std::nullopt;
}

} // namespace

double parse_positive(std::string_view flag, std::string_view text, double max) {
    const std::string s(text);
    const std::optional<double> parsed = whole_number(s);
    const double v = parsed.value_or(0.0);
    if (!parsed) {
        throw UsageError{std::string(flag) + ": expected a number, got '" + s + "'"};
    }
    if (!std::isfinite(v) || v <= 0.0 || v > max) {
        throw UsageError{std::string(flag) + ": must be > 0 and <= " + std::to_string(max) +
                         ", got " + s};
    }
    return v;
}

glm::vec3 parse_vec3(std::string_view flag, std::string_view text, double max_abs) {
    glm::vec3 v{0.0f};
    std::string_view rest = text;
    for (int a = 0; a < 3; ++a) {
        const std::size_t comma = a < 2 ? rest.find(',') : std::string_view::npos;
        if (a < 2 && comma == std::string_view::npos) {
            throw UsageError{std::string(flag) + ": expected X,Y,Z, got '" + std::string(text) +
                             "'"};
        }
        const std::optional<double> x = whole_number(std::string(rest.substr(0, comma)));
        if (!x || !std::isfinite(*x) || std::abs(*x) > max_abs) {
            throw UsageError{std::string(flag) + ": expected X,Y,Z of numbers within +-" +
                             std::to_string(max_abs) + ", got '" + std::string(text) + "'"};
        }
        v[a] = static_cast<float>(*x);
        rest = comma == std::string_view::npos ? std::string_view{} : rest.substr(comma + 1);
    }
    return v;
}

bool ArgReader::next() {
    if (++i_ >= argc_) {
        return false;
    }
    flag_ = argv_[i_];
    return true;
}

std::string_view ArgReader::value() {
    if (i_ + 1 >= argc_) {
        throw UsageError{std::string(flag_) + ": missing value"};
    }
    return argv_[++i_];
}

void ArgReader::unknown() const {
    throw UsageError{"unknown argument '" + std::string(flag_) + "' (see --help)"};
}

bool read_override(ArgReader& args, SceneOverrides& o) {
    const std::string_view f = args.flag();
    if (f == "--seed") {
        o.seed = parse_uint(f, args.value(), 0, ~0ull);
    } else if (f == "--threads") {
        o.threads = static_cast<unsigned>(parse_uint(f, args.value(), 1, 256));
    } else if (f == "--dt") {
        o.dt = static_cast<float>(parse_positive(f, args.value(), 1.0));
    } else if (f == "--max-flakes") {
        o.max_flakes = static_cast<std::uint32_t>(parse_uint(f, args.value(), 1, 16u << 20));
        // Asking for a pool on the command line is the caller's word for it.
        o.budget.flakes = std::max(o.budget.flakes, std::uint64_t{*o.max_flakes});
    } else if (f == "--integrator") {
        const std::string_view name = args.value();
        const auto i = parse_integrator(name);
        if (!i) {
            throw UsageError{"--integrator: unknown '" + std::string(name) + "' (" +
                             integrator_choices() + ")"};
        }
        o.integrator = *i;
    } else if (f == "--wind") {
        o.wind = parse_vec3(f, args.value(), 100.0);
    } else if (f == "--auto-snow") {
        o.auto_snow = true;
    } else {
        return false;
    }
    return true;
}

void print_usage(const Usage& usage) {
    std::fputs(usage.head, stdout);
    std::fputs(override_usage, stdout);
    std::fputs(usage.tail, stdout);
}

bool read_shared(ArgReader& args, const SceneArgs& into) {
    const std::string_view f = args.flag();
    if (read_override(args, into.overrides)) {
        return true;
    }
    if (f == "--help" || f == "-h") {
        into.help = true;
        return true;
    }
    if (f == "--scene") {
        into.scene = std::string(args.value());
        return true;
    }
    return false;
}

} // namespace snow::cli
