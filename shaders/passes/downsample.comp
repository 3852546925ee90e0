// Box-filters k x k sub-pixels of a high-resolution tile into output pixels (ground truth).
layout(local_size_x = 8, local_size_y = 8) in;

layout(rgba32f, binding = 0) readonly uniform image2D uHighTotal;
layout(rgba32f, binding = 1) readonly uniform image2D uHighSpecular;
layout(rgba32f, binding = 2) writeonly uniform image2D uOutTotal;
layout(rgba32f, binding = 3) writeonly uniform image2D uOutSpecular;

uniform int uSubpixels;     // k
uniform ivec2 uTileSize;    // output pixels in this tile
uniform ivec2 uOutOrigin;   // where the tile goes in the output (GL, y up)

void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(p, uTileSize))) return;
  vec3 total = vec3(0.0), specular = vec3(0.0);
  for (int y = 0; y < uSubpixels; ++y)
    for (int x = 0; x < uSubpixels; ++x) {
      ivec2 q = p * uSubpixels + ivec2(x, y);
      total += imageLoad(uHighTotal, q).rgb;
      specular += imageLoad(uHighSpecular, q).rgb;
    }
  float inv = 1.0 / float(uSubpixels * uSubpixels);
  imageStore(uOutTotal, uOutOrigin + p, vec4(total * inv, 1.0));
  imageStore(uOutSpecular, uOutOrigin + p, vec4(specular * inv, 1.0));
}
