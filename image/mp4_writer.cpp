// H.264 video in an MP4 file through libavcodec (libx264) and libavformat:
// yuv420p in BT.709's limited range, as browsers play it, the index at the
// file's start ("faststart") so that a page plays it before it is whole.

#include <stdexcept>

extern "C" {
#include <libavcodec/avcodec.h>
#include <libavformat/avformat.h>
#include <libavutil/log.h>
#include <libavutil/opt.h>
#include <libswscale/swscale.h>
}

#include "image/animation_writers.hpp"

namespace umbra {
namespace {

// x264's constant rate factor: 18 is "visually lossless" in x264's own
// guidance, where its default of 23 shows banding on a studio's soft floor.
constexpr const char* kRateFactor = "18";

class Mp4Writer : public AnimationWriter {
 public:
  Mp4Writer(const std::string& path, const std::string& shown, const AnimationSettings& s) : shown_(shown) {
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
    check(av_frame_make_writable(frame_), "out of memory for a frame");
    const uint8_t* rows[1] = {image.pixels.data()};
    const int stride[1] = {image.width * 3};
    sws_scale(scale_, rows, stride, 0, image.height, frame_->data, frame_->linesize);
    frame_->pts = next_pts_++;
    send(frame_);
  }

  void finish() override {
    send(nullptr);  // drains the encoder
    check(av_write_trailer(format_), "cannot finish the video");
    check(avio_closep(&format_->pb), "cannot finish the video");
  }

 private:
  void start(const std::string& path, const AnimationSettings& s) {
    const std::string& shown = shown_;
    if (s.width % 2 != 0 || s.height % 2 != 0)
      throw std::runtime_error(shown + ": an MP4 video's frames (yuv420p) have an even width and height; got " +
                               std::to_string(s.width) + "x" + std::to_string(s.height));
    av_log_set_level(AV_LOG_ERROR);  // x264's notes on the CPU, not errors, stay off the terminal
    const AVCodec* codec = avcodec_find_encoder_by_name("libx264");
    if (!codec) throw std::runtime_error(shown + ": this libavcodec has no H.264 encoder (libx264)");
    check(avformat_alloc_output_context2(&format_, nullptr, "mp4", path.c_str()), "cannot start the MP4 file");
    stream_ = avformat_new_stream(format_, nullptr);
    codec_ = avcodec_alloc_context3(codec);
    if (!stream_ || !codec_) throw std::runtime_error(shown + ": out of memory starting the video");
    codec_->width = s.width;
    codec_->height = s.height;
    const AVRational rate = av_d2q(s.fps, 1000000);
    codec_->framerate = rate;
    codec_->time_base = av_inv_q(rate);
    codec_->pix_fmt = AV_PIX_FMT_YUV420P;
    codec_->color_primaries = AVCOL_PRI_BT709;
    codec_->color_trc = AVCOL_TRC_BT709;
    codec_->colorspace = AVCOL_SPC_BT709;
    codec_->color_range = AVCOL_RANGE_MPEG;
    if (format_->oformat->flags & AVFMT_GLOBALHEADER) codec_->flags |= AV_CODEC_FLAG_GLOBAL_HEADER;
    AVDictionary* options = nullptr;
    av_dict_set(&options, "crf", kRateFactor, 0);
    av_dict_set(&options, "preset", "medium", 0);
    const int opened = avcodec_open2(codec_, codec, &options);
    av_dict_free(&options);
    check(opened, "cannot start the H.264 encoder");
    check(avcodec_parameters_from_context(stream_->codecpar, codec_), "cannot start the video stream");
    stream_->time_base = codec_->time_base;
    check(avio_open(&format_->pb, path.c_str(), AVIO_FLAG_WRITE), "cannot write the video");
    AVDictionary* muxing = nullptr;
    av_dict_set(&muxing, "movflags", "+faststart", 0);
    const int header = avformat_write_header(format_, &muxing);
    av_dict_free(&muxing);
    check(header, "cannot write the video");
    frame_ = av_frame_alloc();
    packet_ = av_packet_alloc();
    if (!frame_ || !packet_) throw std::runtime_error(shown + ": out of memory starting the video");
    frame_->format = codec_->pix_fmt;
    frame_->width = s.width;
    frame_->height = s.height;
    check(av_frame_get_buffer(frame_, 0), "out of memory for a frame");
    // sRGB's full range into BT.709's limited range, chroma averaged over each 2x2.
    scale_ = sws_getContext(s.width, s.height, AV_PIX_FMT_RGB24, s.width, s.height, AV_PIX_FMT_YUV420P,
                            SWS_BICUBIC | SWS_ACCURATE_RND, nullptr, nullptr, nullptr);
    if (!scale_) throw std::runtime_error(shown + ": cannot convert frames to yuv420p");
    sws_setColorspaceDetails(scale_, sws_getCoefficients(SWS_CS_ITU709), 1, sws_getCoefficients(SWS_CS_ITU709), 0, 0, 1 << 16,
                             1 << 16);
  }

  void release() {
    sws_freeContext(scale_);
    av_frame_free(&frame_);
    av_packet_free(&packet_);
    avcodec_free_context(&codec_);
    if (format_ && format_->pb) avio_closep(&format_->pb);
    avformat_free_context(format_);
    scale_ = nullptr, format_ = nullptr;
  }

  void check(int code, const char* what) const {
    if (code >= 0) return;
    char why[AV_ERROR_MAX_STRING_SIZE] = {};
    av_strerror(code, why, sizeof why);
    throw std::runtime_error(shown_ + ": " + what + ": " + why);
  }

  void send(AVFrame* frame) {
    check(avcodec_send_frame(codec_, frame), "the H.264 encoder failed");
    for (;;) {
      const int got = avcodec_receive_packet(codec_, packet_);
      if (got == AVERROR(EAGAIN) || got == AVERROR_EOF) return;
      check(got, "the H.264 encoder failed");
      av_packet_rescale_ts(packet_, codec_->time_base, stream_->time_base);
      packet_->stream_index = stream_->index;
      check(av_interleaved_write_frame(format_, packet_), "cannot write the video");
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
