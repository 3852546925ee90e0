// Chi-square goodness-of-fit tests of every sampling routine of the reference (placeholder, being written).
#include <gtest/gtest.h>
