// The encode pipeline: RGBA Image -> (swscale, BT.709 limited range) yuv420p AVFrame
// -> encoder -> packets rescaled from the encoder's 1/fps clock to the stream's time
// base -> MP4 muxer (moov atom moved to the front: +faststart, for streaming players).
#include "fsi/video.hpp"

extern "C" {
#include <libavcodec/avcodec.h>
#include <libavformat/avformat.h>
#include <libavutil/error.h>
#include <libavutil/log.h>
#include <libavutil/opt.h>
#include <libswscale/swscale.h>
}

#include <cstdio>
#include <stdexcept>
#include <string>

namespace fsi::render {
namespace {

std::string av_error(int code) {
  char buf[AV_ERROR_MAX_STRING_SIZE] = {};
  av_strerror(code, buf, sizeof buf);
  return buf;
}

void check(int code, const std::filesystem::path& file, const char* what) {
  if (code < 0) {
    throw std::runtime_error(file.string() + ": " + what + " failed (" + av_error(code) + ")");
  }
}

const AVCodec* find_encoder(const std::string& preferred) {
  if (const AVCodec* c = avcodec_find_encoder_by_name(preferred.c_str())) return c;
  if (const AVCodec* c = avcodec_find_encoder(AV_CODEC_ID_H264)) {
    std::fprintf(stderr, "fsi VideoWriter: warning: encoder '%s' not available, using '%s'\n",
                 preferred.c_str(), c->name);
    return c;
  }
  if (const AVCodec* c = avcodec_find_encoder(AV_CODEC_ID_MPEG4)) {
    std::fprintf(stderr,
                 "fsi VideoWriter: warning: no H.264 encoder available, using MPEG-4 ('%s')\n",
                 c->name);
    return c;
  }
  return nullptr;
}

}  // namespace

struct VideoWriter::Impl {
  std::filesystem::path file;
  int width = 0, height = 0;  // of the frames given
  int enc_width = 0, enc_height = 0;
  AVFormatContext* format = nullptr;
  AVCodecContext* encoder = nullptr;
  AVStream* stream = nullptr;
  AVFrame* frame = nullptr;
  AVPacket* packet = nullptr;
  SwsContext* sws = nullptr;
  long frames = 0;
  bool open = false;

  ~Impl() {
    sws_freeContext(sws);
    av_packet_free(&packet);
    av_frame_free(&frame);
    avcodec_free_context(&encoder);
    if (format) {
      if (format->pb) avio_closep(&format->pb);
      avformat_free_context(format);
    }
  }

