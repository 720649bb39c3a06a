#include "render/render_method.hpp"

#include <iterator>

namespace umbra {
const MethodRow& row_of(RenderMethod method) {
  for (const MethodRow& row : kMethods)
    if (row.method == method) return row;
  return kMethods[0];
}

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
