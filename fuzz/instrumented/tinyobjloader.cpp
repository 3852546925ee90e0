// tinyobjloader compiled into the OBJ fuzz target with its instrumentation, from the installed
// header (Debian's library is built without it); these definitions take precedence over it.
#define TINYOBJLOADER_IMPLEMENTATION
#include <tiny_obj_loader.h>
