// snow inside the Irrlicht engine: a glTF scene loaded with snow::scene, an
// animator that ticks the Simulation from the engine's (stopped, hand-set)
// clock, the ground's snow as a mesh buffer and the flakes as billboards.
// Prints the ticks run and the state hash (snow_run's for as many ticks)
// and checks the mesh heights against the snow depth. C++17: see snow_feed.hpp.
//   irrlicht_snow [--scene FILE] [--frames N] [--frame-ms MS] [--driver null|software|burnings]
//                 [--screenshot FILE.png] [--expect-hash HEX]
#include "snow_nodes.hpp"

#include <algorithm>
#include <charconv>
#include <cinttypes>
#include <cstdio>
#include <exception>
#include <iterator>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <string_view>

namespace {

const char* const usage =
    "usage: irrlicht_snow [options]\n"
    "  --scene FILE         glTF scene (default: assets/scenes/village.gltf)\n"
    "  --frames N           engine frames to run, >= 1 (default 801)\n"
    "  --frame-ms MS        engine time per frame, 1 to 1000 ms (default 25); the snow\n"
    "                       ticks at the scene's dt, at most 8 ticks a frame (FixedStep)\n"
    "  --driver NAME        null | software | burnings (default null; the last two need X)\n"
    "  --screenshot FILE    after the last frame, write it as an image (not with null)\n"
    "  --expect-hash HEX    exit 1 unless the state hash is this (16 hex digits)\n"
    "Exit status: 0 ok, 1 a check failed, 2 bad arguments or scene.\n";

constexpr irr::u32 width = 640, height = 480;

struct Options {
    std::string scene = SNOW_EXAMPLE_SCENE;
    std::uint32_t frames = 801;
    std::uint32_t frame_ms = 25;
    std::string driver_name = "null";
    irr::video::E_DRIVER_TYPE driver = irr::video::EDT_NULL;
    std::string screenshot;
    std::optional<std::uint64_t> expect_hash;
    bool help = false;
};

/// The whole of `text` as a number in `base`; nothing when it is not one.
template <typename T>
std::optional<T> parse_number(std::string_view text, int base = 10) {
    T value{};
    const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value, base);
    if (ec != std::errc{} || end != text.data() + text.size()) {
        return std::nullopt;
    }
    return value;
}

/// Options from the command line, or an error that names the flag.
std::optional<Options> parse_options(int argc, char** argv, std::string& error) {
    Options o;
    for (int i = 1; i < argc; ++i) {
        const std::string_view flag = argv[i];
        if (flag == "--help") {
            o.help = true;
            continue;
        }
        constexpr std::string_view with_value[] = {"--scene",  "--frames",     "--frame-ms",
                                                   "--driver", "--screenshot", "--expect-hash"};
        if (std::find(std::begin(with_value), std::end(with_value), flag) == std::end(with_value)) {
            error = "unknown flag " + std::string(flag);
            return std::nullopt;
        }
        if (i + 1 >= argc) {
            error = std::string(flag) + " needs a value";
            return std::nullopt;
        }
        const std::string_view value = argv[++i];
        const auto bad = [&](const char* expected) {
            error = std::string(flag).append(" must be ").append(expected).append(" (got '");
            error.append(value).append("')");
            return std::nullopt;
        };
        if (flag == "--scene") {
            o.scene = value;
        } else if (flag == "--frames") {
            const auto n = parse_number<std::uint32_t>(value);
            if (!n || *n == 0) {
                return bad("an integer >= 1");
            }
            o.frames = *n;
        } else if (flag == "--frame-ms") {
            const auto n = parse_number<std::uint32_t>(value);
            if (!n || *n == 0 || *n > 1000) {
                return bad("an integer from 1 to 1000");
            }
            o.frame_ms = *n;
        } else if (flag == "--driver") {
            o.driver_name = value;
            if (value == "null") {
                o.driver = irr::video::EDT_NULL;
            } else if (value == "software") {
                o.driver = irr::video::EDT_SOFTWARE;
            } else if (value == "burnings") {
                o.driver = irr::video::EDT_BURNINGSVIDEO;
            } else {
                return bad("null, software or burnings");
            }
        } else if (flag == "--screenshot") {
            o.screenshot = value;
        } else { // --expect-hash
            const auto h = parse_number<std::uint64_t>(value, 16);
            if (value.size() != 16 || !h) {
                return bad("16 hex digits");
            }
            o.expect_hash = h;
        }
    }
    if (std::uint64_t{o.frames} * o.frame_ms > std::numeric_limits<irr::u32>::max()) {
        error = "--frames times --frame-ms passes the engine clock's 2^32 ms";
        return std::nullopt;
    }
    if (!o.screenshot.empty() && o.driver == irr::video::EDT_NULL) {
        error = "--screenshot needs --driver software or burnings (null draws nothing)";
        return std::nullopt;
    }
    return o;
}

struct DropDevice {
    void operator()(irr::IrrlichtDevice* d) const { d->drop(); }
};

