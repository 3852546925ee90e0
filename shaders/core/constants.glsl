// Numeric constants shared by every module.
const float PI = 3.14159265358979;
const float INV_PI = 0.31830988618379;
const float TWO_PI = 6.28318530717959;
// Alphas are clamped to this in NDF evaluation so a perfect mirror (alpha = 0) stays finite.
const float MIN_ALPHA = 1e-4;
