// The snow side of the Irrlicht host, behind a header with neither snow's
// nor Irrlicht's types. Irrlicht 1.8's headers are not C++20 (irrXML.h
// declares its constructors as xmlChar<T>(), which C++20 forbids and GCC
// 11-13 reject) and snow's package needs C++20, so the engine's sources
// compile as C++17 and see snow only through this; snow_feed.cpp is C++20.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

struct Vec3 {
    float x = 0.0f, y = 0.0f, z = 0.0f;
};

/// The scene's start camera and sky.
struct View {
    Vec3 position, target;
    float fov_y_deg = 50.0f, near_plane = 0.05f, far_plane = 200.0f;
    Vec3 sky;
};

/// One cell of the ground.
struct GroundPoint {
    float x = 0.0f, z = 0.0f; ///< the cell's centre (m)
    float height = 0.0f;      ///< its bare base + its snow depth (m)
    float depth = 0.0f;       ///< its snow depth (m)
    bool solid = false;       ///< geometry under it (a cover's void cells have none)
};

/// A snow scene as the host sees it: loaded from glTF, stepped by engine
/// time, read as flakes and as the ground's heights.
class SnowFeed {
  public:
    /// Loads a glTF scene with snow's default settings (as snow_run does);
    /// null with `error` set when the file, or its ground, is missing.
    static std::unique_ptr<SnowFeed> load(const std::string& path, std::string& error);
    ~SnowFeed();
    SnowFeed(const SnowFeed&) = delete;
    SnowFeed& operator=(const SnowFeed&) = delete;

    /// Adds engine time and runs the whole ticks it makes up (snow::FixedStep
    /// carries the rest to the next call); returns how many ran.
    std::uint32_t advance(std::uint32_t elapsed_ms);

    [[nodiscard]] std::string name() const;
    [[nodiscard]] View view() const;
    /// The box flakes live in (leaving it removes them).
    [[nodiscard]] Vec3 bounds_min() const;
    [[nodiscard]] Vec3 bounds_max() const;
    /// Positions of the airborne flakes.
    void flakes(std::vector<Vec3>& out) const;

    /// The ground's cells along x and z.
    [[nodiscard]] std::uint32_t ground_nx() const;
    [[nodiscard]] std::uint32_t ground_nz() const;
    /// Every cell of the ground, row by row (x fastest), from the surface as it is now.
    void ground(std::vector<GroundPoint>& out) const;
    /// Changes whenever which cells are solid may have changed (a cover's
    /// base following its geometry).
    [[nodiscard]] std::uint64_t ground_base_version() const;
    /// Deepest snow on the whole ground (m).
    [[nodiscard]] float deepest_snow() const;

    [[nodiscard]] std::uint64_t ticks() const;
    [[nodiscard]] std::uint64_t state_hash() const;

  private:
    struct State;
    explicit SnowFeed(std::unique_ptr<State> state);
    std::unique_ptr<State> state_;
};
