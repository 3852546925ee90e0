#pragma once
// The vector types and functions used across glintlab (GLM, GLSL-like).
#include <algorithm>
#include <glm/glm.hpp>
