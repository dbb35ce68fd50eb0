// fsi-scenario-doc: writes docs/scenarios.md, the reference of every scenario key, from
// the scenario schema itself (engine/src/io/scenario_schema.hpp: key, rule, unit, range)
// and the defaults of fsi::example1_scenario(); the meaning of each key is the doc
// comment of its member in engine/include/fsi/scenario.hpp. A key added to the schema
// therefore appears here by itself; a key without a doc comment makes this program fail.
//
//   fsi-scenario-doc [SCENARIO_HPP] > docs/scenarios.md     (tools/gen-scenario-doc)
//
// SCENARIO_HPP defaults to the header of the source tree this was built from. The CTest
// scenario_doc fails when docs/scenarios.md differs from this program's output.
#include <array>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <map>
#include <regex>
#include <sstream>
#include <stdexcept>
#include <optional>
#include <string>
#include <type_traits>
#include <vector>

#include "fsi/scenario.hpp"
#include "io/number_text.hpp"
#include "io/scenario_schema.hpp"

#ifndef FSI_SCENARIO_HEADER
#define FSI_SCENARIO_HEADER "engine/include/fsi/scenario.hpp"
#endif

namespace {

using fsi::io::number_text;

// ---- doc comments of scenario.hpp ------------------------------------------------------

/// struct name -> member name -> its doc comment (leading /// lines and a trailing ///<).
using Comments = std::map<std::string, std::map<std::string, std::string>>;

std::string trim(const std::string& s) {
  const auto a = s.find_first_not_of(" \t");
  if (a == std::string::npos) return "";
  const auto b = s.find_last_not_of(" \t");
  return s.substr(a, b - a + 1);
}

void append_text(std::string& to, const std::string& more) {
  if (more.empty()) return;
  if (!to.empty()) to += ' ';
  to += more;
}

Comments read_comments(const std::string& file) {
  std::ifstream in(file);
  if (!in) throw std::runtime_error("cannot read " + file);
  Comments comments;
  static const std::regex struct_begin(R"(^struct\s+(\w+)\s*\{)");
  // A member: type, name, optional initializer, ';', optional trailing ///< comment.
  static const std::regex member(
      R"(^\s+[A-Za-z_][\w:<>, ]*?[\s>&*]+(\w+)\s*(=[^;]*|\{[^;]*\})?;\s*(///<\s*(.*))?$)");
  std::string current, pending;
  for (std::string line; std::getline(in, line);) {
    std::smatch m;
    if (std::regex_search(line, m, struct_begin)) {
      current = m[1];
      pending.clear();
      continue;
    }
    if (current.empty()) continue;
    const std::string t = trim(line);
    if (t.rfind("};", 0) == 0) {
      current.clear();
      pending.clear();
    } else if (t.rfind("///", 0) == 0 && t.rfind("///<", 0) != 0) {
      append_text(pending, trim(t.substr(3)));
    } else if (std::regex_match(line, m, member)) {
      std::string text = pending;
      if (m[4].matched) append_text(text, trim(m[4]));
      comments[current][m[1]] = text;
      pending.clear();
    } else {
      pending.clear();
    }
  }
  return comments;
}

// ---- the schema walk --------------------------------------------------------------------

struct Row {
  std::string path;     ///< JSON pointer, [] for "every item of the array"
  std::string type;     ///< what the value is
  std::string range;    ///< allowed values and unit
  std::string deflt;    ///< Example 1's value
  std::string meaning;  ///< the member's doc comment
};

struct Section {
  std::string title;
  std::vector<Row> rows;
};

template <class T>
const char* struct_name();
template <> const char* struct_name<fsi::MeshSpec>() { return "MeshSpec"; }
template <> const char* struct_name<fsi::BlockSpec>() { return "BlockSpec"; }
template <> const char* struct_name<fsi::AxisPiece>() { return "AxisPiece"; }
template <> const char* struct_name<fsi::BodySpec>() { return "BodySpec"; }
template <> const char* struct_name<fsi::FluidSpec>() { return "FluidSpec"; }
template <> const char* struct_name<fsi::SolidSpec>() { return "SolidSpec"; }
template <> const char* struct_name<fsi::NumericsSpec>() { return "NumericsSpec"; }
template <> const char* struct_name<fsi::ContactSpec>() { return "ContactSpec"; }
template <> const char* struct_name<fsi::OutputSpec>() { return "OutputSpec"; }

/// Members without a doc comment (reported together at the end).
std::vector<std::string> missing;

std::string point_text(const fsi::Point2& p) { return "[" + number_text(p.x) + ", " + number_text(p.y) + "]"; }

class DocWriter {
 public:
  /// Writes the rows of struct `owner` (JSON path `prefix`) into sections[section];
  /// keys in `required` have no default (array items).
  DocWriter(const Comments& comments, std::vector<Section>& sections, std::size_t section,
            std::string prefix, std::string owner, std::vector<std::string> required)
      : comments_(comments), sections_(sections), section_(section), prefix_(std::move(prefix)),
        owner_(std::move(owner)), required_(std::move(required)) {}

