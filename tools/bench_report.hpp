#pragma once
// What umbra bench writes: a Markdown table, a CSV file and a plot of error
// against frame time (drawn by gnuplot).

#include <ostream>
#include <string>
#include <vector>

namespace umbra {

struct BenchRow {
  std::string scene;   // file name
  std::string method;  // method_name()
  int segments = 0;    // sphere N; 0 where the scene has no sphere or the method has none
  int map_size = 0;    // shadow map texels a side, for shadowmap; else 0
  long wrong_pixels = 0, surface_pixels = 0;  // over every light's mask
  // The ray-cast reference itself: the others' errors are measured against
  // it, and it has none to report (the table says "reference", the CSV
  // leaves its error empty).
  bool reference = false;
  double median_ms = 0.0;
  int frames = 0;
  std::string parameter() const;  // "N = 64", "map 1024" or "-"
  double error() const { return surface_pixels ? double(wrong_pixels) / double(surface_pixels) : 0.0; }
};

// One row per measurement; the last column compares the frame time with
// zfail at the same N on the same scene (raycast: at the largest N).
void write_markdown_table(std::ostream& out, const std::vector<BenchRow>& rows, int width, int height);
// Throws std::runtime_error when the file cannot be written.
void write_csv(const std::vector<BenchRow>& rows, int width, int height, const std::string& path);
// One panel per scene, a curve per method. OUT.png gets a PNG; OUT.txt a
// text plot (gnuplot's dumb terminal). Throws std::runtime_error when
// gnuplot fails or is missing.
void write_plot(const std::vector<BenchRow>& rows, const std::string& path);
// True when gnuplot can be run.
bool gnuplot_available();

}  // namespace umbra
