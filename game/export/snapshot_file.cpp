#include "game/export/snapshot_file.hpp"

#include <cerrno>
#include <cstring>
#include <fstream>
#include <iterator>
#include <vector>

namespace snow {

void save_snapshot_file(const Simulation& sim, const std::filesystem::path& file) {
    write_file(file, sim.save_bytes());
}

void load_snapshot_file(Simulation& sim, const std::filesystem::path& file) {
    std::string name =
        "snapshot file '"; // (built in steps: GCC 12's -Wrestrict misfires on "'" + s)
    name += file.string();
    name += '\'';
    std::error_code ec;
    if (std::filesystem::is_directory(file, ec)) {
        throw Error(name, "is a folder, not a snapshot");
    }
    std::ifstream in(file, std::ios::binary);
    if (!in) {
        throw Error(name, std::string("cannot be read: ") + std::strerror(errno));
    }
    const std::vector<char> text{std::istreambuf_iterator<char>(in), {}};
    if (in.bad()) {
        throw Error(name, "cannot be read to its end");
    }
    try {
        sim.load_bytes(std::as_bytes(std::span<const char>(text)));
    } catch (const SimulationError& e) {
        throw Error(name, e.what());
    }
}

} // namespace snow
