#pragma once
// The method reference of docs/methods.md, generated from the descriptors (Mitsuba 3's way: the
// docs come from the same declaration as the parameter checks). `glintlab methods --markdown`
// prints it; tools/update-reference-docs.sh splices it into the docs between
// <!-- generated:method-reference --> and <!-- /generated:method-reference -->.
#include <string>
#include <vector>

#include "shading/method.hpp"

namespace glintlab {

/// Markdown, one section per method in the given order: id, title, summary, citation, files, a
/// table of parameters (name, default, allowed values, description) and the tables it reads.
/// Starts and ends with a blank line, so that it sits between the markers as it is printed.
std::string method_reference_markdown(const std::vector<MethodDescriptor>& methods);

}  // namespace glintlab
