#include "tools/bench_report.hpp"

#include <fcntl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <map>
#include <sstream>
#include <stdexcept>

#include "image/partial_file.hpp"

namespace umbra {
namespace {

std::string fixed(double v, int digits) {
  std::ostringstream s;
  s << std::fixed << std::setprecision(digits) << v;
  return s.str();
}

// The scenes and, per scene, the methods, in the order first met.
std::vector<std::string> in_order(const std::vector<BenchRow>& rows, const std::string* scene) {
  std::vector<std::string> seen;
  for (const BenchRow& r : rows) {
    if (scene && r.scene != *scene) continue;
    const std::string& key = scene ? r.method : r.scene;
    if (std::find(seen.begin(), seen.end(), key) == seen.end()) seen.push_back(key);
  }
  return seen;
}

// `text` as a gnuplot string that stays a string: single quotes, in which
// gnuplot expands neither backslash escapes nor `command` substitution, with
// a quote doubled; a control character (a line break would end the command
// and start another) shown as '?'. Labels only: the text is not kept exact.
std::string quoted_for_gnuplot(const std::string& text) {
  std::string q = "'";
  for (const char c : text) {
    if (c == '\'') q += "''";
    else if ((unsigned char)c < 0x20 || c == 0x7f) q += '?';
    else q += c;
  }
  return q + "'";
}

// `text` as one CSV field (RFC 4180): in double quotes, each one doubled,
// where it holds a comma, a quote or a line break.
std::string csv_field(const std::string& text) {
  if (text.find_first_of(",\"\r\n") == std::string::npos) return text;
  std::string q = "\"";
  for (const char c : text) q += c == '"' ? std::string("\"\"") : std::string(1, c);
  return q + "\"";
}

// A Markdown table cell: a '|' would end it and a line break the row.
std::string table_cell(const std::string& text) {
  std::string cell;
  for (const char c : text) cell += c == '|' ? std::string("\\|") : c == '\n' || c == '\r' ? std::string(" ") : std::string(1, c);
  return cell;
}

// Runs gnuplot on `script` without a shell, the script on its standard
// input from an unnamed temporary file, and returns what it wrote on its
// standard output (the plot: the script sets no output file, so no name of
// the user's ever reaches gnuplot's text). Throws std::runtime_error naming
// `path` when gnuplot cannot be run or fails.
std::string run_gnuplot(const std::string& script, const std::string& path) {
  const auto fail = [&](const std::string& why) { return std::runtime_error(path + ": gnuplot failed: " + why); };
  std::FILE* input = std::tmpfile();  // removed when closed, whatever ends this process
  if (!input) throw fail(std::string("no temporary file: ") + std::strerror(errno));
  const bool written = std::fwrite(script.data(), 1, script.size(), input) == script.size() && std::fflush(input) == 0;
  std::rewind(input);
  int output[2];
  if (!written || ::pipe(output) != 0) {
    std::fclose(input);
    throw fail(std::string("cannot pass it the script: ") + std::strerror(errno));
  }
  std::cout.flush(), std::cerr.flush();
  const pid_t pid = ::fork();
  if (pid == 0) {
    ::dup2(::fileno(input), STDIN_FILENO);
    ::dup2(output[1], STDOUT_FILENO);
    const int null = ::open("/dev/null", O_WRONLY);
    if (null >= 0) ::dup2(null, STDERR_FILENO);
    ::close(output[0]);
    ::execlp("gnuplot", "gnuplot", static_cast<char*>(nullptr));
    ::_exit(127);
  }
  ::close(output[1]);
  std::fclose(input);
  std::string plot;
  char buffer[65536];
  for (ssize_t n; pid > 0 && ((n = ::read(output[0], buffer, sizeof buffer)) > 0 || (n < 0 && errno == EINTR));)
    if (n > 0) plot.append(buffer, size_t(n));
  ::close(output[0]);
  if (pid < 0) throw fail(std::string("cannot start it: ") + std::strerror(errno));
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0)
    throw fail(WIFEXITED(status) ? "exit " + std::to_string(WEXITSTATUS(status)) : std::string("ended by a signal"));
  if (plot.empty()) throw fail("it drew nothing");
  return plot;
}

}  // namespace

std::string BenchRow::parameter() const {
  if (map_size) return "map " + std::to_string(map_size);
  return segments ? "N = " + std::to_string(segments) : "-";
}

