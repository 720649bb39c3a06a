#pragma once
// The ways umbra can shadow a scene (`--method`): the shadow-volume plan and
// its fixed variants, and the CPU ray-cast reference.

#include <optional>
#include <string>
#include <vector>

namespace umbra {

enum class RenderMethod {
  kAuto,       // shadow volumes; per light z-pass where the eye is outside every volume, z-fail elsewhere
  kZFail,      // shadow volumes, capped z-fail for every light (Everitt and Kilgard 2002)
  kZPass,      // shadow volumes, uncapped z-pass for every light: wrong where the eye is in a volume
  kTriangles,  // z-fail, and every mesh cast per triangle instead of from its silhouette
  kShadowMap,  // a cube shadow map per light (Williams 1978): no volumes, error grows as the map shrinks
  kPlanar,     // casters projected onto the triangles' planes (Blinn 1988): no shadow on anything else
  kRaycast,    // the CPU reference: exact shadow rays (Appel 1968, Whitted 1980)
};

// The pass that draws a method's shadows: one ShadowTechnique each
// (shadow_technique.hpp), but for the CPU reference, which draws no GL frame.
enum class ShadowPass {
  kCountedVolumes,  // auto, zfail, zpass, triangles: the plan says how each light counts
  kShadowMap,
  kPlanar,
  kRayCast,
};

// How a method counts its shadow volumes, per light: not at all (its pass
// is not kCountedVolumes), z-pass or z-fail by whether the near plane may be
// in shadow (auto), or always one of the two.
enum class VolumeCounting { kNone, kPerLight, kZPass, kZFail };

// How umbra bench sweeps a method: at each sphere N (--segments), at each N
// but only in scenes with meshes, at each shadow map size (--map-sizes), or
// once, as the reference every other method is measured against.
enum class BenchSweep { kSphereSegments, kSegmentsWithMeshes, kMapSizes, kReference };

// Every method once, its row beside its enum value: its name on the command
// line, how it shadows (as --explain says), its pass and how it counts, and
// its line in the commands' --help. Everything that differs between methods
// reads its row (row_of, or the functions below), never a switch on the
// method.
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
inline constexpr MethodRow kMethods[] = {
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

const MethodRow& row_of(RenderMethod method);
const char* method_name(RenderMethod method);
BenchSweep method_bench_sweep(RenderMethod method);
ShadowPass method_pass(RenderMethod method);
// How it shadows, in a phrase: "no volumes: a cube map of distances from each light".
const char* method_technique(RenderMethod method);
// It counts shadow volumes (z-pass or z-fail): its pass is kCountedVolumes.
bool counts_volumes(RenderMethod method);
VolumeCounting method_counting(RenderMethod method);
// It leaves out the casters whose volumes cannot reach the view (auto).
bool culls_casters(RenderMethod method);
// It casts every mesh per triangle, not from its silhouette or by edge
// multiplicity (the slow reference).
bool casts_per_triangle(RenderMethod method);
// Whether its shadows are the ray-cast reference's in every view (exact
// shadow volumes, and the reference itself; not z-pass, wrong where the eye
// is in a volume, nor the shadow map or planar projection): only then may a
// picture's edge pixels be drawn again from exact rays (AntialiasedPixels).
bool draws_exact_shadows(RenderMethod method);
// Whether a shadow catcher keeps the method's shadows: all but planar, which
// marks shadows in the stencil, so that no shadowed fragment reaches the
// shader to be counted.
bool keeps_caught_shadows(RenderMethod method);
// umbra view draws it; the next such method in the table's order, after the last the first.
bool is_interactive(RenderMethod method);
RenderMethod next_interactive_method(RenderMethod method);
std::optional<RenderMethod> method_from_name(const std::string& name);
// What it does, in a sentence or two for --help.
std::string method_help(RenderMethod method);
// Every method, in the table's order.
std::vector<RenderMethod> all_methods();
// "auto|zfail|zpass|triangles|shadowmap|planar|raycast", for usage text and errors.
std::string method_names();

}  // namespace umbra
