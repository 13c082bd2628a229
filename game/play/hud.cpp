#include "game/play/hud.hpp"
#include "systems/api/simulation_internals.hpp"

#include "game/play/game_input.hpp"
#include "game/play/hud_info.hpp"
#include "systems/core/units.hpp"

#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl3.h>
#include <imgui.h>

namespace snow {

Hud::Hud(GLFWwindow* window) {
    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    ImGui::GetIO().IniFilename = nullptr; // no imgui.ini next to the player's files
    ImGui::StyleColorsDark();
    ImGui_ImplGlfw_InitForOpenGL(window, true);
    ImGui_ImplOpenGL3_Init("#version 330 core");
}

Hud::~Hud() {
    ImGui_ImplOpenGL3_Shutdown();
    ImGui_ImplGlfw_Shutdown();
    ImGui::DestroyContext();
}

bool Hud::wants_mouse() const {
    return ImGui::GetIO().WantCaptureMouse;
}

void Hud::draw(const GameSession& session, const FrameTimings& frame, float fps) {
    const Simulation& sim = session.sim();
    const HudInfo info = hud_info(session, fps);
    ImGui_ImplOpenGL3_NewFrame();
    ImGui_ImplGlfw_NewFrame();
    ImGui::NewFrame();
    ImGui::SetNextWindowPos(ImVec2(8, 8), ImGuiCond_FirstUseEver);
    ImGui::SetNextWindowBgAlpha(0.6f);
    ImGui::Begin("snow", nullptr, ImGuiWindowFlags_AlwaysAutoResize);
    const MassReport m = sim.mass();
    ImGui::Text("%.1f fps  tick %llu%s", static_cast<double>(info.fps),
                static_cast<unsigned long long>(sim.tick_count()), info.paused ? "  PAUSED" : "");
    ImGui::Text("flakes alive %u (drawn %u)", flake_pool(sim).alive, frame.flakes_drawn);
    const auto kg = [](std::uint64_t units) { return static_cast<double>(units) * unit_kg; };
    ImGui::Text("snow %.3f kg spawned = %.3f airborne + %.3f settled", kg(m.spawned),
                kg(m.airborne), kg(m.settled));
    ImGui::Text("    + %.3f carried + %.3f removed%s", kg(m.carried), kg(m.removed),
                m.balanced() ? "" : "  UNBALANCED");
    ImGui::Text("time x%u: %llu ticks/frame%s", info.time_scale,
                static_cast<unsigned long long>(info.ticks_per_frame),
                info.ticks_capped ? " (held back by the frame budget)" : "");
    if (info.depth_under) {
        ImGui::Text("snow under you %.1f cm, 1 m ahead %.1f cm",
                    100.0 * static_cast<double>(*info.depth_under),
                    100.0 * static_cast<double>(info.depth_ahead.value_or(0.0f)));
    }
    ImGui::Text("quality %s, camera %s, fog %s", info.quality.c_str(), info.camera_mode.c_str(),
                info.fog_on ? "on" : "off");
    if (ImGui::CollapsingHeader("ms per system", ImGuiTreeNodeFlags_DefaultOpen)) {
        for (const SystemStats& s : schedule_of(sim).stats()) {
            ImGui::Text("%-13s %7.3f", s.name.c_str(),
                        s.calls ? s.total_ms / static_cast<double>(s.calls) : 0.0);
        }
    }
    if (ImGui::CollapsingHeader("ms per render pass")) {
        for (const PassTiming& p : frame.passes) {
            ImGui::Text("%-13s %7.3f%s", p.name.c_str(), p.cpu_ms, p.ran ? "" : " (skipped)");
        }
    }
    if (!info.last_message.empty()) {
        ImGui::TextUnformatted(info.last_message.c_str());
    }
    if (!info.help) {
        ImGui::TextUnformatted("H: keys");
    } else {
        ImGui::Separator();
        for (const KeyHelp& k : key_help()) {
            ImGui::Text("%-14s %s", k.key, k.what);
        }
    }
    ImGui::End();
    ImGui::Render();
    ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
}

} // namespace snow
