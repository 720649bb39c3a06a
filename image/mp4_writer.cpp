// H.264 video in an MP4 file through libavcodec (libx264) and libavformat:
// yuv420p in BT.709's limited range, as browsers play it, the index at the
// file's start ("faststart") so that a page plays it before it is whole.
// The libraries are opened at run time, when a video is written: linked,
// they and the hundred-odd libraries libavcodec links would be loaded and
// mapped by every run of umbra.

#include <stdexcept>
#include <string>

extern "C" {
#include <libavcodec/avcodec.h>
#include <libavformat/avformat.h>
#include <libavutil/log.h>
#include <libswscale/swscale.h>
}

#include "image/animation_writers.hpp"
#include "image/loaded_library.hpp"

namespace umbra {
namespace {

// Each function the writer calls, with the library it is in: one list,
// which both declares the pointers and resolves them.
#define UMBRA_AV_FUNCTIONS(X)                                                                                          \
  X(avutil, av_log_set_level) X(avutil, av_d2q) X(avutil, av_dict_set) X(avutil, av_dict_free) X(avutil, av_strerror)   \
  X(avutil, av_frame_alloc) X(avutil, av_frame_free) X(avutil, av_frame_get_buffer) X(avutil, av_frame_make_writable) \
  X(avcodec, avcodec_find_encoder_by_name) X(avcodec, avcodec_alloc_context3) X(avcodec, avcodec_free_context)        \
  X(avcodec, avcodec_open2) X(avcodec, avcodec_parameters_from_context) X(avcodec, avcodec_send_frame)               \
  X(avcodec, avcodec_receive_packet) X(avcodec, av_packet_alloc) X(avcodec, av_packet_free)                          \
  X(avcodec, av_packet_rescale_ts) X(avformat, avformat_alloc_output_context2) X(avformat, avformat_new_stream)      \
  X(avformat, avformat_write_header) X(avformat, av_interleaved_write_frame) X(avformat, av_write_trailer)            \
  X(avformat, avformat_free_context) X(avformat, avio_open) X(avformat, avio_closep) X(swscale, sws_getContext)       \
  X(swscale, sws_setColorspaceDetails) X(swscale, sws_getCoefficients) X(swscale, sws_scale) X(swscale, sws_freeContext)

struct Av {
#define UMBRA_AV_POINTER(library, name) decltype(&::name) name = nullptr;
  UMBRA_AV_FUNCTIONS(UMBRA_AV_POINTER)
#undef UMBRA_AV_POINTER
};

// The libraries of the version umbra was built with (their sonames carry
// the major version, which fixes the structures' layout).
const Av& av() {
  static const Av functions = [] {
    const auto open = [](const char* name, int major) {
      const std::string file = "lib" + std::string(name) + ".so." + std::to_string(major);
      return LoadedLibrary("an MP4 video", {file.c_str()}, file + " (Debian's lib" + name + std::to_string(major) + ")");
    };
    const LoadedLibrary avutil = open("avutil", LIBAVUTIL_VERSION_MAJOR), avcodec = open("avcodec", LIBAVCODEC_VERSION_MAJOR),
                        avformat = open("avformat", LIBAVFORMAT_VERSION_MAJOR), swscale = open("swscale", LIBSWSCALE_VERSION_MAJOR);
    Av f;
#define UMBRA_AV_RESOLVE(library, name) library.resolve(#name, f.name);
    UMBRA_AV_FUNCTIONS(UMBRA_AV_RESOLVE)
#undef UMBRA_AV_RESOLVE
    return f;  // the libraries stay loaded for the life of the process
  }();
  return functions;
}

// x264's constant rate factor: 18 is "visually lossless" in x264's own
// guidance, where its default of 23 shows banding on a studio's soft floor.
constexpr const char* kRateFactor = "18";

class Mp4Writer : public AnimationWriter {
 public:
  Mp4Writer(const std::string& path, const std::string& shown, const AnimationSettings& s) : shown_(shown) {
    av();  // the libraries first: without them there is nothing to release
    try {
      start(path, s);
    } catch (...) {
      release();
      throw;
    }
  }

  ~Mp4Writer() override { release(); }

  void add(const Image& image) override {
    if (image.channels != 3) throw std::logic_error("an MP4's frames are RGB");
    check(av().av_frame_make_writable(frame_), "out of memory for a frame");
    const uint8_t* rows[1] = {image.pixels.data()};
    const int stride[1] = {image.width * 3};
    av().sws_scale(scale_, rows, stride, 0, image.height, frame_->data, frame_->linesize);
    frame_->pts = next_pts_++;
    send(frame_);
  }

  void finish() override {
    send(nullptr);  // drains the encoder
    check(av().av_write_trailer(format_), "cannot finish the video");
    check(av().avio_closep(&format_->pb), "cannot finish the video");
  }

