// The wind field's grid: its lattices, a still field of a def, the packed
// cell-centre velocities readers sample, its settings' rules and its
// snapshot record. The solver that steps it: wind_field_solver.cpp.
#include "systems/wind/wind_field.hpp"

#include "systems/core/state_bytes.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

namespace snow {

Lattice Lattice::make(const std::uint32_t (&n)[3], int face_axis) {
    Lattice l;
    for (int a = 0; a < 3; ++a) {
        const auto cells = static_cast<std::int32_t>(n[a]);
        const bool on_faces = a == face_axis;
        l.dim[a] = on_faces ? cells + 1 : cells + 2;
        l.shift[a] = on_faces ? 0.0f : 0.5f;
        l.last[a] = on_faces ? cells - 1 : cells;
    }
    return l;
}

WindField make_wind_field(const WindFieldDef& def, const Aabb& bounds) {
    WindField f;
    f.def = def;
    f.n[0] = def.cells_x;
    f.n[1] = def.cells_y;
    f.n[2] = def.cells_z;
    f.origin = bounds.min;
    const glm::vec3 size = bounds.size();
    for (int a = 0; a < 3; ++a) {
        f.inv_cell[a] = static_cast<float>(f.n[a]) / size[a];
        f.face[a] = Lattice::make(f.n, a);
        f.velocity[a].assign(f.face[a].size(), 0.0f);
    }
    f.centre = Lattice::make(f.n, 3);
    f.pressure.assign(f.centre.size(), 0.0f);
    for (auto& c : f.at_centre) {
        c.assign(f.centre.size(), 0.0f);
    }
    f.packed_centre.assign(f.centre.size(), pack_wind(0.0f, 0.0f, 0.0f));
    return f;
}

void pack_centre(WindField& f) {
    const float* u = f.at_centre[0].data();
    const float* v = f.at_centre[1].data();
    const float* w = f.at_centre[2].data();
    std::uint64_t* out = f.packed_centre.data();
    for (std::size_t i = 0; i < f.packed_centre.size(); ++i) {
        out[i] = pack_wind(u[i], v[i], w[i]);
    }
}

namespace {

template <typename Io, typename Def>
void def_record(Io& io, Def& d) {
    for (auto* v : {&d.cells_x, &d.cells_y, &d.cells_z, &d.update_every, &d.sample_every,
                    &d.pressure_iterations}) {
        io(*v);
    }
    io(d.eddy_viscosity);
}

template <typename Io, typename Field>
void field_state_record(Io& io, Field& f, bool& transport) {
    for (auto& v : f.velocity) {
        io(v);
    }
    io(f.pressure);
    io(f.inflow);
    io(f.wait);
    io(f.steps);
    for (auto& v : f.at_centre) {
        io(v);
    }
    io(transport);
}

template <typename Io, typename Transport>
void transport_record(Io& io, Transport& t) {
    for (auto* v : {&t.roughness, &t.height, &t.fast_forward, &t.adjustment_length}) {
        io(*v);
    }
}

} // namespace

void save_state(ByteWriter& out, const WindField& f) {
    def_record(out, f.def);
    out(f.def.tunnel);
    bool transport = f.transport.has_value();
    field_state_record(out, f, transport);
    if (transport) {
        transport_record(out, *f.transport);
    }
}

void load_def(ByteReader& in, WindFieldDef& def) {
    def_record(in, def);
    in(def.tunnel);
}

void load_state(ByteReader& in, WindField& f) {
    bool transport = false;
    field_state_record(in, f, transport);
    bool ok = std::isfinite(f.inflow.x) && std::isfinite(f.inflow.y) && std::isfinite(f.inflow.z) &&
              f.pressure.size() == f.centre.size() && all_finite(f.pressure);
    for (int a = 0; a < 3; ++a) {
        ok = ok && f.velocity[a].size() == f.face[a].size() && all_finite(f.velocity[a]) &&
             f.at_centre[a].size() == f.centre.size() && all_finite(f.at_centre[a]);
    }
    in.require(ok, "has velocities of another grid or non-finite ones");
    f.transport.reset();
    if (transport) {
        transport_record(in, f.transport.emplace());
    }
    pack_centre(f);
}

Invalid validate(const WindFieldDef& d) {
    Invalid e = check_fields("wind.field", wind_field_fields, d);
    const std::uint64_t cells = std::uint64_t{d.cells_x} * d.cells_y * d.cells_z;
    check::number(e, "wind.field.cells (total)", up_to(max_wind_field_cells),
                  static_cast<double>(cells));
    return e;
}

void hash_state(StateHasher& h, const WindField& f) {
    ByteWriter out(h);
    def_record(out, f.def);
    if (f.def.tunnel) { // a field with open sides hashes as before tunnels
        out(f.def.tunnel);
    }
    out(f.origin);
    out(f.inv_cell);
    for (const auto& v : f.velocity) {
        out(v);
    }
    out(f.pressure);
    out(f.inflow);
    out(f.wait);
    out(f.steps);
    if (f.transport) {
        transport_record(out, *f.transport);
    }
}

} // namespace snow
