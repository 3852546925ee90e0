#pragma once
// Text for one cell of a Markdown table (the generated method and material references).
#include <string>

namespace glintlab {

/// `text` with each '|', which would end the cell, escaped.
inline std::string markdown_cell(const std::string& text) {
  std::string out;
  for (char c : text) out += c == '|' ? std::string("\\|") : std::string(1, c);
  return out;
}

}  // namespace glintlab
