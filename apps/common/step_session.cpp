// fsi-step's commands. Each handler returns the whole answer; handle() turns every
// exception into {"error": ...}, so no input ends the session but "quit" and EOF.
#include "step_session.hpp"

#include <fsi/error.hpp>
#include <fsi/png.hpp>
#include <sstream>
#include <vector>

#include "frame_options.hpp"
#include "functionals_json.hpp"
#include "scenario_overrides.hpp"
#include "triangle_quality.hpp"

namespace fsi::app {
namespace {

constexpr const char* kOrigin = "<command>";

constexpr const char* kCommands[] = {
    "step [N]",
    "render FILE.png [field=vx|vy|vmag|p|umag] [zoom=x0,y0,x1,y1] [size=WxH] [mesh=0|1] "
    "[stretch=0|1]",
    "functionals",
    "quality   (the sub-triangles' largest angles and smallest area: where the cut mesh is poor)",
    "set KEY VALUE   (KEY: a /numerics key, e.g. time_step_s, newton_budget, failure_policy)",
    "numerics",
    "save FILE",
    "load FILE",
    "remesh SCENARIO.json   (go on on that scenario's mesh: everything else must be the same)",
    "rereference   (u measured from the ball moved and turned with the body: its rigid motion leaves u)",
    "scenario FILE.json   (writes the scenario in use: its numerics as set, its mesh as remeshed)",
    "help",
    "quit"};

std::vector<std::string> split_words(const std::string& line) {
  std::istringstream in(line);
  std::vector<std::string> words;
  for (std::string w; in >> w;) words.push_back(w);
  return words;
}

void want_args(const std::vector<std::string>& words, std::size_t lo, std::size_t hi,
               const char* form) {
  if (words.size() - 1 < lo || words.size() - 1 > hi) {
    throw InputError(kOrigin, words[0], std::string("usage: ") + form);
  }
}

/// The last step's report in full: what a script needs to see why Newton stalled.
nlohmann::ordered_json report_json(const StepReport& r) {
  nlohmann::ordered_json j;
  j["converged"] = r.converged;
  j["accepted"] = r.accepted;
  j["time_step_s"] = r.time_step_s;
  j["newton_iterations"] = r.newton_iterations;
  j["factorizations"] = r.factorizations;
  j["jacobian_assemblies"] = r.jacobian_assemblies;
  j["krylov_iterations"] = r.krylov_iterations;
  j["residual_norms"] = r.residual_norms;
  if (const ResidualPeak& w = r.largest_residual; w.node >= 0) {
    j["largest_residual"] = {{"equation", equation_name(w.equation)},
                             {"node", w.node},
                             {"where_m", {w.where_m.x, w.where_m.y}},
                             {"phase", w.phase},
                             {"scaled_value", w.scaled_value}};
  }
  j["seconds"] = {{"geometry", r.geometry_seconds}, {"mapping", r.mapping_seconds},
                  {"assembly", r.assembly_seconds}, {"factorization", r.factorization_seconds},
                  {"solve", r.solve_seconds}};
  nlohmann::ordered_json events = nlohmann::ordered_json::array();
  for (const StepEvent& e : r.events) events.push_back(e.text);
  j["events"] = events;
  return j;
}

}  // namespace

StepSession::StepSession(const Scenario& scenario)
    : engine_(scenario), numerics_(scenario.numerics) {}

const char* StepSession::hint() {
  return "fsi-step: one command per line, one JSON answer each; 'help' lists them, "
         "'quit' or Ctrl-D ends.";
}

nlohmann::ordered_json StepSession::ok() const {
  nlohmann::ordered_json j;
  j["ok"] = true;
  j["t"] = engine_.state().time_s;
  j["step"] = engine_.state().step;
  return j;
}

std::optional<nlohmann::ordered_json> StepSession::handle(const std::string& line) {
  const std::vector<std::string> w = split_words(line);
  if (w.empty() || w[0][0] == '#') return std::nullopt;
  try {
    const std::string& c = w[0];
    if (c == "step") {
      want_args(w, 0, 1, "step [N]");
      return step(w.size() > 1 ? parse_int(w[1], 1, 1000000, kOrigin, "step N") : 1);
    }
    if (c == "render") return render(w);
    if (c == "functionals") {
      want_args(w, 0, 0, "functionals");
      auto j = ok();
      j["functionals"] = functionals_json(engine_.state().functionals);
      return j;
    }
    if (c == "quality") {
      want_args(w, 0, 0, "quality");
      const TriangleQuality q = measure_triangles(engine_.view());
      auto j = ok();
      j["quality"] = {{"triangles", q.triangles},
                      {"max_angle_above_150_deg", q.max_angle_above_150_deg},
                      {"max_angle_above_160_deg", q.max_angle_above_160_deg},
                      {"max_angle_above_170_deg", q.max_angle_above_170_deg},
                      {"worst_max_angle_deg", q.worst_max_angle_deg},
                      {"worst_at_m", {q.worst_at.x, q.worst_at.y}},
                      {"smallest_area_m2", q.smallest_area_m2},
                      {"smallest_at_m", {q.smallest_at.x, q.smallest_at.y}}};
      return j;
    }
    if (c == "set") {
      want_args(w, 2, 2, "set KEY VALUE");
      return set(w[1], w[2]);
    }
    if (c == "numerics") {
      want_args(w, 0, 0, "numerics");
      auto j = ok();
      Scenario s = engine_.scenario();
      s.numerics = numerics_;
      j["numerics"] = nlohmann::ordered_json::parse(to_json(s))["numerics"];
      return j;
    }
    if (c == "save" || c == "load") {
      want_args(w, 1, 1, c == "save" ? "save FILE" : "load FILE");
      if (c == "save") {
        save_checkpoint(engine_, w[1]);
      } else {
        load_checkpoint(engine_, w[1]);
      }
      auto j = ok();
      j["file"] = w[1];
      return j;
    }
    if (c == "remesh") {
      want_args(w, 1, 1, "remesh SCENARIO.json");
      // The run's scenario (with the numerics set in this session) on the file's mesh.
      Scenario remeshed = engine_.scenario();
      remeshed.numerics = numerics_;
      remeshed.mesh = load_scenario(w[1]).mesh;
      Engine next(remeshed);
      next.remesh_from(engine_);
      engine_ = std::move(next);
      renderer_.reset();  // it may hold the old mesh's buffers
      auto j = ok();
      j["file"] = w[1];
      j["nodes"] = engine_.view().nodes.size();
      return j;
    }
    if (c == "rereference") {
      want_args(w, 0, 0, "rereference");
      auto j = ok();
      j["angle_rad"] = engine_.rereference();
      const State& s = engine_.state();
      j["reference_offset_m"] = {s.reference_offset_x_m, s.reference_offset_y_m};
      j["reference_rotation_rad"] = s.reference_rotation_rad;
      if (!s.body_references.empty()) {  // several bodies: each one's, body1 first
        nlohmann::ordered_json bodies = nlohmann::ordered_json::array();
        for (const State::BodyReference& b : s.body_references)
          bodies.push_back({{"reference_offset_m", {b.offset_x_m, b.offset_y_m}}, {"reference_rotation_rad", b.rotation_rad}});
        j["bodies"] = std::move(bodies);
      }
      return j;
    }
    if (c == "scenario") {
      want_args(w, 1, 1, "scenario FILE.json");
      Scenario s = engine_.scenario();
      s.numerics = numerics_;
      write_scenario_file(s, w[1]);
      auto j = ok();
      j["file"] = w[1];
      return j;
    }
    if (c == "help") {
      auto j = ok();
      j["commands"] = kCommands;
      return j;
    }
    if (c == "quit" || c == "exit") {
      quit_ = true;
      auto j = ok();
      j["bye"] = true;
      return j;
    }
    throw InputError(kOrigin, c, "unknown command; 'help' lists the commands");
  } catch (const std::exception& e) {
    return nlohmann::ordered_json{{"error", e.what()}};
  }
}

nlohmann::ordered_json StepSession::step(long n) {
  StepReport last;  // n >= 1: the loop runs at least once
  for (long i = 0; i < n && (i == 0 || last.accepted); ++i) {
    last = engine_.step();
    (last.converged ? converged_ : unconverged_) += 1;
  }
  auto j = ok();
  j["converged_steps"] = converged_;
  j["unconverged_steps"] = unconverged_;
  j["last_message"] = last.message;
  j["last_report"] = report_json(last);
  // Where the body (each body) is now: the functionals of the state after the steps.
  j["functionals"] = functionals_json(engine_.state().functionals);
  if (!last.accepted) j["rejected"] = true;  // the state did not advance; change numerics first
  return j;
}

nlohmann::ordered_json StepSession::render(const std::vector<std::string>& words) {
  if (words.size() < 2 || words[1].find('=') != std::string::npos) {
    throw InputError(kOrigin, "render", std::string("usage: ") + kCommands[1]);
  }
  const Scenario& s = engine_.scenario();
  render::FrameSpec spec;
  spec.width = s.output.width_px;
  spec.height = s.output.height_px;
  spec.quantity = render::parse_quantity(s.output.field);
  spec.show_mesh = s.output.mesh_overlay;
  for (std::size_t i = 2; i < words.size(); ++i) {
    const std::size_t eq = words[i].find('=');
    const std::string key = words[i].substr(0, eq);
    const std::string value = eq == std::string::npos ? "" : words[i].substr(eq + 1);
    if (key == "field") {
      spec.quantity = parse_field(value, kOrigin, "render field");
    } else if (key == "zoom") {
      spec.window = parse_zoom(value, kOrigin, "render zoom");
    } else if (key == "size") {
      parse_size(value, kOrigin, "render size", spec.width, spec.height);
    } else if (key == "mesh") {
      spec.show_mesh = parse_int(value, 0, 1, kOrigin, "render mesh") == 1;
    } else if (key == "stretch") {
      // 1: the zoom window fills the picture (x and y scaled apart), e.g. for a 1 mm film.
      spec.keep_aspect = parse_int(value, 0, 1, kOrigin, "render stretch") == 0;
    } else {
      throw InputError(kOrigin, words[i],
                       "unknown render option; field=, zoom=, size=, mesh=, stretch=");
    }
  }
  const FieldView view = engine_.view();
  if (s.output.range_min < s.output.range_max) {
    spec.range = render::ColorRange{s.output.range_min, s.output.range_max};
  } else {
    spec.range = render::auto_range(view, spec.quantity);
  }
  if (!renderer_) renderer_ = std::make_unique<render::Renderer>();
  render::write_png(words[1], renderer_->render(view, spec));
  auto j = ok();
  j["file"] = words[1];
  j["field"] = std::string(render::quantity_info(spec.quantity).name);
  j["width"] = spec.width;
  j["height"] = spec.height;
  j["stretch"] = !spec.keep_aspect;
  j["range"] = {spec.range->lo, spec.range->hi};
  return j;
}

nlohmann::ordered_json StepSession::set(const std::string& key, const std::string& value) {
  if (key.empty() || key.find('/') != std::string::npos) {
    throw InputError(kOrigin, key, "set wants a key of /numerics, e.g. time_step_s");
  }
  Scenario current = engine_.scenario();
  current.numerics = numerics_;
  const Scenario changed =
      apply_overrides(current, {{"/numerics/" + key, parse_value(value)}}, kOrigin);
  numerics_ = changed.numerics;
  engine_.set_numerics(numerics_);
  auto j = ok();
  j["numerics"] = nlohmann::ordered_json::parse(to_json(changed))["numerics"];
  return j;
}

}  // namespace fsi::app
