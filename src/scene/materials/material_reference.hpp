#pragma once
// The material-kind reference of docs/scene-format.md, generated from the kinds' declarations
// (as the method reference is from the methods'): `glintlab materials --markdown` prints it, and
// tools/update-reference-docs.sh splices it between <!-- generated:material-reference --> and
// <!-- /generated:material-reference -->; tests/docs fail while the two differ.
#include <string>
#include <vector>

#include "scene/materials/material_kind.hpp"

namespace glintlab {

/// Markdown, one section per kind in the given order: id, title, summary, citation, its files and
/// a table of its keys (the lobe's, then its parameters) with defaults, ranges and meanings.
std::string material_reference_markdown(const std::vector<MaterialKind>& kinds);

/// Plain text for `glintlab materials`: each kind with its keys, defaults and ranges.
std::string material_listing(const std::vector<MaterialKind>& kinds);

}  // namespace glintlab
