// Footprint kernels of the specular AA methods (placeholder, being written).
#include <gtest/gtest.h>
