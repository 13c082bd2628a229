// The engine's side of the host (C++17, see snow_feed.hpp): an animator
// that steps the snow from the engine's clock, a mesh buffer whose heights
// follow the ground's snow, and a scene node that draws the airborne flakes.
#pragma once

#include "snow_feed.hpp"

#include <irrlicht/irrlicht.h>

#include <cstddef>
#include <cstdint>
#include <vector>

/// snow (like glTF) is right-handed, Irrlicht left-handed: z flips on the
/// way in, so the engine's picture is not a mirror image of snow's.
inline irr::core::vector3df to_irr(const Vec3& p) {
    return {p.x, p.y, -p.z};
}

/// The ground's snow as a grid mesh: one vertex per cell, at its bare base
/// plus its snow depth, coloured by depth. Bands of rows, a mesh buffer each:
/// Irrlicht's software driver draws at most 21 844 triangles of one buffer.
class SnowGround {
  public:
    explicit SnowGround(const SnowFeed& feed);
    ~SnowGround();
    SnowGround(const SnowGround&) = delete;
    SnowGround& operator=(const SnowGround&) = delete;

    [[nodiscard]] irr::scene::IMesh* mesh() const { return mesh_; }
    [[nodiscard]] std::size_t vertex_count() const;
    [[nodiscard]] std::size_t band_count() const { return bands_.size(); }

    /// Follows the snow after ticks: new heights and colours, and new
    /// triangles when the base changed (a cover following its geometry).
    void update();
    /// Vertices whose height is not base + depth of their cell, as the feed
    /// computes them afresh.
    [[nodiscard]] std::size_t mismatches() const;

  private:
    struct Band {
        irr::scene::SMeshBuffer* buffer;
        std::uint32_t first_row, rows; ///< rows of cells; a band's last is the next one's first
    };
    /// Triangles between the solid cells.
    void rebuild_triangles();
    /// Heights, colours and bounding boxes from points_.
    void write_points();

    const SnowFeed& feed_;
    std::uint32_t nx_;
    std::vector<GroundPoint> points_;
    std::uint64_t base_version_;
    irr::scene::SMesh* mesh_;
    std::vector<Band> bands_;
};

/// Steps the snow by whole ticks as the engine's clock advances, then
/// updates the ground's mesh.
class SnowAnimator : public irr::scene::ISceneNodeAnimator {
  public:
    SnowAnimator(SnowFeed& feed, SnowGround& ground, irr::u32 start_ms);
    void animateNode(irr::scene::ISceneNode* node, irr::u32 time_ms) override;
    /// None: a clone would step the same snow a second time per frame.
    irr::scene::ISceneNodeAnimator* createClone(irr::scene::ISceneNode* node,
                                                irr::scene::ISceneManager* manager) override;

  private:
    SnowFeed& feed_;
    SnowGround& ground_;
    irr::u32 last_ms_;
};

/// The airborne flakes as camera-facing quads, read from the snow at draw
/// time (rendering reads the state, never writes it).
class FlakeNode : public irr::scene::ISceneNode {
  public:
    FlakeNode(const SnowFeed& feed, irr::scene::ISceneNode* parent,
              irr::scene::ISceneManager* manager);

    void OnRegisterSceneNode() override;
    void render() override;
    [[nodiscard]] const irr::core::aabbox3df& getBoundingBox() const override { return box_; }
    [[nodiscard]] irr::u32 getMaterialCount() const override { return 1; }
    [[nodiscard]] irr::video::SMaterial& getMaterial(irr::u32) override { return material_; }

    /// Flakes the last render() drew.
    [[nodiscard]] std::size_t drawn() const { return drawn_; }

  private:
    const SnowFeed& feed_;
    irr::core::aabbox3df box_;
    irr::video::SMaterial material_;
    std::vector<Vec3> flakes_;
    std::vector<irr::video::S3DVertex> vertices_;
    std::vector<irr::u16> indices_; ///< the quads of one batch
    std::size_t drawn_ = 0;
};
