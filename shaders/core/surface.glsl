// The per-pixel surface record every method receives (docs/methods.md, "The method interface").
// Built once per fragment in uniform control flow by passes/forward.frag.
#include "core/footprint.glsl"

struct Surface {
  vec3 position;   // world space
  vec3 view;       // unit vector from the surface to the camera
  vec3 normal;     // shading normal (normal-mapped, facing the viewer)
  vec3 tangent;    // shading frame x (alpha_x direction), orthogonal to normal
  vec3 bitangent;  // shading frame y (alpha_y direction), on the side of the texture's +v
  float anisotropyRotation;  // radians from the vertex tangent to the alpha_x direction
  vec3 vertexNormal;     // interpolated geometric frame, before the normal map (facing the viewer)
  vec3 vertexTangent;
  vec3 vertexBitangent;
  vec3 mappedNormal;     // tangent-space normal-map value, filtered and NOT renormalised
                         // (its length measures the normals' spread; (0, 0, 1) without a map)
  vec2 uv;         // normal-map coordinates (tiling applied)
  Footprint footprint;  // how all of the above changes over the pixel (core/footprint.glsl)
  // Material
  int ndf;
  vec2 alpha;
  float rho;       // slope correlation of the material's lobe (glinty materials; 0 otherwise)
  vec3 f0;
  vec3 diffuse;
  bool hasNormalMap;
};

// Reflected radiance towards the viewer, split so that metrics can isolate the specular part.
struct Radiance {
  vec3 diffuse;
  vec3 specular;
};

// Sets the shading normal and rebuilds the frame around it: the vertex tangent orthogonalised,
// and the bitangent on the side of the texture's +v, so that anisotropy and normal-map slopes keep
// their meaning under mirroring transforms and on back faces (the frame is left-handed there;
// everything downstream uses toLocal/toWorld, which do not care); then both turned by the
// material's anisotropy rotation (exactly the same frame at rotation 0).
void setShadingNormal(inout Surface s, vec3 n) {
  s.normal = n;
  vec3 t = normalize(s.vertexTangent - n * dot(n, s.vertexTangent));
  vec3 b = cross(n, t);
  if (dot(b, s.vertexBitangent) < 0.0) b = -b;
  float c = cos(s.anisotropyRotation), si = sin(s.anisotropyRotation);
  s.tangent = c * t + si * b;
  s.bitangent = c * b - si * t;
}

// The vertex tangent frame around an interpolated normal n already turned to the seen side
// (side = -1 when it was flipped): the tangent orthogonalised, the bitangent along the texture's +v.
void vertexTangentFrame(vec3 n, vec4 tangent, float side, out vec3 t, out vec3 b) {
  t = normalize(tangent.xyz - n * dot(n, tangent.xyz));
  b = cross(n, t) * (tangent.w * side);
}

// A tangent-space normal-map value m in the frame (t, b, n), normalised.
vec3 mappedNormal(vec3 m, vec3 t, vec3 b, vec3 n) { return normalize(m.x * t + m.y * b + m.z * n); }

// The half vector towards l and its derivatives per pixel from the footprint alone (l's own
// derivatives: pointDirectionDerivative for a light at a point, 0 for a distant one): what a
// backend without screen-space derivatives calls (core/footprint.glsl; no normal map).
HalfVectorDifferential surfaceHalfVectorDifferential(Surface s, vec3 l, vec3 dldx, vec3 dldy) {
  return halfVectorDifferential(s.footprint, s.view, l, dldx, dldy, mat3(s.tangent, s.bitangent, s.normal),
                                s.vertexNormal, s.vertexTangent);
}

vec3 toLocal(Surface s, vec3 w) { return vec3(dot(w, s.tangent), dot(w, s.bitangent), dot(w, s.normal)); }
vec3 toWorld(Surface s, vec3 w) { return w.x * s.tangent + w.y * s.bitangent + w.z * s.normal; }
