// Byte snapshots (Simulation::save_bytes / load_bytes): the Snapshot of
// save_snapshot() as versioned bytes for save games, replays and lockstep. Layout
// (docs/embedding.md "Snapshots"): magic, format version, payload length,
// a tag of the constants that shape the state, the scene's fingerprint, the
// payload (one record per stateful type, each written beside its type,
// gathered in the order below) and an FNV-1a checksum of all that precedes it.
#include "systems/api/simulation_internals.hpp"
#include "systems/api/snapshot_layout.hpp"

#include "systems/api/state_records.hpp"

#include "ecs/state_hash.hpp"
#include "systems/api/validation.hpp"
#include "systems/core/limits.hpp"
#include "systems/core/state_bytes.hpp"
#include "systems/flakes/held_wind.hpp"

#include <array>
#include <string>

namespace snow {

namespace {

/// The compile-time constants whose values the saved state depends on.
std::uint64_t build_tag() {
    StateHasher h;
    h.value(max_flake_units);
    h.value(dirty_tile_shift);
    h.value(held_wind_steps_per_mps);
    h.value(FlakePool::parked_y);
    return h.digest();
}

/// Reads what write_each wrote: each entity must hold a T in `world` (which
/// gives the item its scene settings before `load` reads its state).
template <typename T, typename Load>
void load_each(ByteReader& in, const World& world, const char* what,
               Vector<std::pair<Entity, T>>& items, const Load& load) {
    in.record(what);
    std::uint64_t n = 0;
    in(n);
    in.require(n == world.count<T>(), "has another number of them than the scene");
    for (std::uint64_t k = 0; k < n; ++k) {
        in.record(what, k);
        Entity e;
        in(e.bits);
        const T* now = world.alive(e) ? world.try_get<T>(e) : nullptr;
        in.require(now != nullptr, "belongs to an entity the scene does not have");
        items.emplace_back(e, *now);
        load(e, items.back().second);
    }
}

/// Settings read from the bytes must be ones the facade would have accepted.
void require_valid(const ByteReader& in, const Invalid& bad) {
    if (!bad.empty()) {
        in.fail("holds an invalid setting: " + bad.text());
    }
}

} // namespace

std::uint64_t snapshot_checksum(std::span<const std::byte> framed) {
    StateHasher h;
    h.bytes(framed.data(), framed.size());
    return h.digest();
}

// Written straight from the world, in save_snapshot()'s order and extent (no copy
// of the state first).
std::vector<std::byte> Simulation::save_bytes() const {
    const World& world = impl_->world;
    ByteWriter out;
    for (const char c : snapshot_magic) {
        out(c);
    }
    out(snapshot_format);
    out(std::uint64_t{0}); // payload length, filled in below
    const std::size_t payload_at = out.bytes().size();
    out(build_tag());
    out(impl_->scene_fingerprint());
    out(tick_count());
    ledger_record(out, world.resource<MassLedger>(), counters());
    save_state(out, world.resource<FlakePool>());
    write_optional(out, world.try_resource<Wind>());
    write_optional(out, world.try_resource<WindField>());
    const auto* map = world.try_resource<OcclusionMap>();
    write_optional(
        out, map != nullptr && map->built ? map : nullptr); // as save_snapshot(): only a built map
    write_each<SnowSurface>(out, world);
    write_each<SnowCover>(out, world);
    write_each<Body>(out, world);
    std::vector<std::byte>& bytes = out.bytes(); // the host's: allocated as it allocates
    const std::uint64_t payload = bytes.size() - payload_at;
    std::memcpy(bytes.data() + payload_at - sizeof payload, &payload, sizeof payload);
    out(snapshot_checksum(bytes));
    return std::move(bytes);
}

void Simulation::load_bytes(std::span<const std::byte> bytes) {
    const World& world = impl_->world;
    ByteReader head(bytes);
    if (bytes.size() < snapshot_header_bytes + snapshot_checksum_bytes) {
        head.fail("is cut short (" + std::to_string(bytes.size()) +
                  " bytes; a snapshot has at least " +
                  std::to_string(snapshot_header_bytes + snapshot_checksum_bytes) + ")");
    }
    std::array<char, 8> magic{};
    for (char& c : magic) {
        head(c);
    }
    head.require(magic == snapshot_magic,
                 "is not a snow snapshot (its first bytes are not SNOWSNAP)");
    std::uint32_t format = 0;
    head(format);
    if (format != snapshot_format) {
        head.fail("has format version " + std::to_string(format) + "; this build reads version " +
                  std::to_string(snapshot_format));
    }
    std::uint64_t payload = 0;
    head(payload);
    const std::uint64_t present = bytes.size() - snapshot_header_bytes - snapshot_checksum_bytes;
    if (payload != present) {
        head.fail(std::string(payload > present ? "is cut short" : "has bytes past its end") +
                  " (its header says " + std::to_string(payload) + " payload bytes, " +
                  std::to_string(present) + " are there)");
    }
    std::uint64_t sum = 0;
    std::memcpy(&sum, bytes.data() + bytes.size() - snapshot_checksum_bytes,
                snapshot_checksum_bytes);
    head.require(sum == snapshot_checksum(bytes.first(bytes.size() - snapshot_checksum_bytes)),
                 "is corrupted (its checksum does not match its bytes)");

    ByteReader in(bytes.subspan(snapshot_header_bytes, payload));
    std::uint64_t tag = 0, scene = 0;
    in(tag);
    in.require(tag == build_tag(), "was written by a build with other simulation constants");
    in(scene);
    in.require(scene == impl_->scene_fingerprint(),
               "belongs to a different scene or settings (its fingerprint differs)");
    Snapshot s;
    in.record("clock");
    in(s.clock.tick);
    in.record("ledger");
    ledger_record(in, s.ledger, s.counters);
    in.record("flakes");
    s.flakes.reset(world.resource<FlakePool>().capacity());
    load_state(in, s.flakes);
    in.record("wind");
    bool wind = false;
    in(wind);
    if (wind) {
        load_state(in, s.wind.emplace());
        require_valid(in, validate(*s.wind));
    }
    in.record("wind_field");
    bool field = false;
    in(field);
    if (field) {
        WindFieldDef def;
        load_def(in, def);
        require_valid(in, validate(def));
        // A float per cell at least follows: a grid the bytes cannot hold is
        // corrupt, and is refused before it is allocated (a fuzz finding:
        // 22 KB that declared a field of millions of cells).
        in.require(std::uint64_t{def.cells_x} * def.cells_y * def.cells_z <=
                       in.left() / sizeof(float),
                   "declares a wind field larger than its bytes");
        s.wind_field = make_wind_field(def, config().bounds);
        load_state(in, *s.wind_field);
        if (s.wind_field->transport) {
            require_valid(in, validate(*s.wind_field->transport));
        }
    }
    in.record("sky_map");
    bool map = false;
    in(map);
    if (map) {
        load_state(in, s.sky_map.emplace());
    }
    load_each(in, world, "surfaces", s.surfaces,
              [&](Entity, SnowSurface& surface) { load_state(in, surface); });
    load_each(in, world, "covers", s.covers, [&](Entity e, SnowCover& cover) {
        load_state(in, cover, world.get<SnowSurface>(e).cell_count());
    });
    load_each(in, world, "bodies", s.bodies, [&](Entity, Body& body) { load_state(in, body); });
    in.record("");
    in.require(in.left() == 0, "has bytes after its last record");

    // Every unit accounted for, as at the end of every tick.
    std::uint64_t held = s.flakes.airborne_units() + s.ledger.removed();
    for (const auto& [e, surface] : s.surfaces) {
        held += surface.settled_units();
    }
    for (const auto& [e, body] : s.bodies) {
        held += body.carried;
    }
    in.require(held == s.ledger.spawned, "does not account for every unit of snow it spawned");
    restore_snapshot(*this, s);
}

} // namespace snow
