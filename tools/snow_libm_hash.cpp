// snow_libm_hash: for each libm function the simulation calls that is not
// exact or correctly rounded by IEEE 754 (docs/toolchain.md "libm"), a hash
// of its results over the inputs the simulation gives it (in the precision
// the simulation keeps), one line each:
// NAME CALLS HASH. scripts/check_aarch64.sh compares the x86-64 and aarch64
// lines; any difference is a result that differs between the two.
// Exit status: 0 ok, 2 any argument.
#include "systems/flakes/snowfall.hpp"
#include "systems/wind/saltation.hpp"

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <numbers>

namespace {

/// FNV-1a over the results' bits, and how many there were.
struct Digest {
    std::uint64_t hash = 0xcbf29ce484222325ull;
    std::uint64_t calls = 0;

    template <typename T>
    void add(T result) {
        unsigned char bytes[sizeof(T)];
        std::memcpy(bytes, &result, sizeof(T));
        for (const unsigned char b : bytes) {
            hash = (hash ^ b) * 0x100000001b3ull;
        }
        ++calls;
    }
};

void print(const char* name, const Digest& d) {
    std::printf("%-7s %10llu %016llx\n", name, static_cast<unsigned long long>(d.calls),
                static_cast<unsigned long long>(d.hash));
}

float float_from_bits(std::uint32_t bits) {
    float x = 0.0f;
    std::memcpy(&x, &bits, sizeof(x));
    return x;
}

std::uint32_t bits_of(float x) {
    std::uint32_t bits = 0;
    std::memcpy(&bits, &x, sizeof(bits));
    return bits;
}

/// add(digest, x) for every `stride`-th float x in [lo, hi] (0 <= lo <= hi),
/// both ends included.
template <typename F>
Digest every_float(float lo, float hi, std::uint32_t stride, F add) {
    Digest d;
    const std::uint32_t last = bits_of(hi);
    for (std::uint32_t b = bits_of(lo); b < last; b += stride) {
        add(d, float_from_bits(b));
    }
    add(d, hi);
    return d;
}

/// splitmix64: the same sequence on every machine.
struct Draws {
    std::uint64_t state = 0;

    /// Uniform in [lo, hi), to 53 bits.
    double uniform(double lo, double hi) {
        std::uint64_t z = (state += 0x9e3779b97f4a7c15ull);
        z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
        z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
        z ^= z >> 31;
        return lo + (hi - lo) * (static_cast<double>(z >> 11) * 0x1.0p-53);
    }
    float uniform_float(float lo, float hi) { return static_cast<float>(uniform(lo, hi)); }
};

constexpr std::uint32_t pairs = 1u << 22;

} // namespace

