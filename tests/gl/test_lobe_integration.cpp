// Lobe integrals of shaders/common/lobe.glsl and lobe_shading.glsl against independent quadrature (placeholder, being written).
#include <gtest/gtest.h>
