// tinygltf compiled into the glTF fuzz target with its instrumentation, from the installed header
// (Debian's library is built without it); these definitions take precedence over it.
#define TINYGLTF_IMPLEMENTATION
#include <tiny_gltf.h>