 private:
  void start(const std::string& path, const AnimationSettings& s) {
    const std::string& shown = shown_;
    if (s.width % 2 != 0 || s.height % 2 != 0)
      throw std::runtime_error(shown + ": an MP4 video's frames (yuv420p) have an even width and height; got " +
                               std::to_string(s.width) + "x" + std::to_string(s.height));
    av().av_log_set_level(AV_LOG_ERROR);  // x264's notes on the CPU, not errors, stay off the terminal
    const AVCodec* codec = av().avcodec_find_encoder_by_name("libx264");
    if (!codec) throw std::runtime_error(shown + ": this libavcodec has no H.264 encoder (libx264)");
    check(av().avformat_alloc_output_context2(&format_, nullptr, "mp4", path.c_str()), "cannot start the MP4 file");
    stream_ = av().avformat_new_stream(format_, nullptr);
    codec_ = av().avcodec_alloc_context3(codec);
    if (!stream_ || !codec_) throw std::runtime_error(shown + ": out of memory starting the video");
    codec_->width = s.width;
    codec_->height = s.height;
    const AVRational rate = av().av_d2q(s.fps, 1000000);
    codec_->framerate = rate;
    codec_->time_base = av_inv_q(rate);
    codec_->pix_fmt = AV_PIX_FMT_YUV420P;
    codec_->color_primaries = AVCOL_PRI_BT709;
    codec_->color_trc = AVCOL_TRC_BT709;
    codec_->colorspace = AVCOL_SPC_BT709;
    codec_->color_range = AVCOL_RANGE_MPEG;
    if (format_->oformat->flags & AVFMT_GLOBALHEADER) codec_->flags |= AV_CODEC_FLAG_GLOBAL_HEADER;
    AVDictionary* options = nullptr;
    av().av_dict_set(&options, "crf", kRateFactor, 0);
    av().av_dict_set(&options, "preset", "medium", 0);
    const int opened = av().avcodec_open2(codec_, codec, &options);
    av().av_dict_free(&options);
    check(opened, "cannot start the H.264 encoder");
    check(av().avcodec_parameters_from_context(stream_->codecpar, codec_), "cannot start the video stream");
    stream_->time_base = codec_->time_base;
    check(av().avio_open(&format_->pb, path.c_str(), AVIO_FLAG_WRITE), "cannot write the video");
    AVDictionary* muxing = nullptr;
    av().av_dict_set(&muxing, "movflags", "+faststart", 0);
    const int header = av().avformat_write_header(format_, &muxing);
    av().av_dict_free(&muxing);
    check(header, "cannot write the video");
    frame_ = av().av_frame_alloc();
    packet_ = av().av_packet_alloc();
    if (!frame_ || !packet_) throw std::runtime_error(shown + ": out of memory starting the video");
    frame_->format = codec_->pix_fmt;
    frame_->width = s.width;
    frame_->height = s.height;
    check(av().av_frame_get_buffer(frame_, 0), "out of memory for a frame");
    // sRGB's full range into BT.709's limited range, chroma averaged over each 2x2.
    scale_ = av().sws_getContext(s.width, s.height, AV_PIX_FMT_RGB24, s.width, s.height, AV_PIX_FMT_YUV420P,
                                  SWS_BICUBIC | SWS_ACCURATE_RND, nullptr, nullptr, nullptr);
    if (!scale_) throw std::runtime_error(shown + ": cannot convert frames to yuv420p");
    const int* bt709 = av().sws_getCoefficients(SWS_CS_ITU709);
    av().sws_setColorspaceDetails(scale_, bt709, 1, bt709, 0, 0, 1 << 16, 1 << 16);
  }

  void release() {
    av().sws_freeContext(scale_);
    av().av_frame_free(&frame_);
    av().av_packet_free(&packet_);
    av().avcodec_free_context(&codec_);
    if (format_ && format_->pb) av().avio_closep(&format_->pb);
    av().avformat_free_context(format_);
    scale_ = nullptr, format_ = nullptr;
  }

  void check(int code, const char* what) const {
    if (code >= 0) return;
    char why[AV_ERROR_MAX_STRING_SIZE] = {};
    av().av_strerror(code, why, sizeof why);
    throw std::runtime_error(shown_ + ": " + what + ": " + why);
  }

  void send(AVFrame* frame) {
    check(av().avcodec_send_frame(codec_, frame), "the H.264 encoder failed");
    for (;;) {
      const int got = av().avcodec_receive_packet(codec_, packet_);
      if (got == AVERROR(EAGAIN) || got == AVERROR_EOF) return;
      check(got, "the H.264 encoder failed");
      av().av_packet_rescale_ts(packet_, codec_->time_base, stream_->time_base);
      packet_->stream_index = stream_->index;
      check(av().av_interleaved_write_frame(format_, packet_), "cannot write the video");
    }
  }

  std::string shown_;
  AVFormatContext* format_ = nullptr;
  AVStream* stream_ = nullptr;
  AVCodecContext* codec_ = nullptr;
  AVFrame* frame_ = nullptr;
  AVPacket* packet_ = nullptr;
  SwsContext* scale_ = nullptr;
  int64_t next_pts_ = 0;
};

}  // namespace

std::unique_ptr<AnimationWriter> open_mp4(const std::string& path, const std::string& shown, const AnimationSettings& settings) {
  return std::make_unique<Mp4Writer>(path, shown, settings);
}

}  // namespace umbra
