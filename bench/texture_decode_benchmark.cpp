// Decoding a texture map: stb_image, which umbra uses (one library for PNG,
// JPEG, BMP and TGA, already a dependency for the contact sheet's font),
// against the libraries a user would pick per format: libpng's simplified
// API and libjpeg-turbo's. Real maps from Debian's assimp-testmodels: a
// 2048x2048 RGB PNG and a 1024x2048 JPEG. Time per decode, into RGBA.
#include <benchmark/benchmark.h>

#include <cstdio>
#include <fstream>
#include <iterator>
#include <stdexcept>
#include <string>
#include <vector>

#include <jpeglib.h>
#include <png.h>
#include <stb_image.h>

namespace {

const char* const kPng = "/usr/share/assimp/models/glTF/CesiumMilkTruck/CesiumMilkTruck.png";
const char* const kJpeg = "/usr/share/assimp/models/LWO/LWO2/MappingModes/earthSpherical.jpg";

std::string bytes_of(const char* path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error(std::string("cannot open ") + path + " (Debian's assimp-testmodels)");
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

void stb(benchmark::State& state, const char* path) {
  const std::string file = bytes_of(path);
  for (auto _ : state) {
    int w = 0, h = 0, n = 0;
    stbi_uc* pixels = stbi_load_from_memory(reinterpret_cast<const stbi_uc*>(file.data()), int(file.size()), &w, &h, &n, 4);
    if (!pixels) state.SkipWithError("stb_image failed");
    benchmark::DoNotOptimize(pixels);
    stbi_image_free(pixels);
  }
}

void BM_StbImagePng(benchmark::State& state) { stb(state, kPng); }
void BM_StbImageJpeg(benchmark::State& state) { stb(state, kJpeg); }

void BM_LibPng(benchmark::State& state) {
  const std::string file = bytes_of(kPng);
  std::vector<unsigned char> pixels;
  for (auto _ : state) {
    png_image image{};
    image.version = PNG_IMAGE_VERSION;
    if (!png_image_begin_read_from_memory(&image, file.data(), file.size())) state.SkipWithError("libpng failed");
    image.format = PNG_FORMAT_RGBA;
    pixels.resize(PNG_IMAGE_SIZE(image));
    png_image_finish_read(&image, nullptr, pixels.data(), 0, nullptr);
    benchmark::DoNotOptimize(pixels.data());
  }
}

void BM_LibJpegTurbo(benchmark::State& state) {
  const std::string file = bytes_of(kJpeg);
  std::vector<unsigned char> pixels;
  for (auto _ : state) {
    jpeg_decompress_struct info{};
    jpeg_error_mgr errors{};
    info.err = jpeg_std_error(&errors);
    jpeg_create_decompress(&info);
    jpeg_mem_src(&info, reinterpret_cast<const unsigned char*>(file.data()), file.size());
    jpeg_read_header(&info, TRUE);
    info.out_color_space = JCS_EXT_RGBA;
    jpeg_start_decompress(&info);
    pixels.resize(size_t(info.output_width) * info.output_height * 4);
    while (info.output_scanline < info.output_height) {
      unsigned char* row = pixels.data() + size_t(info.output_scanline) * info.output_width * 4;
      jpeg_read_scanlines(&info, &row, 1);
    }
    jpeg_finish_decompress(&info);
    jpeg_destroy_decompress(&info);
    benchmark::DoNotOptimize(pixels.data());
  }
}

BENCHMARK(BM_StbImagePng)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_LibPng)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_StbImageJpeg)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_LibJpegTurbo)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
