#pragma once
// toml++ parses dotted keys and table headers recursively, one stack frame per level: a header of
// 50,000 levels ([a.a.a...], 100 KB) overflows the stack inside toml::parse. A scene needs a few
// levels; this scan bounds them before the parser sees the text.
#include <string>
#include <string_view>

namespace glintlab {

/// The most levels one key path (a table header or a dotted key) may have in a scene file.
inline constexpr int kMaxTomlKeyDepth = 64;

/// Throws InputError "FILE:LINE: a key path of N levels ...; allowed: at most kMaxTomlKeyDepth"
/// for the first key path deeper than the limit. Strings and comments are skipped; a bound, not a
/// parser: a float counts as a path of two levels, which is far below the limit.
void check_toml_key_depth(std::string_view text, const std::string& file);

}  // namespace glintlab
