#include "render/render_method.hpp"

#include <iterator>

namespace umbra {
namespace {

// Every method once: its name on the command line, how it shadows (as
// --explain says), and its line in the commands' --help.
struct MethodRow {
  RenderMethod method;
  const char* name;
  const char* technique;
  ShadowPass pass;
  VolumeCounting counting;
  bool culls;         // culls_casters
  bool per_triangle;  // casts_per_triangle
  bool interactive;  // umbra view draws it, and its m key cycles to it
  bool exact;        // its shadows are the reference's in every view (draws_exact_shadows)
  BenchSweep bench;
  const char* help;
};
constexpr MethodRow kMethods[] = {
    {RenderMethod::kAuto, "auto", "shadow volumes counted in a float buffer, z-pass or z-fail per light",
     ShadowPass::kCountedVolumes, VolumeCounting::kPerLight, /*culls*/ true, /*per_triangle*/ false,
     /*interactive*/ true, /*exact*/ true, BenchSweep::kSphereSegments,
     "shadow volumes; per light z-pass without caps where the near plane is outside every volume, capped z-fail "
     "elsewhere; casters whose volumes cannot reach the view are left out"},
    {RenderMethod::kZFail, "zfail", "shadow volumes counted in a float buffer, capped z-fail for every light",
     ShadowPass::kCountedVolumes, VolumeCounting::kZFail, false, false, true, true, BenchSweep::kSphereSegments,
     "capped z-fail for every light (Everitt and Kilgard 2002)"},
    {RenderMethod::kZPass, "zpass", "shadow volumes counted in a float buffer, uncapped z-pass for every light",
     ShadowPass::kCountedVolumes, VolumeCounting::kZPass, false, false, true, false, BenchSweep::kSphereSegments,
     "uncapped z-pass for every light (Heidmann 1991); wrong where the near plane is in a volume"},
    {RenderMethod::kTriangles, "triangles", "shadow volumes counted in a float buffer, capped z-fail, a volume per mesh triangle",
     ShadowPass::kCountedVolumes, VolumeCounting::kZFail, false, true, true, true, BenchSweep::kSegmentsWithMeshes,
     "z-fail, every mesh cast per triangle (the slow reference) rather than from its silhouette or by edge multiplicity"},
    {RenderMethod::kShadowMap, "shadowmap", "no volumes: a cube map of distances from each light",
     ShadowPass::kShadowMap, VolumeCounting::kNone, false, false, true, false, BenchSweep::kMapSizes,
     "a cube shadow map per light (Williams 1978), --map-size texels a side; no volumes"},
    {RenderMethod::kPlanar, "planar", "no volumes: casters projected onto the triangles' planes",
     ShadowPass::kPlanar, VolumeCounting::kNone, false, false, true, false, BenchSweep::kSphereSegments,
     "every caster projected onto the planes of the scene's triangles (Blinn 1988); spheres and meshes receive no "
     "shadow, which --explain says"},
    {RenderMethod::kRaycast, "raycast", "no GL: exact shadow rays on the CPU",
     ShadowPass::kRayCast, VolumeCounting::kNone, false, false, false, true, BenchSweep::kReference,
     "the CPU reference: exact shadow rays (Appel 1968, Whitted 1980), true spheres (no GL, no N-gon)"},
};

const MethodRow& row_of(RenderMethod method) {
  for (const MethodRow& row : kMethods)
    if (row.method == method) return row;
  return kMethods[0];
}

}  // namespace

const char* method_name(RenderMethod method) { return row_of(method).name; }

const char* method_technique(RenderMethod method) { return row_of(method).technique; }

ShadowPass method_pass(RenderMethod method) { return row_of(method).pass; }

BenchSweep method_bench_sweep(RenderMethod method) { return row_of(method).bench; }

bool counts_volumes(RenderMethod method) { return method_pass(method) == ShadowPass::kCountedVolumes; }

VolumeCounting method_counting(RenderMethod method) { return row_of(method).counting; }

bool culls_casters(RenderMethod method) { return row_of(method).culls; }

bool casts_per_triangle(RenderMethod method) { return row_of(method).per_triangle; }

bool draws_exact_shadows(RenderMethod method) { return row_of(method).exact; }

bool keeps_caught_shadows(RenderMethod method) { return method_pass(method) != ShadowPass::kPlanar; }

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

std::string method_help(RenderMethod method) { return row_of(method).help; }

std::vector<RenderMethod> all_methods() {
  std::vector<RenderMethod> methods;
  for (const MethodRow& row : kMethods) methods.push_back(row.method);
  return methods;
}

std::string method_names() {
  std::string names;
  for (const MethodRow& row : kMethods) names += (names.empty() ? "" : "|") + std::string(row.name);
  return names;
}

}  // namespace umbra
