// Fuzz-style robustness of the scene loader (OSS-Fuzz habit, deterministic):
// hundreds of fixed-seed mutations of the village scene, as .gltf (byte
// flips, truncations, swapped values, deleted characters) and as .glb (lying
// header and chunk fields, flipped bytes, truncations), must each give either
// a working simulation or one clean error, never a crash. CI runs this under
// ASan + UBSan (SNOW_SANITIZE), which turns any out-of-range read into a failure.
#include "tests/game/scene/scene_test_files.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cctype>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace snow {
namespace {

/// splitmix64: a fixed, portable sequence (the test must mutate the same way everywhere).
struct Mutator {
    std::uint64_t state;
    std::uint64_t next() {
        std::uint64_t z = (state += 0x9E3779B97F4A7C15ull);
        z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
        z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
        return z ^ (z >> 31);
    }
    std::size_t below(std::size_t n) { return static_cast<std::size_t>(next() % n); }
};

std::string village_text() {
    std::ifstream in(std::string(SNOW_SOURCE_DIR) + "/assets/scenes/village.gltf",
                     std::ios::binary);
    std::ostringstream os;
    os << in.rdbuf();
    return os.str();
}

/// Start and length of every JSON number in the text outside the base64 buffer.
std::vector<std::pair<std::size_t, std::size_t>> number_tokens(const std::string& t) {
    std::vector<std::pair<std::size_t, std::size_t>> out;
    bool in_string = false;
    for (std::size_t i = 0; i < t.size(); ++i) {
        if (t[i] == '"') {
            in_string = !in_string;
        } else if (!in_string && (std::isdigit(static_cast<unsigned char>(t[i])) || t[i] == '-')) {
            std::size_t j = i;
            while (j < t.size() && (std::isdigit(static_cast<unsigned char>(t[j])) || t[j] == '-' ||
                                    t[j] == '+' || t[j] == '.' || t[j] == 'e' || t[j] == 'E')) {
                ++j;
            }
            out.emplace_back(i, j - i);
            i = j - 1;
        }
    }
    return out;
}

/// Loads one mutated file; returns true if it loaded. A loaded scene must tick.
bool load_one(const std::string& bytes, std::size_t case_id,
              const std::string& name = "fuzz.gltf") {
    const SceneLoadResult r = load_scene_memory(bytes, name);
    EXPECT_NE(r.sim == nullptr, r.error.empty()) << "case " << case_id << ": " << r.error;
    if (r.sim == nullptr) {
        EXPECT_EQ(r.error.rfind(name + ": ", 0), 0u) << "case " << case_id << ": " << r.error;
        return false;
    }
    r.sim->run(2);
    EXPECT_TRUE(r.sim->mass().balanced()) << "case " << case_id;
    return true;
}

TEST(SceneFuzz, VillageMutationsLoadOrFailCleanly) {
    const std::string base = village_text();
    ASSERT_GT(base.size(), 1000u);
    ASSERT_TRUE(load_one(base, 0));
    // The JSON part (before the base64 payload) is where structure lives.
    const std::size_t json_end = base.find("base64,");
    ASSERT_NE(json_end, std::string::npos);
    const auto numbers = number_tokens(base.substr(0, json_end));
    ASSERT_GT(numbers.size(), 100u);
    static const std::array<const char*, 18> nasty{
        "0",          "-1",         "1e9",         "1e38",  "-1e38", "1e-30",
        "4294967296", "2147483648", "-2147483649", "65535", "0.5",   "\"x\"",
        "null",       "[]",         "{}",          "true",  "1e400", "[1,2,3]"};

    Mutator rng{2024};
    std::size_t loaded = 0, rejected = 0, cases = 0;
    const auto run = [&](const std::string& text) {
        (load_one(text, ++cases) ? loaded : rejected) += 1;
    };
    for (int i = 0; i < 200; ++i) { // single bit flips, mostly in the JSON
        std::string t = base;
        const std::size_t at = rng.below(i % 4 == 0 ? t.size() : json_end);
        t[at] = static_cast<char>(t[at] ^ (1 << rng.below(8)));
        run(t);
    }
    for (int i = 0; i < 60; ++i) { // truncations
        run(base.substr(0, rng.below(base.size())));
    }
    for (int i = 0; i < 200; ++i) { // one number replaced by a hostile value
        const auto [pos, len] = numbers[rng.below(numbers.size())];
        std::string t = base;
        t.replace(pos, len, nasty[rng.below(nasty.size())]);
        run(t);
    }
    for (int i = 0; i < 60; ++i) { // two numbers swapped
        const auto [p1, l1] = numbers[rng.below(numbers.size())];
        const auto [p2, l2] = numbers[rng.below(numbers.size())];
        if (p1 == p2) {
            continue;
        }
        std::string t = base;
        const std::string a = base.substr(p1, l1), b = base.substr(p2, l2);
        // Replace the later one first so the earlier position stays valid.
        if (p1 < p2) {
            t.replace(p2, l2, a);
            t.replace(p1, l1, b);
        } else {
            t.replace(p1, l1, b);
            t.replace(p2, l2, a);
        }
        run(t);
    }
    for (int i = 0; i < 60; ++i) { // a structural character deleted
        std::string t = base;
        std::size_t at = rng.below(json_end);
        while (at < json_end && std::string("{}[],:\"").find(t[at]) == std::string::npos) {
            ++at;
        }
        t.erase(at, 1);
        run(t);
    }
    // Both outcomes occur: the mutations reach deep validation, not only the parser.
    EXPECT_GT(rejected, 100u);
    EXPECT_GT(loaded, 20u);
    std::printf("[ scene fuzz ] %zu cases: %zu loaded, %zu rejected cleanly\n", cases, loaded,
                rejected);
}

TEST(SceneFuzz, GlbMutationsLoadOrFailCleanly) {
    const std::string base = test::gltf_to_glb(village_text());
    ASSERT_TRUE(load_one(base, 0, "fuzz.glb"));
    const auto u32_at = [&](std::size_t at) {
        std::uint32_t v = 0;
        std::memcpy(&v, base.data() + at, sizeof v);
        return v;
    };
    const std::size_t json_length = u32_at(12);
    const std::size_t bin_header = 20 + json_length;
    // The u32 fields of the container: header length, then each chunk's length and type.
    const std::array<std::size_t, 5> fields{8, 12, 16, bin_header, bin_header + 4};
    const auto size = static_cast<std::uint32_t>(base.size());
    const std::array<std::uint32_t, 12> nasty{0,
                                              1,
                                              4,
                                              size - 1,
                                              size,
                                              size + 1,
                                              0x7FFFFFFFu,
                                              0xFFFFFFFFu,
                                              static_cast<std::uint32_t>(json_length - 4),
                                              static_cast<std::uint32_t>(json_length + 4),
                                              0x4E4F534Au,
                                              0x004E4942u};

    Mutator rng{2025};
    std::size_t loaded = 0, rejected = 0, cases = 0;
    const auto run = [&](const std::string& bytes) {
        (load_one(bytes, ++cases, "fuzz.glb") ? loaded : rejected) += 1;
    };
    for (int i = 0; i < 120; ++i) { // one container field replaced by a hostile value
        std::string t = base;
        const std::uint32_t v = nasty[rng.below(nasty.size())];
        std::memcpy(t.data() + fields[rng.below(fields.size())], &v, sizeof v);
        run(t);
    }
    for (int i = 0; i < 80; ++i) { // a random byte of the 28 container bytes
        std::string t = base;
        const std::size_t k = rng.below(28);
        const std::size_t at = k < 20 ? k : bin_header + (k - 20);
        t[at] = static_cast<char>(rng.below(256));
        run(t);
    }
    for (int i = 0; i < 60; ++i) { // truncations
        run(base.substr(0, rng.below(base.size())));
    }
    for (int i = 0; i < 120; ++i) { // single bit flips anywhere, half of them in the BIN chunk
        std::string t = base;
        const std::size_t at = i % 2 == 0 ? bin_header + 8 + rng.below(base.size() - bin_header - 8)
                                          : rng.below(base.size());
        t[at] = static_cast<char>(t[at] ^ (1 << rng.below(8)));
        run(t);
    }
    EXPECT_GT(rejected, 200u);
    EXPECT_GT(loaded, 20u);
    std::printf("[ scene fuzz ] %zu .glb cases: %zu loaded, %zu rejected cleanly\n", cases, loaded,
                rejected);
}

} // namespace
} // namespace snow
