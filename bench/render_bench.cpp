// Time per 1280x720 frame of the stages of movie making, on the synthetic
// falling-ball field over a graded 65x65-node triangle mesh (4225 nodes, 8192
// triangles, the size of a coarse engine run):
//   render  - FieldView -> Image (draw, read back, downsample), per supersampling factor
//   png     - Image -> PNG file (write_png: libdeflate level 4, unfiltered RGB)
//   video   - Image -> H.264 frame (swscale + libx264 + MP4 mux), per x264 preset
//   frame and PNG - what fsi-movie does per picture: render into a reused Image with the
//             default FrameSpec (supersampling 1) and write_png it to a file
// "On one core": taskset -c 1 build/bench/fsi-bench-render (llvmpipe then draws in
// the calling thread, so the CPU column is all of the work).
// Run: build/bench/fsi-bench-render   (tools/bench runs every benchmark)
#include <benchmark/benchmark.h>

#include <filesystem>
#include <fsi/png.hpp>
#include <fsi/renderer.hpp>
#include <fsi/sample_field.hpp>
#include <string>
#include <vector>
#ifdef FSI_RENDER_HAS_VIDEO
#include <fsi/video.hpp>
#endif

namespace {

using namespace fsi::render;

constexpr int frame_width = 1280, frame_height = 720;

fsi::FieldView bench_view(double t = 1.0) {
  SampleFieldOptions o;
  o.nx = o.ny = 65;
  o.graded = true;
  o.time_s = t;
  o.ball_y = -0.3 - 0.1 * t;
  return sample_field_view(o);
}

FrameSpec bench_spec(int supersample) {
  FrameSpec s;
  s.width = frame_width;
  s.height = frame_height;
  s.quantity = Quantity::vy;
  s.range = ColorRange{-0.2, 0.2};
  s.title = "benchmark";
  s.supersample = supersample;
  return s;
}

std::filesystem::path scratch(const std::string& name) {
  const auto dir = std::filesystem::temp_directory_path() / "fsi-bench-render";
  std::filesystem::create_directories(dir);
  return dir / name;
}

void per_frame_counter(benchmark::State& state) {
  // Wall-clock seconds per frame (the benchmarks use real time: llvmpipe and x264 work
  // in their own threads).
  state.counters["per_frame"] = benchmark::Counter(
      double(state.iterations()), benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}

void BM_Render(benchmark::State& state) {
  Renderer r{GlBackend::osmesa};
  const fsi::FieldView view = bench_view();
  const FrameSpec spec = bench_spec(int(state.range(0)));
  for (auto _ : state) benchmark::DoNotOptimize(r.render(view, spec));
  per_frame_counter(state);
}
BENCHMARK(BM_Render)
    ->Arg(1)
    ->Arg(2)
    ->ArgName("supersample")
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

void BM_RenderMesh(benchmark::State& state) {
  Renderer r{GlBackend::osmesa};
  const fsi::FieldView view = bench_view();
  FrameSpec spec = bench_spec(int(state.range(0)));
  spec.show_mesh = true;
  for (auto _ : state) benchmark::DoNotOptimize(r.render(view, spec));
  per_frame_counter(state);
}
BENCHMARK(BM_RenderMesh)
    ->Arg(1)
    ->Arg(2)
    ->ArgName("supersample")
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

void BM_WritePng(benchmark::State& state) {
  Renderer r{GlBackend::osmesa};
  const Image frame = r.render(bench_view(), bench_spec(2));
  const auto file = scratch("frame.png");
  for (auto _ : state) write_png(file, frame);
  state.counters["bytes"] = double(std::filesystem::file_size(file));
  per_frame_counter(state);
}
BENCHMARK(BM_WritePng)->Unit(benchmark::kMillisecond)->UseRealTime();

// What fsi-movie does per picture: draw the frame with the default FrameSpec (its
// supersampling) and write it as a PNG file with write_png's default settings.
void BM_FrameRenderAndPng(benchmark::State& state, int width, int height) {
  Renderer r{GlBackend::osmesa};
  const fsi::FieldView view = bench_view();
  FrameSpec spec;
  spec.width = width;
  spec.height = height;
  spec.quantity = Quantity::vy;
  spec.range = ColorRange{-0.2, 0.2};
  spec.title = "ball_drop";
  const auto file = scratch("frame_and_png.png");
  Image frame;  // reused, as fsi-movie does
  for (auto _ : state) {
    r.render(view, spec, frame);
    write_png(file, frame);
  }
  state.counters["bytes"] = double(std::filesystem::file_size(file));
  per_frame_counter(state);
}
BENCHMARK_CAPTURE(BM_FrameRenderAndPng, 1280x720, 1280, 720)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

#ifdef FSI_RENDER_HAS_VIDEO
// Frames cycle through 10 time levels of the falling ball so the encoder sees motion;
// the writer is closed (flushed) inside the timing, so buffered frames are counted.
void BM_EncodeVideo(benchmark::State& state, std::string preset) {
  Renderer r{GlBackend::osmesa};
  std::vector<Image> frames;
  for (int i = 0; i < 10; ++i)
    frames.push_back(r.render(bench_view(1.0 + 0.05 * i), bench_spec(2)));
  VideoOptions o;
  o.preset = preset;
  const auto file = scratch("movie-" + preset + ".mp4");
  long n = 0;
  {
    VideoWriter video(file, frame_width, frame_height, o);
    for (auto _ : state) video.write(frames[n++ % frames.size()]);
    video.close();
  }
  state.counters["bytes_per_frame"] = double(std::filesystem::file_size(file)) / double(n);
  per_frame_counter(state);
}
BENCHMARK_CAPTURE(BM_EncodeVideo, medium, std::string("medium"))
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK_CAPTURE(BM_EncodeVideo, veryfast, std::string("veryfast"))
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
#endif

}  // namespace

BENCHMARK_MAIN();
