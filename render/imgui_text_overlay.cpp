// Dear ImGui with its GLFW and OpenGL 3 backends (compiled into Debian's
// libimgui.a). The OpenGL 3 backend loads its few GL functions itself.
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl3.h>
#include <imgui.h>

#include <stdexcept>

#include "render/text_overlay.hpp"
#include "render/window_context.hpp"

namespace umbra {

TextOverlay::TextOverlay(WindowContext& window) {
  IMGUI_CHECKVERSION();
  ImGui::CreateContext();
  ImGui::GetIO().IniFilename = nullptr;  // no imgui.ini beside the user's files
  // install_callbacks: ImGui chains to the window's own input callbacks.
  if (!ImGui_ImplGlfw_InitForOpenGL(static_cast<GLFWwindow*>(window.native_window()), true) ||
      !ImGui_ImplOpenGL3_Init("#version 330 core")) {
    ImGui::DestroyContext();
    throw std::runtime_error("Dear ImGui: cannot start its GLFW and OpenGL 3 backends");
  }
}

TextOverlay::~TextOverlay() {
  ImGui_ImplOpenGL3_Shutdown();
  ImGui_ImplGlfw_Shutdown();
  ImGui::DestroyContext();
}

void TextOverlay::draw(const std::vector<std::string>& lines) {
  ImGui_ImplOpenGL3_NewFrame();
  ImGui_ImplGlfw_NewFrame();
  ImGui::NewFrame();
  ImGui::SetNextWindowPos(ImVec2(8.0f, 8.0f));
  ImGui::SetNextWindowBgAlpha(0.6f);
  ImGui::Begin("umbra", nullptr,
               ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoSavedSettings |
                   ImGuiWindowFlags_NoFocusOnAppearing | ImGuiWindowFlags_NoNav | ImGuiWindowFlags_NoInputs);
  for (const std::string& line : lines) ImGui::TextUnformatted(line.c_str());
  ImGui::End();
  ImGui::Render();
  ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
}

}  // namespace umbra
