#pragma once
// What the glTF 2.0 specification requires of a document, checked before anything is written, so
// the writer never produces a file that a validator or viewer would reject.
#include "scene/gltf/gltf_writer.hpp"

namespace glintlab::gltf {

/// Throws InputError naming the element (e.g. "glTF document: mesh 2 primitive 0: index 9 out of
/// range (8 vertices)") for the first violation found.
void check_document(const Document& doc);

}  // namespace glintlab::gltf
