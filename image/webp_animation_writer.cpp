// Animated WebP through libwebp's animation encoder (WebPAnimEncoder, in
// libwebpmux): lossless, or lossy at a quality; looping forever.

#include <cmath>
#include <fstream>
#include <stdexcept>

#include <webp/encode.h>
#include <webp/mux.h>

#include "image/animation_writers.hpp"

namespace umbra {
namespace {

class WebpAnimationWriter : public AnimationWriter {
 public:
  WebpAnimationWriter(const std::string& path, const std::string& shown, const AnimationSettings& s)
      : path_(path), shown_(shown), settings_(s) {
    WebPAnimEncoderOptions options;
    if (!WebPAnimEncoderOptionsInit(&options) || !WebPConfigInit(&config_))
      throw std::runtime_error(shown + ": this libwebp does not match the one umbra was built with");
    options.anim_params.loop_count = 0;  // forever
    if (s.quality) {
      config_.lossless = 0;
      config_.quality = float(*s.quality);
      // Every frame a key frame: lossy sub-frames blended over the last
      // frame leave rectangles of stale tone on a floor's smooth gradient.
      options.kmin = 0, options.kmax = 1;
    } else {
      config_.lossless = 1;
    }
    encoder_ = WebPAnimEncoderNew(s.width, s.height, &options);
    if (!encoder_) throw std::runtime_error(shown + ": cannot start the WebP encoder");
  }
  ~WebpAnimationWriter() override { WebPAnimEncoderDelete(encoder_); }

  void add(const Image& image) override {
    WebPPicture picture;
    if (!WebPPictureInit(&picture)) throw std::runtime_error(shown_ + ": cannot start a WebP frame");
    picture.use_argb = 1;
    picture.width = image.width;
    picture.height = image.height;
    const bool imported = image.channels == 4 ? WebPPictureImportRGBA(&picture, image.pixels.data(), image.width * 4)
                                              : WebPPictureImportRGB(&picture, image.pixels.data(), image.width * 3);
    const bool added = imported && WebPAnimEncoderAdd(encoder_, &picture, timestamp(frames_), &config_);
    WebPPictureFree(&picture);
    if (!added) throw std::runtime_error(shown_ + ": the WebP encoder failed: " + WebPAnimEncoderGetError(encoder_));
    ++frames_;
  }

  void finish() override {
    WebPData data;
    WebPDataInit(&data);
    // The last frame lasts until the end's timestamp.
    if (!WebPAnimEncoderAdd(encoder_, nullptr, timestamp(frames_), nullptr) || !WebPAnimEncoderAssemble(encoder_, &data))
      throw std::runtime_error(shown_ + ": the WebP encoder failed: " + WebPAnimEncoderGetError(encoder_));
    std::ofstream out(path_, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(data.bytes), std::streamsize(data.size));
    WebPDataClear(&data);
    if (!out.flush()) throw std::runtime_error(shown_ + ": cannot write the animation");
  }

 private:
  // Frame i starts at i / fps seconds, in whole milliseconds.
  int timestamp(int frame) const { return int(std::lround(frame * 1000.0 / settings_.fps)); }

  std::string path_, shown_;
  AnimationSettings settings_;
  WebPConfig config_;
  WebPAnimEncoder* encoder_ = nullptr;
  int frames_ = 0;
};

}  // namespace

std::unique_ptr<AnimationWriter> open_animated_webp(const std::string& path, const std::string& shown,
                                                    const AnimationSettings& settings) {
  return std::make_unique<WebpAnimationWriter>(path, shown, settings);
}

}  // namespace umbra
