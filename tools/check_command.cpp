#include "tools/check_command.hpp"

#include <algorithm>
#include <atomic>
#include <filesystem>
#include <future>
#include <iostream>
#include <optional>
#include <sstream>
#include <thread>

#include "mesh/input_error.hpp"
#include "mesh/mesh_check.hpp"
#include "mesh/mesh_file.hpp"
#include "mesh/mesh_repair.hpp"
#include "tools/command_line.hpp"

namespace umbra {

const char* const kCheckUsage =
    R"(usage: umbra check MESH... [--json] [--repair OUT] [--time-limit SEC]

Checks that each mesh (OBJ, OFF, PLY or STL) is a closed, consistently
oriented 2-manifold without self-intersections, which is what casting a
shadow from silhouette edges needs, and says exactly why not: border edges
and holes, non-manifold edges and vertices, duplicate and degenerate faces,
faces to flip, self-intersecting face pairs, with a few of each named by
their index in the file (counting from 0) and line. Several meshes are
checked in parallel.

options:
  --json            one JSON object per mesh per line (keys in docs/check.md)
  --repair OUT      (one MESH only) write a repaired copy to OUT (OBJ, OFF,
                    PLY or STL by its extension): merge repeated vertices,
                    drop degenerate and duplicate faces, stitch borders,
                    orient consistently and outward; then check OUT and say
                    what changed and what is still wrong. Never writes MESH.
  --time-limit SEC  stop the search for self-intersections after SEC seconds
                    per mesh and report that it stopped (default 60; 0 skips)
  -h, --help        show this help

exit status: 0 every mesh is a closed 2-manifold, 1 one is not (after the
repair, with --repair), 2 one could not be read, the repaired mesh could not
be written, or a usage error.
)";

namespace {

struct CheckCommandOptions {
  std::vector<std::string> meshes;
  bool json = false;
  std::optional<std::string> repair_output;
  CheckOptions check;
  bool help = false;
};

CheckCommandOptions parse_check_options(const std::vector<std::string>& argv) {
  CheckCommandOptions o;
  Arguments args(argv);
  while (!args.done()) {
    const std::string a = args.take();
    if (a == "-h" || a == "--help") o.help = true;
    else if (a == "--json") o.json = true;
    else if (a == "--repair") o.repair_output = args.value_of(a);
    else if (a == "--time-limit") {
      o.check.self_intersection_seconds = parse_finite_number(a, args.value_of(a));
      if (o.check.self_intersection_seconds < 0.0) throw UsageError("--time-limit must not be negative");
    } else if (a.size() > 1 && a[0] == '-') throw UsageError("unknown option " + a);
    else o.meshes.push_back(a);
  }
  if (o.help) return o;
  if (o.meshes.empty()) throw UsageError("no mesh file given");
  if (o.repair_output) {
    if (o.meshes.size() != 1) throw UsageError("--repair takes one mesh at a time");
    if (mesh_format_of(*o.repair_output).empty())
      throw UsageError("--repair needs an output ending in .obj, .off, .ply or .stl, got \"" + *o.repair_output + "\"");
    std::error_code ec;
    if (*o.repair_output == o.meshes[0] || std::filesystem::equivalent(*o.repair_output, o.meshes[0], ec))
      throw UsageError("--repair would overwrite its input \"" + o.meshes[0] + "\"; name another file");
  }
  return o;
}

// One mesh's outcome: what to print, and its exit status.
struct CheckOutcome {
  std::string out, err;
  int status = 0;
};

CheckOutcome check_one(const std::string& path, const CheckCommandOptions& options) {
  CheckOutcome outcome;
  std::ostringstream out, err;
  try {
    const MeshReport report = check_mesh(read_polygon_soup(path), options.check);
    options.json ? report.print_json(out) : report.print_text(out);
    outcome.status = report.is_closed_manifold() ? 0 : 1;
  } catch (const InputError& e) {
    err << e.what() << "\n";
    if (options.json) out << "{\"path\":" << json_string(path) << ",\"error\":" << json_string(e.what()) << "}\n";
    outcome.status = 2;
  } catch (const std::bad_alloc&) {
    err << path << ": not enough memory to check this mesh\n";
    outcome.status = 2;
  } catch (const std::exception& e) {
    err << path << ": the check failed: " << e.what() << "\n";
    outcome.status = 2;
  }
  outcome.out = out.str();
  outcome.err = err.str();
  return outcome;
}

int repair_one(const std::string& path, const std::string& output, const CheckCommandOptions& options) {
  try {
    const PolygonSoup soup = read_polygon_soup(path);
    const RepairSummary summary = repair_mesh(soup, output);
    const MeshReport after = check_mesh(read_polygon_soup(output), options.check);
    if (options.json) {
      after.print_json(std::cout);
    } else {
      std::cout << "repaired " << path << " into " << output << ":\n";
      for (const std::string& change : summary.changes) std::cout << "  " << change << "\n";
      if (summary.changes.empty()) std::cout << "  nothing to change\n";
      after.print_text(std::cout);
    }
    return after.is_closed_manifold() ? 0 : 1;
  } catch (const InputError& e) {
    std::cerr << e.what() << "\n";
    return 2;
  } catch (const std::exception& e) {
    std::cerr << path << ": repair failed: " << e.what() << "\n";
    return 1;
  }
}

}  // namespace

int run_check_command(const std::vector<std::string>& argv) {
  CheckCommandOptions options;
  if (const auto exit_status = parse_command_line("check", kCheckUsage, argv, parse_check_options, options))
    return *exit_status;
  if (options.repair_output) return repair_one(options.meshes[0], *options.repair_output, options);

  // Workers take meshes in order; results are printed in order as they finish.
  const size_t count = options.meshes.size();
  std::vector<std::promise<CheckOutcome>> promises(count);
  std::vector<std::future<CheckOutcome>> results;
  for (auto& p : promises) results.push_back(p.get_future());
  std::atomic<size_t> next{0};
  const size_t worker_count = std::min<size_t>(count, std::max(1u, std::thread::hardware_concurrency()));
  std::vector<std::thread> workers;
  for (size_t w = 0; w < worker_count; ++w) {
    workers.emplace_back([&] {
      for (size_t i = next++; i < count; i = next++) promises[i].set_value(check_one(options.meshes[i], options));
    });
  }
  int status = 0;
  for (auto& result : results) {
    const CheckOutcome outcome = result.get();
    std::cout << outcome.out << std::flush;
    std::cerr << outcome.err << std::flush;
    status = std::max(status, outcome.status);
  }
  for (std::thread& t : workers) t.join();
  return status;
}

}  // namespace umbra
