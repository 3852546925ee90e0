// Narrow lobes under lights with extent: energy and continuity against the reference (placeholder, being written).
#include <gtest/gtest.h>