int main(int argc, char**) {
    if (argc != 1) {
        std::fprintf(stderr, "usage: snow_libm_hash (no arguments)\n");
        return 2;
    }
    // spawn (systems/flakes/snowfall.cpp): a parcel's size from its draw u
    // (exp, log1p: the clipped exponential spectrum), then its fall speed and
    // mass (pow), through the simulation's own functions: every 2^-20 of u for
    // the default spectrum and each crystal type, then random spectra.
    {
        Digest d;
        const auto add_parcel = [&d](const snow::Emitter& e, float u) {
            const float size = snow::size_at(e, u);
            d.add(size);
            d.add(snow::fall_speed(e.crystal, size));
            d.add(snow::flake_mass_mg(e.crystal, size));
        };
        Draws r{1};
        for (const snow::CrystalType crystal :
             {snow::CrystalType::dendrite_aggregate, snow::CrystalType::rimed_aggregate}) {
            snow::Emitter e;
            e.crystal = crystal;
            for (std::uint32_t k = 0; k < (1u << 20); ++k) {
                add_parcel(e, static_cast<float>(k) * (1.0f / 1048576.0f));
            }
            for (std::uint32_t i = 0; i < pairs / 8; ++i) {
                e.size_min = r.uniform_float(1.0e-4f, 0.01f);
                e.size_max = e.size_min + r.uniform_float(0.0f, 0.05f);
                e.size_mean = r.uniform_float(1.0e-4f, 0.02f);
                add_parcel(e, r.uniform_float(0.0f, 1.0f));
            }
        }
        print("spawn", d);
    }
    // settle (systems/snowpack/settle_system.cpp): Anderson's rates, e^x of
    // temperature and density terms, and a cell's shrink, expm1(−rate·dt).
    {
        Digest d;
        Draws r{6};
        for (std::uint32_t i = 0; i < pairs; ++i) {
            d.add(std::exp(r.uniform(-60.0, 60.0)));
            d.add(std::expm1(-r.uniform(0.0, 1.0)));
        }
        print("settle", d);
    }
    // wind_transport (systems/wind/saltation.hpp): the log law's ln(z/z0) of
    // a read height and a roughness, and the threshold of a cell's density
    // (e^x, fresh snow up to max_packing times the densest).
    {
        Digest law, threshold;
        Draws r{7};
        for (std::uint32_t i = 0; i < pairs; ++i) {
            const float z = r.uniform_float(1.0e-3f, 100.0f); // drawn in this order
            const float z0 = r.uniform_float(1.0e-6f, 1.0e-3f);
            law.add(snow::friction_per_wind(z, z0));
            threshold.add(snow::threshold_friction_velocity(r.uniform(40.0, 480.0)));
        }
        print("log_law", law);
        print("threshold", threshold);
    }
    // integrate (exponential rule): e^(−c·dt), c·dt >= 0, down to 0.
    print("expf", every_float(0.0f, 104.0f, 61, [](Digest& d, float x) { d.add(std::exp(-x)); }));
    // wind_system: a gust's sin(π·phase), phase in [0, 1]; the scene loader's
    // sky camera: sin(fov/2).
    print("sinf",
          every_float(0.0f, 3.14159265f, 31, [](Digest& d, float x) { d.add(std::sin(x)); }));
    // carve_system: the distance a body moved in a tick.
    {
        Digest d;
        Draws r{2};
        for (std::uint32_t i = 0; i < pairs; ++i) {
            const float dx = r.uniform_float(-20.0f, 20.0f); // drawn in this order
            const float dz = r.uniform_float(-20.0f, 20.0f);
            d.add(std::hypot(dx, dz));
        }
        print("hypotf", d);
    }
    // occlusion: the wind's direction (float components, in double).
    {
        Digest d;
        Draws r{3};
        for (std::uint32_t i = 0; i < pairs; ++i) {
            const double wz = r.uniform_float(-50.0f, 50.0f), wx = r.uniform_float(-50.0f, 50.0f);
            d.add(std::atan2(wz, wx));
        }
        print("atan2", d);
    }
    // occlusion: the sky camera's shear, tan(tilt)·(cos, sin)(wind angle), of
    // float angles in double (GCC makes the pair one sincos call, as there);
    // snow_surface: tan(repose°·π/180).
    print("sincos", every_float(0.0f, 6.2831855f, 127, [](Digest& d, float a) {
              const double x = a;
              d.add(std::cos(x));
              d.add(std::sin(x));
          }));
    {
        Digest d = every_float(0.0f, 1.5707963f, 127, [](Digest& dt, float t) {
            dt.add(std::tan(static_cast<double>(t)));
        });
        for (float deg = 0.5f; deg < 90.0f; deg += 0.5f) {
            d.add(std::tan(deg * std::numbers::pi / 180.0));
        }
        print("tan", d);
    }
    // body: a snowball's radius from its volume, rounded to float as the
    // simulation keeps it (the double results differ between glibc's x86-64
    // and aarch64 builds in the last bit for about one input in five).
    {
        Digest d;
        Draws r{4};
        for (std::uint32_t i = 0; i < pairs; ++i) {
            d.add(static_cast<float>(std::cbrt(r.uniform(0.0, 1000.0))));
        }
        print("cbrtf", d);
    }
    return 0;
}
