// Bounded JSON parsing: nlohmann's parser plus a callback that tracks where it is.
#include "io/json_text.hpp"

#include <set>
#include <vector>

#include "fsi/error.hpp"
#include "io/scenario_rules.hpp"

namespace fsi::io {

using json = nlohmann::json;

namespace {

/// One open object or array while parsing.
struct Frame {
  bool is_array = false;
  std::size_t index = 0;       ///< array: index of the current item
  std::string key;             ///< object: the current key
  std::set<std::string> keys;  ///< object: keys seen so far
};

/// Follows the parser through the document so errors can name the key path.
class Tracker {
 public:
  explicit Tracker(const std::string& origin) : origin_(origin) {}

  bool operator()(int depth, json::parse_event_t event, json& parsed) {
    switch (event) {
      case json::parse_event_t::object_start:
      case json::parse_event_t::array_start:
        if (depth >= kMaxJsonDepth || frames_.size() >= static_cast<std::size_t>(kMaxJsonDepth)) {
          throw InputError(
              origin_, path(),
              "JSON is nested deeper than " + std::to_string(kMaxJsonDepth) + " levels");
        }
        frames_.push_back(Frame{event == json::parse_event_t::array_start, 0, {}, {}});
        break;
      case json::parse_event_t::key: {
        Frame& top = frames_.back();
        top.key = parsed.get<std::string>();
        if (!top.keys.insert(top.key).second) {
          throw InputError(origin_, path(), "duplicate key (each key may appear once)");
        }
        break;
      }
      case json::parse_event_t::object_end:
      case json::parse_event_t::array_end:
        if (!frames_.empty()) frames_.pop_back();
        item_done();
        break;
      case json::parse_event_t::value:
        item_done();
        break;
    }
    return true;
  }

  /// JSON pointer of the value being parsed.
  std::string path() const {
    std::string p;
    for (const Frame& f : frames_) {
      p += "/" + (f.is_array ? std::to_string(f.index) : f.key);
    }
    return p;
  }

 private:
  void item_done() {
    if (!frames_.empty() && frames_.back().is_array) ++frames_.back().index;
  }

  const std::string& origin_;
  std::vector<Frame> frames_;
};

/// "line 3, column 7" of byte offset `byte` (1-based, as the parser counts).
std::string line_column(const std::string& text, std::size_t byte) {
  std::size_t line = 1, column = 1;
  for (std::size_t i = 0; i + 1 < byte && i < text.size(); ++i) {
    if (text[i] == '\n') {
      ++line;
      column = 1;
    } else {
      ++column;
    }
  }
  return "line " + std::to_string(line) + ", column " + std::to_string(column);
}

/// The parser's own explanation without its "[json.exception...] parse error at ...:" prefix.
std::string parser_reason(const std::string& what) {
  const auto colon = what.find(": ");
  return colon == std::string::npos ? what : what.substr(colon + 2);
}

}  // namespace

json parse_json_text(const std::string& text, const std::string& origin,
                     const AllowedAt& allowed_at) {
  if (text.size() > kMaxScenarioBytes) {
    throw InputError(origin, "",
                     "text is " + std::to_string(text.size()) + " bytes, must be at most " +
                         std::to_string(kMaxScenarioBytes) + " bytes");
  }
  Tracker tracker(origin);
  try {
    return json::parse(text, std::ref(tracker), /*allow_exceptions=*/true,
                       /*ignore_comments=*/false);
  } catch (const json::parse_error& e) {
    throw InputError(
        origin, tracker.path(),
        "not valid JSON at " + line_column(text, e.byte) + ": " + parser_reason(e.what()));
  } catch (const json::out_of_range& e) {
    // 406: a number literal beyond the double range (e.g. 1e999).
    const std::string path = tracker.path();
    throw InputError(origin, path,
                     (allowed_at ? allowed_at(path) : std::string("must be a finite number")) +
                         ", got a number that overflows a double (" + parser_reason(e.what()) +
                         ")");
  } catch (const json::exception& e) {
    throw InputError(origin, tracker.path(), std::string("not valid JSON: ") + e.what());
  }
}

}  // namespace fsi::io
