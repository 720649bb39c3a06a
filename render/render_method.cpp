#include "render/render_method.hpp"

namespace umbra {
namespace {

constexpr RenderMethod kAll[] = {RenderMethod::kAuto, RenderMethod::kZFail, RenderMethod::kZPass,
                                 RenderMethod::kTriangles, RenderMethod::kShadowMap, RenderMethod::kPlanar,
                                 RenderMethod::kRaycast};

}  // namespace

const char* method_name(RenderMethod method) {
  switch (method) {
    case RenderMethod::kAuto: return "auto";
    case RenderMethod::kZFail: return "zfail";
    case RenderMethod::kZPass: return "zpass";
    case RenderMethod::kTriangles: return "triangles";
    case RenderMethod::kShadowMap: return "shadowmap";
    case RenderMethod::kPlanar: return "planar";
    case RenderMethod::kRaycast: return "raycast";
  }
  return "?";
}

std::optional<RenderMethod> method_from_name(const std::string& name) {
  for (const RenderMethod m : kAll)
    if (name == method_name(m)) return m;
  return std::nullopt;
}

std::string method_names() {
  std::string names;
  for (const RenderMethod m : kAll) names += (names.empty() ? "" : "|") + std::string(method_name(m));
  return names;
}

}  // namespace umbra
