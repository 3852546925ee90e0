// Wrapping integer indices into [0, n) for either sign: GLSL leaves % of negative operands undefined.
// Floor division in float, then one correction step either way (exact for |a| < 2^24).
ivec2 floorMod(ivec2 a, ivec2 n) {
  ivec2 r = a - n * ivec2(floor(vec2(a) / vec2(n)));
  r += mix(ivec2(0), n, lessThan(r, ivec2(0)));
  return r - mix(ivec2(0), n, greaterThanEqual(r, n));
}