irr::video::SColor to_color(const Vec3& c) {
    const auto channel = [](float v) {
        return static_cast<irr::u32>(std::clamp(v, 0.0f, 1.0f) * 255.0f);
    };
    return irr::video::SColor(255, channel(c.x), channel(c.y), channel(c.z));
}

/// Runs the scene in the engine; returns the exit status.
int run(const Options& o) {
    std::string error;
    const std::unique_ptr<SnowFeed> feed = SnowFeed::load(o.scene, error);
    if (!feed) {
        std::fprintf(stderr, "irrlicht_snow: %s\n", error.c_str());
        return 2;
    }
    irr::SIrrlichtCreationParameters params;
    params.DriverType = o.driver;
    params.WindowSize = irr::core::dimension2du(width, height);
    params.Bits = 32;
    params.LoggingLevel = irr::ELL_WARNING; // no version banner in the host's output
    const std::unique_ptr<irr::IrrlichtDevice, DropDevice> device(irr::createDeviceEx(params));
    if (!device) {
        std::fprintf(stderr, "irrlicht_snow: no %s device (software drivers need X: xvfb-run -a)\n",
                     o.driver_name.c_str());
        return 1;
    }
    irr::video::IVideoDriver* driver = device->getVideoDriver();
    irr::scene::ISceneManager* smgr = device->getSceneManager();

    SnowGround ground(*feed);
    irr::scene::IMeshSceneNode* ground_node = smgr->addMeshSceneNode(ground.mesh());
    auto* flakes = new FlakeNode(*feed, smgr->getRootSceneNode(), smgr);
    flakes->drop(); // the root node holds it
    const View view = feed->view();
    irr::scene::ICameraSceneNode* camera =
        smgr->addCameraSceneNode(nullptr, to_irr(view.position), to_irr(view.target));
    camera->setFOV(view.fov_y_deg * irr::core::DEGTORAD);
    camera->setNearValue(view.near_plane);
    camera->setFarValue(view.far_plane);

    // A stopped clock set by hand: every run sees the same frame times.
    irr::ITimer* timer = device->getTimer();
    timer->stop();
    timer->setTime(0);
    auto* animator = new SnowAnimator(*feed, ground, timer->getTime());
    ground_node->addAnimator(animator);
    animator->drop();

    const irr::video::SColor sky = to_color(view.sky);
    for (std::uint32_t frame = 1; frame <= o.frames; ++frame) {
        timer->setTime(frame * o.frame_ms);
        if (!device->run()) {
            std::fprintf(stderr, "irrlicht_snow: the device closed at frame %u\n", frame);
            return 1;
        }
        driver->beginScene(true, true, sky);
        smgr->drawAll(); // animators first: the snow ticks, then the nodes draw it
        driver->endScene();
    }

    const std::uint64_t hash = feed->state_hash();
    std::printf("irrlicht_snow: %s, driver %s, %u frames of %u ms: %" PRIu64
                " ticks, %zu flakes drawn\n",
                feed->name().c_str(), o.driver_name.c_str(), o.frames, o.frame_ms, feed->ticks(),
                flakes->drawn());
    std::printf("irrlicht_snow: state hash %016" PRIx64 "\n", hash);
    const std::size_t bad = ground.mismatches();
    std::printf("irrlicht_snow: ground mesh %zu vertices in %zu buffers (%u x %u cells), "
                "%zu heights differ from base + depth; deepest snow %.4f m\n",
                ground.vertex_count(), ground.band_count(), feed->ground_nx(), feed->ground_nz(),
                bad, static_cast<double>(feed->deepest_snow()));

    int status = 0;
    if (!o.screenshot.empty()) {
        irr::video::IImage* image = driver->createScreenShot();
        const bool written =
            image != nullptr && driver->writeImageToFile(image, o.screenshot.c_str());
        if (image != nullptr) {
            image->drop();
        }
        if (!written) {
            std::fprintf(stderr, "irrlicht_snow: could not write %s\n", o.screenshot.c_str());
            status = 1;
        } else {
            std::printf("irrlicht_snow: wrote %s\n", o.screenshot.c_str());
        }
    }
    if (bad != 0) {
        std::fprintf(stderr, "irrlicht_snow: the ground mesh does not follow the snow\n");
        status = 1;
    }
    if (o.expect_hash && *o.expect_hash != hash) {
        std::fprintf(stderr, "irrlicht_snow: state hash %016" PRIx64 ", expected %016" PRIx64 "\n",
                     hash, *o.expect_hash);
        status = 1;
    }
    return status;
}

} // namespace

int main(int argc, char** argv) {
    std::string error;
    const std::optional<Options> options = parse_options(argc, argv, error);
    if (!options) {
        std::fprintf(stderr, "irrlicht_snow: %s (see --help)\n", error.c_str());
        return 2;
    }
    if (options->help) {
        std::fputs(usage, stdout);
        return 0;
    }
    try {
        return run(*options);
    } catch (const std::exception& e) { // snow::Error is a std::runtime_error
        std::fprintf(stderr, "irrlicht_snow: %s\n", e.what());
        return 1;
    }
}