  template <class T, class R>
  void operator()(std::string_view key, const T& member, const R& rule) {
    Row row;
    row.path = prefix_ + "/" + std::string(key);
    const bool listed = describe(row, member, rule);
    if (listed) row.meaning = meaning(key);
    for (const std::string& r : required_)
      if (r == key) row.deflt = "required";
    if (listed) sections_[section_].rows.push_back(row);
  }

 private:
  std::string meaning(std::string_view key) const {
    const auto s = comments_.find(owner_);
    if (s != comments_.end()) {
      const auto m = s->second.find(std::string(key));
      if (m != s->second.end() && !m->second.empty()) return m->second;
    }
    missing.push_back(owner_ + "::" + std::string(key));
    return "";
  }

  static bool describe(Row& row, const double& v, const fsi::io::Real& r) {
    row.type = "number";
    row.range = r.text();
    row.deflt = number_text(v);
    return true;
  }
  static bool describe(Row& row, const int& v, const fsi::io::Int& r) {
    row.type = "integer";
    row.range = "[" + std::to_string(r.lo) + ", " + std::to_string(r.hi) + "]";
    row.deflt = std::to_string(v);
    return true;
  }
  static bool describe(Row& row, const bool& v, const fsi::io::Flag&) {
    row.type = "true/false";
    row.deflt = v ? "true" : "false";
    return true;
  }
  static bool describe(Row& row, const std::string& v, const fsi::io::Name&) {
    row.type = "name";
    row.range = "1-" + std::to_string(fsi::io::Name::kMaxLength) +
                " characters of A-Z a-z 0-9 _ . + = -";
    row.deflt = "\"" + v + "\"";
    return true;
  }
  static bool describe(Row& row, const std::string& v, const fsi::io::Choice& r) {
    row.type = "string";
    row.range = r.text();
    row.deflt = "\"" + v + "\"";
    return true;
  }
  template <class E>
    requires std::is_enum_v<E>
  static bool describe(Row& row, const E& v, const fsi::io::Choice& r) {
    row.type = "string";
    row.range = r.text();
    row.deflt = "\"" + std::string(r.names[static_cast<std::size_t>(v)]) + "\"";
    return true;
  }
  static bool describe(Row& row, const fsi::Point2& v, const fsi::io::Real& r) {
    row.type = "[x, y]";
    row.range = "each " + r.text();
    row.deflt = point_text(v);
    return true;
  }
  static bool describe(Row& row, const std::array<fsi::Point2, 4>& v, const fsi::io::Real& r) {
    row.type = "4 x [x, y]";
    row.range = "each " + r.text();
    std::string t = "[";
    for (std::size_t i = 0; i < v.size(); ++i) t += (i ? ", " : "") + point_text(v[i]);
    row.deflt = t + "]";
    return true;
  }
  static bool describe(Row& row, const std::vector<fsi::Segment2>& v,
                       const fsi::io::List<fsi::io::Real>& r) {
    row.type = "list of [[x0, y0], [x1, y1]]";
    row.range = std::to_string(r.min) + "-" + std::to_string(r.max) + " segments, coordinates " +
                r.item.text();
    std::string t = "[";
    for (std::size_t i = 0; i < v.size(); ++i)
      t += std::string(i ? ", " : "") + "[" + point_text(v[i].a) + ", " + point_text(v[i].b) + "]";
    row.deflt = t + "]";
    return true;
  }
  /// A nested object: a section of its own, with the member's values as defaults.
  template <class T>
  bool describe(Row& row, const T& member, const fsi::io::Fields&) {
    walk(member, row.path, {});
    return false;
  }
  /// An object that may be left out: a row here, and a section for its keys (their
  /// defaults those of T{}, when it is given).
  template <class T>
  bool describe(Row& row, const std::optional<T>&, const fsi::io::Fields&) {
    row.type = "object (optional)";
    row.range = "see `" + row.path + "`";
    row.deflt = "absent";
    walk(T{}, row.path, {});
    return true;
  }
  /// An array of objects: a row here, and a section for its items, whose keys default to
  /// those of an item that leaves them out (T{}) unless the item must give them.
  template <class T>
  bool describe(Row& row, const std::vector<T>& items, const fsi::io::List<fsi::io::Fields>& r) {
    row.type = "list of objects";
    row.range = std::to_string(r.min) + "-" + std::to_string(r.max) + " items, see `" + row.path +
                "[]`";
    row.deflt = items.empty() ? "[]" : std::to_string(items.size()) + " (Example 1's)";
    // A struct already documented under another key (the axis pieces of x, y, y_right).
    const std::string tag = std::string(" (") + struct_name<T>() + ")";
    for (const Section& s : sections_)
      if (s.title.size() > tag.size() && s.title.compare(s.title.size() - tag.size(), tag.size(), tag) == 0) {
        row.range = std::to_string(r.min) + "-" + std::to_string(r.max) + " items, each as " +
                    s.title.substr(0, s.title.size() - tag.size());
        return true;
      }
    const T item{};
    const auto required = fsi::io::required_keys(&item);
    walk(item, row.path + "[]", std::vector<std::string>(required.begin(), required.end()));
    return true;
  }

