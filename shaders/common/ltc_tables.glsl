// TEMPORARY STUB (lead): replaced by the LTC table helper's module on merge.
#include "generated/gpu_contract.glsl"
#ifndef TABLE_UNIT_LTC_GGX
#define TABLE_UNIT_LTC_GGX 15
#endif
layout(binding = TABLE_UNIT_LTC_GGX) uniform sampler2DArray uLtcGgx;
vec2 ltcTableUv(float alpha, float cosTheta) {
  return vec2(sqrt(alpha), sqrt(max(1.0 - cosTheta, 0.0))) * (63.0 / 64.0) + 0.5 / 64.0;
}
mat3 ltcInverseMatrix(sampler2DArray t, float alpha, float cosTheta) {
  vec4 m = texture(t, vec3(ltcTableUv(alpha, cosTheta), 0.0));
  return mat3(vec3(m.x, 0.0, m.z), vec3(0.0, 1.0, 0.0), vec3(m.y, 0.0, m.w));
}
vec4 ltcTerms(sampler2DArray t, float alpha, float cosTheta) { return texture(t, vec3(ltcTableUv(alpha, cosTheta), 1.0)); }
float ltcSphereFormFactor(vec3 F) {
  float len = length(F);
  return len * max(F.z / max(len, 1e-30), 0.0);  // stub: no clipping table
}
