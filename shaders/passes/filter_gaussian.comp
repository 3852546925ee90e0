// One axis of the reference's Gaussian pixel filter (render/subpixel_filter.cpp): each output
// pixel along uAxis is the normalised Gaussian-weighted mean of the samples within uReach pixels
// of its centre. Run along x, then along y: the 2D filter over a square support is the product of
// the two, and its per-pixel normaliser over a rectangle of samples (cut at the film's edges) is
// the product of the two axes' normalisers, so the two passes give the 2D normalised filter exactly.
layout(local_size_x = 8, local_size_y = 8) in;

layout(rgba32f, binding = 0) readonly uniform image2D uInTotal;
layout(rgba32f, binding = 1) readonly uniform image2D uInSpecular;
layout(rgba32f, binding = 2) writeonly uniform image2D uOutTotal;
layout(rgba32f, binding = 3) writeonly uniform image2D uOutSpecular;

uniform ivec2 uAxis;        // (1, 0): along x; (0, 1): along y
uniform int uSubpixels;     // k: samples per pixel along the axis
uniform int uSamples;       // samples along the axis in the input (the region's pixels times k)
uniform float uJitter;      // each sample's offset from its cell's corner along the axis, in sub-pixels
uniform int uPixelOffset;   // pixels of the region before the output's first pixel
uniform float uSigma;       // pixels
uniform float uReach;       // pixels: max(3 sigma, half a sample spacing), so no pixel is left without one
uniform int uSupport;       // whole pixels on each side within uReach
uniform ivec2 uOutSize;
uniform ivec2 uOutOrigin;   // where output (0, 0) goes

void main() {
  ivec2 o = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(o, uOutSize))) return;
  int pixel = uPixelOffset + o.x * uAxis.x + o.y * uAxis.y;  // along the axis, from the region's start
  ivec2 across = o * (ivec2(1) - uAxis);
  float centre = float(pixel) + 0.5;
  float k = float(uSubpixels);
  int first = max(0, (pixel - uSupport) * uSubpixels);
  int last = min(uSamples, (pixel + uSupport + 1) * uSubpixels);
  vec3 total = vec3(0.0), specular = vec3(0.0);
  float norm = 0.0;
  for (int i = first; i < last; ++i) {
    float d = (float(i) + uJitter) / k - centre;  // the sample's position: its cell's corner plus the jitter
    float w = abs(d) <= uReach ? exp(-0.5 * d * d / (uSigma * uSigma)) : 0.0;
    ivec2 q = across + i * uAxis;
    total += w * imageLoad(uInTotal, q).rgb;
    specular += w * imageLoad(uInSpecular, q).rgb;
    norm += w;
  }
  imageStore(uOutTotal, uOutOrigin + o, vec4(total / norm, 1.0));
  imageStore(uOutSpecular, uOutOrigin + o, vec4(specular / norm, 1.0));
}
