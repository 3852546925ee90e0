// LEAN's slope covariance in the shading frame against the reference (placeholder, being written).
#include <gtest/gtest.h>
