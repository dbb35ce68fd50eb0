// Decodes a whole video to count its frames: header frame counts are estimates (and
// absent in some containers), a test wants the truth.
#include "fsi/video.hpp"

extern "C" {
#include <libavcodec/avcodec.h>
#include <libavformat/avformat.h>
}

#include <stdexcept>
#include <string>

namespace fsi::render {
namespace {

// Frees what avformat/avcodec allocated, however probe_video leaves.
struct Decoding {
  AVFormatContext* format = nullptr;
  AVCodecContext* decoder = nullptr;
  AVPacket* packet = av_packet_alloc();
  AVFrame* frame = av_frame_alloc();
  ~Decoding() {
    av_frame_free(&frame);
    av_packet_free(&packet);
    avcodec_free_context(&decoder);
    avformat_close_input(&format);
  }
};

}  // namespace

VideoInfo probe_video(const std::filesystem::path& file) {
  Decoding d;
  auto fail = [&file](const std::string& what) {
    return std::runtime_error(file.string() + ": " + what);
  };
  if (avformat_open_input(&d.format, file.c_str(), nullptr, nullptr) < 0) {
    throw fail("cannot open as a video");
  }
  if (avformat_find_stream_info(d.format, nullptr) < 0) throw fail("no stream information");
  const AVCodec* codec = nullptr;
  const int index = av_find_best_stream(d.format, AVMEDIA_TYPE_VIDEO, -1, -1, &codec, 0);
  if (index < 0 || !codec) throw fail("no decodable video stream");
  AVStream* stream = d.format->streams[index];
  d.decoder = avcodec_alloc_context3(codec);
  if (!d.decoder || !d.packet || !d.frame) throw fail("out of memory");
  if (avcodec_parameters_to_context(d.decoder, stream->codecpar) < 0 ||
      avcodec_open2(d.decoder, codec, nullptr) < 0) {
    throw fail("cannot open the decoder");
  }
  VideoInfo info;
  info.codec = avcodec_get_name(stream->codecpar->codec_id);
  info.container = d.format->iformat->name;
  info.width = stream->codecpar->width;
  info.height = stream->codecpar->height;
  info.fps = av_q2d(stream->r_frame_rate);  // avg_frame_rate is skewed by B-frame delay
  auto drain = [&] {
    while (avcodec_receive_frame(d.decoder, d.frame) == 0) {
      ++info.frames;
      av_frame_unref(d.frame);
    }
  };
  while (av_read_frame(d.format, d.packet) >= 0) {
    if (d.packet->stream_index == index) {
      if (avcodec_send_packet(d.decoder, d.packet) < 0) throw fail("corrupt packet");
      drain();
    }
    av_packet_unref(d.packet);
  }
  avcodec_send_packet(d.decoder, nullptr);  // flush the frames still in the decoder
  drain();
  return info;
}

}  // namespace fsi::render
