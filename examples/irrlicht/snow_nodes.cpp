#include "snow_nodes.hpp"

#include <algorithm>

namespace {

/// Irrlicht's software driver (EDT_SOFTWARE) silently drops the triangles
/// of one draw call past 65 534 indices: the ground's bands and the flakes'
/// batches stay within it (and so within 16-bit indices).
constexpr std::uint32_t max_triangles = 65534 / 3;
/// Quads per draw call of the flakes.
constexpr std::uint32_t quads_per_batch = max_triangles / 2;
/// Flakes are millimetres wide; quads this wide (m) cover a pixel or two at
/// the distance of a scene's camera, so each flake shows.
constexpr float flake_quad_m = 0.05f;
/// Snow this deep (m) draws fully white, bare ground grey-brown: seconds of
/// snowfall lay millimetres, which the mesh's heights alone would not show.
constexpr float full_white_m = 0.005f;

irr::video::SColor snow_color(float depth) {
    const irr::video::SColor white(255, 250, 252, 255), bare(255, 95, 88, 78);
    return white.getInterpolated(bare, std::min(depth / full_white_m, 1.0f));
}

} // namespace

SnowGround::SnowGround(const SnowFeed& feed)
    : feed_(feed), nx_(feed.ground_nx()), base_version_(feed.ground_base_version()),
      mesh_(new irr::scene::SMesh) {
    feed_.ground(points_);
    const std::uint32_t nz = feed.ground_nz();
    // Rows of quads per band; a surface has at most 4096 cells a side, so
    // a band holds two rows at least.
    const std::uint32_t quad_rows = max_triangles / (2 * std::max(nx_ - 1, 1u));
    for (std::uint32_t first = 0; first < std::max(nz - 1, 1u); first += quad_rows) {
        const Band band{new irr::scene::SMeshBuffer, first, std::min(quad_rows + 1, nz - first)};
        band.buffer->Vertices.reallocate(band.rows * nx_);
        for (std::size_t i = std::size_t{first} * nx_; i < std::size_t{first + band.rows} * nx_;
             ++i) {
            band.buffer->Vertices.push_back(irr::video::S3DVertex(
                to_irr({points_[i].x, 0.0f, points_[i].z}), irr::core::vector3df(0.0f, 1.0f, 0.0f),
                irr::video::SColor(255, 255, 255, 255), irr::core::vector2df(0.0f, 0.0f)));
        }
        band.buffer->Material.Lighting = false;
        band.buffer->Material.BackfaceCulling = false; // the z flip turned the winding round
        mesh_->addMeshBuffer(band.buffer);
        bands_.push_back(band);
    }
    rebuild_triangles();
    write_points();
}

SnowGround::~SnowGround() {
    for (const Band& band : bands_) {
        band.buffer->drop();
    }
    mesh_->drop();
}

std::size_t SnowGround::vertex_count() const {
    std::size_t n = 0;
    for (const Band& band : bands_) {
        n += band.buffer->getVertexCount();
    }
    return n;
}

void SnowGround::update() {
    feed_.ground(points_);
    if (feed_.ground_base_version() != base_version_) {
        base_version_ = feed_.ground_base_version();
        rebuild_triangles();
    }
    write_points();
}

std::size_t SnowGround::mismatches() const {
    std::vector<GroundPoint> now;
    feed_.ground(now);
    std::size_t bad = 0;
    for (const Band& band : bands_) {
        const std::size_t first = std::size_t{band.first_row} * nx_;
        for (irr::u32 v = 0; v < band.buffer->getVertexCount(); ++v) {
            bad += band.buffer->Vertices[v].Pos.Y != now[first + v].height;
        }
    }
    return bad;
}

void SnowGround::rebuild_triangles() {
    for (const Band& band : bands_) {
        const GroundPoint* p = &points_[std::size_t{band.first_row} * nx_];
        band.buffer->Indices.set_used(0);
        for (std::uint32_t r = 0; r + 1 < band.rows; ++r) {
            for (std::uint32_t c = 0; c + 1 < nx_; ++c) {
                const auto a = static_cast<irr::u16>(r * nx_ + c);
                const auto b = static_cast<irr::u16>(a + 1);
                const auto d = static_cast<irr::u16>(a + nx_);
                const auto e = static_cast<irr::u16>(d + 1);
                if (p[a].solid && p[b].solid && p[d].solid && p[e].solid) {
                    for (const irr::u16 i : {a, d, b, b, d, e}) {
                        band.buffer->Indices.push_back(i);
                    }
                }
            }
        }
        band.buffer->setDirty(irr::scene::EBT_INDEX);
    }
}

