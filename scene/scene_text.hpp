#pragma once
// How scene messages quote a word and write a number, alike in the parser and
// the mesh loader.

#include <sstream>
#include <string>

namespace umbra {

inline std::string in_quotes(const std::string& s) { return "\"" + s + "\""; }

// As a stream writes it: "0.5", "-2", "1e+300".
inline std::string number_text(double v) {
  std::ostringstream s;
  s << v;
  return s.str();
}

}  // namespace umbra
