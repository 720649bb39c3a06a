// Google Benchmark: the ray-cast reference's mask for every light (an eye ray
// per pixel, a shadow ray per light), searched by brute force and through
// Embree's hierarchy, on scenes of growing size. Both give the same answers
// (tests/render/ray_caster_test.cpp); this measures what the hierarchy saves.
//
//   build/bench/reference_benchmark [--benchmark_repetitions=5 --benchmark_report_aggregates_only=true]
#include <benchmark/benchmark.h>

#include <cmath>
#include <sstream>
#include <string>

#include "scene/scene_parser.hpp"
#include "scene/camera.hpp"
#include "reference/ray_caster.hpp"

namespace umbra {
namespace {

constexpr int kSize = 128;  // pixels a side

// The scenes' floor under k x k small spheres: 2 + k^2 primitives.
Scene sphere_grid(int k) {
  std::ostringstream text;
  text << "light 0.3 0.4 2\ntriangle -1 -1 -1  1 -1 -1  1 1 -1\ntriangle -1 -1 -1  1 1 -1  -1 1 -1\n";
  for (int i = 0; i < k; ++i)
    for (int j = 0; j < k; ++j)
      text << "sphere " << -0.9 + 1.8 * (i + 0.5) / k << " " << -0.9 + 1.8 * (j + 0.5) / k << " 0 " << 0.4 / k << "\n";
  return parse_scene_text(text.str(), "grid.scene");
}

void reference_masks(benchmark::State& state, RayCaster::Search search) {
  const Scene scene = sphere_grid(int(state.range(0)));
  const RayCaster caster(scene, search);
  for (auto _ : state) {
    int lit = 0;
    for (int y = 0; y < kSize; ++y)
      for (int x = 0; x < kSize; ++x) {
        const auto hit = caster.nearest_hit(scene.camera.pixel_ray(kSize, kSize, x, y));
        if (hit) lit += !caster.shadow_ray_blocked(hit->point, hit->object, scene.lights[0].position);
      }
    benchmark::DoNotOptimize(lit);
  }
  state.counters["primitives"] = double(2 + state.range(0) * state.range(0));
}

void BM_ReferenceBruteForce(benchmark::State& state) { reference_masks(state, RayCaster::Search::kBruteForce); }
void BM_ReferenceHierarchy(benchmark::State& state) { reference_masks(state, RayCaster::Search::kHierarchy); }

// 4, 64, 256 and 1024 spheres.
BENCHMARK(BM_ReferenceBruteForce)->Arg(2)->Arg(8)->Arg(16)->Arg(32)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_ReferenceHierarchy)->Arg(2)->Arg(8)->Arg(16)->Arg(32)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace umbra

BENCHMARK_MAIN();
