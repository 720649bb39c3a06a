#include "render/render_method.hpp"

#include <iterator>

namespace umbra {
namespace {

// Every method once: its name on the command line and how it shadows, as
// --explain says.
struct MethodRow {
  RenderMethod method;
  const char* name;
  const char* technique;
  bool counts_volumes;  // in the stencil, z-pass or z-fail
  bool interactive;     // umbra view draws it, and its m key cycles to it
};
constexpr MethodRow kMethods[] = {
    {RenderMethod::kAuto, "auto", "two-sided stencil with wrapping, z-pass or z-fail per light", true, true},
    {RenderMethod::kZFail, "zfail", "two-sided stencil with wrapping, capped z-fail for every light", true, true},
    {RenderMethod::kZPass, "zpass", "two-sided stencil with wrapping, uncapped z-pass for every light", true, true},
    {RenderMethod::kTriangles, "triangles", "two-sided stencil with wrapping, capped z-fail, a volume per mesh triangle", true, true},
    {RenderMethod::kShadowMap, "shadowmap", "no stencil: a cube map of distances from each light", false, true},
    {RenderMethod::kPlanar, "planar", "no stencil: casters projected onto the triangles' planes", false, true},
    {RenderMethod::kRaycast, "raycast", "no GL: exact shadow rays on the CPU", false, false},
};

const MethodRow& row_of(RenderMethod method) {
  for (const MethodRow& row : kMethods)
    if (row.method == method) return row;
  return kMethods[0];
}

}  // namespace

const char* method_name(RenderMethod method) { return row_of(method).name; }

const char* method_technique(RenderMethod method) { return row_of(method).technique; }

bool counts_volumes(RenderMethod method) { return row_of(method).counts_volumes; }

bool is_interactive(RenderMethod method) { return row_of(method).interactive; }

RenderMethod next_interactive_method(RenderMethod method) {
  const MethodRow* row = &row_of(method);
  const MethodRow* const end = std::end(kMethods);
  do row = row + 1 == end ? kMethods : row + 1;
  while (!row->interactive);
  return row->method;
}

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
