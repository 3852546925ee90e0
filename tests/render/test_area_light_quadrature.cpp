// Glossy planes under quad and disk lights against an independent C++ quadrature (placeholder, being written).
#include <gtest/gtest.h>
