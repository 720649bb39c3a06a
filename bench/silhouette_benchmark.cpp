// Google Benchmark: the per-frame work of a mesh shadow (face classification
// and volume extraction over the flat adjacency arrays), beside the memory
// bandwidth bound of that loop, and the silhouette volume against per-triangle
// volumes for the same mesh, in triangles built and in render time.
//
//   build/bench/silhouette_benchmark [--benchmark_repetitions=5 --benchmark_report_aggregates_only=true]
#include <benchmark/benchmark.h>

#include <cmath>
#include <numeric>

#include <glm/trigonometric.hpp>

#include "mesh/topology/crease_normals.hpp"
#include "mesh/topology/half_edge_mesh.hpp"
#include "mesh/check/mesh_check.hpp"
#include "scene/mesh_loader.hpp"
#include "scene/scene_parser.hpp"
#include "scene/terminator.hpp"
#include "render/headless_context.hpp"
#include "render/render_plan.hpp"
#include "render/shadow_renderer.hpp"
#include "silhouette/light_facing.hpp"
#include "silhouette/face_plane.hpp"
#include "silhouette/mesh_adjacency.hpp"
#include "silhouette/mesh_caster.hpp"
#include "silhouette/mesh_volume.hpp"

namespace umbra {
namespace {

// A torus of n x m quads split into 2 n m triangles (radii 1 and 0.35).
void torus(int n, int m, std::vector<glm::dvec3>& positions, std::vector<std::array<uint32_t, 3>>& triangles) {
  const double tau = 6.283185307179586;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < m; ++j) {
      const double u = tau * i / n, v = tau * j / m;
      positions.push_back({(1 + 0.35 * std::cos(v)) * std::cos(u), (1 + 0.35 * std::cos(v)) * std::sin(u), 0.35 * std::sin(v)});
    }
  const auto at = [&](int i, int j) { return uint32_t((i % n) * m + (j % m)); };
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < m; ++j) {
      triangles.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
      triangles.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
    }
}

const MeshAdjacency& torus_adjacency(int n, int m) {
  static std::map<std::pair<int, int>, MeshAdjacency> cache;
  auto it = cache.find({n, m});
  if (it == cache.end()) {
    std::vector<glm::dvec3> positions;
    std::vector<std::array<uint32_t, 3>> triangles;
    torus(n, m, positions, triangles);
    it = cache.emplace(std::make_pair(n, m), build_mesh_adjacency(positions, triangles)).first;
  }
  return it->second;
}

// Bytes one classify + extract pass must at least read and write: the face
// planes and the faces of every edge read once, the triangles of the faces
// turned away from the light read, the facing flags written and read back,
// and the indices written.
double bytes_per_pass(const MeshAdjacency& mesh, const MeshVolumeIndices& volume) {
  const double faces = double(mesh.planes.size());
  return faces * sizeof(MeshAdjacency::FacePlane) + double(mesh.edge_faces.size()) * sizeof(mesh.edge_faces[0]) +
         double(volume.light_cap_triangles) * sizeof(mesh.triangles[0]) + 2.0 * faces +
         double(volume.count) * sizeof(uint32_t);
}

void BM_ClassifyAndExtract(benchmark::State& state) {
  const MeshAdjacency& mesh = torus_adjacency(int(state.range(0)), int(state.range(1)));
  std::vector<uint8_t> facing;
  MeshVolumeIndices volume;
  double angle = 0.0;
  for (auto _ : state) {
    angle += 0.01;  // the light orbits, as in umbra view
    mesh_volume_indices(mesh, {3.0 * std::cos(angle), 3.0 * std::sin(angle), 2.0}, facing, volume);
    benchmark::DoNotOptimize(volume.buffer.data());
  }
  state.counters["triangles"] = double(mesh.triangles.size());
  state.counters["side_quads"] = volume.side_quads;
  state.counters["bytes_per_pass"] = bytes_per_pass(mesh, volume);
  state.SetBytesProcessed(int64_t(state.iterations() * bytes_per_pass(mesh, volume)));
}
// 250 x 200 quads: 100,000 triangles; 800 x 640: 1,024,000.
BENCHMARK(BM_ClassifyAndExtract)->Args({250, 200})->Args({800, 640})->Unit(benchmark::kMillisecond);

