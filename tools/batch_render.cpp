#include "tools/batch_render.hpp"

#include <algorithm>
#include <cmath>
#include <csignal>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <optional>
#include <sstream>

#include <nlohmann/json.hpp>

#include "image/contact_sheet.hpp"
#include "image/image.hpp"
#include "image/partial_file.hpp"
#include "image/picture_file.hpp"
#include "mesh/input_error.hpp"
#include "mesh/io/mapped_file.hpp"
#include "render/headless_context.hpp"
#include "scene/scene_checks.hpp"
#include "scene/staged_scene.hpp"
#include "tools/command_line.hpp"
#include "tools/fault_injection.hpp"
#include "tools/isolated_runs.hpp"
#include "tools/picture_choices.hpp"
#include "tools/picture_drawing.hpp"
#include "tools/picture_names.hpp"
#include "tools/progress_bar.hpp"
#include "tools/view_set_files.hpp"

namespace umbra {
namespace {

constexpr int kSheetThumbWidth = 200;  // a contact sheet's tiles, in pixels

// What a run says of one input file: its line of --json, and its part of
// the summary. Every input gets one.
struct Record {
  std::string path, picture;
  std::string status;  // one of the statuses below
  double seconds = 0.0;
  size_t triangles = 0;  // drawn: the scene's triangles, meshes' and floor's
  std::string error;     // failed, timed out, crashed: why
  std::string kind;      // what kind of failure: input_problem_name's, or one of the kinds below; "" for none
  std::string messages;  // for stderr: warnings, then the error
};
const char* const kDrawn = "drawn";
const char* const kSkipped = "skipped";  // --skip-existing: its picture is newer than it
const char* const kFailed = "failed";
const char* const kTimedOut = "timed out";
const char* const kCrashed = "crashed";
const char* const kPassedOver = "passed over";
const char* const kStopped = "stopped";  // SIGINT, SIGTERM or SIGHUP came before it was drawn

// A failure's kind, for those who count them over a corpus: an input's
// problem (input_problem_name: malformed, unreadable, unsupported-format,
// empty, no-faces), or one of these.
const char* const kTimeoutKind = "timeout";
const char* const kCrashedKind = "crashed";
const char* const kOutOfMemoryKind = "out-of-memory";  // a failed allocation, or the kernel's OOM killer (SIGKILL)
const char* const kStoppedKind = "stopped";
const char* const kOtherKind = "other";  // the GL, or a picture that could not be written

// One line of JSON. Paths are bytes, JSON text is UTF-8: a byte that is no
// part of UTF-8 becomes U+FFFD (docs/rendering.md says so).
std::string json_line(const Record& r) {
  nlohmann::ordered_json line;
  line["path"] = r.path;
  // Only a file whose picture this run drew, or found up to date, names one:
  // any other's path would lead to no file, or to an older picture.
  const bool pictured = r.status == kDrawn || r.status == kSkipped;
  line["picture"] = pictured && !r.picture.empty() ? nlohmann::ordered_json(r.picture) : nlohmann::ordered_json();
  line["status"] = r.status;
  line["kind"] = r.kind.empty() ? nlohmann::ordered_json() : nlohmann::ordered_json(r.kind);
  line["seconds"] = std::round(r.seconds * 1000.0) / 1000.0;
  line["triangles"] = r.triangles;
  line["error"] = r.error.empty() ? nlohmann::ordered_json() : nlohmann::ordered_json(r.error);
  return line.dump(-1, ' ', false, nlohmann::ordered_json::error_handler_t::replace) + "\n";
}

// One file's picture, drawn in this process (a worker's: see render_job), in
// `context`, made on first use and kept for the worker's next file. Fills
// `record`'s status, triangles, error and messages.
void render_one(const std::string& path, const std::string& root, const std::string& out, const BatchRenderOptions& o,
                std::optional<HeadlessContext>& context, Record& record) {
  ReadOptions maps = o.reading;
  maps.root = root;
  try {
    if (o.views) {
      inject_fault(path);
      PictureChoices choices;
      choices.settings = o.settings, choices.staging = o.staging, choices.gl = o.gl, choices.antialias = o.antialias;
      choices.antialias_all = o.antialias_all, choices.show_volumes = o.show_volumes, choices.size_given = o.size_given;
      std::optional<WrittenViews> written;
      if (o.animation) {
        std::filesystem::create_directories(std::filesystem::path(out).parent_path());
        written = write_animation_file(path, out, choices, *o.views, *o.animation, maps, context, {}, record.messages);
      } else {
        written = write_view_files(path, std::filesystem::path(out).parent_path().string(), choices, *o.views, maps, context, {},
                                   record.messages);
      }
      record.status = kDrawn;
      record.triangles = written->triangles;
      return;
    }
    // The picture's temporary file first, as a single render makes its
    // outputs: a folder that cannot be written fails before the drawing.
    std::filesystem::create_directories(std::filesystem::path(out).parent_path());
    PartialFile picture(out, "the image");
    inject_fault(path);
    if (const std::optional<InputError> error = neither_scene_nor_mesh(path)) throw *error;
    Scene scene = parse_scene_or_mesh_file(path, {}, nullptr, staging_for(o.staging, o.settings), maps);
    for (const Warning& w : scene.warnings) record.messages += w.where.str() + ": warning: " + w.message + "\n";
    require_lights_off_casters(scene);
    require_caught_shadows_kept(scene, o.settings.method);
    RenderSettings settings = o.settings;
    set_picture_size(settings, o.size_given, scene);
    set_picture_samples(settings, o.antialias, o.antialias_all, o.show_volumes, scene);
    require_drawable_size(settings.width, settings.height, settings.frame_samples());
    PictureRequest request;
    request.show_volumes = o.show_volumes;
    const Image image = draw_picture(scene, settings, request, context, o.gl).image;
    write_picture_into(image, picture);
    picture.commit();
    record.status = kDrawn;
    record.triangles = scene.triangles.size();
    for (const Mesh& m : scene.meshes) record.triangles += m.triangles.size();
  } catch (const std::bad_alloc&) {
    record.status = kFailed;
    record.kind = kOutOfMemoryKind;
    record.error = path + ": not enough memory to render it";
  } catch (const InputError& e) {
    record.status = kFailed;
    record.kind = input_problem_name(e.problem());
    record.error = e.what();
  } catch (const std::exception& e) {
    record.status = kFailed;
    record.kind = kOtherKind;
    record.error = e.what();
  }
  if (!record.error.empty()) record.messages += record.error + "\n";
}

// A worker's job: renders one file, and hands back its record as the
// status, the triangles, the kind, the error (one line) and the messages.
std::string render_job(const std::string& path, const std::string& root, const std::string& out, const BatchRenderOptions& o,
                       std::optional<HeadlessContext>& context) {
  Record record;
  render_one(path, root, out, o, context, record);
  std::string error = record.error;
  std::replace(error.begin(), error.end(), '\n', ' ');
  return record.status + "\n" + std::to_string(record.triangles) + "\n" + record.kind + "\n" + error + "\n" + record.messages;
}

// The record a job handed back, or what ended it.
void read_job_result(const IsolatedResult& result, double timeout_s, Record& record) {
  record.seconds = result.seconds;
  if (const std::string ended = unfinished_phrase(result, timeout_s); !ended.empty()) {
    record.status = result.ending == IsolatedResult::Ending::kTimedOut ? kTimedOut : kCrashed;
    record.kind = result.ending == IsolatedResult::Ending::kTimedOut ? kTimeoutKind
                  : result.signal == SIGKILL                         ? kOutOfMemoryKind
                                                                     : kCrashedKind;
    record.error = record.path + ": " + ended;
    record.messages = record.error + "\n";
    return;
  }
  std::istringstream in(result.output);
  std::string triangles;
  if (!std::getline(in, record.status) || !std::getline(in, triangles) || !std::getline(in, record.kind) ||
      !std::getline(in, record.error)) {
    record.status = kCrashed;
    record.kind = kCrashedKind;
    record.error = record.path + ": the render ended without a result (exit status " + std::to_string(result.exit_status) + ")";
    record.messages = record.error + "\n";
    return;
  }
  record.triangles = std::stoull(triangles);
  record.messages.assign(std::istreambuf_iterator<char>(in), {});
}

// A model's first view, for the contact sheet: the picture its
// transforms.json names first, in the same folder.
std::string first_view_picture(const std::string& transforms) {
  const nlohmann::json json = nlohmann::json::parse(MappedFile(transforms).bytes());
  return (std::filesystem::path(transforms).parent_path() / json.at("frames").at(0).at("file_path").get<std::string>()).string();
}

// Whether `picture` is newer than `input` (--skip-existing).
bool up_to_date(const std::string& picture, const std::string& input) {
  std::error_code a, b;
  const auto drawn = std::filesystem::last_write_time(picture, a), changed = std::filesystem::last_write_time(input, b);
  return !a && !b && drawn >= changed;
}

}  // namespace

int run_batch_render(const BatchRenderOptions& o) {
  std::optional<MeshPaths> searched = found_mesh_paths(o.paths, "render");
  if (!searched) return 2;
  MeshPaths& found = *searched;
  // Said once for all the shards: by the first.
  if (o.shard && o.shard->index > 0) found.passed_over.clear(), found.unsupported.clear();
  for (const auto& [path, what] : found.passed_over) {
    std::cerr << "umbra render: passed over " << path << ": " << what << "\n";
    if (o.json) std::cout << json_line({path, "", kPassedOver, 0.0, 0, what, input_problem_name(InputProblem::kUnsupportedFormat), ""});
  }
  // Every file found has its record: those in no format umbra reads too, counted in one line.
  const size_t passed_over = found.passed_over.size() + found.unsupported.size();
  if (!found.unsupported.empty()) std::cerr << "umbra render: " << unsupported_summary(found.unsupported) << "\n";
  if (o.json)
    for (const std::string& path : found.unsupported)
      std::cout << json_line({path, "", kPassedOver, 0.0, 0, unsupported_reason(), input_problem_name(InputProblem::kUnsupportedFormat), ""});
  // Named for all the files, before the shards part: every shard names alike.
  const std::vector<std::string> all_names = distinct_picture_names(found.meshes, found.names, found.roots);
  // The sheet is written last: it must not take the place of an input or of
  // one of the run's own pictures (any shard's).
  if (o.sheet) {
    std::string refusal;
    for (size_t i = 0; i < found.meshes.size() && refusal.empty(); ++i) {
      if (same_file(*o.sheet, found.meshes[i])) refusal = "--sheet would overwrite its input \"" + found.meshes[i] + "\"";
      else if (o.views && same_file(std::filesystem::path(*o.sheet).parent_path().string(),
                                    (std::filesystem::path(o.out_dir) / all_names[i]).string()))
        refusal = "--sheet " + *o.sheet + " is in the folder of the views of \"" + found.meshes[i] + "\"";
      else if (same_file(*o.sheet, (std::filesystem::path(o.out_dir) / (all_names[i] + ".png")).string()))
        refusal = "--sheet " + *o.sheet + " is where the picture of \"" + found.meshes[i] + "\" goes";
    }
    if (!refusal.empty()) {
      std::cerr << "umbra render: " << refusal << "; name another file\n(see umbra render --help)\n";
      return 2;
    }
  }
  const std::vector<std::string> files = o.shard ? shard_of(found.meshes, *o.shard) : found.meshes;
  const std::vector<std::string> names = o.shard ? shard_of(all_names, *o.shard) : all_names;
  const std::vector<std::string> roots = o.shard ? shard_of(found.roots, *o.shard) : found.roots;
  const size_t count = files.size();
  std::vector<Record> records(count);
  for (size_t i = 0; i < count; ++i) {
    // A model's views stand for its picture by their transforms.json, written last; its animation is one file.
    const std::string output = o.animation ? names[i] + animation_row(o.animation->format).extension
                               : o.views   ? names[i] + "/transforms.json"
                                           : names[i] + ".png";
    records[i].path = files[i], records[i].picture = (std::filesystem::path(o.out_dir) / output).string();
  }
  const auto start = std::chrono::steady_clock::now();

  // Records are printed in file order, each as soon as it and those before
  // it are done, as umbra check prints its reports.
  std::vector<char> ended(count, 0);
  size_t finished = 0, printed = 0;
  ProgressBar progress(count);
  const auto end = [&](size_t i) {
    ended[i] = 1;
    progress.clear();
    std::cerr << records[i].messages << std::flush;
    for (; printed < count && ended[printed]; ++printed)
      if (o.json) std::cout << json_line(records[printed]) << std::flush;
    progress.update(++finished, files[i]);
  };
  std::vector<size_t> to_draw;
  for (size_t i = 0; i < count; ++i) {
    if (o.skip_existing && up_to_date(records[i].picture, files[i])) {
      records[i].status = kSkipped;
      end(i);
    } else {
      to_draw.push_back(i);
    }
  }
  // In worker processes: a file that hangs, crashes or runs out of memory
  // costs only its own picture. Each worker keeps its GL context (its own
  // copy of `context`) from one file to the next.
  std::optional<HeadlessContext> context;
  int stopped_by = 0;
  try {
    stopped_by = run_isolated(
        to_draw.size(), o.jobs, o.timeout_s,
        [&](size_t k) {
          const size_t i = to_draw[k];
          return render_job(files[i], roots[i], records[i].picture, o, context);
        },
        [&](size_t k, const IsolatedResult& result) {
          read_job_result(result, o.timeout_s, records[to_draw[k]]);
          // A worker killed while it wrote (a crash, or SIGKILL past a timeout's
          // grace: no handler ran) leaves its temporary file.
          if (result.ending != IsolatedResult::Ending::kFinished) {
            const std::string& out = records[to_draw[k]].picture;
            if (o.views && !o.animation) remove_abandoned_temporaries_in(std::filesystem::path(out).parent_path().string());
            else remove_abandoned_temporaries(out);
          }
          end(to_draw[k]);
        });
  } catch (const std::exception& e) {  // no process or pipe to be had: what was drawn stays
    progress.clear();
    std::cerr << "umbra render: " << e.what() << "\n";
    return 1;
  }
  progress.clear();
  if (stopped_by) {
    // The files not reached, recorded as such, so that --json counts every input.
    for (size_t i = 0; i < count; ++i)
      if (!ended[i]) {
        records[i].status = kStopped;
        records[i].kind = kStoppedKind;
        records[i].error = records[i].path + ": not drawn: umbra was stopped (" + signal_name(stopped_by) + ")";
        ended[i] = 1;
      }
    for (; printed < count; ++printed)
      if (o.json) std::cout << json_line(records[printed]) << std::flush;
  }

  size_t drawn = 0, skipped = 0, timed_out = 0, stopped = 0;
  for (const Record& r : records) {
    drawn += r.status == kDrawn;
    skipped += r.status == kSkipped;
    timed_out += r.status == kTimedOut;
    stopped += r.status == kStopped;
  }
  const size_t failed = count - drawn - skipped - stopped;
  bool sheet_failed = false;
  if (o.sheet && stopped_by) {
    std::cerr << "umbra render: no contact sheet: the run was stopped before every picture was drawn\n";
  } else if (o.sheet) {
    // This run's pictures (drawn, or up to date), read back in file order:
    // held one at a time while drawing, so that a folder of large pictures
    // fits in memory; never an older picture of a file that failed now,
    // whose tile says that it failed instead.
    std::vector<SheetPicture> sheet;
    for (size_t i = 0; i < count; ++i) {
      if (records[i].status != kDrawn && records[i].status != kSkipped) {
        sheet.push_back({names[i], Image(), records[i].status});
        continue;
      }
      try {
        sheet.push_back({names[i], thumbnail(read_png(o.views ? first_view_picture(records[i].picture) : records[i].picture),
                                             kSheetThumbWidth), ""});
      } catch (const std::exception& e) {
        std::cerr << e.what() << "\n";
      }
    }
    try {
      write_picture(contact_sheet(sheet, kSheetThumbWidth), *o.sheet);
      const size_t without = size_t(std::count_if(sheet.begin(), sheet.end(), [](const SheetPicture& p) { return p.picture.width == 0; }));
      std::cerr << "umbra render: wrote the contact sheet " << *o.sheet << " (" << sheet.size() - without << " pictures"
                << (without ? ", " + std::to_string(without) + " failed" : "") << ")\n";
    } catch (const std::exception& e) {
      std::cerr << e.what() << "\n";
      sheet_failed = true;
    }
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  char elapsed[32];
  std::snprintf(elapsed, sizeof elapsed, "%.1f s", seconds);
  std::cerr << "umbra render: " << count << (count == 1 ? " file" : " files")
            << (o.shard ? " (shard " + std::to_string(o.shard->index) + "/" + std::to_string(o.shard->count) + " of " +
                              std::to_string(found.meshes.size()) + ")"
                        : "")
            << " in " << elapsed << ": " << drawn
            << (o.animation ? (drawn == 1 ? " animation" : " animations")
                : o.views   ? (drawn == 1 ? " file's views" : " files' views")
                            : (drawn == 1 ? " picture" : " pictures"))
            << " in " << o.out_dir
            << (skipped ? ", " + std::to_string(skipped) + " up to date (--skip-existing)" : "") << ", " << failed << " failed"
            << (timed_out ? " (" + std::to_string(timed_out) + " timed out)" : "")
            << (passed_over ? "; " + std::to_string(passed_over) + (passed_over == 1 ? " file" : " files") + " passed over" : "")
            << "\n";
  if (stopped_by) {
    std::cerr << "umbra render: stopped (" << signal_name(stopped_by) << "): " << stopped << " of " << count
              << (count == 1 ? " file" : " files") << " not drawn; the same command with --skip-existing draws only those\n";
    return 128 + stopped_by;
  }
  return failed == 0 && !sheet_failed ? 0 : 1;
}

}  // namespace umbra