void SnowGround::write_points() {
    bool any = false;
    irr::core::aabbox3df mesh_box;
    for (const Band& band : bands_) {
        const std::size_t first = std::size_t{band.first_row} * nx_;
        bool first_solid = true;
        irr::core::aabbox3df box;
        for (irr::u32 v = 0; v < band.buffer->getVertexCount(); ++v) {
            const GroundPoint& p = points_[first + v];
            irr::video::S3DVertex& vertex = band.buffer->Vertices[v];
            vertex.Pos.Y = p.height;
            vertex.Color = snow_color(p.depth);
            if (!p.solid) {
                continue; // far below and in no triangle: kept out of the box
            }
            if (first_solid) {
                box.reset(vertex.Pos);
                first_solid = false;
            } else {
                box.addInternalPoint(vertex.Pos);
            }
        }
        band.buffer->BoundingBox = box;
        band.buffer->setDirty(irr::scene::EBT_VERTEX);
        if (!first_solid) {
            if (any) {
                mesh_box.addInternalBox(box);
            } else {
                mesh_box = box;
                any = true;
            }
        }
    }
    mesh_->BoundingBox = mesh_box;
}

SnowAnimator::SnowAnimator(SnowFeed& feed, SnowGround& ground, irr::u32 start_ms)
    : feed_(feed), ground_(ground), last_ms_(start_ms) {}

void SnowAnimator::animateNode(irr::scene::ISceneNode*, irr::u32 time_ms) {
    const std::uint32_t ticks = feed_.advance(time_ms - last_ms_);
    last_ms_ = time_ms;
    if (ticks > 0) {
        ground_.update();
    }
}

irr::scene::ISceneNodeAnimator* SnowAnimator::createClone(irr::scene::ISceneNode*,
                                                          irr::scene::ISceneManager*) {
    return nullptr;
}

FlakeNode::FlakeNode(const SnowFeed& feed, irr::scene::ISceneNode* parent,
                     irr::scene::ISceneManager* manager)
    : ISceneNode(parent, manager), feed_(feed) {
    box_.reset(to_irr(feed.bounds_min()));
    box_.addInternalPoint(to_irr(feed.bounds_max()));
    material_.Lighting = false;
    material_.BackfaceCulling = false;
    for (std::uint32_t q = 0; q < quads_per_batch; ++q) {
        for (const std::uint32_t corner : {0u, 1u, 2u, 0u, 2u, 3u}) {
            indices_.push_back(static_cast<irr::u16>(q * 4 + corner));
        }
    }
}

void FlakeNode::OnRegisterSceneNode() {
    if (IsVisible) {
        SceneManager->registerNodeForRendering(this);
    }
    ISceneNode::OnRegisterSceneNode();
}

void FlakeNode::render() {
    const irr::scene::ICameraSceneNode* camera = SceneManager->getActiveCamera();
    if (camera == nullptr) {
        return;
    }
    // The view matrix's first two columns are the camera's right and up axes.
    const irr::core::matrix4& view = camera->getViewMatrix();
    const float half = flake_quad_m / 2.0f;
    const irr::core::vector3df right = irr::core::vector3df(view[0], view[4], view[8]) * half;
    const irr::core::vector3df up = irr::core::vector3df(view[1], view[5], view[9]) * half;
    const irr::core::vector3df normal(0.0f, 1.0f, 0.0f);
    const irr::video::SColor white(255, 255, 255, 255);
    feed_.flakes(flakes_);
    vertices_.clear();
    for (const Vec3& flake : flakes_) {
        const irr::core::vector3df p = to_irr(flake);
        for (const irr::core::vector3df& corner :
             {p - right - up, p - right + up, p + right + up, p + right - up}) {
            vertices_.emplace_back(corner, normal, white, irr::core::vector2df(0.0f, 0.0f));
        }
    }
    irr::video::IVideoDriver* driver = SceneManager->getVideoDriver();
    driver->setTransform(irr::video::ETS_WORLD, irr::core::IdentityMatrix);
    driver->setMaterial(material_);
    for (std::size_t first = 0; first < flakes_.size(); first += quads_per_batch) {
        const auto n =
            static_cast<irr::u32>(std::min<std::size_t>(flakes_.size() - first, quads_per_batch));
        driver->drawIndexedTriangleList(&vertices_[first * 4], n * 4, indices_.data(), n * 2);
    }
    drawn_ = flakes_.size();
}
