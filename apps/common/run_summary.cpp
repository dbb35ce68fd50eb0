// summary.json: counts and first occurrences, so a long run is judged without its logs.
#include "run_summary.hpp"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <stdexcept>

#include "functionals_json.hpp"

namespace fsi::app {
namespace {

const char* kind_name(StepEvent::Kind k) {
  switch (k) {
    case StepEvent::Kind::real_contact:
      return "real_contact";
    case StepEvent::Kind::contact_force_active:
      return "contact_force_active";
    case StepEvent::Kind::step_halved:
      return "step_halved";
    case StepEvent::Kind::rolled_back:
      return "rolled_back";
    case StepEvent::Kind::non_finite:
      return "non_finite";
    case StepEvent::Kind::degenerated:
      return "degenerated";
    case StepEvent::Kind::contact_retried:
      return "contact_retried";
    case StepEvent::Kind::left_domain:
      return "left_domain";
  }
  return "unknown";
}

bool kind_from_name(const std::string& name, StepEvent::Kind& kind) {
  for (StepEvent::Kind k : {StepEvent::Kind::real_contact, StepEvent::Kind::contact_force_active,
                            StepEvent::Kind::step_halved, StepEvent::Kind::rolled_back,
                            StepEvent::Kind::non_finite, StepEvent::Kind::degenerated,
                            StepEvent::Kind::contact_retried, StepEvent::Kind::left_domain}) {
    if (name == kind_name(k)) {
      kind = k;
      return true;
    }
  }
  return false;
}

/// An event of an earlier summary.json ("events" or "contacts" entry).
StepEvent event_from_json(const nlohmann::json& j, StepEvent::Kind kind, const char* time_key) {
  StepEvent e;
  e.kind = kind;
  e.time_s = j.value(time_key, 0.0);
  e.wall = j.value("wall", -1);
  e.text = j.value("text", std::string());
  if (j.contains("where_m") && j["where_m"].is_array() && j["where_m"].size() == 2) {
    e.where_m = {j["where_m"][0].get<double>(), j["where_m"][1].get<double>()};
  }
  return e;
}

}  // namespace

RunSummary::RunSummary(const Scenario& scenario)
    : name_(scenario.name),
      source_(scenario.source.string()),
      fingerprint_(fingerprint(scenario)),
      end_time_s_(scenario.numerics.end_time_s) {}

void RunSummary::count_step_length(double length_s) {
  char text[32];
  std::snprintf(text, sizeof text, "%.6g", length_s);
  ++step_lengths_[std::strtod(text, nullptr)];
}

void RunSummary::record_step(const StepReport& report, const State& state) {
  ++steps_;
  if (report.accepted) count_step_length(report.time_step_s);
  if (!report.converged) ++unconverged_;
  if (!report.accepted) ++rejected_;
  time_s_ = state.time_s;
  last_ = state.functionals;
  const double d = state.functionals.min_distance_m;
  if (report.accepted && (!have_min_ || d < min_distance_m_)) {
    have_min_ = true;
    min_distance_m_ = d;
    min_distance_time_s_ = state.time_s;
  }
  std::set<int> touching;
  for (const StepEvent& e : report.events) {
    ++events_.try_emplace(e.kind, EventRecord{e, 0}).first->second.count;
    if (e.kind != StepEvent::Kind::real_contact) continue;
    touching.insert(e.wall);
    if (!touching_walls_.contains(e.wall)) touch_downs_.push_back(e);
  }
  touching_walls_ = std::move(touching);
}

void RunSummary::continue_from(const EarlierRun& earlier) {
  continued_from_step_ = earlier.step;
  double previous_time_s = 0.0;  // the rows start at step 1
  for (const EarlierRun::Row& r : earlier.rows) {
    ++steps_;
    count_step_length(r.time_s - previous_time_s);
    previous_time_s = r.time_s;
    if (!r.converged) ++unconverged_;
    time_s_ = r.time_s;
    last_ = r.functionals;
    if (!have_min_ || r.functionals.min_distance_m < min_distance_m_) {
      have_min_ = true;
      min_distance_m_ = r.functionals.min_distance_m;
      min_distance_time_s_ = r.time_s;
    }
  }
  // Events and touch-downs up to the checkpoint's time (half a step of slack for rounding).
  const double until = earlier.time_s + 1e-9;
  const nlohmann::json& j = earlier.summary;
  if (!j.is_object()) return;
  if (j.contains("events") && j["events"].is_array()) {
    for (const nlohmann::json& e : j["events"]) {
      StepEvent::Kind kind;
      if (!e.is_object() || !kind_from_name(e.value("kind", std::string()), kind)) continue;
      if (e.value("first_time_s", 1e300) > until) continue;
      events_[kind] = EventRecord{event_from_json(e, kind, "first_time_s"), 1};
    }
  }
  if (j.contains("contacts") && j["contacts"].is_array()) {
    for (const nlohmann::json& c : j["contacts"]) {
      if (!c.is_object() || c.value("time_s", 1e300) > until) continue;
      touch_downs_.push_back(event_from_json(c, StepEvent::Kind::real_contact, "time_s"));
    }
  }
  // Still touching at the checkpoint: the next step's contact is not a new touch-down.
  if (!earlier.rows.empty() && earlier.rows.back().functionals.min_distance_m < 1e-12 &&
      !touch_downs_.empty()) {
    touching_walls_.insert(touch_downs_.back().wall);
  }
}

void RunSummary::add_output(const std::filesystem::path& file) {
  if (std::find(outputs_.begin(), outputs_.end(), file) == outputs_.end()) outputs_.push_back(file);
}

nlohmann::ordered_json RunSummary::to_json(double wall_seconds, bool is_final,
                                           const std::filesystem::path& folder) const {
  nlohmann::ordered_json j;
  j["scenario"] = {{"name", name_}, {"source", source_}, {"fingerprint", fingerprint_}};
  j["final"] = is_final;  // false: written during the run (or the process died)
  j["interrupted"] = interrupted_;
  j["stop_reason"] = stop_reason_;
  if (continued_from_step_ >= 0) j["continued_from_step"] = continued_from_step_;
  j["steps"] = steps_;
  j["simulated_time_s"] = time_s_;
  j["end_time_s"] = end_time_s_;
  j["wall_time_s"] = wall_seconds;
  j["converged_steps"] = steps_ - unconverged_;
  j["unconverged_steps"] = unconverged_;
  j["rejected_steps"] = rejected_;
  nlohmann::ordered_json by_length = nlohmann::ordered_json::array();
  for (const auto& [length_s, n] : step_lengths_) by_length.push_back({{"length_s", length_s}, {"steps", n}});
  j["step_lengths"] = std::move(by_length);
  if (have_min_) {
    j["min_distance"] = {{"distance_m", number_json(min_distance_m_)},
                         {"time_s", min_distance_time_s_}};
  } else {
    j["min_distance"] = nullptr;
  }
  nlohmann::ordered_json events = nlohmann::ordered_json::array();
  for (const auto& [kind, rec] : events_) {
    nlohmann::ordered_json e;
    e["kind"] = kind_name(kind);
    e["first_time_s"] = rec.first.time_s;
    if (kind == StepEvent::Kind::real_contact || kind == StepEvent::Kind::degenerated ||
        kind == StepEvent::Kind::left_domain)
      e["where_m"] = {rec.first.where_m.x, rec.first.where_m.y};
    if (kind == StepEvent::Kind::real_contact) e["wall"] = rec.first.wall;
    e["steps"] = rec.count;
    e["text"] = rec.first.text;
    events.push_back(std::move(e));
  }
  j["events"] = std::move(events);
  nlohmann::ordered_json contacts = nlohmann::ordered_json::array();
  std::string sequence;
  for (const StepEvent& c : touch_downs_) {
    contacts.push_back({{"wall", c.wall}, {"time_s", c.time_s}, {"where_m", {c.where_m.x, c.where_m.y}}});
    char item[48];
    std::snprintf(item, sizeof item, "%s%d@%.4f", sequence.empty() ? "" : ";", c.wall, c.time_s);
    sequence += item;
  }
  j["contacts"] = std::move(contacts);
  j["contact_sequence"] = sequence;
  j["final_functionals"] = functionals_json(last_);
  nlohmann::ordered_json outputs = nlohmann::ordered_json::array();
  for (const auto& f : outputs_) outputs.push_back(f.lexically_relative(folder).generic_string());
  j["outputs"] = std::move(outputs);
  return j;
}

void RunSummary::write(const std::filesystem::path& file, double wall_seconds,
                       bool is_final) const {
  const std::filesystem::path tmp = file.string() + ".tmp";
  {
    std::ofstream out(tmp, std::ios::trunc);
    out << to_json(wall_seconds, is_final, file.parent_path()).dump(2) << '\n';
    if (!out) throw std::runtime_error(tmp.string() + ": cannot write the run summary");
  }
  std::filesystem::rename(tmp, file);
}

}  // namespace fsi::app
