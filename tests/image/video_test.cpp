// Writes short MP4s and decodes them again with libavformat/libavcodec (probe_video).
#include <gtest/gtest.h>

#ifdef FSI_RENDER_HAS_VIDEO
#include <filesystem>
#include <fsi/renderer.hpp>
#include <fsi/sample_field.hpp>
#include <fsi/video.hpp>

namespace fsi::render {
namespace {

std::filesystem::path scratch(const std::string& name) {
  return std::filesystem::path(FSI_BINARY_DIR) / "image-test-output" / name;
}

TEST(Video, TwelveRenderedFramesDecodeAsH264) {
  const auto file = scratch("twelve.mp4");
  std::filesystem::remove(file);
  Renderer r{GlBackend::osmesa};
  FrameSpec s;
  s.width = 320;
  s.height = 240;
  s.quantity = Quantity::vy;
  s.range = ColorRange{-0.2, 0.2};
  {
    VideoWriter video(file, s.width, s.height, VideoOptions{.fps = 12});
    for (int i = 0; i < 12; ++i) {
      SampleFieldOptions o;
      o.time_s = i / 12.0;
      o.ball_y = -0.2 - 0.02 * i;
      video.write(r.render(sample_field_view(o), s));
    }
    EXPECT_EQ(video.frames_written(), 12);
    EXPECT_EQ(video.encoder_name(), "libx264");
    // No close(): the destructor must finalize the file.
  }
  const VideoInfo info = probe_video(file);
  EXPECT_EQ(info.frames, 12);
  EXPECT_EQ(info.width, 320);
  EXPECT_EQ(info.height, 240);
  EXPECT_EQ(info.codec, "h264");
  EXPECT_NEAR(info.fps, 12.0, 1e-6);
  EXPECT_NE(info.container.find("mp4"), std::string::npos);
}

TEST(Video, OddSizesAreRoundedDownToEven) {
  const auto file = scratch("odd.mp4");
  VideoWriter video(file, 101, 75);
  EXPECT_EQ(video.encoded_width(), 100);
  EXPECT_EQ(video.encoded_height(), 74);
  for (int i = 0; i < 3; ++i) video.write(Image::filled(101, 75, 40 * i, 100, 200));
  EXPECT_THROW(video.write(Image::filled(100, 75)), std::invalid_argument);
  video.close();
  video.close();  // idempotent
  const VideoInfo info = probe_video(file);
  EXPECT_EQ(info.frames, 3);
  EXPECT_EQ(info.width, 100);
  EXPECT_EQ(info.height, 74);
}

TEST(Video, ProbeOfANonVideoThrows) {
  EXPECT_THROW(probe_video(scratch("nothing-here.mp4")), std::runtime_error);
}

}  // namespace
}  // namespace fsi::render
#else
TEST(Video, BuiltWithoutVideo) { GTEST_SKIP() << "FSI_WITH_VIDEO=OFF"; }
#endif
