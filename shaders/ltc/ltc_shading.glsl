// One light with extent shaded by linearly transformed cosines (Heitz, Dupuy, Hill, Neubelt 2016):
// the specular lobe f cos of the material's GGX for this view is replaced by the fitted LTC of the
// same roughness (ltc/ltc_tables.glsl, table `ltc-ggx`) and integrated over the light exactly,
// horizon included: polygons clipped at the horizon, disks, spheres and suns as ellipses whose
// equivalent spherical caps are clipped by the sphere table (Heitz & Hill 2017). The diffuse term
// is the exact Lambert integral (M^-1 = identity).
//
// The frame (docs/methods.md, "Area lights by LTC"): z = the shading normal (normal-mapped), x =
// the view's projection on the tangent plane, so the horizon is the shading normal's. The tables
// are isotropic; a lobe of roughness matrix A is the isotropic table's LTC at the roughness along
// the view, stretched about the mirror direction into A's shape (ltcLobe), with the magnitude and
// Fresnel terms at the rms roughness sqrt(tr A / 2). A lobe averaged over a slope-space box is
// first given the matrix of the same peak density (ltcLobeMatrix). Beckmann lobes have no table
// and keep the representative point.
#include "core/brdf.glsl"
#include "lights/lights.glsl"
#include "lobe/lobe.glsl"
#include "ltc/ltc.glsl"
#include "ltc/ltc_tables.glsl"
#include "core/surface.glsl"

// The roughness matrix the LTC is built for. A matrix lobe's own A. A lobe averaged over a
// slope-space box of half sides f: the box lobe's peak slope density is its average over the box
// centred on the peak, P(0) = (the NDF's mass in the box) / (4 f_x f_y) (lobe/box_average.glsl),
// and the GGX of that peak has sqrt(det A') = 1 / (pi P(0)); A' = A + k diag(f_x^2, f_y^2), k > 0
// solving det A' = (pi P(0))^-2, keeps the box's proportions (sqrt(det A) as the box vanishes,
// 4 f_x f_y / pi for a mirror). (A second-moment match, A + 2 f^2 / 3 as for Beckmann, means
// nothing for GGX, whose slopes have no second moment: a mirror sphere under a 0.25-degree sun kept
// 61% to 190% of its energy as the highlight moved within its pixel.)
mat2 ltcLobeMatrix(Lobe lobe) {
  if (lobe.footprint == vec2(0.0)) return lobe.A;
  vec2 alpha = sqrt(vec2(lobe.A[0][0], lobe.A[1][1]));
  float peak = peakBoxAveragedSlopeDensity(lobe.ndf, lobe.footprint, alpha);
  float target = 1.0 / max(PI * PI * peak * peak, 1e-36);  // det A'
  vec2 f2 = lobe.footprint * lobe.footprint;
  // det(A + k F) = f2.x f2.y k^2 + (a00 f2.y + a11 f2.x) k + det A: the positive root of = target.
  float qa = f2.x * f2.y, qb = lobe.A[0][0] * f2.y + lobe.A[1][1] * f2.x, qc = determinant(lobe.A) - target;
  float k = qa > 0.0 ? (-qb + sqrt(max(qb * qb - 4.0 * qa * qc, 0.0))) / (2.0 * qa) : -qc / max(qb, 1e-36);
  mat2 A = lobe.A;
  A[0][0] += max(k, 0.0) * f2.x;
  A[1][1] += max(k, 0.0) * f2.y;
  return A;
}

// Rows: the local frame's x and y turned so that x is the view's azimuth (the LTC's frame).
mat3 ltcViewFrame(vec3 wo) {
  float len = length(wo.xy);
  vec2 x = len > 1e-7 ? wo.xy / len : vec2(1.0, 0.0);
  return transpose(mat3(vec3(x, 0.0), vec3(-x.y, x.x, 0.0), vec3(0.0, 0.0, 1.0)));
}

// A lobe's LTC for the view wo: M^-1 acting on local-frame vectors, and the table's magnitude and
// Fresnel terms.
struct LtcLobe {
  mat3 Minv;
  vec4 terms;
};

