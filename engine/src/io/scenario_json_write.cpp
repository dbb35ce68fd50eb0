// Scenario to JSON (every field, doubles in shortest round-trip form) and its fingerprint.
#include <cstdio>
#include <nlohmann/json.hpp>
#include <string>
#include <optional>
#include <type_traits>
#include <utility>

#include "fsi/scenario.hpp"
#include "io/fingerprint.hpp"
#include "io/fnv1a.hpp"
#include "io/scenario_schema.hpp"

namespace fsi {
namespace io {
namespace {

/// Builds a JSON object from a struct's visit_fields. `Json` is nlohmann::ordered_json
/// for files people read (schema order) and nlohmann::json (sorted keys) for hashing.
template <class Json>
class JsonWriter {
 public:
  Json object = Json::object();

  template <class T, class R>
  void operator()(std::string_view key, const T& member, const R& rule) {
    object[std::string(key)] = value(member, rule);
  }
  /// An optional object left out is not written.
  template <class T, class R>
  void operator()(std::string_view key, const std::optional<T>& member, const R& rule) {
    if (member) object[std::string(key)] = value(*member, rule);
  }

 private:
  template <class R>
  static Json value(const double& v, const R&) {
    return v;
  }
  template <class R>
  static Json value(const int& v, const R&) {
    return v;
  }
  template <class R>
  static Json value(const bool& v, const R&) {
    return v;
  }
  template <class R>
  static Json value(const std::string& v, const R&) {
    return v;
  }
  /// An enum stored by name (FailurePolicy, Method).
  template <class E>
    requires std::is_enum_v<E>
  static Json value(const E& v, const Choice& rule) {
    return std::string(rule.names[static_cast<std::size_t>(v)]);
  }
  template <class R>
  static Json value(const Point2& p, const R&) {
    return Json::array({p.x, p.y});
  }
  template <class R>
  static Json value(const Segment2& s, const R& rule) {
    return Json::array({value(s.a, rule), value(s.b, rule)});
  }
  template <class R>
  static Json value(const std::array<Point2, 4>& corners, const R& rule) {
    Json a = Json::array();
    for (const Point2& p : corners) a.push_back(value(p, rule));
    return a;
  }
  template <class T, class R>
  static Json value(const std::vector<T>& items, const List<R>& rule) {
    Json a = Json::array();
    for (const T& item : items) a.push_back(value(item, rule.item));
    return a;
  }
  template <class T>
  static Json value(const T& member, const Fields&) {
    JsonWriter nested;
    visit_fields(nested, member);
    return nested.object;
  }
};

}  // namespace
}  // namespace io

std::string to_json(const Scenario& scenario) {
  io::JsonWriter<nlohmann::ordered_json> writer;
  io::visit_fields(writer, scenario);
  // The form the scene uses: one body or the list (a file gives one of them).
  writer.object.erase(scenario.bodies.empty() ? "bodies" : "body");
  // Names are checked to be ASCII by validate(); `replace` keeps an unvalidated
  // scenario with broken UTF-8 printable instead of throwing.
  return writer.object.dump(2, ' ', false, nlohmann::json::error_handler_t::replace) + "\n";
}

namespace io {
namespace {

/// The canonical JSON of a checkpoint format 3 fingerprint: every field except those
/// that do not change any step.
nlohmann::json fingerprint_object_v3(const Scenario& scenario) {
  io::JsonWriter<nlohmann::json> writer;  // sorted keys: independent of member order
  io::visit_fields(writer, scenario);
  // The name, the output settings and the end time do not change any step: a finished
  // run can be resumed from its checkpoint with a later end time.
  writer.object.erase("name");
  writer.object.erase("output");
  // The preset the numerics came from: only the resolved numerics below count.
  writer.object.erase("method");
  writer.object["numerics"].erase("end_time_s");
  // Mesh keys added later count only when used, for the same reason as the numerics below.
  for (auto& block : writer.object["mesh"]["blocks"])
    if (block["y_right"].empty()) block.erase("y_right");
  // Numerics added after checkpoint version 3 count only when set: at the chapter's value
  // (numerics_for(Method::chapter), the defaults when they were added) every step is the
  // same as before they existed, so older checkpoints stay loadable.
  const NumericsSpec defaults = numerics_for(Method::chapter);
  const NumericsSpec& n = scenario.numerics;
  // The step limits as the lengths they were written as before the doublings.
  auto& numerics = writer.object["numerics"];
  numerics.erase("time_step_max_doublings");
  numerics.erase("time_step_wall_zone_doublings");
  numerics["time_step_max_s"] = n.time_step_max_s();
  numerics["time_step_wall_zone_max_s"] = n.time_step_wall_zone_max_s();
  const std::pair<const char*, bool> at_default[] = {
      {"cip_wall_film_factor", n.cip_wall_film_factor == defaults.cip_wall_film_factor},
      {"cut_snap", n.cut_snap == defaults.cut_snap},
      {"cut_snap_distance_m", n.cut_snap_distance_m == defaults.cut_snap_distance_m},
      {"cut_align_fraction", n.cut_align_fraction == defaults.cut_align_fraction},
      {"cavitation_pressure_pa", n.cavitation_pressure_pa == defaults.cavitation_pressure_pa},
      {"backflow_beta", n.backflow_beta == defaults.backflow_beta},
      {"accept_flagged_reduction", n.accept_flagged_reduction == defaults.accept_flagged_reduction},
      {"accept_flagged_max_residual", n.accept_flagged_max_residual == defaults.accept_flagged_max_residual},
      {"time_step_max_s", n.time_step_max_doublings == defaults.time_step_max_doublings},
      {"time_step_wall_zone_m", n.time_step_wall_zone_m == defaults.time_step_wall_zone_m},
      {"time_step_patch_fraction", n.time_step_patch_fraction == defaults.time_step_patch_fraction},
      {"time_step_wall_zone_max_s", n.time_step_wall_zone_doublings == defaults.time_step_wall_zone_doublings},
      {"time_error_tolerance_m", n.time_error_tolerance_m == defaults.time_error_tolerance_m},
      {"accept_best_max_residual", n.accept_best_max_residual == defaults.accept_best_max_residual},
      {"krylov_iterations", n.krylov_iterations == defaults.krylov_iterations},
      {"assembly_threads", n.assembly_threads == defaults.assembly_threads},
      {"rereference_angle_rad", n.rereference_angle_rad == defaults.rereference_angle_rad}};
  for (const auto& [key, is_default] : at_default)
    if (is_default) writer.object["numerics"].erase(key);
  // Likewise contact.corners_as_walls at its default: checkpoints written before the key
  // existed go on with tread edges that push like walls (docs/method.md, "Corners push
  // like walls").
  if (scenario.contact.corners_as_walls == ContactSpec{}.corners_as_walls)
    writer.object["contact"].erase("corners_as_walls");
  // And the corner barrier at its defaults (docs/method.md, "Corner barrier").
  if (scenario.contact.corner_barrier_speed_mps == ContactSpec{}.corner_barrier_speed_mps)
    writer.object["contact"].erase("corner_barrier_speed_mps");
  if (scenario.contact.corner_barrier_reach_m == ContactSpec{}.corner_barrier_reach_m)
    writer.object["contact"].erase("corner_barrier_reach_m");
  // And buoyancy off and the circle, as every scenario was before the keys existed.
  if (!scenario.buoyancy) writer.object.erase("buoyancy");
  // The same for the keys of several bodies and other shapes.
  const auto erase_circle_keys = [](nlohmann::json& body) {
    if (body["shape"] != "circle") return;
    body.erase("shape");
    body.erase("half_size_m");
    body.erase("angle_rad");
  };
  erase_circle_keys(writer.object["body"]);
  for (auto& body : writer.object["bodies"]) erase_circle_keys(body);
  if (scenario.bodies.empty()) writer.object.erase("bodies");
  return std::move(writer.object);
}

std::string hash_hex(const nlohmann::json& object) {
  const std::string canonical = object.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
  char hex[17];
  std::snprintf(hex, sizeof hex, "%016llx", static_cast<unsigned long long>(io::fnv1a(canonical)));
  return hex;
}

}  // namespace

std::string fingerprint_v3(const Scenario& scenario) { return hash_hex(fingerprint_object_v3(scenario)); }

}  // namespace io

std::string fingerprint(const Scenario& scenario) {
  nlohmann::json object = io::fingerprint_object_v3(scenario);
  // Since checkpoint version 4 the solver controls are left out too: they decide how hard
  // Newton tries and what happens when it fails, not the discrete problem a state belongs
  // to, so a run may go on from its checkpoint with another budget or failure policy
  // (the rho_f = 1000 stairs run, docs/solver.md "Failure policy").
  for (const char* key : io::kSolverControlKeys) object["numerics"].erase(key);
  return io::hash_hex(object);
}

}  // namespace fsi