  // Sends `f` (nullptr flushes) and writes every packet the encoder hands back.
  void encode(AVFrame* f) {
    check(avcodec_send_frame(encoder, f), file, "avcodec_send_frame");
    for (;;) {
      const int r = avcodec_receive_packet(encoder, packet);
      if (r == AVERROR(EAGAIN) || r == AVERROR_EOF) return;
      check(r, file, "avcodec_receive_packet");
      // Every frame lasts one tick of 1/fps. Without a duration the MP4 edit list ends
      // at the last presentation time and players drop the final frame.
      if (packet->duration == 0) packet->duration = 1;
      av_packet_rescale_ts(packet, encoder->time_base, stream->time_base);
      packet->stream_index = stream->index;
      check(av_interleaved_write_frame(format, packet), file, "writing a packet");
    }
  }
};

VideoWriter::VideoWriter(const std::filesystem::path& file, int width, int height,
                         const VideoOptions& options)
    : impl_(std::make_unique<Impl>()) {
  Impl& m = *impl_;
  m.file = file;
  m.width = width;
  m.height = height;
  m.enc_width = width & ~1;
  m.enc_height = height & ~1;
  if (m.enc_width < 2 || m.enc_height < 2 || options.fps <= 0) {
    throw std::invalid_argument(file.string() + ": bad video size " + std::to_string(width) + "x" +
                                std::to_string(height) + " or fps " + std::to_string(options.fps));
  }
  if (file.has_parent_path()) std::filesystem::create_directories(file.parent_path());
  // FFmpeg's default log level (info) prints encoder banners and muxer notes into the
  // apps' progress output: keep warnings and errors, unless the program chose a level.
  if (av_log_get_level() == AV_LOG_INFO) av_log_set_level(AV_LOG_WARNING);
  check(avformat_alloc_output_context2(&m.format, nullptr, "mp4", file.c_str()), file,
        "creating the MP4 muxer");
  const AVCodec* codec = find_encoder(options.encoder);
  if (!codec) throw std::runtime_error(file.string() + ": no H.264 or MPEG-4 encoder available");
  m.stream = avformat_new_stream(m.format, nullptr);
  m.encoder = avcodec_alloc_context3(codec);
  m.frame = av_frame_alloc();
  m.packet = av_packet_alloc();
  if (!m.stream || !m.encoder || !m.frame || !m.packet) {
    throw std::runtime_error(file.string() + ": out of memory setting up the encoder");
  }
  AVCodecContext* e = m.encoder;
  e->width = m.enc_width;
  e->height = m.enc_height;
  e->pix_fmt = AV_PIX_FMT_YUV420P;
  e->time_base = AVRational{1, options.fps};
  e->framerate = AVRational{options.fps, 1};
  e->gop_size = 2 * options.fps;  // a key frame every 2 s: seekable, still small
  // Tag what swscale produces below, so players convert back with the same matrix.
  e->color_range = AVCOL_RANGE_MPEG;
  e->colorspace = AVCOL_SPC_BT709;
  e->color_primaries = AVCOL_PRI_BT709;
  e->color_trc = AVCOL_TRC_BT709;
  if (m.format->oformat->flags & AVFMT_GLOBALHEADER) e->flags |= AV_CODEC_FLAG_GLOBAL_HEADER;
  AVDictionary* codec_opts = nullptr;
  if (std::string(codec->name) == "libx264") {
    av_dict_set(&codec_opts, "preset", options.preset.c_str(), 0);
    av_dict_set(&codec_opts, "crf", std::to_string(options.crf).c_str(), 0);
    av_dict_set(&codec_opts, "x264-params", "log=1", 0);  // warnings and errors only, no summary
  } else {
    e->bit_rate = 8'000'000;  // fallback encoders have no crf: a generous fixed rate
  }
  const int opened = avcodec_open2(e, codec, &codec_opts);
  av_dict_free(&codec_opts);
  check(opened, file, "opening the encoder");
  check(avcodec_parameters_from_context(m.stream->codecpar, e), file, "copying codec parameters");
  m.stream->time_base = e->time_base;  // a hint; the muxer may choose its own

  m.frame->format = e->pix_fmt;
  m.frame->width = e->width;
  m.frame->height = e->height;
  check(av_frame_get_buffer(m.frame, 0), file, "allocating a frame");
  m.sws = sws_getContext(m.enc_width, m.enc_height, AV_PIX_FMT_RGBA, m.enc_width, m.enc_height,
                         AV_PIX_FMT_YUV420P, SWS_BILINEAR | SWS_ACCURATE_RND, nullptr, nullptr,
                         nullptr);
  if (!m.sws) throw std::runtime_error(file.string() + ": cannot create the RGB->YUV converter");
  // Full-range RGB in, BT.709 limited-range YUV out (the tags set above).
  sws_setColorspaceDetails(m.sws, sws_getCoefficients(SWS_CS_ITU709), 1,
                           sws_getCoefficients(SWS_CS_ITU709), 0, 0, 1 << 16, 1 << 16);

  check(avio_open(&m.format->pb, file.c_str(), AVIO_FLAG_WRITE), file, "opening for writing");
  AVDictionary* mux_opts = nullptr;
  av_dict_set(&mux_opts, "movflags", "+faststart", 0);
  const int written = avformat_write_header(m.format, &mux_opts);
  av_dict_free(&mux_opts);
  check(written, file, "writing the MP4 header");
  m.open = true;
}

VideoWriter::~VideoWriter() {
  if (!impl_) return;  // moved from
  try {
    close();
  } catch (const std::exception& e) {
    std::fprintf(stderr, "fsi VideoWriter: %s\n", e.what());
  }
}

VideoWriter::VideoWriter(VideoWriter&&) noexcept = default;
VideoWriter& VideoWriter::operator=(VideoWriter&& other) noexcept {
  if (this != &other) {
    try {
      if (impl_) close();
    } catch (const std::exception& e) {
      std::fprintf(stderr, "fsi VideoWriter: %s\n", e.what());
    }
    impl_ = std::move(other.impl_);
  }
  return *this;
}

void VideoWriter::write(const Image& image) {
  Impl& m = *impl_;
  if (!m.open) throw std::logic_error(m.file.string() + ": write() after close()");
  if (image.width != m.width || image.height != m.height ||
      image.rgba.size() != 4 * std::size_t(image.width) * image.height) {
    throw std::invalid_argument(m.file.string() + ": frame is " + std::to_string(image.width) +
                                "x" + std::to_string(image.height) + ", the video " +
                                std::to_string(m.width) + "x" + std::to_string(m.height));
  }
  // The encoder may still hold a reference to the previous frame's buffers.
  check(av_frame_make_writable(m.frame), m.file, "av_frame_make_writable");
  const std::uint8_t* src[1] = {image.rgba.data()};
  const int stride[1] = {4 * image.width};  // the full row: an odd last column is skipped
  sws_scale(m.sws, src, stride, 0, m.enc_height, m.frame->data, m.frame->linesize);
  m.frame->pts = m.frames;  // in the encoder's time base 1/fps
  m.encode(m.frame);
  ++m.frames;
}

void VideoWriter::close() {
  Impl& m = *impl_;
  if (!m.open) return;
  m.open = false;  // whatever happens below, do not try twice
  m.encode(nullptr);
  check(av_write_trailer(m.format), m.file, "writing the MP4 trailer");
  check(avio_closep(&m.format->pb), m.file, "closing the file");
}

long VideoWriter::frames_written() const { return impl_->frames; }
int VideoWriter::encoded_width() const { return impl_->enc_width; }
int VideoWriter::encoded_height() const { return impl_->enc_height; }
std::string VideoWriter::encoder_name() const { return impl_->encoder->codec->name; }

}  // namespace fsi::render