// The isotropic table made to hold a lobe of roughness matrix A (ltcLobeMatrix; docs/methods.md, "Area lights by
// LTC"). In the view's frame A = [[a00, a01], [a01, a11]] (x along the view's azimuth). The table
// is read at alpha = sqrt(a00), the lobe's roughness along the view, whose plane carries the
// table's view-dependent shape (and the view's masking); B = alpha A^-1/2 (symmetric) maps the
// lobe's slopes onto those of the isotropic GGX of alpha, exactly for the slope density P22. The
// same B acts on directions about the mirror direction r = (-sin, 0, cos), in the basis (e_par,
// e_y, r) of the plane of incidence (T = E diag(B, 1) E^T): r stays, so the peak stays where the
// lobe's is, and the highlight's elongation and axes follow A. Exact for the slopes, T is
// approximate for the reflection's Jacobian (far from r, at grazing views). For an isotropic lobe
// B = I and T = I: the table's own LTC. The magnitude and Fresnel terms are read at the rms
// roughness sqrt(tr A / 2): the directional albedo of the anisotropic GGX is within about 10% of
// the isotropic GGX's of its rms roughness (alpha 0.05 .. 1, 1:1 .. 10:1; up to 24% over at views
// 70 degrees from the normal along the narrow axis of a lobe with an axis of alpha 1), where the
// peak-equivalent (det A)^(1/4) overestimates it up to 1.6-fold (a wide axis of alpha 1 loses
// energy to masking and the horizon).
// `anisotropic` (a constant at every call): false where A is known to be alpha^2 I, whose B and T
// are the identity and whose rms roughness is alpha: the table's own LTC, without the stretch.
LtcLobe ltcLobe(mat2 A, vec3 wo, const bool anisotropic) {
  mat3 frame = ltcViewFrame(wo);
  if (!anisotropic) {
    float a = min(sqrt(A[0][0]), 1.0);
    return LtcLobe(ltcInverseMatrix(uLtcGgx, a, wo.z) * frame, ltcTerms(uLtcGgx, a, wo.z));
  }
  vec2 x = vec2(frame[0][0], frame[1][0]), y = vec2(frame[0][1], frame[1][1]);  // its rows
  float a00 = dot(x, A * x), a01 = dot(x, A * y), a11 = dot(y, A * y);
  // det A from the local frame (rotation-invariant; exact for a diagonal A, where the view frame's
  // a00 a11 - a01^2 cancels), at least that of a 20000:1 lobe, so that B stays within float range.
  float sqrtDet = sqrt(max(determinant(A), 6.25e-10 * (a00 + a11) * (a00 + a11)));
  float alpha = sqrt(a00);
  // A^-1/2 = adj(A + sqrt(det) I) / (sqrt(det) sqrt(tr A + 2 sqrt(det))), so B = alpha A^-1/2:
  float k = alpha / (sqrtDet * sqrt(a00 + a11 + 2.0 * sqrtDet));
  mat3 B = mat3(vec3(k * (a11 + sqrtDet), -k * a01, 0.0), vec3(-k * a01, k * (a00 + sqrtDet), 0.0),
                vec3(0.0, 0.0, 1.0));
  float c = wo.z, s = sqrt(max(1.0 - c * c, 0.0));
  mat3 E = mat3(vec3(c, 0.0, s), vec3(0.0, 1.0, 0.0), vec3(-s, 0.0, c));
  mat3 T = E * B * transpose(E);
  float rms = sqrt(0.5 * (a00 + a11));
  return LtcLobe(ltcInverseMatrix(uLtcGgx, min(alpha, 1.0), wo.z) * T * frame, ltcTerms(uLtcGgx, min(rms, 1.0), wo.z));
}

// A light with extent as the LTC integrals see it from one shading point, in the local frame,
// made once per light and shared by every integral over it (the diffuse form factor and each
// lobe's): a polygon's sides clipped at the surface's horizon, or a disk form scaled to unit size
// (only the cone matters: far and wide lights stay within float range).
struct LtcLightForm {
  LtcPolygonEdges edges;  // polygon forms (lightHasPolygonForm, a constant for a light of known kind)
  bool surrounds;         // inside a sphere light: every direction sees it, every integral is 1
  bool facing;            // a disk form facing the point (spheres, suns): a circular cone
  float sinHalf;          // the sine of that cone's half-angle
  vec3 centre, u, w;      // the disk's centre and orthogonal semi-axes
};

