#include "game/cli_args.hpp"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
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

double parse_positive(std::string_view flag, std::string_view text, double max) {
    const std::string s(text);
    std::size_t used = 0;
    double v = 0.0;
    try {
        v = std::stod(s, &used);
    } catch (const std::exception&) {
        used = 0;
    }
    if (s.empty() || used != s.size()) {
        throw UsageError{std::string(flag) + ": expected a number, got '" + s + "'"};
    }
    if (!std::isfinite(v) || v <= 0.0 || v > max) {
        throw UsageError{std::string(flag) + ": must be > 0 and <= " + std::to_string(max) +
                         ", got " + s};
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
    } else if (f == "--integrator") {
        const std::string_view name = args.value();
        const auto i = parse_integrator(name);
        if (!i) {
            throw UsageError{"--integrator: unknown '" + std::string(name) + "' (" +
                             integrator_choices() + ")"};
        }
        o.integrator = *i;
    } else if (f == "--auto-snow") {
        o.auto_snow = true;
    } else {
        return false;
    }
    return true;
}

bool read_shared(ArgReader& args, const Usage& usage, const SceneArgs& into) {
    const std::string_view f = args.flag();
    if (read_override(args, into.overrides)) {
        return true;
    }
    if (f == "--help" || f == "-h") {
        std::fputs(usage.head, stdout);
        std::fputs(override_usage, stdout);
        std::fputs(usage.tail, stdout);
        std::exit(0);
    }
    if (f == "--scene") {
        into.scene = std::string(args.value());
        return true;
    }
    return false;
}

} // namespace snow::cli
