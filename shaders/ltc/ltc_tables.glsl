// The LTC tables (Heitz, Dupuy, Hill, Neubelt 2016; our own fit, src/tables/ltc/ltc_fit.hpp), ltc-ggx and
// ltc-ndf (src/tables/ltc_*_table.cpp; units TABLE_UNIT_LTC_GGX/NDF from the table registry).
// Layout (src/tables/ltc/ltc_table.hpp): LTC_TABLE_SIZE^2 cells (64 x 64; the tables declare it, the
// generated contract defines it), x = roughness r = sqrt(alpha) (alpha floored at MIN_ALPHA),
// y = sqrt(1 - cos(theta_v)), in the frame z = normal, x = the view's tangent direction.
//   layer 0: M^-1 / m11 as (m00, m02, m20, m22);
//   layer 1 of uLtcGgx: (magnitude, fresnel, clipped-sphere ratio S, 0): the integral of the GGX
//     specular lobe times Schlick's F is f0 * magnitude + (1 - f0) * fresnel (ltcSpecularScale);
//   layer 1 of uLtcNdf: (magnitude of D(h) / (4 v.h) over l.z > 0, total NDF, 0, 0).
#include "generated/gpu_contract.glsl"

layout(binding = TABLE_UNIT_LTC_GGX) uniform sampler2DArray uLtcGgx;
layout(binding = TABLE_UNIT_LTC_NDF) uniform sampler2DArray uLtcNdf;

// Table coordinates in [0, 1]^2 to the texture coordinates of the cell centres.
vec2 ltcTableUv(vec2 coordinates) {
  return coordinates * ((LTC_TABLE_SIZE - 1.0) / LTC_TABLE_SIZE) + 0.5 / LTC_TABLE_SIZE;
}

vec2 ltcCellUv(float alpha, float cosTheta) {
  return ltcTableUv(vec2(sqrt(max(alpha, 0.0)), sqrt(1.0 - clamp(cosTheta, 0.0, 1.0))));
}

// M^-1 of the cell (normalised by its (1,1) element; scale does not change the distribution).
mat3 ltcInverseMatrix(sampler2DArray t, float alpha, float cosTheta) {
  vec4 m = textureLod(t, vec3(ltcCellUv(alpha, cosTheta), 0.0), 0.0);
  return mat3(vec3(m.x, 0.0, m.z), vec3(0.0, 1.0, 0.0), vec3(m.y, 0.0, m.w));
}

// Layer 1 of the cell: see the file comment.
vec4 ltcTerms(sampler2DArray t, float alpha, float cosTheta) {
  return textureLod(t, vec3(ltcCellUv(alpha, cosTheta), 1.0), 0.0);
}

// The GGX lobe's integral with Schlick's Fresnel, from ltcTerms(uLtcGgx, ...).
vec3 ltcSpecularScale(vec4 terms, vec3 f0) { return f0 * terms.x + (1.0 - f0) * terms.y; }

// The form factor, clipped to the horizon, of the spherical cap with vector form factor F (F = the
// sum over a polygon's edges of acos(v_i.v_j) normalize(cross(v_i, v_j)) / (2 pi), or of a sphere:
// |F| = sin^2(angular radius), F.z = |F| cos(elevation of its centre)): |F| * S(F.z / |F|, |F|)
// from layer 1 .z of uLtcGgx (Heitz & Hill 2017's "clipless" evaluation).
float ltcSphereFormFactor(vec3 F) {
  float len = length(F);
  float z = F.z / max(len, 1e-30);
  return len * textureLod(uLtcGgx, vec3(ltcTableUv(vec2(z * 0.5 + 0.5, len)), 1.0), 0.0).z;
}