// Silhouette edges found two ways, for the same torus and light: over the
// flat arrays the renderer uses (faces classified into a byte array, then
// each edge's two faces looked up), and by walking the OpenMesh half-edge
// structure itself (faces classified into an OpenMesh property, then each
// edge's two half-edges' faces). Argument 2: 0 flat arrays, 1 OpenMesh.
void BM_SilhouetteEdges(benchmark::State& state) {
  const int n = int(state.range(0)), m = int(state.range(1));
  std::vector<glm::dvec3> positions;
  std::vector<std::array<uint32_t, 3>> triangles;
  torus(n, m, positions, triangles);
  const MeshAdjacency& flat = torus_adjacency(n, m);
  HalfEdgeMesh mesh = build_half_edge_mesh(positions, triangles);
  OpenMesh::FPropHandleT<FacePlane> plane;
  OpenMesh::FPropHandleT<uint8_t> facing_property;
  mesh.add_property(plane);
  mesh.add_property(facing_property);
  for (const auto f : mesh.faces()) {
    std::array<glm::dvec3, 3> p;
    int k = 0;
    for (const auto v : mesh.fv_range(f)) p[size_t(k++)] = positions[size_t(v.idx())];
    mesh.property(plane, f) = face_plane(p[0], p[1], p[2]);
  }
  std::vector<uint8_t> facing;
  std::vector<std::array<uint32_t, 2>> silhouette;
  double angle = 0.0;
  for (auto _ : state) {
    angle += 0.01;
    const glm::dvec3 light(3.0 * std::cos(angle), 3.0 * std::sin(angle), 2.0);
    const double light_distance = glm::length(light);
    silhouette.clear();
    if (state.range(2) == 0) {
      classify_light_facing(flat, light, facing);
      for (size_t e = 0; e < flat.edge_faces.size(); ++e)
        if (facing[flat.edge_faces[e][0]] != facing[flat.edge_faces[e][1]]) silhouette.push_back(flat.edge_vertices[e]);
    } else {
      for (const auto f : mesh.faces()) {
        std::array<glm::dvec3, 3> p;
        int k = 0;
        for (const auto v : mesh.fv_range(f)) p[size_t(k++)] = positions[size_t(v.idx())];
        mesh.property(facing_property, f) = light_side(mesh.property(plane, f), p[0], p[1], p[2], light, light_distance) > 0;
      }
      for (const auto e : mesh.edges()) {
        const auto h = mesh.halfedge_handle(e, 0);
        if (mesh.property(facing_property, mesh.face_handle(h)) != mesh.property(facing_property, mesh.opposite_face_handle(h)))
          silhouette.push_back({uint32_t(mesh.from_vertex_handle(h).idx()), uint32_t(mesh.to_vertex_handle(h).idx())});
      }
    }
    benchmark::DoNotOptimize(silhouette.data());
  }
  state.counters["silhouette_edges"] = double(silhouette.size());
}
BENCHMARK(BM_SilhouetteEdges)->Args({250, 200, 0})->Args({250, 200, 1})->Args({800, 640, 0})->Args({800, 640, 1})
    ->Unit(benchmark::kMillisecond);

// The same torus through the mesh caster, closed (argument 2 = 0: the
// silhouette volume) or with one face removed (1: open, so the whole mesh
// takes the edge-multiplicity volume): what a frame costs on the CPU for a
// closed mesh and for an open one.
void BM_CasterVolume(benchmark::State& state) {
  std::vector<glm::dvec3> positions;
  std::vector<std::array<uint32_t, 3>> triangles;
  torus(int(state.range(0)), int(state.range(1)), positions, triangles);
  if (state.range(2) != 0) triangles.pop_back();
  const MeshCaster caster = prepare_mesh_caster(positions, triangles);
  MeshCasterScratch scratch;
  MeshVolumeIndices volume;
  double angle = 0.0;
  for (auto _ : state) {
    angle += 0.01;
    mesh_caster_volume_indices(caster, {3.0 * std::cos(angle), 3.0 * std::sin(angle), 2.0}, scratch, volume);
    benchmark::DoNotOptimize(volume.buffer.data());
  }
  state.counters["side_quads"] = volume.side_quads;
  state.counters["volume_triangles"] = double(volume.count / 3);
}
BENCHMARK(BM_CasterVolume)->Args({250, 200, 0})->Args({250, 200, 1})->Args({800, 640, 0})->Args({800, 640, 1})
    ->Unit(benchmark::kMillisecond);

