// stb_image compiled into the fuzz targets with their instrumentation, from the installed header
// (Debian's libstb is built without it): coverage then guides the fuzzer through the decoders, and
// these definitions take precedence over the shared library's.
#define STB_IMAGE_IMPLEMENTATION
#include <stb/stb_image.h>
