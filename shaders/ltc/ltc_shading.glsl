// One light with extent shaded by linearly transformed cosines (Heitz, Dupuy, Hill, Neubelt 2016):
// the specular lobe f cos of the material's GGX for this view is replaced by the fitted LTC of the
// same roughness (ltc/ltc_tables.glsl, table `ltc-ggx`) and integrated over the light exactly,
// horizon included: polygons clipped at the horizon, disks, spheres and suns as ellipses whose
// equivalent spherical caps are clipped by the sphere table (Heitz & Hill 2017). The diffuse term
// is the exact Lambert integral (M^-1 = identity).
//
// The frame (docs/methods.md, "Area lights by LTC"): z = the shading normal (normal-mapped), x =
// the view's projection on the tangent plane, so the horizon is the shading normal's. The tables
// are isotropic; a lobe of roughness matrix A is shaded as the isotropic GGX of the same peak,
// alpha^2 = sqrt(det A), and a slope-space averaging box of half sides f adds its second moment
// 2 f^2 / 3 to A's diagonal. Beckmann lobes have no table and keep the representative point.
#include "core/brdf.glsl"
#include "lights/lights.glsl"
#include "lobe/lobe.glsl"
#include "ltc/ltc.glsl"
#include "ltc/ltc_tables.glsl"
#include "core/surface.glsl"

// The isotropic GGX alpha an LTC table is read at for a lobe (see above).
float ltcLobeAlpha(Lobe lobe) {
  mat2 A = lobe.A;
  vec2 box = lobe.footprint * lobe.footprint * (2.0 / 3.0);
  A[0][0] += box.x;
  A[1][1] += box.y;
  return sqrt(sqrt(max(determinant(A), 1e-36)));
}

// Rows: the local frame's x and y turned so that x is the view's azimuth (the LTC's frame).
mat3 ltcViewFrame(vec3 wo) {
  float len = length(wo.xy);
  vec2 x = len > 1e-7 ? wo.xy / len : vec2(1.0, 0.0);
  return transpose(mat3(vec3(x, 0.0), vec3(-x.y, x.x, 0.0), vec3(0.0, 0.0, 1.0)));
}

// The form factor of the light seen from s.position under the lobe M^-1 (a matrix acting on
// local-frame vectors), clipped at the horizon. `lambert` (a constant at every call): M^-1 is the
// identity, so a polygon needs one clip and a disk form facing the point (spheres, suns) is a
// circular cone, whose vector form factor is sin^2 of its half-angle along its axis.
float ltcLightIntegral(Surface s, LightData L, mat3 Minv, const bool lambert) {
  if (lightHasPolygonForm(L)) {
    vec3 vertex[LIGHT_POLYGON_MAX_VERTICES];
    int count = lightPolygonForm(L, vertex);
    for (int i = 0; i < LIGHT_POLYGON_MAX_VERTICES; ++i) vertex[i] = toLocal(s, vertex[i] - s.position);
    return lambert ? ltcPolygonFormFactorClipped(vertex, count) : ltcPolygonIntegral(Minv, vertex, count);
  }
  LightDisk disk = lightDiskForm(L, s.position);
  // Inside a sphere light every direction sees it: the LTC integrates to 1 over the hemisphere.
  if (disk.angularRadius >= 0.5 * PI - 1e-4) return 1.0;
  vec3 c = disk.centre - s.position;
  if (lambert && disk.facing) {
    float sinHalf = sin(disk.angularRadius);
    return ltcSphereFormFactor(sinHalf * sinHalf * normalize(toLocal(s, c)));
  }
  vec3 n = disk.normal;
  vec3 u = normalize(abs(n.x) < 0.9 ? cross(n, vec3(1.0, 0.0, 0.0)) : cross(n, vec3(0.0, 1.0, 0.0)));
  vec3 w = cross(n, u);
  // Only the cone matters: the disk scaled to unit size keeps far and wide lights within float range.
  float scale = 1.0 / max(length(c), disk.radius);
  vec3 F = ltcDiskVectorFormFactor(Minv, toLocal(s, c * scale), toLocal(s, u * (disk.radius * scale)),
                                   toLocal(s, w * (disk.radius * scale)));
  return ltcSphereFormFactor(F);
}

// Specular and diffuse radiance of one light with extent, or zero when the light is behind the
// surface or the surface faces away from the viewer.
Radiance shadeLobeLtc(Surface s, LightData L, Lobe lobe, vec3 wo) {
  Radiance result = Radiance(vec3(0.0), vec3(0.0));
  vec3 centreDir = lightCentreDirection(L, s.position);
  if (lightSolidAngle(L, s.position, centreDir) <= 0.0) return result;  // the emitting side faces away
  vec3 radiance = lightRadiance(L);
  result.diffuse = s.diffuse * ltcLightIntegral(s, L, mat3(1.0), true) * radiance;

  float alpha = ltcLobeAlpha(lobe);
  mat3 Minv = ltcInverseMatrix(uLtcGgx, alpha, wo.z) * ltcViewFrame(wo);
  vec4 terms = ltcTerms(uLtcGgx, alpha, wo.z);
  // The lobe times Schlick's Fresnel integrated over the hemisphere (the tables' magnitude and Fresnel terms).
  vec3 albedo = ltcSpecularScale(terms, s.f0);
  result.specular = albedo * ltcLightIntegral(s, L, Minv, false) * radiance;
  return result;
}
