#include "tools/check_command.hpp"

#include <algorithm>
#include <atomic>
#include <cctype>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <mutex>
#include <optional>
#include <sstream>
#include <thread>
#include <vector>

#include <tbb/global_control.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include "mesh/file_extension.hpp"
#include "mesh/input_error.hpp"
#include "mesh/check/mesh_check.hpp"
#include "mesh/io/mesh_file.hpp"
#include "mesh/io/mesh_format.hpp"
#include "image/partial_file.hpp"
#include "image/picture_file.hpp"
#include "mesh/check/mesh_repair.hpp"
#include "tools/isolated_runs.hpp"
#include "tools/check_report_page.hpp"
#include "scene/scene_text.hpp"
#include "tools/command_line.hpp"
#include "tools/defect_picture.hpp"
#include "tools/fault_injection.hpp"
#include "tools/mesh_paths.hpp"
#include "tools/picture_names.hpp"
#include "tools/standard_input.hpp"
#include "tools/progress_bar.hpp"

namespace umbra {

const std::string kCheckUsage =
    R"(usage: umbra check PATH... [--json] [--jobs N] [--shard K/N] [--time-limit SEC]
       umbra check MESH --repair OUT
       umbra check PATH... --repair OUTDIR
       umbra check - [options]   (a mesh on standard input)

Checks that each mesh (in any format umbra formats lists) is a closed,
consistently oriented 2-manifold without
self-intersections, which is what casting a shadow from silhouette edges
needs, and says exactly why not: border edges and holes, non-manifold
edges and vertices, duplicate and degenerate faces, faces to flip,
self-intersecting face pairs, with a few of each named by their index in
the file (counting from 0) and line. Exporters' quirks that are read anyway
(docs/check.md) come as warnings.

A PATH is a mesh file or a folder, searched recursively for mesh files (by
content, or by a format's extension: umbra formats), each folder's files in
sorted order. Reports come in the order of the list, each
as soon as it and those before it are done; with more than one mesh, a
summary line follows on stderr.

options:
{options}  --                    end of options: every argument after it is a PATH

exit status: 0 every mesh is a closed 2-manifold, its search for
self-intersections complete and finding none (a solid, with --solid); 1 one
is not (after the repair, with --repair); 2 one could not be read (every
other mesh is still reported), the repaired mesh or a defect picture could
not be written, or a usage error.
)";

namespace {

constexpr int kDefectPictureSize = 800;  // --picture's width and height, render's default
constexpr int kReportPictureSize = 320;  // --report's own pictures: a table's thumbnails

struct CheckCommandOptions {
  std::vector<std::string> meshes;  // as given: files and folders
  bool json = false;
  bool brief = false;
  bool solid = false;  // the exit status gates on is_solid, not is_closed_manifold
  size_t jobs = std::max(1u, std::thread::hardware_concurrency());
  std::optional<Shard> shard;
  std::optional<std::string> repair_output;
  std::optional<size_t> max_hole_edges;  // unset: kDefaultMaxHoleEdges
  std::optional<double> merge_tolerance;
  std::optional<std::string> picture;  // --picture: where the defect picture goes, or with several meshes the folder
  bool picture_folder = false;         // --picture names a folder: several meshes, a picture each
  std::optional<std::string> report;   // --report: the page to write
  bool no_pictures = false;            // --no-pictures: the report's rows without them
  bool repair_folder = false;          // --repair names a folder: several meshes, a repaired copy of each
  StageView view;                      // the pictures' camera (--camera-azimuth, ...)
  std::vector<std::string> view_given;  // those named
  CheckOptions check;
  ReadOptions reading = ReadOptions::skip();  // --cad-deflection, --cad-angle; no texture maps
  double timeout_s = 0.0;  // >0: meshes checked in worker processes, each stopped after this long
};

CheckCommandOptions parse_check_options(const std::vector<std::string>& argv) {
  CheckCommandOptions o;
  CommandOptions options;
  options.flag("--json", o.json, "one JSON object per mesh per line, JSON Lines (keys in docs/check.md)");
  options.flag("--brief", o.brief,
               "one line per mesh on stdout, its path, what it holds and its verdict (an unreadable one, its path and why), for grep "
               "and sort");
  options.flag("--solid", o.solid,
               "the exit status says whether every mesh is a solid, as a printer needs one (closed, manifold, oriented alike, facing "
               "outward, crossing no face of its own), not a closed 2-manifold: the report's \"solid\" line says why not");
  options.value("--jobs", {"N", "check N meshes at a time, using at most N threads in all (default: the number of cores)"},
                [&](const std::string& n, const std::string& t) { o.jobs = size_t(parse_int_in(n, t, 1, 4096)); });
  options.value("--shard",
                {"K/N", "check only part K (counting from 0) of N disjoint parts of the list: N machines with K = 0 ... N-1 check "
                        "it all, and their outputs, concatenated in order of K, are this command's output without --shard "
                        "(docs/batch-checks.md)"},
                [&](const std::string& n, const std::string& t) { o.shard = parse_shard(n, t); });
  options.value("--repair",
                {"OUT", "write a repaired copy to OUT, a {repair extensions} file: merge repeated vertices, drop degenerate and "
                        "duplicate faces, stitch borders, fill holes, orient consistently and outward, merge overlapping parts into "
                        "their union; then check OUT and say what changed and what is still wrong. Never writes MESH. An .obj keeps "
                        "the materials, texture coordinates, normals and colours, its library and maps beside it (STEM.mtl, "
                        "STEM.NAME); a .3mf keeps a 3MF's objects, build items, transforms, unit and colours; a .ply keeps the "
                        "colours. With several meshes or a folder, OUT is a folder: each mesh's copy goes where umbra render puts a "
                        "folder's pictures, in its own format (glTF and the rest as NAME.obj)"},
                [&](const std::string&, const std::string& t) { o.repair_output = t; });
  options.value("--max-hole-edges",
                {"N", "(with --repair) fill only holes of at most N edges (default " + std::to_string(kDefaultMaxHoleEdges) +
                          "; 0 fills none): a larger one is more often an opening the model means"},
                [&](const std::string& n, const std::string& t) { o.max_hole_edges = size_t(parse_int_in(n, t, 0, 1000000)); });
  options.value("--merge-tolerance",
                {"D", "(with --repair) merge points at most D apart (in the model's units) before anything else; by default only "
                      "equal ones are merged"},
                [&](const std::string& n, const std::string& t) {
                  o.merge_tolerance = parse_finite_number(n, t);
                  if (!(*o.merge_tolerance > 0.0)) throw UsageError(n + " must be a distance above 0, got \"" + t + "\"");
                });
  options.value("--picture",
                {"OUT.png", "also draw the mesh, staged as umbra render stages it, with its defects where they are: border edges "
                            "red, non-manifold edges blue, non-manifold vertices magenta, self-intersecting faces orange, faces to "
                            "flip teal (fainter where a surface hides them), and a legend with the counts; OUT's name says PNG or "
                            "JPEG. With several meshes or a folder, OUT is a folder, and each mesh's picture is named as umbra render "
                            "names a folder's (meshes are then checked one at a time)"},
                [&](const std::string&, const std::string& t) { o.picture = t; });
  options.value("--report",
                {"REPORT.html", "also write one web page of every mesh's report, a row each with its defect picture (--picture's, "
                                "or small ones drawn into REPORT-pictures/), verdict and measures, sortable by any column and "
                                "filtered by verdict; static, it opens from the disk with no server"},
                [&](const std::string&, const std::string& t) { o.report = t; });
  options.flag("--no-pictures", o.no_pictures,
               "(with --report) rows without pictures: thousands of meshes are checked in seconds, and drawn in minutes");
  options.paragraph(
      "With --picture or --report, the pictures' camera, as umbra render takes it: angles in degrees round the model's centre, "
      "azimuth 0 from its front; defects under a model show from below (--camera-elevation -30).");
  add_camera_orbit_options(options, o.view, o.view_given);
  options.paragraph("");
  options.value("--time-limit",
                {"SEC", "stop the search for self-intersections after SEC seconds per mesh and report that it stopped (default " +
                            number_text(o.check.self_intersection_seconds) +
                            "; 0 skips it). A mesh whose search was skipped or stopped is \"not known to be clean\": no closed "
                            "2-manifold, exit status 1"},
                [&](const std::string& n, const std::string& t) {
                  o.check.self_intersection_seconds = parse_finite_number(n, t);
                  if (o.check.self_intersection_seconds < 0.0) throw UsageError("--time-limit must not be negative");
                });
  options.value("--timeout",
                {"SEC", "check the meshes in worker processes and stop one after SEC seconds: a mesh that hangs, crashes or runs out "
                        "of memory is reported as unreadable (exit status 2), and the rest go on"},
                [&](const std::string& n, const std::string& t) {
                  o.timeout_s = parse_finite_number(n, t);
                  if (!(o.timeout_s > 0.0)) throw UsageError(n + " must be a number of seconds above 0, got \"" + t + "\"");
                });
  add_reading_options(options, o.reading, false);
  options.help_option();
  options.positionals(o.meshes);
  options.parse(argv);
  if (o.meshes.empty()) throw UsageError("no mesh file given");
  if (o.json && o.brief) throw UsageError("--json and --brief are two forms of the same report: give one");
  if (o.max_hole_edges && !o.repair_output) throw UsageError("--max-hole-edges says which holes --repair fills: give --repair OUT");
  if (o.merge_tolerance && !o.repair_output) throw UsageError("--merge-tolerance says which points --repair merges: give --repair OUT");
  if (o.report) {
    if (o.repair_output) throw UsageError("--report shows what the check finds; check the repaired file for its report");
    const std::string extension = lowercase_extension(*o.report);
    if (extension != ".html" && extension != ".htm") throw UsageError("--report writes a web page: name a .html file, got \"" + *o.report + "\"");
    for (const std::string& mesh : o.meshes) require_other_than_input("--report", *o.report, mesh);
    if (o.no_pictures && o.picture) throw UsageError("--no-pictures leaves out the pictures --picture asks for: give one");
  }
  if (o.no_pictures && !o.report) throw UsageError("--no-pictures is for --report's rows: give --report REPORT.html");
  if (!o.view_given.empty() && ((!o.picture && !o.report) || o.no_pictures))
    throw UsageError(o.view_given.front() + " places the defect pictures' camera: give --picture or --report");
  if (o.picture) {
    if (o.repair_output) throw UsageError("--picture draws the mesh as it is; check the repaired file for its picture");
    const std::string& p = *o.picture;
    std::error_code ec;
    o.picture_folder = o.meshes.size() != 1 || std::filesystem::is_directory(o.meshes[0], ec);
    if (o.picture_folder) {
      if (std::filesystem::exists(p, ec) && !std::filesystem::is_directory(p, ec))
        throw UsageError("--picture " + p + " is a file; several meshes make a picture each, in a folder: name a folder");
      if (!std::filesystem::exists(p, ec) && p.back() != '/' && picture_format_of(p))
        throw UsageError("--picture " + p + " names a picture, but several meshes make a picture each, in a folder: name a "
                         "folder (\"" + p + "/\" makes one of that name)");
    } else {
      require_picture_name("--picture", p);
      if (p == "-") throw UsageError("--picture needs a file: standard output holds the report");
      require_other_than_input("--picture", p, o.meshes[0]);
    }
  }
  if (o.repair_output && (o.meshes.size() != 1 || std::filesystem::is_directory(o.meshes[0]))) {
    // Several meshes or a folder: a repaired copy of each, in a folder.
    const std::string& out = *o.repair_output;
    std::error_code ec;
    if (std::filesystem::exists(out, ec) && !std::filesystem::is_directory(out, ec))
      throw UsageError("--repair " + out + " is a file; several meshes are repaired each into a folder: name a folder");
    if (!std::filesystem::exists(out, ec) && out.back() != '/' && repair_can_write(out))
      throw UsageError("--repair " + out + " names a mesh file, but several meshes are repaired each into a folder: name a "
                       "folder (\"" + out + "/\" makes one of that name)");
    for (const std::string& mesh : o.meshes)
      if (mesh == "-") throw UsageError("- (standard input) is one mesh: repair it on its own");
    o.repair_folder = true;
  }
  if (o.repair_output && !o.repair_folder) {
    if (o.shard) throw UsageError("--repair checks one mesh: --shard does not apply");
    if (o.timeout_s > 0.0) throw UsageError("--repair checks one mesh: --timeout does not apply");
    if (!repair_can_write(*o.repair_output))
      throw UsageError("--repair needs an output ending in " + mesh_format_extensions(true) + ", got \"" + *o.repair_output + "\"");
    require_other_than_input("--repair", *o.repair_output, o.meshes[0]);
    const std::filesystem::path folder = std::filesystem::path(*o.repair_output).parent_path();
    std::error_code ec;
    if (!folder.empty() && !std::filesystem::is_directory(folder, ec))
      throw UsageError("--repair " + *o.repair_output + ": there is no folder \"" + folder.string() + "\" to write it in");
  }
  return o;
}

// One mesh's outcome: what to print, its exit status, and for --report its
// line of JSON (the report's, or the error's).
struct CheckOutcome {
  std::string out, err;
  int status = 0;
  std::string record;
  bool picture_failed = false;  // the check stands; the exit status says 2
  // What the report says, which the summary counts as the JSON and the page
  // do (the status follows --solid); all false for a mesh not checked.
  bool checked = false, closed_manifold = false, solid = false;
};

// A mesh that could not be checked: said on stderr, and still its line of
// JSON (every mesh gets one).
CheckOutcome unchecked(const std::string& path, const std::string& message, const CheckCommandOptions& options) {
  const std::string record = options.report ? json_error_line(path, message) : "";
  if (options.brief) return {message + "\n", "", 2, record, false};  // its line in the list, which starts with its path
  return {options.json ? json_error_line(path, message) : "", message + "\n", 2, record, false};
}

// The report in the form the options ask for.
void print_report(const MeshReport& report, const CheckCommandOptions& options, std::ostream& out) {
  if (options.json) report.print_json(out);
  else if (options.brief) report.print_brief(out, options.solid);
  else report.print_text(out);
}

// `soup`'s defect picture (DefectPicture), from its report made with every
// defect listed, written to `output`.
void write_defect_picture(const std::string& path, const PolygonSoup& soup, const MeshReport& report, const std::string& output,
                          int size, const StageView& view) {
  const DefectPicture picture(soup, report, up_axis_of_file(path), size, size, view);
  const Image image = picture.draw(gl_with_environment(HeadlessGl::kAuto));
  if (const std::filesystem::path folder = std::filesystem::path(output).parent_path(); !folder.empty())
    std::filesystem::create_directories(folder);
  write_picture(image, output);
}

// One mesh's check, and with `picture` its defect picture there too.
CheckOutcome check_one(const std::string& path, const CheckCommandOptions& options, const std::string& picture = "") {
  try {
    inject_fault(path);
    PolygonSoup soup = read_polygon_soup(path, options.reading);
    CheckOptions check = options.check;
    if (!picture.empty()) check.max_examples = SIZE_MAX;  // every defect drawn; the report prints a few
    const MeshReport report = picture.empty() ? check_mesh(std::move(soup), check) : check_mesh(soup, check);
    std::ostringstream out;
    print_report(report, options, out);
    CheckOutcome outcome{out.str(), "", (options.solid ? report.is_solid() : report.is_closed_manifold()) ? 0 : 1, "", false,
                         true, report.is_closed_manifold(), report.is_solid()};
    if (options.report) {
      std::ostringstream line;
      report.print_json(line);
      outcome.record = line.str();
    }
    if (picture.empty()) return outcome;
    try {
      write_defect_picture(path, soup, report, picture, options.picture ? kDefectPictureSize : kReportPictureSize, options.view);
      if (options.picture && !options.picture_folder) outcome.err = "umbra check: drew the defects of " + path + " to " + picture + "\n";
    } catch (const std::exception& e) {
      outcome.err = path + ": no defect picture: " + e.what() + "\n";
      outcome.picture_failed = true;
    }
    return outcome;
  } catch (const InputError& e) {
    return unchecked(path, e.what(), options);
  } catch (const std::bad_alloc&) {
    return unchecked(path, path + ": not enough memory to check this mesh", options);
  } catch (const std::exception& e) {
    return unchecked(path, path + ": the check failed: " + e.what(), options);
  }
}

// check_one in a worker process (--timeout): its outcome as the status,
// the lengths of its output and its record, whether its picture failed and
// its report's two verdicts, then the output, the record and its messages.
std::string check_job(const std::string& path, const CheckCommandOptions& options, const std::string& picture) {
  const CheckOutcome o = check_one(path, options, picture);
  return std::to_string(o.status) + "\n" + std::to_string(o.out.size()) + "\n" + std::to_string(o.record.size()) + "\n" +
         (o.picture_failed ? "1" : "0") + (o.checked ? "1" : "0") + (o.closed_manifold ? "1" : "0") + (o.solid ? "1" : "0") + "\n" +
         o.out + o.record + o.err;
}

CheckOutcome read_check_job(const std::string& path, const IsolatedResult& result, const CheckCommandOptions& options) {
  if (const std::string ended = unfinished_phrase(result, options.timeout_s); !ended.empty())
    return unchecked(path, path + ": " + ended, options);
  std::istringstream in(result.output);
  std::string status, length, record_length, flags;
  if (!std::getline(in, status) || !std::getline(in, length) || !std::getline(in, record_length) || !std::getline(in, flags) ||
      flags.size() != 4)
    return unchecked(path, path + ": the check ended without a result (exit status " + std::to_string(result.exit_status) + ")", options);
  const size_t out_size = std::min(size_t(std::stoull(length)), result.output.size());
  const size_t record_size = std::stoull(record_length);
  const std::string rest(std::istreambuf_iterator<char>(in), {});
  return {rest.substr(0, out_size), rest.substr(std::min(out_size + record_size, rest.size())), std::stoi(status),
          rest.substr(std::min(out_size, rest.size()), record_size), flags[0] == '1', flags[1] == '1', flags[2] == '1', flags[3] == '1'};
}

// Whether the repair may put a companion file (an OBJ's material library,
// a map) at `path`: not over a file it reads, and not over a material
// library umbra did not write, which another OBJ beside it may name.
void require_companion_may_replace(const CompanionFile& companion, const std::string& input, const PolygonSoup& soup) {
  std::error_code ec;
  if (!std::filesystem::exists(companion.path, ec)) return;
  std::vector<std::string> read = {input};
  for (const SoupMaterial& m : soup.materials)
    if (m.texture && !m.texture->file.empty()) read.push_back(m.texture->file);
  for (const std::string& file : read)
    if (std::filesystem::equivalent(companion.path, file, ec))
      throw InputError({companion.path, 0, 0}, "the repair would overwrite this file, which the mesh reads, with " + companion.what +
                                                    ": name the output otherwise");
  std::ifstream existing(companion.path, std::ios::binary);
  if (companion.path.size() > 4 && companion.path.substr(companion.path.size() - 4) == ".mtl") {
    std::string first_line;
    std::getline(existing, first_line);
    if (first_line.find("written by umbra check --repair") == std::string::npos)
      throw InputError({companion.path, 0, 0},
                       "the repair would overwrite this material library, which umbra did not write: name the output otherwise");
    return;
  }
  // A map's copy: a file of the same bytes (an earlier repair's copy) is
  // left as it is in effect; any other file is somebody's.
  const std::string bytes(std::istreambuf_iterator<char>(existing), {});
  if (bytes != companion.bytes)
    throw InputError({companion.path, 0, 0}, "the repair would overwrite this file, which is not " + companion.what +
                                                  ", with a copy of it: name the output otherwise");
}

int repair_one(const std::string& path, const std::string& output, const CheckCommandOptions& options) {
  try {
    // Read with its maps, which an OBJ's material library names again; what
    // the reader passed over (a map it could not read) is said, as render says it.
    ReadOptions with_maps = options.reading;
    with_maps.read = true;
    const PolygonSoup soup = read_polygon_soup(path, with_maps);
    for (const ReadWarning& w : soup.warnings) std::cerr << FileLoc{path, w.line, 0}.str() << ": warning: " << w.message << "\n";
    PartialFile partial(output, "the repaired mesh", PartialFile::Ending::kKeepExtension);
    const RepairSummary summary = repair_mesh(
        soup, output, partial.temporary_path(),
        RepairOptions{options.max_hole_edges.value_or(kDefaultMaxHoleEdges), options.merge_tolerance.value_or(0.0)});
    std::vector<std::unique_ptr<PartialFile>> companions;
    for (const CompanionFile& companion : summary.companions) {
      require_companion_may_replace(companion, path, soup);
      companions.push_back(std::make_unique<PartialFile>(companion.path, companion.what));
      std::ofstream out(companions.back()->temporary_path(), std::ios::binary);
      if (!out.write(companion.bytes.data(), std::streamsize(companion.bytes.size())) || (out.close(), !out))
        throw InputError({companion.path, 0, 0}, "cannot write " + companion.what);
    }
    for (const auto& companion : companions) companion->commit();
    partial.commit();
    const MeshReport after = check_mesh(read_polygon_soup(output, ReadOptions::skip()), options.check);
    if (options.json || options.brief) {
      print_report(after, options, std::cout);
    } else {
      std::cout << "repaired " << path << " into " << output << ":\n";
      for (const std::string& change : summary.changes) std::cout << "  " << change << "\n";
      if (summary.changes.empty()) std::cout << "  nothing to change\n";
      after.print_text(std::cout);
    }
    return (options.solid ? after.is_solid() : after.is_closed_manifold()) ? 0 : 1;
  } catch (const InputError& e) {
    std::cerr << e.what() << "\n";
    return 2;
  } catch (const std::exception& e) {
    std::cerr << path << ": repair failed: " << e.what() << "\n";
    return 1;
  }
}

// `umbra check PATH... --repair OUTDIR`: each mesh found repaired into
// OUTDIR, named as a folder render names its pictures (its path in the
// folder, files that would clash told apart), in its own format where the
// repair writes it and as OBJ beside that name where it does not (x.glb to
// x.glb.obj); then the count of each outcome.
int repair_each(const std::string& out_dir, const CheckCommandOptions& options) {
  const std::optional<MeshPaths> searched = found_mesh_paths(options.meshes, "check");
  if (!searched) return 2;
  const MeshPaths& found = *searched;
  for (const auto& [path, what] : found.passed_over) std::cerr << "umbra check: passed over " << path << ": " << what << "\n";
  if (!found.unsupported.empty()) std::cerr << "umbra check: " << unsupported_summary(found.unsupported) << "\n";
  const std::vector<std::string> names = distinct_picture_names(found.meshes, found.names, found.roots);
  std::vector<std::string> outputs;
  for (size_t i = 0; i < found.meshes.size(); ++i) {
    outputs.push_back((std::filesystem::path(out_dir) / names[i]).string());
    if (!repair_can_write(outputs.back())) outputs.back() += ".obj";
    if (same_file(outputs.back(), found.meshes[i])) {  // OUTDIR is the folder it reads: said before any work
      std::cerr << "umbra check: --repair would overwrite its input \"" << found.meshes[i] << "\"; name another folder\n"
                << "(see umbra check --help)\n";
      return 2;
    }
  }
  int status = 0;
  size_t closed = 0, open = 0, failed = 0;
  for (size_t i = 0; i < found.meshes.size(); ++i) {
    const std::string& output = outputs[i];
    std::error_code ec;
    std::filesystem::create_directories(std::filesystem::path(output).parent_path(), ec);
    const int one = repair_one(found.meshes[i], output, options);
    (one == 0 ? closed : one == 1 ? open : failed) += 1;
    status = std::max(status, one);
  }
  std::cerr << "umbra check: repaired " << found.meshes.size() << (found.meshes.size() == 1 ? " mesh" : " meshes") << " into "
            << out_dir << ": " << closed
            << (options.solid ? (closed == 1 ? " solid, " : " solids, ") : (closed == 1 ? " closed 2-manifold, " : " closed 2-manifolds, "))
            << open << " not, " << failed << " failed\n";
  return status;
}

}  // namespace

int run_check_command(const std::vector<std::string>& argv) {
  CheckCommandOptions options;
  if (const auto exit_status = parse_command_line("check", kCheckUsage, argv, parse_check_options, options))
    return *exit_status;
  // "-", alone: the mesh on standard input, copied to a file for the readers.
  std::optional<StandardInputFile> input;
  try {
    if (options.meshes.size() > 1 && std::count(options.meshes.begin(), options.meshes.end(), "-"))
      throw UsageError("- (standard input) is one mesh: check it on its own");
    if (options.meshes[0] == "-") input.emplace("-"), options.meshes[0] = input->path();
  } catch (const UsageError& e) {
    std::cerr << "umbra check: " << e.what() << "\n(see umbra check --help)\n";
    return 2;
  } catch (const std::exception& e) {
    std::cerr << e.what() << "\n";
    return 2;
  }
  if (options.repair_output && !options.repair_folder) return repair_one(options.meshes[0], *options.repair_output, options);
  if (options.repair_output) return repair_each(*options.repair_output, options);

  std::optional<MeshPaths> searched = found_mesh_paths(options.meshes, "check");
  if (!searched) return 2;
  MeshPaths& found = *searched;
  const std::vector<std::string>& all = found.meshes;
  // Said once for all the shards: by the first.
  if (options.shard && options.shard->index > 0) found.passed_over.clear(), found.unsupported.clear();
  for (const auto& [path, what] : found.passed_over) std::cerr << "umbra check: passed over " << path << ": " << what << "\n";
  // Every file found has its record: those in no format umbra reads too, counted in one line.
  if (!found.unsupported.empty()) std::cerr << "umbra check: " << unsupported_summary(found.unsupported) << "\n";
  if (options.json)
    for (const std::string& path : found.unsupported)
      std::cout << json_passed_over_line(path, unsupported_reason(), input_problem_name(InputProblem::kUnsupportedFormat));
  const std::vector<std::string> meshes = options.shard ? shard_of(all, *options.shard) : all;
  // Each mesh's defect picture, if asked: named as umbra render names a
  // folder's pictures, for all the meshes before the shards part.
  // --report without --picture: small ones beside the page, in REPORT-pictures/.
  std::vector<std::string> pictures(meshes.size());
  if (options.picture && !options.picture_folder) pictures[0] = *options.picture;
  const std::optional<std::string> picture_folder =
      options.picture_folder ? options.picture
      : options.report && !options.picture && !options.no_pictures
          ? std::optional<std::string>((std::filesystem::path(*options.report).replace_extension().string() + "-pictures"))
          : std::nullopt;
  if (picture_folder) {
    const std::vector<std::string> names = distinct_picture_names(found.meshes, found.names, found.roots);
    const std::vector<std::string> ours = options.shard ? shard_of(names, *options.shard) : names;
    for (size_t i = 0; i < meshes.size(); ++i) pictures[i] = (std::filesystem::path(*picture_folder) / (ours[i] + ".png")).string();
  }
  std::vector<std::string> records;  // --report's, in file order
  const auto start = std::chrono::steady_clock::now();

  // Workers take meshes in order; reports are printed in order, each as soon
  // as it and those before it are done, by whichever worker finishes the
  // last of them.
  const size_t count = meshes.size();
  std::vector<std::optional<CheckOutcome>> outcomes(count);
  std::atomic<size_t> next{0};
  std::mutex print_mutex;
  size_t finished = 0, printed = 0, closed = 0, open = 0, unreadable = 0, solids = 0;
  int status = 0;
  ProgressBar progress(count);
  const auto print_ready = [&] {  // under print_mutex
    for (; printed < count && outcomes[printed]; ++printed) {
      const CheckOutcome& outcome = *outcomes[printed];
      progress.clear();
      std::cout << outcome.out << std::flush;
      std::cerr << outcome.err << std::flush;
      if (options.report) records.push_back(outcome.record);
      status = std::max({status, outcome.status, outcome.picture_failed ? 2 : 0});
      (!outcome.checked ? unreadable : outcome.closed_manifold ? closed : open) += 1;
      solids += outcome.solid;
      outcomes[printed].reset();
    }
    if (printed < count) progress.update(finished, meshes[printed]);
  };
  if (options.timeout_s > 0.0) {
    // In worker processes: a mesh that hangs, crashes or runs out
    // of memory costs only its own report.
    try {
      const int stopped_by = run_isolated(
          count, options.jobs, options.timeout_s, [&](size_t i) { return check_job(meshes[i], options, pictures[i]); },
          [&](size_t i, const IsolatedResult& result) {
            outcomes[i] = read_check_job(meshes[i], result, options);
            ++finished;
            print_ready();
          });
      if (stopped_by) {  // no report page: it would hold only some of the meshes
        progress.clear();
        std::cerr << "umbra check: stopped (" << signal_name(stopped_by) << "): " << printed << " of " << count
                  << (count == 1 ? " mesh" : " meshes") << " reported, in file order\n";
        return 128 + stopped_by;
      }
    } catch (const std::exception& e) {  // no process or pipe to be had: what was reported stays
      progress.clear();
      std::cerr << "umbra check: " << e.what() << "\n";
      return 2;
    }
  } else {
    // --jobs bounds the threads of the whole process: this one and TBB's
    // workers, which check meshes and run the searches inside them alike.
    const tbb::global_control threads(tbb::global_control::max_allowed_parallelism, options.jobs);
    // Defect pictures are drawn on this thread alone, a mesh at a time (each
    // check still searches on every core): Mesa's EGL, whose contexts TBB's
    // workers had made, freed their threads' state twice as the process
    // ended (glibc's "double free", 5 runs in 6 with two workers).
    const bool draws = std::any_of(pictures.begin(), pictures.end(), [](const std::string& p) { return !p.empty(); });
    if (draws) {
      for (size_t i = 0; i < count; ++i) {
        outcomes[i] = check_one(meshes[i], options, pictures[i]);
        ++finished;
        print_ready();
      }
    }
    tbb::task_arena arena(int(options.jobs));
    if (!draws) arena.execute([&] {
      tbb::parallel_for(size_t(0), std::min(count, options.jobs), [&](size_t) {
        for (size_t i = next++; i < count; i = next++) {
          // Isolated: while a check waits for its own parallel work, its thread
          // takes no other mesh, which would hold back this mesh's report.
          CheckOutcome outcome = tbb::this_task_arena::isolate([&] { return check_one(meshes[i], options, pictures[i]); });
          const std::lock_guard<std::mutex> lock(print_mutex);
          outcomes[i] = std::move(outcome);
          ++finished;
          print_ready();
        }
      });
    });
  }
  if (options.report) {
    try {
      write_check_report_page(*options.report, meshes, records, pictures);
      std::cerr << "umbra check: wrote the report of " << count << (count == 1 ? " mesh" : " meshes") << " to " << *options.report << "\n";
    } catch (const std::exception& e) {
      std::cerr << "umbra check: " << e.what() << "\n";
      status = 2;
    }
  }
  const size_t passed_over = found.passed_over.size() + found.unsupported.size();
  if (count > 1 || all.size() != options.meshes.size() || options.shard || passed_over > 0) {
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    char elapsed[32];
    std::snprintf(elapsed, sizeof elapsed, "%.1f s", seconds);
    std::cerr << "umbra check: " << count << (count == 1 ? " mesh" : " meshes")
              << (options.shard ? " (shard " + std::to_string(options.shard->index) + "/" + std::to_string(options.shard->count) + " of " + std::to_string(all.size()) + ")" : "")
              << " in " << elapsed << ": " << closed << " closed 2-manifold" << (closed == 1 ? "" : "s") << ", " << open
              << " not, " << unreadable << " unreadable"
              << (options.solid ? "; " + std::to_string(solids) + (solids == 1 ? " solid" : " solids") : std::string())
              << (passed_over == 0 ? std::string() : "; " + std::to_string(passed_over) + (passed_over == 1 ? " file" : " files") + " passed over")
              << "\n";
  }
  return status;
}

}  // namespace umbra
