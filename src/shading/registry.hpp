#pragma once
// The method registry, by id. Adding a method: write shaders/methods/<id>.glsl, a descriptor in
// src/shading/methods/<id>.cpp, and one line in registry.cpp.
#include <string>
#include <vector>

#include "shading/method.hpp"

namespace glintlab {

/// All methods, in the order they are listed and compared.
const std::vector<MethodDescriptor>& all_methods();
/// Throws InputError for an unknown id, listing the known ones.
const MethodDescriptor& find_method(const std::string& id);
/// Splits "a,b,c" (or "all") into descriptors; throws InputError for unknown ids.
std::vector<const MethodDescriptor*> parse_method_list(const std::string& list);

}  // namespace glintlab
