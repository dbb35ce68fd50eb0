#pragma once
/// \file frame_options.hpp
/// The picture options both apps accept, parsed from their text forms:
/// field (vx|vy|vmag|p|umag), zoom "x0,y0,x1,y1" [m], size "WxH" [px], mesh 0|1.
/// Each parser throws fsi::InputError(origin, option, why) on bad text.
#include <fsi/renderer.hpp>
#include <string>

namespace fsi::app {

/// "vy" -> Quantity::vy; lists the allowed names otherwise.
render::Quantity parse_field(const std::string& text, const std::string& origin,
                             const std::string& option);

/// "x0,y0,x1,y1" with x0 < x1, y0 < y1 [m].
render::ViewWindow parse_zoom(const std::string& text, const std::string& origin,
                              const std::string& option);

/// "WxH", each in [16, 8192] px.
void parse_size(const std::string& text, const std::string& origin, const std::string& option,
                int& width, int& height);

/// An integer in [lo, hi], the whole text.
int parse_int(const std::string& text, long lo, long hi, const std::string& origin,
              const std::string& option);

/// The value after option argv[i] (advancing i past it); throws
/// fsi::InputError("command line", option, "needs a value") at the end of the line.
std::string option_value(int& i, int argc, char** argv);

/// A finite number, the whole text.
double parse_number(const std::string& text, const std::string& origin, const std::string& option);

}  // namespace fsi::app