  template <class T>
  void walk(const T& member, const std::string& path, std::vector<std::string> required) {
    sections_.push_back(Section{"`" + path + "` (" + struct_name<T>() + ")", {}});
    DocWriter inner(comments_, sections_, sections_.size() - 1, path, struct_name<T>(),
                    std::move(required));
    fsi::io::visit_fields(inner, member);
  }

  const Comments& comments_;
  std::vector<Section>& sections_;
  std::size_t section_;
  std::string prefix_;
  std::string owner_;
  std::vector<std::string> required_;
};

std::string cell(const std::string& s) {
  std::string t;
  for (char c : s) t += c == '|' ? std::string("\\|") : std::string(1, c);
  return t;
}

}  // namespace

int main(int argc, char** argv) {
  try {
    const std::string header = argc > 1 ? argv[1] : FSI_SCENARIO_HEADER;
    const Comments comments = read_comments(header);
    std::vector<Section> sections{Section{"Top level (Scenario)", {}}};
    DocWriter top(comments, sections, 0, "", "Scenario", {});
    const fsi::Scenario example1 = fsi::example1_scenario();
    fsi::io::visit_fields(top, example1);
    // The chapter's preset where it differs: "default (chapter: value)".
    std::vector<Section> chapter_sections{Section{"Top level (Scenario)", {}}};
    DocWriter chapter_top(comments, chapter_sections, 0, "", "Scenario", {});
    const fsi::Scenario chapter = fsi::example1_scenario(fsi::Method::chapter);
    fsi::io::visit_fields(chapter_top, chapter);
    for (std::size_t i = 0; i < sections.size(); ++i)
      for (std::size_t j = 0; j < sections[i].rows.size(); ++j) {
        Row& row = sections[i].rows[j];
        const Row& chapter = chapter_sections[i].rows[j];
        if (row.path != "/method" && row.deflt != chapter.deflt) row.deflt += " (chapter: " + chapter.deflt + ")";
      }

    if (!missing.empty()) {
      std::string list;
      for (const std::string& m : missing) list += "\n  " + m;
      throw std::runtime_error("fsi-scenario-doc: these scenario keys have no doc comment in " + header +
                               " (write one: /// above the member or ///< after it):" + list);
    }
    std::ostringstream out;
    out << "# Scenario keys\n\n"
           "<!-- Generated by build/tools/src/fsi-scenario-doc from engine/src/io/scenario_schema.hpp\n"
           "     and the doc comments of engine/include/fsi/scenario.hpp. Do not edit: run\n"
           "     tools/gen-scenario-doc. The CTest scenario_doc fails while this file is out of date. -->\n\n"
           "A scenario is a JSON file whose keys are listed below, section by section. Every key\n"
           "a file leaves out keeps its *default*, the value of the chapter's Example 1\n"
           "(`fsi::example1_scenario()`, the falling ball on the 4225-node mesh), so `{}` is Example 1.\n"
           "The numerics start from the preset `/method` names: `\"fsi\"` (the default, the\n"
           "configuration that works) or `\"chapter\"` (the chapter's method unchanged); where the\n"
           "chapter's value differs, the default column gives it as \"(chapter: value)\". Keys a file\n"
           "gives win over the preset. Keys marked \"advanced\" are solver knobs a scenario rarely sets.\n"
           "Files with the older keys `time_step_max_s` and `time_step_wall_zone_max_s` still load: they\n"
           "become `time_step_max_doublings` and `time_step_wall_zone_doublings`,\n"
           "floor(log2(value / time_step_s)) (`tools/migrate-scenario` rewrites such a file).\n"
           "Arrays are replaced as a whole. Keys of array items marked *required* must be given.\n"
           "Unknown keys, duplicate keys, wrong types and values outside the range are errors that\n"
           "name the file, the key's path (e.g. `/numerics/time_step_s`) and the range. The apps\n"
           "change any key with `--set PATH=JSON` (e.g. `--set /solid/mu_pa=5e4`). Units are those\n"
           "after the range and in the key names (`_m`, `_s`, `_pa`, `_kgpm3`, `_m2ps`, `_mps`,\n"
           "`_mps2`, `_px`, `_rad`). \"ours\" marks a key that is not in the chapter\n"
           "([method.md](method.md#our-additions-to-the-chapter)).\n";
    for (const Section& s : sections) {
      if (s.rows.empty()) continue;
      out << "\n## " << s.title << "\n\n"
          << "| key | type | range and unit | default | meaning |\n|---|---|---|---|---|\n";
      for (const Row& r : s.rows)
        out << "| `" << r.path << "` | " << cell(r.type) << " | " << cell(r.range) << " | "
            << cell(r.deflt) << " | " << cell(r.meaning) << " |\n";
    }
    std::cout << out.str();
    return 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "%s\n", e.what());
    return 1;
  }
}
