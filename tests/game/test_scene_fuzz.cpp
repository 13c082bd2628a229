// Fuzz-style robustness of the scene loader (OSS-Fuzz habit, deterministic):
// hundreds of fixed-seed mutations of the village scene (byte flips,
// truncations, swapped values, deleted characters) must each give either a
// working simulation or one clean error, never a crash. CI runs this under
// ASan + UBSan (SNOW_SANITIZE), which turns any out-of-range read into a failure.
#include "game/scene/scene_loader.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cctype>
#include <cstdint>
#include <cstdio>
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

/// Loads one mutated text; returns true if it loaded. A loaded scene must tick.
bool load_one(const std::string& text, std::size_t case_id) {
    const SceneLoadResult r = load_scene_memory(text, "fuzz.gltf");
    EXPECT_NE(r.sim == nullptr, r.error.empty()) << "case " << case_id << ": " << r.error;
    if (r.sim == nullptr) {
        EXPECT_EQ(r.error.rfind("fuzz.gltf: ", 0), 0u) << "case " << case_id << ": " << r.error;
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

} // namespace
} // namespace snow
