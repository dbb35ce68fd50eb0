// validate(): each value against its rule from scenario_schema.hpp, then the relations.
#include <string>
#include <type_traits>
#include <vector>

#include "fsi/scenario.hpp"
#include "io/number_text.hpp"
#include "io/scenario_checks.hpp"
#include "io/scenario_rules.hpp"
#include "io/scenario_schema.hpp"

namespace fsi {
namespace io {
namespace {

/// Walks a struct's visit_fields and checks every member against its rule.
class RuleChecker {
 public:
  explicit RuleChecker(const KeyPath& at) : at_(at) {}

  template <class T, class R>
  void operator()(std::string_view key, const T& member, const R& rule) {
    check_member(at_ / key, member, rule);
  }

 private:
  static void check_member(const KeyPath& at, const double& v, const Real& rule) {
    check(at, v, rule);
  }
  static void check_member(const KeyPath& at, const int& v, const Int& rule) {
    check(at, static_cast<long long>(v), rule);
  }
  static void check_member(const KeyPath&, const bool&, const Flag&) {}
  static void check_member(const KeyPath& at, const std::string& v, const Name& rule) {
    check(at, v, rule);
  }
  static void check_member(const KeyPath& at, const std::string& v, const Choice& rule) {
    check(at, v, rule);
  }
  template <class E>
    requires std::is_enum_v<E>
  static void check_member(const KeyPath& at, const E& v, const Choice& rule) {
    const auto index = static_cast<std::size_t>(v);
    if (index >= rule.names.size()) {
      fail(at, allowed(rule) + ", got enum value " + std::to_string(index));
    }
  }
  static void check_member(const KeyPath& at, const Point2& p, const Real& rule) {
    check(at / 0, p.x, rule);
    check(at / 1, p.y, rule);
  }
  static void check_member(const KeyPath& at, const Segment2& s, const Real& rule) {
    check_member(at / 0, s.a, rule);
    check_member(at / 1, s.b, rule);
  }
  static void check_member(const KeyPath& at, const std::array<Point2, 4>& c, const Real& rule) {
    for (std::size_t i = 0; i < c.size(); ++i) check_member(at / i, c[i], rule);
  }
  template <class T, class R>
  static void check_member(const KeyPath& at, const std::vector<T>& items, const List<R>& rule) {
    if (items.size() < rule.min || items.size() > rule.max) {
      fail(at, "must have " + std::to_string(rule.min) + " to " + std::to_string(rule.max) +
                   " entries, got " + std::to_string(items.size()));
    }
    for (std::size_t i = 0; i < items.size(); ++i) check_member(at / i, items[i], rule.item);
  }
  template <class T>
  static void check_member(const KeyPath& at, const std::optional<T>& member, const Fields& rule) {
    if (member) check_member(at, *member, rule);
  }
  template <class T>
  static void check_member(const KeyPath& at, const T& member, const Fields&) {
    RuleChecker nested(at);
    visit_fields(nested, member);
  }

  KeyPath at_;
};

void check_numerics(const NumericsSpec& n, const KeyPath& at) {
  if (n.time_step_s > n.end_time_s) {
    fail(at / "time_step_s", "must not exceed end_time_s = " + number_text(n.end_time_s) +
                                 " s, got " + number_text(n.time_step_s));
  }
  // The blend g of T_m goes from 0 at eps to 1 at delta (both in patch sizes).
  if (!(n.blend_eps_patches < n.blend_delta_patches)) {
    fail(at / "blend_eps_patches",
         "must be smaller than blend_delta_patches = " + number_text(n.blend_delta_patches) +
             " patches, got " + number_text(n.blend_eps_patches));
  }
}


void check_contact(const ContactSpec& c, const KeyPath& at) {
  if (c.gamma_c > 0.0 && !(c.dist0_m > 0.0)) {
    fail(at / "dist0_m",
         "must be in (0, 1000] m when gamma_c > 0 (the force acts below dist0), "
         "got " +
             number_text(c.dist0_m));
  }
}

void check_output(const OutputSpec& o, const KeyPath& at) {
  if (o.range_min > o.range_max) {
    fail(at / "range_min", "must be <= range_max = " + number_text(o.range_max) +
                               " (equal: automatic range), got " + number_text(o.range_min));
  }
}

}  // namespace
}  // namespace io

void validate(const Scenario& scenario) {
  const std::string origin = scenario.source.string();
  const io::KeyPath root{&origin, ""};
  io::RuleChecker rules(root);
  io::visit_fields(rules, scenario);
  io::check_mesh(scenario.mesh, root / "mesh");
  io::check_body_and_walls(scenario, root);
  io::check_numerics(scenario.numerics, root / "numerics");
  io::check_contact(scenario.contact, root / "contact");
  io::check_output(scenario.output, root / "output");
}

}  // namespace fsi
