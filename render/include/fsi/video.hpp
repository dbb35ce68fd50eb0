#pragma once
/// \file video.hpp
/// H.264 in MP4 through FFmpeg (libavcodec/libavformat/libswscale). Only present when
/// fsi is built with FSI_WITH_VIDEO=ON; then FSI_RENDER_HAS_VIDEO is defined to 1.
#include <filesystem>
#include <memory>
#include <string>

#include "fsi/image.hpp"

namespace fsi::render {

struct VideoOptions {
  int fps = 25;  ///< frames per second [1/s]
  /// libx264 constant rate factor: 0 lossless .. 51 worst; 18 is visually lossless for
  /// these flat-shaded pictures, 23 is x264's default.
  int crf = 18;
  std::string preset = "medium";  ///< libx264 speed/size trade-off: ultrafast .. veryslow
  /// Encoder tried first. When missing: any H.264 encoder, then MPEG-4 Part 2, each
  /// with a warning on stderr.
  std::string encoder = "libx264";
};

/// Writes frames to an MP4 file. The file is complete only once close() ran; the
/// destructor calls it (errors there are printed to stderr, not thrown), so a writer
/// that goes out of scope, even through an exception, still leaves a playable file.
class VideoWriter {
 public:
  /// Opens `file` for frames of width x height [px]. H.264 with 4:2:0 chroma needs even
  /// sizes: an odd last column/row is dropped. Throws std::runtime_error on failure.
  VideoWriter(const std::filesystem::path& file, int width, int height,
              const VideoOptions& options = {});
  ~VideoWriter();
  VideoWriter(VideoWriter&&) noexcept;
  VideoWriter& operator=(VideoWriter&&) noexcept;

  /// Encodes one frame; its size must be the one given to the constructor.
  void write(const Image& frame);
  /// Flushes the encoder and finalizes the file. Idempotent.
  void close();

  long frames_written() const;
  int encoded_width() const;         ///< [px], even
  int encoded_height() const;        ///< [px], even
  std::string encoder_name() const;  ///< e.g. "libx264"

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

/// What a decoder finds in a video file (used by tests and tools to check outputs).
struct VideoInfo {
  long frames = 0;            ///< decoded frames (every packet decoded, not a header guess)
  int width = 0, height = 0;  ///< [px]
  std::string codec;          ///< codec name, e.g. "h264"
  std::string container;      ///< e.g. "mov,mp4,m4a,3gp,3g2,mj2"
  double fps = 0;             ///< nominal frame rate [1/s]
};

/// Opens and fully decodes the first video stream. Throws std::runtime_error naming
/// the file when it cannot be read.
VideoInfo probe_video(const std::filesystem::path& file);

}  // namespace fsi::render
