// Counter-based random numbers for procedural surfaces (binomial glints, point-process glints):
// a hash of a cell's integer coordinates, so nothing is stored and any cell's numbers are
// independent of every other's and the same wherever and whenever they are asked for.

// pcg4d (Jarzynski & Olano 2020, "Hash Functions for GPU Rendering", JCGT 9(3)): four 32-bit words
// from four, every output bit depending on every input bit.
uvec4 pcg4d(uvec4 v) {
  v = v * 1664525u + 1013904223u;
  v.x += v.y * v.w;
  v.y += v.z * v.x;
  v.z += v.x * v.y;
  v.w += v.y * v.z;
  v ^= v >> 16u;
  v.x += v.y * v.w;
  v.y += v.z * v.x;
  v.z += v.x * v.y;
  v.w += v.y * v.z;
  return v;
}

// Uniform numbers in [0, 1) from the top 24 bits (exact in fp32).
vec2 randomUnit2(uvec2 v) { return vec2(v >> 8u) * (1.0 / 16777216.0); }

// A standard normal number from two uniform ones (Box & Muller 1958); 1 - u.x > 0, so finite.
float randomNormal(vec2 u) { return sqrt(-2.0 * log(1.0 - u.x)) * cos(6.28318530717959 * u.y); }
