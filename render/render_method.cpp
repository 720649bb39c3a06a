#include "render/render_method.hpp"

namespace umbra {
namespace {

// Every method once: its name on the command line and how it shadows, as
// --explain says.
struct MethodRow {
  RenderMethod method;
  const char* name;
  const char* technique;
};
constexpr MethodRow kMethods[] = {
    {RenderMethod::kAuto, "auto", "two-sided stencil with wrapping, z-pass or z-fail per light"},
    {RenderMethod::kZFail, "zfail", "two-sided stencil with wrapping, capped z-fail for every light"},
    {RenderMethod::kZPass, "zpass", "two-sided stencil with wrapping, uncapped z-pass for every light"},
    {RenderMethod::kTriangles, "triangles", "two-sided stencil with wrapping, capped z-fail, a volume per mesh triangle"},
    {RenderMethod::kShadowMap, "shadowmap", "no stencil: a cube map of distances from each light"},
    {RenderMethod::kPlanar, "planar", "no stencil: casters projected onto the triangles' planes"},
    {RenderMethod::kRaycast, "raycast", "no GL: exact shadow rays on the CPU"},
};

const MethodRow& row_of(RenderMethod method) {
  for (const MethodRow& row : kMethods)
    if (row.method == method) return row;
  return kMethods[0];
}

}  // namespace

const char* method_name(RenderMethod method) { return row_of(method).name; }

const char* method_technique(RenderMethod method) { return row_of(method).technique; }

std::optional<RenderMethod> method_from_name(const std::string& name) {
  for (const MethodRow& row : kMethods)
    if (name == row.name) return row.method;
  return std::nullopt;
}

std::string method_names() {
  std::string names;
  for (const MethodRow& row : kMethods) names += (names.empty() ? "" : "|") + std::string(row.name);
  return names;
}

}  // namespace umbra
