#pragma once
// A script command's arguments as values, each failure an InputError naming the script's file and
// line, the command and its usage (view/view_script.cpp reads the words; view_script_run.cpp acts).
#include <cstddef>
#include <string>

#include "view/view_script.hpp"

namespace glintlab {

/// "FILE:LINE: ".
std::string script_where(const ScriptCommand& c);
float script_number(const ScriptCommand& c, std::size_t i);
/// A whole number.
int script_integer(const ScriptCommand& c, std::size_t i);
/// "on" or "off".
bool script_on_off(const ScriptCommand& c, std::size_t i);

}  // namespace glintlab
