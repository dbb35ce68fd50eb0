// fsi-movie end to end on a tiny scenario: every output of a finished run, and a run
// stopped by SIGINT that still leaves a playable movie and an honest summary.
#include <fcntl.h>
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fsi/output.hpp>
#include <fsi/png.hpp>
#include <fsi/scenario.hpp>
#include <fstream>
#include <iterator>
#include <nlohmann/json.hpp>
#include <string>
#include <thread>
#include <vector>
#ifdef FSI_RENDER_HAS_VIDEO
#include <fsi/video.hpp>
#endif

namespace {

namespace fs = std::filesystem;

const fs::path kScenario = fs::path(FSI_SOURCE_DIR) / "tests/data/tiny_drop.json";

fs::path fresh_dir(const std::string& name) {
  const fs::path dir = fs::path(FSI_BINARY_DIR) / "test_tmp" / "movie_app" / name;
  fs::remove_all(dir);
  fs::create_directories(dir.parent_path());
  return dir;
}

std::string read_text(const fs::path& file) {
  std::ifstream in(file);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

std::vector<std::string> read_lines(const fs::path& file) {
  std::ifstream in(file);
  std::vector<std::string> lines;
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

/// `line` of a CSV without its cell number `index` (0-based).
std::string without_cell(std::string line, int index) {
  std::size_t begin = 0;
  for (int cell = 0; cell < index; ++cell) begin = line.find(',', begin) + 1;
  const std::size_t end = line.find(',', begin);
  line.erase(begin, end == std::string::npos ? std::string::npos : end + 1 - begin);
  return line;
}

/// Starts fsi-movie with `args`, stdout and stderr into `log`. Returns the child's pid.
pid_t start_movie(const std::vector<std::string>& args, const fs::path& log) {
  std::vector<std::string> argv_text{FSI_MOVIE_EXE};
  argv_text.insert(argv_text.end(), args.begin(), args.end());
  const pid_t pid = fork();
  if (pid == 0) {
    const int fd = open(log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    dup2(fd, STDOUT_FILENO);
    dup2(fd, STDERR_FILENO);
    std::vector<char*> argv;
    for (std::string& a : argv_text) argv.push_back(a.data());
    argv.push_back(nullptr);
    execv(argv[0], argv.data());
    _exit(127);
  }
  return pid;
}

/// Waits for the child; its exit code, or 128 + signal.
int wait_exit_code(pid_t pid) {
  int status = 0;
  waitpid(pid, &status, 0);
  return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}

TEST(MovieApp, WritesEveryOutputOfAShortRun) {
  const fs::path out = fresh_dir("short");
  const pid_t pid = start_movie(
      {kScenario.string(), out.string(), "--frame-every", "5", "--size", "320x240", "--quiet"},
      out.string() + ".log");
  ASSERT_EQ(wait_exit_code(pid), 0) << read_text(out.string() + ".log");

  for (const char* frame : {"frame_000000.png", "frame_000005.png", "frame_000010.png"}) {
    const fsi::render::Image im = fsi::render::read_png(out / "frames" / frame);
    EXPECT_EQ(im.width, 320);
    EXPECT_EQ(im.height, 240);
  }
#ifdef FSI_RENDER_HAS_VIDEO
  const fsi::render::VideoInfo info = fsi::render::probe_video(out / "movie.mp4");
  EXPECT_EQ(info.frames, 3);
  EXPECT_EQ(info.width, 320);
#endif

  const std::vector<std::string> csv = read_lines(out / "functionals.csv");
  ASSERT_EQ(csv.size(), 11u) << "header + one row per step";
  EXPECT_EQ(csv[0], fsi::io::functionals_csv_header(true));
  EXPECT_EQ(csv[10].substr(0, 3), "10,");

  for (const char* plot :
       {"plot_distance.png", "plot_height.png", "plot_velocity.png", "plot_mass.png"}) {
    EXPECT_FALSE(fsi::render::read_png(out / plot).empty()) << plot;
  }

  const std::string pvd = read_text(out / "vtk/frames.pvd");
  for (const char* vtu : {"frame_000000.vtu", "frame_000005.vtu", "frame_000010.vtu"}) {
    EXPECT_NE(pvd.find(vtu), std::string::npos) << vtu;
    EXPECT_TRUE(fs::exists(out / "vtk" / vtu)) << vtu;
  }

  const auto summary = nlohmann::json::parse(read_text(out / "summary.json"));
  EXPECT_EQ(summary["scenario"]["name"], "tiny_drop");
  EXPECT_EQ(summary["scenario"]["fingerprint"].get<std::string>().size(), 16u);
  EXPECT_EQ(summary["steps"], 10);
  EXPECT_EQ(summary["final"], true);
  EXPECT_EQ(summary["interrupted"], false);
  EXPECT_EQ(summary["unconverged_steps"], 0);
  EXPECT_NEAR(summary["simulated_time_s"].get<double>(), 0.1, 1e-9);
  EXPECT_GT(summary["min_distance"]["distance_m"].get<double>(), 0.5);
  EXPECT_TRUE(summary["events"].is_array());
  // The run's scenario is written out and loads again as the same physics and numerics.
  EXPECT_EQ(fsi::fingerprint(fsi::load_scenario(out / "scenario.json")),
            summary["scenario"]["fingerprint"].get<std::string>());
  const std::string outputs = summary["outputs"].dump();
  for (const char* f : {"functionals.csv", "scenario.json", "frames", "vtk/frames.pvd", "plot_mass.png"}) {
    EXPECT_NE(outputs.find(f), std::string::npos) << f;
  }
}

TEST(MovieApp, FramesComeEveryFrameIntervalOfSimulatedTime) {
  // Steps of 2k far from the ground (numerics.time_step_max_doublings = 1, set here in its
  // old form time_step_max_s, which still works; the first one or two are k,
  // the step-length controller starts there): a frame every frame_every x k = 0.02 s of
  // simulated time is one every 2k step, not every second step.
  const fs::path out = fresh_dir("long_steps");
  const pid_t pid = start_movie({kScenario.string(), out.string(), "--frame-every", "2", "--set",
                                 "/numerics/time_step_max_s=0.02", "--no-video", "--no-vtu", "--quiet"},
                                out.string() + ".log");
  ASSERT_EQ(wait_exit_code(pid), 0) << read_text(out.string() + ".log");
  std::vector<std::string> frames;
  for (const auto& e : fs::directory_iterator(out / "frames")) frames.push_back(e.path().filename().string());
  std::sort(frames.begin(), frames.end());
  const auto summary = nlohmann::json::parse(read_text(out / "summary.json"));
  EXPECT_NEAR(summary["simulated_time_s"].get<double>(), 0.1, 1e-9);
  // Frames at t = 0, 0.02, ..., 0.1 s: six, the last after the last step.
  ASSERT_EQ(frames.size(), 6u);
  EXPECT_EQ(frames.front(), "frame_000000.png");
  char last[32];
  std::snprintf(last, sizeof last, "frame_%06d.png", summary["steps"].get<int>());
  EXPECT_EQ(frames.back(), last);
  // Steps of k, then of 2k: fewer than the ten of a constant k.
  const nlohmann::json& lengths = summary["step_lengths"];
  ASSERT_EQ(lengths.size(), 2u) << lengths.dump();
  EXPECT_DOUBLE_EQ(lengths[0]["length_s"].get<double>(), 0.01);
  EXPECT_DOUBLE_EQ(lengths[1]["length_s"].get<double>(), 0.02);
  EXPECT_LE(lengths[0]["steps"].get<int>(), 2) << lengths.dump();
  EXPECT_LE(summary["steps"].get<int>(), 6);
}

TEST(MovieApp, ResumesFromItsCheckpointsBitIdentically) {
  const fs::path full = fresh_dir("checkpointed"), resumed = fresh_dir("resumed");
  const std::vector<std::string> quiet_csv{"--no-png", "--no-video", "--no-vtu", "--quiet"};
  std::vector<std::string> args{kScenario.string(), full.string(), "--checkpoint-every", "4"};
  args.insert(args.end(), quiet_csv.begin(), quiet_csv.end());
  ASSERT_EQ(wait_exit_code(start_movie(args, full.string() + ".log")), 0)
      << read_text(full.string() + ".log");
  EXPECT_TRUE(fs::exists(full / "checkpoints/step_000004.ckpt"));
  EXPECT_TRUE(fs::exists(full / "checkpoints/step_000008.ckpt"));
  // The last state too (the end time falls between), for a --continue to a later end.
  EXPECT_TRUE(fs::exists(full / "checkpoints/step_000010.ckpt"));
  EXPECT_FALSE(fs::exists(full / "checkpoints/step_000009.ckpt"));

  args = {kScenario.string(), resumed.string(), "--resume",
          (full / "checkpoints/step_000004.ckpt").string()};
  args.insert(args.end(), quiet_csv.begin(), quiet_csv.end());
  ASSERT_EQ(wait_exit_code(start_movie(args, resumed.string() + ".log")), 0)
      << read_text(resumed.string() + ".log");
  const std::vector<std::string> a = read_lines(full / "functionals.csv");
  const std::vector<std::string> b = read_lines(resumed / "functionals.csv");
  ASSERT_EQ(a.size(), 11u);
  ASSERT_EQ(b.size(), 7u) << "header + steps 5..10";
  for (std::size_t i = 1; i < b.size(); ++i) EXPECT_EQ(b[i], a[i + 4]) << "row " << i;

  // A finished run can be extended: the end time is not part of the fingerprint.
  const fs::path extended = fresh_dir("extended");
  args = {kScenario.string(), extended.string(), "--end-time", "0.12", "--resume",
          (full / "checkpoints/step_000008.ckpt").string()};
  args.insert(args.end(), quiet_csv.begin(), quiet_csv.end());
  ASSERT_EQ(wait_exit_code(start_movie(args, extended.string() + ".log")), 0)
      << read_text(extended.string() + ".log");
  const std::vector<std::string> c = read_lines(extended / "functionals.csv");
  ASSERT_EQ(c.size(), 5u) << "header + steps 9..12";
  EXPECT_EQ(c[1], a[9]);
  EXPECT_EQ(c[2], a[10]);

  // A checkpoint of another scenario is refused with a message, not run.
  args = {kScenario.string(), resumed.string(), "--set", "/solid/mu_pa=4e5", "--resume",
          (full / "checkpoints/step_000004.ckpt").string(), "--quiet"};
  EXPECT_EQ(wait_exit_code(start_movie(args, resumed.string() + ".log")), 2);
  EXPECT_NE(read_text(resumed.string() + ".log").find("step_000004.ckpt"), std::string::npos);
}

TEST(MovieApp, ExitsWithOneWhenTheEngineStopsTheRunEarly) {
  // One Newton iteration per step, no halving and no best accepted: the engine rejects the
  // first step. summary.json names the stop, and the exit code says the run failed.
  const fs::path out = fresh_dir("rejected");
  const std::vector<std::string> args{kScenario.string(), out.string(), "--no-png", "--no-video", "--no-vtu",
                                      "--quiet", "--set", "/numerics/failure_policy=\"halve_step\"",
                                      "--set", "/numerics/newton_budget=1", "--set", "/numerics/max_halvings=0",
                                      "--set", "/numerics/accept_best_max_residual=1e-300"};
  EXPECT_EQ(wait_exit_code(start_movie(args, out.string() + ".log")), 1) << read_text(out.string() + ".log");
  const auto summary = nlohmann::json::parse(read_text(out / "summary.json"));
  EXPECT_NE(summary["stop_reason"].get<std::string>().find("rejected step 1"), std::string::npos);
  EXPECT_NE(read_text(out.string() + ".log").find("stopped before the end time"), std::string::npos);
}

TEST(MovieApp, ContinuesAStoppedRunInItsFolder) {
  const std::vector<std::string> quiet_csv{"--no-png", "--no-video", "--no-vtu", "--quiet"};
  const fs::path straight = fresh_dir("straight"), stopped = fresh_dir("stopped");
  std::vector<std::string> args{kScenario.string(), straight.string()};
  args.insert(args.end(), quiet_csv.begin(), quiet_csv.end());
  ASSERT_EQ(wait_exit_code(start_movie(args, straight.string() + ".log")), 0);

  // Stopped after step 6 with a checkpoint at step 4: the last state's checkpoint (step 6)
  // is removed as if the process had been killed, so steps 5 and 6 are done again.
  args = {kScenario.string(), stopped.string(), "--end-time", "0.06", "--checkpoint-every", "4"};
  args.insert(args.end(), quiet_csv.begin(), quiet_csv.end());
  ASSERT_EQ(wait_exit_code(start_movie(args, stopped.string() + ".log")), 0);
  ASSERT_TRUE(fs::remove(stopped / "checkpoints/step_000006.ckpt"));
  args = {kScenario.string(), stopped.string(), "--continue"};
  args.insert(args.end(), quiet_csv.begin(), quiet_csv.end());
  ASSERT_EQ(wait_exit_code(start_movie(args, stopped.string() + ".log")), 0)
      << read_text(stopped.string() + ".log");

  EXPECT_EQ(read_lines(stopped / "functionals.csv"), read_lines(straight / "functionals.csv"));
  const auto a = nlohmann::json::parse(read_text(straight / "summary.json"));
  const auto b = nlohmann::json::parse(read_text(stopped / "summary.json"));
  EXPECT_EQ(b["steps"], a["steps"]);
  EXPECT_EQ(b["simulated_time_s"], a["simulated_time_s"]);
  EXPECT_EQ(b["min_distance"], a["min_distance"]);
  EXPECT_EQ(b["continued_from_step"], 4);

  // A run written before the cavitation_rate_m2ps and rotation_rad columns (the oldest
  // runs) continues too; its rows come back in today's columns (the rate is 0 in this fall
  // without suction, the rotation 0 in the rows read back).
  const fs::path older = fresh_dir("older_columns");
  args = {kScenario.string(), older.string(), "--end-time", "0.06", "--checkpoint-every", "4"};
  args.insert(args.end(), quiet_csv.begin(), quiet_csv.end());
  ASSERT_EQ(wait_exit_code(start_movie(args, older.string() + ".log")), 0);
  {
    std::vector<std::string> lines = read_lines(older / "functionals.csv");
    std::ofstream out(older / "functionals.csv", std::ios::trunc);
    for (std::string line : lines) {
      // Drop the 14th and 15th cells (cavitation_rate_m2ps and rotation_rad, after mass_error).
      out << without_cell(without_cell(line, 13), 13) << '\n';
    }
  }
  ASSERT_EQ(read_lines(older / "functionals.csv")[0].find("cavitation"), std::string::npos);
  args = {kScenario.string(), older.string(), "--continue"};
  args.insert(args.end(), quiet_csv.begin(), quiet_csv.end());
  ASSERT_EQ(wait_exit_code(start_movie(args, older.string() + ".log")), 0)
      << read_text(older.string() + ".log");
  // The same rows but for the rotation of those read back (0 there; a few 1e-17 rad in
  // the straight run of this fall).
  const std::vector<std::string> continued = read_lines(older / "functionals.csv");
  const std::vector<std::string> straight_rows = read_lines(straight / "functionals.csv");
  ASSERT_EQ(continued.size(), straight_rows.size());
  for (std::size_t i = 0; i < continued.size(); ++i)
    EXPECT_EQ(without_cell(continued[i], 14), without_cell(straight_rows[i], 14)) << "line " << i;
  EXPECT_EQ(nlohmann::json::parse(read_text(older / "summary.json"))["continued_from_step"], 6)
      << "from the checkpoint of the first run's last state";

  // Without checkpoints there is nothing to continue from: a message, not a run.
  args = {kScenario.string(), straight.string(), "--continue", "--quiet"};
  EXPECT_EQ(wait_exit_code(start_movie(args, straight.string() + ".log2")), 2);
  EXPECT_NE(read_text(straight.string() + ".log2").find("checkpoint"), std::string::npos);
}

// Pixels of the picture's centre column that show the field (coloured, not the grey or
// white around the plot area; |v| uses viridis, never grey).
int coloured_pixels_in_centre_column(const fs::path& png) {
  const fsi::render::Image image = fsi::render::read_png(png);
  int n = 0;
  for (int y = 0; y < image.height; ++y) {
    const std::uint8_t* px = &image.rgba[4 * (std::size_t(y) * image.width + image.width / 2)];
    if (std::abs(int(px[0]) - int(px[1])) + std::abs(int(px[1]) - int(px[2])) > 40) ++n;
  }
  return n;
}

TEST(MovieApp, StretchLetsAThinZoomFillThePicture) {
  // 1 m wide, 5 cm high: with the aspect kept a strip of a few pixels.
  const fs::path kept = fresh_dir("zoom_kept"), stretched = fresh_dir("zoom_stretched");
  std::vector<std::string> args{kScenario.string(), kept.string(), "--end-time", "0.01",
                                "--zoom", "-0.5,-0.75,0.5,-0.7", "--field", "vmag",
                                "--no-video", "--no-vtu", "--quiet"};
  ASSERT_EQ(wait_exit_code(start_movie(args, kept.string() + ".log")), 0)
      << read_text(kept.string() + ".log");
  args[1] = stretched.string();
  args.push_back("--stretch");
  ASSERT_EQ(wait_exit_code(start_movie(args, stretched.string() + ".log")), 0)
      << read_text(stretched.string() + ".log");
  const int strip = coloured_pixels_in_centre_column(kept / "frames/frame_000000.png");
  const int filled = coloured_pixels_in_centre_column(stretched / "frames/frame_000000.png");
  EXPECT_GT(strip, 0);
  EXPECT_LT(strip, 30);
  EXPECT_GT(filled, 120) << "of 240 rows (the rest: title, axes)";
}

TEST(MovieApp, SecondFieldAndFilmInsetOptions) {
  // Velocity and pressure side by side (the film inset is absent while the ball is far
  // from the floor), and a video-only run that writes no PNG at all.
  const fs::path two = fresh_dir("two_panels"), video_only = fresh_dir("video_only");
  ASSERT_EQ(wait_exit_code(start_movie(
                {kScenario.string(), two.string(), "--end-time", "0.01", "--second-field", "p",
                 "--film-inset", "--no-video", "--no-vtu", "--quiet"},
                two.string() + ".log")),
            0)
      << read_text(two.string() + ".log");
  const fsi::render::Image im = fsi::render::read_png(two / "frames/frame_000000.png");
  EXPECT_EQ(im.width, 320);
  // Both halves hold a colour bar: strongly coloured pixels on either side.
  int left = 0, right = 0;
  for (int y = 0; y < im.height; ++y) {
    for (int x = 0; x < im.width; ++x) {
      const std::uint8_t* p = &im.rgba[im.offset(x, y)];
      const bool colour = std::abs(int(p[0]) - int(p[2])) > 80;
      (x < im.width / 2 ? left : right) += colour;
    }
  }
  EXPECT_GT(left, 100);
  EXPECT_GT(right, 100);
  EXPECT_EQ(wait_exit_code(
                start_movie({kScenario.string(), two.string() + "_bad", "--second-field", "speed"},
                            two.string() + "_bad.log")),
            2);
#ifdef FSI_RENDER_HAS_VIDEO
  ASSERT_EQ(wait_exit_code(start_movie({kScenario.string(), video_only.string(), "--end-time",
                                        "0.02", "--no-png", "--no-vtu", "--quiet"},
                                       video_only.string() + ".log")),
            0)
      << read_text(video_only.string() + ".log");
  EXPECT_FALSE(fs::exists(video_only / "frames"));
  EXPECT_GT(fsi::render::probe_video(video_only / "movie.mp4").frames, 0);
#endif
}

TEST(MovieApp, SigintStopsCleanlyWithAPlayableMovie) {
  const fs::path out = fresh_dir("interrupted");
  const auto start = std::chrono::steady_clock::now();
  const pid_t pid = start_movie({kScenario.string(), out.string(), "--end-time", "5",
                                 "--frame-every", "2", "--size", "320x240", "--no-vtu",
                                 "--checkpoint-every", "100000"},
                                out.string() + ".log");
  // The first frame's summary says the run is under way; then let it go on a little.
  while (!fs::exists(out / "summary.json") &&
         std::chrono::steady_clock::now() - start < std::chrono::seconds(20)) {
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
  std::this_thread::sleep_until(start + std::chrono::seconds(2));
  ASSERT_EQ(kill(pid, SIGINT), 0);
  ASSERT_EQ(wait_exit_code(pid), 130) << read_text(out.string() + ".log");

  const auto summary = nlohmann::json::parse(read_text(out / "summary.json"));
  EXPECT_EQ(summary["interrupted"], true);
  EXPECT_EQ(summary["final"], true);
  const long steps = summary["steps"].get<long>();
  EXPECT_GT(steps, 0);
  EXPECT_LT(steps, 500) << "stopped before the end time";
  EXPECT_EQ(read_lines(out / "functionals.csv").size(), std::size_t(steps) + 1);
  EXPECT_TRUE(fs::exists(out / "plot_distance.png"));
  // The state it stopped at is checkpointed, so a --continue loses no steps.
  char checkpoint[48];
  std::snprintf(checkpoint, sizeof checkpoint, "checkpoints/step_%06ld.ckpt", steps);
  EXPECT_TRUE(fs::exists(out / checkpoint)) << checkpoint;
#ifdef FSI_RENDER_HAS_VIDEO
  // A frame every 2 steps, the initial one, and the last state's if it fell between.
  const long frames = fsi::render::probe_video(out / "movie.mp4").frames;
  EXPECT_GE(frames, 1 + steps / 2);
  EXPECT_LE(frames, 2 + steps / 2);
#endif
}

}  // namespace
