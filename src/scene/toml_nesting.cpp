#include "scene/toml_nesting.hpp"

#include "core/error.hpp"

namespace glintlab {

namespace {

/// The position just past the string that starts at `i` (a basic, literal or multi-line string).
std::size_t skip_string(std::string_view text, std::size_t i) {
  const char quote = text[i];
  const bool multi_line = text.substr(i, 3) == std::string_view(quote == '"' ? "\"\"\"" : "'''");
  std::size_t j = i + (multi_line ? 3 : 1);
  while (j < text.size()) {
    if (quote == '"' && text[j] == '\\') {
      j += 2;  // an escape: \" does not end the string
      continue;
    }
    if (!multi_line && text[j] == '\n') return j;  // unterminated: the parser says so
    if (text[j] == quote && (!multi_line || text.substr(j, 3) == std::string_view(quote == '"' ? "\"\"\"" : "'''")))
      return j + (multi_line ? 3 : 1);
    ++j;
  }
  return j;
}

}  // namespace

void check_toml_key_depth(std::string_view text, const std::string& file) {
  int dots = 0, line = 1;
  for (std::size_t i = 0; i < text.size();) {
    const char c = text[i];
    if (c == '"' || c == '\'') {
      const std::size_t end = skip_string(text, i);
      for (std::size_t k = i; k < end; ++k) line += text[k] == '\n';
      i = end;
      continue;  // a quoted segment of a key path: the path goes on
    }
    if (c == '#') {
      while (i < text.size() && text[i] != '\n') ++i;
      continue;
    }
    if (c == '.') {
      if (++dots >= kMaxTomlKeyDepth)
        throw InputError(file + ":" + std::to_string(line) + ": a key path (a table header or a dotted key) of more than " +
                         std::to_string(kMaxTomlKeyDepth) + " levels; allowed: at most " +
                         std::to_string(kMaxTomlKeyDepth));
    } else if (c == '\n' || c == '=' || c == ',' || c == '[' || c == ']' || c == '{' || c == '}') {
      dots = 0;  // a key path ends at these
    }
    line += c == '\n';
    ++i;
  }
}

}  // namespace glintlab
