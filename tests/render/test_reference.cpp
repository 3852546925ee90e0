// The reference estimator: jitter, unfiltered surfaces, convergence and its own error (placeholder, being written).
#include <gtest/gtest.h>