LtcLightForm ltcLightForm(Surface s, LightData L) {
  LtcLightForm f;
  if (lightHasPolygonForm(L)) {
    vec3 vertex[LIGHT_POLYGON_MAX_VERTICES];
    int count = lightPolygonForm(L, vertex);
    for (int i = 0; i < LIGHT_POLYGON_MAX_VERTICES; ++i) vertex[i] = toLocal(s, vertex[i] - s.position);
    f.edges = ltcPolygonSides(vertex, count);
    ltcClipEdges(f.edges, LIGHT_POLYGON_MAX_VERTICES);
    return f;
  }
  LightDisk disk = lightDiskForm(L, s.position);
  f.surrounds = disk.angularRadius >= 0.5 * PI - 1e-4;
  f.facing = disk.facing;
  f.sinHalf = sin(disk.angularRadius);
  vec3 c = disk.centre - s.position;
  vec3 n = disk.normal;
  vec3 u = normalize(abs(n.x) < 0.9 ? cross(n, vec3(1.0, 0.0, 0.0)) : cross(n, vec3(0.0, 1.0, 0.0)));
  float scale = 1.0 / max(length(c), disk.radius);
  f.centre = toLocal(s, c * scale);
  f.u = toLocal(s, u * (disk.radius * scale));
  f.w = toLocal(s, cross(n, u) * (disk.radius * scale));
  return f;
}

// The light's integral under the lobe M^-1 (a matrix acting on local-frame vectors), clipped at
// the horizon: the polygon by ltcClippedPolygonIntegral, the disk's ellipse through the sphere table.
float ltcLightIntegral(LtcLightForm f, LightData L, mat3 Minv) {
  if (lightHasPolygonForm(L)) return ltcClippedPolygonIntegral(Minv, f.edges);
  if (f.surrounds) return 1.0;
  return ltcSphereFormFactor(ltcDiskVectorFormFactor(Minv, f.centre, f.u, f.w));
}

// The light's Lambert form factor (M^-1 = identity): a polygon needs only the horizon's clip, and
// a disk form facing the point is a circular cone, whose vector form factor is sin^2 of its
// half-angle along its axis.
float ltcLightFormFactor(LtcLightForm f, LightData L) {
  if (lightHasPolygonForm(L)) return ltcEdgesFormFactor(f.edges);
  if (f.surrounds) return 1.0;
  if (f.facing) return ltcSphereFormFactor(f.sinHalf * f.sinHalf * normalize(f.centre));
  return ltcSphereFormFactor(ltcDiskVectorFormFactor(mat3(1.0), f.centre, f.u, f.w));
}

// Specular and diffuse radiance of one light with extent under the LTC of roughness matrix A
// (ltcLobeMatrix of the lobe; `anisotropic` as for ltcLobe), or zero when the light is behind the
// surface or the surface faces away from the viewer.
Radiance shadeLobeLtc(Surface s, LightData L, mat2 A, vec3 wo, const bool anisotropic) {
  Radiance result = Radiance(vec3(0.0), vec3(0.0));
  vec3 centreDir = lightCentreDirection(L, s.position);
  if (lightSolidAngle(L, s.position, centreDir) <= 0.0) return result;  // the emitting side faces away
  vec3 radiance = lightRadiance(L);
  LtcLightForm form = ltcLightForm(s, L);
  result.diffuse = s.diffuse * ltcLightFormFactor(form, L) * radiance;

  LtcLobe ltc = ltcLobe(A, wo, anisotropic);
  // The lobe times Schlick's Fresnel integrated over the hemisphere (the tables' magnitude and Fresnel terms).
  vec3 albedo = ltcSpecularScale(ltc.terms, s.f0);
  result.specular = albedo * ltcLightIntegral(form, L, ltc.Minv) * radiance;
  return result;
}