void write_markdown_table(std::ostream& out, const std::vector<BenchRow>& rows, int width, int height) {
  // zfail's time per scene and N; under N = 0, its time at the largest N,
  // which is what raycast (no N) is compared with.
  std::map<std::pair<std::string, int>, double> zfail_ms;
  std::map<std::string, int> largest_n;
  for (const BenchRow& r : rows)
    if (r.method == "zfail") {
      zfail_ms[{r.scene, r.segments}] = r.median_ms;
      if (r.segments >= largest_n[r.scene]) zfail_ms[{r.scene, 0}] = r.median_ms, largest_n[r.scene] = r.segments;
    }
  out << "| scene | method | parameter | wrong pixels | of " << width << "x" << height
      << " surface | median frame (ms) | vs zfail |\n"
      << "|---|---|---:|---:|---:|---:|---:|\n";
  for (const BenchRow& r : rows) {
    const auto z = zfail_ms.find({r.scene, r.segments});
    out << "| " << table_cell(r.scene) << " | " << table_cell(r.method) << " | " << r.parameter() << " | "
        << (r.reference ? std::string("reference") : fixed(100.0 * r.error(), 3) + "%") << " | "
        << (r.reference ? std::string("-") : std::to_string(r.wrong_pixels)) << " of " << r.surface_pixels << " | "
        << fixed(r.median_ms, 2) << " | "
        << (z != zfail_ms.end() && z->second > 0.0 ? fixed(r.median_ms / z->second, 2) + "x" : "-") << " |\n";
  }
}

void write_csv(const std::vector<BenchRow>& rows, int width, int height, const std::string& path) {
  PartialFile partial(path, "the table");  // renamed into place: never a partial file
  std::ofstream out(partial.temporary_path(), std::ios::binary);
  if (!out) throw std::runtime_error(path + ": cannot write");
  out << "scene,method,segments,map_size,wrong_pixels,surface_pixels,error,median_ms,frames,width,height,reference\n";
  for (const BenchRow& r : rows) {
    out << csv_field(r.scene) << "," << csv_field(r.method) << "," << r.segments << "," << r.map_size << ",";
    if (r.reference) out << "," << r.surface_pixels << ",,";  // no error of its own
    else out << r.wrong_pixels << "," << r.surface_pixels << "," << r.error() << ",";
    out << r.median_ms << "," << r.frames << "," << width << "," << height << "," << int(r.reference) << "\n";
  }
  out.close();
  if (!out) throw std::runtime_error(path + ": cannot write");
  partial.commit();
}

bool gnuplot_available() { return std::system("gnuplot --version >/dev/null 2>&1") == 0; }

void write_plot(const std::vector<BenchRow>& rows, const std::string& path) {
  const bool text = std::filesystem::path(path).extension() == ".txt";
  const std::vector<std::string> scenes = in_order(rows, nullptr);
  const int columns = text ? 1 : std::min<int>(3, int(scenes.size()));
  const int panels_down = (int(scenes.size()) + columns - 1) / columns;
  std::ostringstream g;
  if (text) g << "set terminal dumb size 100," << 28 * panels_down << "\n";
  else g << "set terminal pngcairo size " << 520 * columns << "," << 440 * panels_down << " font \",10\"\n";
  // No "set output": the plot comes on gnuplot's standard output.
  g << "set termoption noenhanced\n"  // scene names keep their underscores
    << "set multiplot layout " << panels_down << "," << columns << "\n"
    << "set logscale x\nset xlabel \"median frame time (ms, log)\"\nset ylabel \"wrong pixels (%)\"\n"
    // The legend below each panel, never over its points; errors from 0 up,
    // as none is below it, with room above the highest.
    << "set key below horizontal maxcols 3\nset grid\nset yrange [0:*]\nset offsets 0, 0, graph 0.05, 0\n";
  // Each method keeps its colour and symbol in every panel, whichever
  // methods a panel has.
  std::vector<std::string> all_methods;
  for (const BenchRow& r : rows)
    if (std::find(all_methods.begin(), all_methods.end(), r.method) == all_methods.end()) all_methods.push_back(r.method);
  const auto style_of = [&](const std::string& method) {
    return std::find(all_methods.begin(), all_methods.end(), method) - all_methods.begin() + 1;
  };
  for (const std::string& scene : scenes) {
    g << "set title " << quoted_for_gnuplot(scene) << "\nplot ";
    const std::vector<std::string> methods = in_order(rows, &scene);
    for (size_t i = 0; i < methods.size(); ++i) {
      // The reference's point sits at 0 by definition, not by measurement.
      const bool reference = std::any_of(rows.begin(), rows.end(), [&](const BenchRow& r) {
        return r.scene == scene && r.method == methods[i] && r.reference;
      });
      g << (i ? ", " : "") << "'-' using 1:2 with linespoints linetype " << style_of(methods[i]) << " title "
        << quoted_for_gnuplot(reference ? methods[i] + " (reference)" : methods[i]);
    }
    g << "\n";
    for (const std::string& method : methods) {
      for (const BenchRow& r : rows)
        if (r.scene == scene && r.method == method) g << std::max(r.median_ms, 1e-3) << " " << 100.0 * r.error() << "\n";
      g << "e\n";
    }
  }
  g << "unset multiplot\n";
  const std::string plot = run_gnuplot(g.str(), path);
  PartialFile partial(path, "the plot");
  std::ofstream out(partial.temporary_path(), std::ios::binary);
  out << plot;
  out.close();
  if (!out) throw std::runtime_error(path + ": cannot write the plot");
  partial.commit();
}

}  // namespace umbra
