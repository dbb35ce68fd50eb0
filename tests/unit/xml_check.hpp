#pragma once
// Just enough XML reading for the VTK writer tests: tag balance, attributes, and the
// text of DataArray elements. Not a general XML parser.
#include <cstdlib>
#include <map>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

namespace fsi::test {

/// True if every opening tag is closed in order (ignores the <?xml ...?> prolog).
inline bool tags_balanced(const std::string& xml, std::string* problem = nullptr) {
  static const std::regex tag(R"(<(/?)([A-Za-z][A-Za-z0-9]*)([^<>]*?)(/?)>)");
  std::vector<std::string> open;
  for (auto it = std::sregex_iterator(xml.begin(), xml.end(), tag); it != std::sregex_iterator();
       ++it) {
    const auto& m = *it;
    if (m[4].length() > 0) continue;  // <tag ... />
    if (m[1].length() == 0) {
      open.push_back(m[2]);
    } else if (open.empty() || open.back() != m[2]) {
      if (problem) *problem = "unexpected </" + m[2].str() + ">";
      return false;
    } else {
      open.pop_back();
    }
  }
  if (!open.empty() && problem) *problem = "unclosed <" + open.back() + ">";
  return open.empty();
}

/// The value of attribute `name` in the first tag `<element ...>`, or "" if absent.
inline std::string attribute(const std::string& xml, const std::string& element,
                             const std::string& name) {
  const std::regex re("<" + element + "\\b[^>]*\\b" + name + "=\"([^\"]*)\"");
  std::smatch m;
  return std::regex_search(xml, m, re) ? m[1].str() : std::string();
}

/// The numbers inside every <DataArray Name="..."> (unnamed ones under "").
inline std::map<std::string, std::vector<double>> data_arrays(const std::string& xml) {
  static const std::regex re(R"(<DataArray\b([^>]*)>([^<]*)</DataArray>)");
  static const std::regex name_re("Name=\"([^\"]*)\"");
  std::map<std::string, std::vector<double>> arrays;
  for (auto it = std::sregex_iterator(xml.begin(), xml.end(), re); it != std::sregex_iterator();
       ++it) {
    const std::string attrs = (*it)[1];
    std::smatch name;
    const std::string key = std::regex_search(attrs, name, name_re) ? name[1].str() : "";
    std::vector<double>& values = arrays[key];
    values.clear();
    std::istringstream text((*it)[2].str());
    std::string token;
    while (text >> token) values.push_back(std::strtod(token.c_str(), nullptr));
  }
  return arrays;
}

}  // namespace fsi::test
