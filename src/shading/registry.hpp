#pragma once
// The method registry, by id. Adding a method is two files, its module and its descriptor:
//   shaders/methods/<id>.glsl        prepareSurface and shadeLight, reading its `param_<name>`s;
//   src/shading/methods/<id>.cpp     the MethodDescriptor, ending in GLINTLAB_REGISTER_METHOD.
// CMake collects src/shading/methods/*.cpp and links them whole (nothing else refers to them);
// the `param_<name>` uniforms are generated from the descriptor's ParamDecls when the method's
// program is built (shading/method_module.hpp). How-to: docs/extending.md.
#include <string>
#include <utility>
#include <vector>

#include "shading/method.hpp"

namespace glintlab {

/// One registered descriptor: how to make it, where it is listed, where it was registered.
struct MethodRegistration {
  MethodDescriptor (*make)();
  /// all_methods() lists methods by ascending key (a declared order, never link order); keys are
  /// spaced so that a method can join its family: see docs/extending.md, "A method".
  int listing_key;
  const char* source_file;  ///< the descriptor's file, for error messages
};

/// Adds a method to the registry; GLINTLAB_REGISTER_METHOD calls it during static initialisation.
/// Throws std::logic_error once the registry has been read.
bool register_method(const MethodRegistration& registration);

/// The descriptors of `registrations` by ascending listing key. Throws std::logic_error naming
/// both files for a repeated id or listing key, and naming the method for an invalid declaration:
/// an id other than a-z, 0-9, '-' and '_'; a parameter name that is not a GLSL identifier, is
/// repeated, or whose default is outside its range; a choice other than a-z, 0-9, '-' and '_'.
/// Throws naming both methods and files for an enumeration declared by two methods with other
/// choices, or two enumerations whose choices make the same GLSL define (choice_define()).
std::vector<MethodDescriptor> ordered_methods(const std::vector<MethodRegistration>& registrations);

/// (<NAME>_<CHOICE>, the choice's index) for every choice of every enumeration `methods` declare,
/// each parameter name once (ordered_methods() checked that its choices agree), in listing order:
/// part of the GLSL contract (generated/gpu_contract.glsl), so that code several methods share
/// tests a choice by its name.
std::vector<std::pair<std::string, std::string>> enumeration_defines(const std::vector<MethodDescriptor>& methods);

/// All methods, in the order they are listed and compared (by listing key).
const std::vector<MethodDescriptor>& all_methods();
/// Throws InputError for an unknown id, listing the known ones.
const MethodDescriptor& find_method(const std::string& id);
/// Splits "a,b,c" (or "all") into descriptors; throws InputError for unknown ids.
std::vector<const MethodDescriptor*> parse_method_list(const std::string& list);

}  // namespace glintlab

/// Registers the descriptor that `make` (a function returning a MethodDescriptor) builds, listed
/// at `listing_key`. Write it once, at namespace scope after `make`, in the descriptor's file.
#define GLINTLAB_REGISTER_METHOD(make, listing_key) \
  [[maybe_unused]] static const bool registered_##make = ::glintlab::register_method({&make, listing_key, __FILE__})
