// Shading of one light with a given specular lobe: exact for delta lights, and for lights with
// extent the lobe integrated over the light's image (below), so that every NDF-filtering method
// differs from the `conventional` baseline only in the lobe it passes in.
#include "common/brdf.glsl"
#include "common/delta_lights.glsl"
#include "common/lights.glsl"
#include "common/lobe.glsl"
#include "common/surface.glsl"

// Closest direction to r inside the cone (axis, sinHalf/cosHalf): the representative point of
// a sphere or distant disk (Karis 2013).
vec3 closestInCone(vec3 r, vec3 axis, float cosHalf, float sinHalf) {
  float c = dot(r, axis);
  if (c >= cosHalf) return r;
  vec3 side = r - c * axis;
  float len = length(side);
  if (len < 1e-6) return axis;
  return normalize(cosHalf * axis + sinHalf * (side / len));
}

// Closest point of a disk or quad to the reflected ray, via the ray's hit with the light plane.
vec3 closestOnPlanarLight(LightData L, vec3 p, vec3 r) {
  vec3 c = L.position_radius.xyz;
  vec3 n = L.direction_cos.xyz;
  float denom = dot(r, n);
  vec3 q = c;
  if (denom < -1e-6) {
    float t = dot(c - p, n) / denom;
    if (t > 0.0) q = p + t * r;
  }
  vec3 d = q - c;
  if (lightType(L) == LIGHT_DISK) {
    float rad = L.position_radius.w;
    float len = length(d);
    return len > rad ? c + d * (rad / len) : q;
  }
  vec3 u = L.axisU.xyz, v = L.axisV.xyz;
  float su = clamp(dot(d, u) / dot(u, u), -1.0, 1.0);
  float sv = clamp(dot(d, v) / dot(v, v), -1.0, 1.0);
  return c + su * u + sv * v;
}

// Solid angle of a light with extent seen from p (centreDir: unit direction to its centre);
// 0 when p is behind a one-sided emitter. Spheres and suns: the projected disk, pi sin^2 theta
// (their irradiance at normal incidence is L times it).
float lightSolidAngle(LightData L, vec3 p, vec3 centreDir) {
  int type = lightType(L);
  if (type == LIGHT_SUN) return PI * coneSin2(sunOneMinusCos(L));
  vec3 d = L.position_radius.xyz - p;
  float d2 = max(dot(d, d), 1e-12);
  if (type == LIGHT_SPHERE) {
    float r = L.position_radius.w;
    return PI * min(r * r / d2, 1.0);
  }
  float cosL = -dot(centreDir, L.direction_cos.xyz);
  return cosL <= 0.0 ? 0.0 : lightArea(L) * cosL / d2;
}

// dl1, dl2: conjugate semi-axes of the light's outline as seen from p, as changes of the unit
// direction lc to its centre (perpendicular to lc; local frame).
LightImage lightImage(vec3 wo, vec3 lc, vec3 dl1, vec3 dl2) {
  vec3 sum = wo + lc;
  float len = max(length(sum), 1e-6);
  vec3 h = sum / len;
  float hz = max(h.z, 1e-4);
  LightImage image;
  image.centre = -h.xy / hz;
  vec3 d1 = (dl1 - h * dot(h, dl1)) / len, d2 = (dl2 - h * dot(h, dl2)) / len;
  image.J = mat2(-(d1.xy + image.centre * d1.z) / hz, -(d2.xy + image.centre * d2.z) / hz);
  return image;
}

// The outline's semi-axes (world space): a cone's circle of radius sin(theta); a disk's circle,
// projected; a quad's half edges, projected and scaled by 2 / sqrt(pi) (the ellipse of equal area).
void lightOutline(LightData L, vec3 p, vec3 lc, float sinHalf, out vec3 dl1, out vec3 dl2) {
  int type = lightType(L);
  if (type == LIGHT_SUN || type == LIGHT_SPHERE) {
    basisAround(lc, dl1, dl2);
    dl1 *= sinHalf;
    dl2 *= sinHalf;
    return;
  }
  vec3 a1, a2;
  if (type == LIGHT_DISK) {
    basisAround(L.direction_cos.xyz, a1, a2);
    a1 *= L.position_radius.w;
    a2 *= L.position_radius.w;
  } else {
    a1 = 1.1283792 * L.axisU.xyz;
    a2 = 1.1283792 * L.axisV.xyz;
  }
  float dist = max(length(L.position_radius.xyz - p), 1e-12);
  dl1 = (a1 - lc * dot(lc, a1)) / dist;
  dl2 = (a2 - lc * dot(lc, a2)) / dist;
}

// One light with a given lobe: exact for delta lights. For lights with extent (docs/methods.md,
// "Lobes"), the integral over the light of f cos = D G F (wo.h) / wo.z per unit half-vector solid
// angle, which in slope space (d omega_h = h.z^3 ds, D = P22 / h.z^4) is
//   L  integral over the light's image of  P22(s) G F (wo.h) / (h.z wo.z) ds.
// The lobe's mass over the image (lobeMassOnImage) carries the integral; G, F and the factor
// (wo.h) / (h.z wo.z) are taken at the representative point (Karis 2013: the light's point
// closest to the reflected ray), where a narrow lobe's mass lies: there h = n and the factor is 1.
// So a narrow lobe gives F L where the reflected ray meets the light (the mirror), a small light
// gives the point light of irradiance L Omega, and every lobe in between is continuous.
Radiance shadeLobe(Surface s, LightData L, Lobe lobe) {
  Radiance result = Radiance(vec3(0.0), vec3(0.0));
  vec3 wo = toLocal(s, s.view);
  if (wo.z <= 0.0) return result;
  if (!lightHasExtent(L)) return shadeDeltaLight(s, lobe, L, wo);

  vec3 centreDir = lightCentreDirection(L, s.position);
  float solidAngle = lightSolidAngle(L, s.position, centreDir);
  if (solidAngle <= 0.0) return result;
  int type = lightType(L);
  float sinHalf = sqrt(min(solidAngle / PI, 1.0));  // sine of the cone of equal (projected) solid angle
  float cosHalf = type == LIGHT_SUN ? 1.0 - sunOneMinusCos(L) : sqrt(1.0 - sinHalf * sinHalf);
  vec3 radiance = lightRadiance(L);

  // Diffuse: the light as a point at its centre.
  result.diffuse = diffuseCos(s.diffuse, toLocal(s, centreDir)) * radiance * solidAngle;

  vec3 r = reflect(-s.view, s.normal);
  vec3 l = type == LIGHT_SUN || type == LIGHT_SPHERE ? closestInCone(r, centreDir, cosHalf, sinHalf)
                                                     : normalize(closestOnPlanarLight(L, s.position, r) - s.position);
  vec3 wi = toLocal(s, l);
  if (wi.z <= 0.0) return result;
  vec3 h = normalize(wo + wi);
  vec3 dl1, dl2;
  lightOutline(L, s.position, centreDir, sinHalf, dl1, dl2);
  float mass = lobeMassOnImage(lobe, lightImage(wo, toLocal(s, centreDir), toLocal(s, dl1), toLocal(s, dl2)));
  // G2 (o.h) / (h_z o_z), with G2 / o_z in its bounded form.
  float geometry = lobeG2OverCos(lobe, wo, wi) * dot(wo, h) / max(h.z, 1e-4);
  result.specular = fresnelSchlick(s.f0, dot(wo, h)) * (mass * geometry) * radiance;
  return result;
}