// The bound: streaming through as many bytes as one pass touches, reading
// 8 bytes at a time and summing, which is what the memory system allows.
void BM_MemoryBandwidth(benchmark::State& state) {
  const MeshAdjacency& mesh = torus_adjacency(int(state.range(0)), int(state.range(1)));
  std::vector<uint8_t> facing;
  MeshVolumeIndices volume;
  mesh_volume_indices(mesh, {3.0, 0.0, 2.0}, facing, volume);
  const size_t words = size_t(bytes_per_pass(mesh, volume) / 8);
  std::vector<uint64_t> buffer(words, 1);
  for (auto _ : state) benchmark::DoNotOptimize(std::accumulate(buffer.begin(), buffer.end(), uint64_t(0)));
  state.SetBytesProcessed(int64_t(state.iterations() * words * 8));
}
BENCHMARK(BM_MemoryBandwidth)->Args({250, 200})->Args({800, 640})->Unit(benchmark::kMillisecond);

// CPU cost of the fallback for the same mesh: every triangle's own volume.
void BM_PerTriangleVolumes(benchmark::State& state) {
  std::vector<glm::dvec3> positions;
  std::vector<std::array<uint32_t, 3>> triangles;
  torus(int(state.range(0)), int(state.range(1)), positions, triangles);
  ShadowVolume volume;
  for (auto _ : state) {
    volume = per_triangle_volume(positions, triangles, {3.0, 0.0, 2.0});
    benchmark::DoNotOptimize(volume.triangles.data());
  }
  state.counters["side_quads"] = volume.side_quads;
  state.counters["volume_triangles"] = double(volume.triangles.size());
}
BENCHMARK(BM_PerTriangleVolumes)->Args({250, 200})->Unit(benchmark::kMillisecond);

// The torus of `rings` x `sides` (over a floor, lit from above) as a scene,
// with one face removed when `open`.
Scene torus_over_a_floor(int rings, int sides, bool open) {
  std::vector<glm::dvec3> positions;
  std::vector<std::array<uint32_t, 3>> triangles;
  torus(rings, sides, positions, triangles);
  if (open) triangles.pop_back();
  Scene scene = parse_scene_text("light 0.5 0.9 1.8\ntriangle -1 -1 -1 1 -1 -1 1 1 -1\ntriangle -1 -1 -1 1 1 -1 -1 1 -1\n",
                                 "bench.scene");
  PolygonSoup soup;
  for (const glm::dvec3& p : positions) soup.add_point(0.5 * p + glm::dvec3(0, 0, -0.3), 0);
  for (const auto& t : triangles) {
    soup.corners.insert(soup.corners.end(), t.begin(), t.end());
    soup.end_polygon(0);
  }
  MeshAnalysis analysis = analyse_mesh(soup, CheckOptions{0.0});
  Mesh mesh;
  mesh.positions = std::move(analysis.positions);
  mesh.triangles = std::move(analysis.triangles);
  mesh.bounds_min = analysis.report.bbox_min;
  mesh.bounds_max = analysis.report.bbox_max;
  mesh.edges = build_edge_table(mesh.triangles, mesh.positions.size());
  mesh.components = find_silhouette_components(mesh.triangles, mesh.edges, mesh.positions.size());
  scene.meshes.push_back(std::move(mesh));
  return scene;
}

// All the CPU work a frame does when its light has moved: the plan's update
// (culling, the count's choice, classifying the faces and extracting the
// silhouette volume's indices), without the GL. Argument 3 = 1 opens the mesh.
void BM_LightMovePlan(benchmark::State& state) {
  Scene scene = torus_over_a_floor(int(state.range(0)), int(state.range(1)), state.range(2) == 1);
  const std::vector<MeshCaster> casters = prepare_mesh_casters(scene);
  RenderSettings settings;
  settings.width = settings.height = 400;
  RenderPlan plan = make_render_plan(scene, casters, settings);
  for (auto _ : state) {
    rotate_lights_about_z(scene, 1.0);
    update_render_plan(scene, casters, plan);
    benchmark::DoNotOptimize(plan.lights[0].side_quads);
  }
  state.counters["side_quads"] = plan.lights[0].side_quads;
}
BENCHMARK(BM_LightMovePlan)->Args({250, 200, 0})->Args({800, 640, 0})->Args({800, 640, 1})->Unit(benchmark::kMillisecond);

