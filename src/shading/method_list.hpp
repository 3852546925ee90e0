#pragma once
// --methods: registered methods and configured variants of them, one parser for every command (and
// for the path tracer's backends `path:<method>`, src/render/reference_backend.hpp).
//   conventional,podee,podee{area=lens},podee{area=lens,glossy=off}
// A variant is a method with some of its parameters set; it is rendered, measured and written as a
// method of its own, so variants of one method share one run (one reference). Its names:
//   display name  as written, "podee{area=lens,glossy=off}" (tables, metrics.json/csv, the report)
//   file name     "podee.area=lens.glossy=off" (images, error maps, videos): the id, then
//                 ".name=value" per setting, as `--param podee.area=lens` spells one setting
// A plain method's names are both its id. Parameter precedence: the method's defaults, then
// --param in the order given (the last one wins), then the variant's own settings.
#include <string>
#include <utility>
#include <vector>

#include "shading/method.hpp"

namespace glintlab {

/// One entry of --methods.
struct MethodVariant {
  const MethodDescriptor* method = nullptr;
  std::vector<std::pair<std::string, std::string>> settings;  ///< name=value inside the braces, as written
  std::string name;                                           ///< display name
  std::string file_name;                                      ///< file-name-safe form
};

/// The entries of a list such as --methods: split at the commas outside braces, so that a variant's
/// settings stay with it. Throws InputError beginning with `where` (e.g. "--backends 'a,b'") for
/// nested or unbalanced braces.
std::vector<std::string> split_outside_braces(const std::string& list, const std::string& where);

/// Splits --methods into methods and variants, in order; "all" (alone or as an entry) is every
/// registered method. Throws InputError naming the entry for an empty entry, unbalanced or nested
/// braces, text after '}', an unknown method, an empty or malformed setting, a parameter the
/// method does not have or given twice, a value it does not allow, and a name listed twice. The
/// messages begin with "--methods 'LIST':", or with `origin` where another option holds the list
/// (`--reference-backend path:deng2022{rank=0}`).
std::vector<MethodVariant> parse_method_variants(const std::string& list, const std::string& origin = "");

/// A method chosen on the command line with its resolved parameter values and its names.
struct MethodChoice {
  const MethodDescriptor* method;
  ParamValues params;
  std::string name;       ///< MethodVariant::name; empty: the id (a choice made in code)
  std::string file_name;  ///< MethodVariant::file_name; empty: the id

  [[nodiscard]] const std::string& display_name() const { return name.empty() ? method->id : name; }
  [[nodiscard]] const std::string& file_stem() const { return file_name.empty() ? method->id : file_name; }
};

/// Resolves --methods and --param (precedence above); throws InputError for what
/// parse_method_variants rejects and for unknown parameters or bad values in --param.
std::vector<MethodChoice> resolve_methods(const std::string& methods, const std::vector<std::string>& params);

}  // namespace glintlab