// What a moved light costs a smooth mesh besides a flat one's: the triangles
// on its terminator (scene/terminator.hpp), from each triangle's side of
// the light, which SurfaceBuffers::use_light works out for each new light
// position. The torus of BM_RenderFrame, shaded smooth.
void BM_SmoothTerminator(benchmark::State& state) {
  Scene scene = torus_over_a_floor(int(state.range(0)), int(state.range(1)), false);
  Mesh& mesh = scene.meshes[0];
  mesh.triangle_normals = crease_normals(mesh.positions, mesh.triangles, 40.0);
  const std::vector<int8_t> sides = triangle_light_sides(mesh, scene.lights[0].position);
  for (auto _ : state) benchmark::DoNotOptimize(terminator_triangles(mesh, sides).data());
}
BENCHMARK(BM_SmoothTerminator)->Args({800, 640})->Unit(benchmark::kMillisecond);

// A frame of `umbra view` on the headless GL that auto picks (UMBRA_GL
// chooses another): 400 x 400, a torus over a floor, its shadow from
// per-triangle volumes (argument 2 = 0), from the silhouette (1), or, with
// one face removed, by edge multiplicity (2). With argument 3 = 1 the light
// orbits, so each frame remakes its volumes; with 0 it stands still, as in
// the viewer paused, and the plan's update finds nothing to do. As in the
// viewer, the volumes are made while the GL draws the first pass, and each
// frame is drawn and finished.
void BM_RenderFrame(benchmark::State& state) {
  const bool per_triangle = state.range(2) == 0;
  const bool light_moves = state.range(3) == 1;
  Scene scene = torus_over_a_floor(int(state.range(0)), int(state.range(1)), state.range(2) == 2);
  const std::vector<MeshCaster> casters = prepare_mesh_casters(scene);
  RenderSettings settings;
  settings.width = settings.height = 400;
  if (per_triangle) settings.method = RenderMethod::kTriangles;
  HeadlessContext context(400, 400);
  RenderPlan plan = make_render_plan(scene, casters, settings);
  ShadowRenderer renderer(scene, plan, DrawSending::kWhole);  // as the viewer sends them
  for (auto _ : state) {
    if (light_moves) rotate_lights_about_z(scene, 1.0);
    update_render_view(scene, plan);
    renderer.draw(false, [&] { update_render_lights(scene, casters, plan); });
    renderer.finish();
  }
  state.counters["volume_triangles"] = double(plan.lights[0].side_quads * 2 + plan.lights[0].light_cap_triangles +
                                              plan.lights[0].dark_cap_triangles);
}
BENCHMARK(BM_RenderFrame)
    ->Args({250, 200, 1, 1})
    ->Args({250, 200, 1, 0})
    ->Args({250, 200, 2, 1})
    ->Args({250, 200, 0, 1})
    ->Args({800, 640, 1, 1})  // 1.02M triangles: the light orbiting, and still
    ->Args({800, 640, 1, 0})
    ->Unit(benchmark::kMillisecond);

// A frame of `umbra view` with the camera orbiting (a degree about the z
// axis a frame), the light still: the 1M-triangle torus as loading leaves a
// closed mesh, its back faces culled and the picture asked at each new view
// whether one shows (argument 0), or settled by a search before the first
// frame, as umbra view does (argument 1: nothing asked).
void BM_ViewFrameCameraOrbiting(benchmark::State& state) {
  Scene scene = torus_over_a_floor(800, 640, false);
  scene.camera = {{1.6, -2.2, 1.4}, {0.0, 0.0, -0.3}, {0.0, 0.0, 1.0}, 45.0};
  scene.meshes[0].back_faces = BackFaces::kHiddenUnlessSeen;  // closed, facing out, not searched
  if (state.range(0) == 1) settle_back_faces_by_search(scene);
  const std::vector<MeshCaster> casters = prepare_mesh_casters(scene);
  RenderSettings settings;
  settings.width = settings.height = 400;
  HeadlessContext context(400, 400);
  RenderPlan plan = make_render_plan(scene, casters, settings);
  ShadowRenderer renderer(scene, plan, DrawSending::kWhole);
  const glm::dvec3 target = scene.camera.target;
  for (auto _ : state) {
    const glm::dvec3 arm = scene.camera.eye - target;
    const double turn = glm::radians(1.0);
    scene.camera.eye = target + glm::dvec3(arm.x * std::cos(turn) - arm.y * std::sin(turn),
                                           arm.x * std::sin(turn) + arm.y * std::cos(turn), arm.z);
    update_render_view(scene, plan);
    renderer.draw(false, [&] { update_render_lights(scene, casters, plan); });
    renderer.finish();
  }
}
BENCHMARK(BM_ViewFrameCameraOrbiting)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
}  // namespace umbra

BENCHMARK_MAIN();
