// Shading from a pixel's reflection space (Podee et al.): the light plane of a disk, sphere or
// sun, the corner rays' hits with it, reflection-vector selection and result weighting, and
// glintlab's lobe extension. Pure: the corner rays come in as data (podee/pixel_corners.glsl
// builds them in the forward pass), so tests run this on the device with any configuration.
// Derivations: docs/methods.md#podee.
#include "core/driver_profile.glsl"
#include "lobe/lobe_shading.glsl"
#include "podee/reflection_space.glsl"

// The reflected rays through the four corners of a pixel.
struct CornerRays {
  vec3 origin[4];     // surface points seen through the corners
  vec3 direction[4];  // unit reflection vectors there
};

// Choices of the method's parameters (src/shading/methods/podee.cpp).
struct ReflectionSpaceOptions {
  int area;     // AREA_EXACT: a disk in its own plane, exactly; AREA_CIRCLE: the paper's plane, the
                // light as a circle of equal area; AREA_LENS: the same, light and reflection space
                // as circles (a lens)
  bool glossy;  // the lobe extension (GLOSSY_ON); false: every material shaded as a mirror (the paper)
};

// The plane on which a pixel's reflection space is measured: through the light's centre c, with
// orthonormal axes u, w along which the light is an ellipse of semi-axes `axes`. Rays reach it
// travelling along +normal. valid is false when p does not see the emitting side.
struct LightPlane {
  vec3 centre, normal, u, w;
  vec2 axes;
  vec3 l;               // unit direction from p to c
  float distance;       // from p to c; 1 for a sun (its plane is placed at unit distance)
  float angularRadius;  // of the cone of the light's solid angle seen from p
  bool valid;
};

// The plane of the light's disk form (lights/light_shapes.glsl) seen from p. ownPlane: a disk that
// does not face p is measured in its own plane, where it is exactly a circle; otherwise in the
// paper's plane, normal to l, where it is to first order in R/d an ellipse (its orthographic
// projection along l). Disks that face p (spheres, suns) are exact circles in the plane normal to l.
LightPlane lightPlane(LightData L, vec3 p, bool ownPlane) {
  LightPlane plane;
  plane.l = lightCentreDirection(L, p);
  plane.normal = plane.l;
  basisAround(plane.l, plane.u, plane.w);
  plane.valid = true;
  LightDisk disk = lightDiskForm(L, p);
  plane.centre = disk.centre;
  plane.distance = disk.distance;
  plane.angularRadius = disk.angularRadius;
  if (disk.facing) {
    plane.axes = vec2(disk.radius);
    return plane;
  }
  // Normal n_L. u = n_L x l lies in both planes; the second axis is foreshortened by
  // cos_L = -n_L . l in the paper's plane.
  vec3 n = disk.normal;
  float cosL = -dot(n, plane.l);
  plane.valid = cosL > 0.0;  // one-sided emitter
  vec3 u = cross(n, plane.l);
  float len = length(u);
  if (len > 1e-6) plane.u = u / len;
  plane.normal = ownPlane ? -n : plane.l;
  plane.w = cross(plane.normal, plane.u);
  plane.axes = disk.radius * vec2(1.0, ownPlane ? 1.0 : max(cosL, 1e-6));
  return plane;
}

// Probability that the lobe, aimed at the light's centre, reflects into the light: slope-space
// mass within the light's image in half-vector slopes, a disk of radius tan(theta_L / 2) stretched
// by 1 / cos(theta_d) across the plane of incidence (reflection halves in-plane angles and
// compresses the others by cos theta_d), taken as the circle of equal area. Isotropic, with
// alpha^2 = sqrt(det A): GGX, the shared disk mass on the peak (ggxDiskMass(0, r) is the slope
// CDF r^2 / (1 + r^2), r^2 = t^2 / alpha^2); Beckmann: 1 - exp(-t^2 / alpha^2).
float lobeMassOnLight(Lobe lobe, float angularRadius, float cosThetaD) {
  float alpha2 = sqrt(max(determinant(lobe.A), 0.0));
  if (alpha2 <= 0.0) return 1.0;
  float t = tan(0.5 * angularRadius);
  float t2 = t * t / max(cosThetaD, 1e-4);
  return lobe.ndf == NDF_BECKMANN ? 1.0 - exp(-t2 / alpha2) : ggxDiskMass(0.0, sqrt(t2 / alpha2));
}

// The light convolved with the pixel's reflection space, as a light: the pixel's average of the
// profile the lobe makes of the light is the lobe's mass over this wider, dimmer light. In
// directions about l (first order: plane offsets over the distance), the light's outline (as
// `shadeLobe` takes it, lightOutline) and the hull q (unit-disk coordinates of the unscaled light)
// add as uniform ellipses with their second moments: C = D D^T + 4 Sigma_Q, semi-axes sqrt(eig C).
// It is a quad (the ellipse's area, lightOutline's 2/sqrt(pi) back) normal to l at the light's
// distance, with the radiance scaled by area(light) / area(C). `spread` scales Sigma_Q.
LightData reflectionSpaceLight(Surface s, LightData L, LightPlane plane, vec2 unitAxes, vec2 q[4], float spread) {
  // Second moments of the hull (two triangles: integral of x x^T = A/12 (sum v v^T + s s^T)).
  // Measured in units of the hull's size (clamped corners lie 1e4 plane distances away).
  float size = max(max(length(q[0]), length(q[1])), max(length(q[2]), length(q[3])));
  size = max(size, 1e-20);
  float area = 0.0;
  vec2 first = vec2(0.0);
  mat2 second = mat2(0.0);
  for (int k = 1; k < 3; ++k) {
    vec2 a = q[0] / size, b = q[k] / size, c = q[k + 1] / size, sum = a + b + c;
    float ar = 0.5 * cross2(b - a, c - a);
    area += ar;
    first += ar * sum / 3.0;
    second += ar / 12.0 * (outerProduct(a, a) + outerProduct(b, b) + outerProduct(c, c) + outerProduct(sum, sum));
  }
  mat2 cov = mat2(0.0);
  if (area > 1e-30) cov = second / area - outerProduct(first / area, first / area);
  // A covariance is positive semi-definite; rounding in thin hulls can break that, so clamp it.
  cov[0][0] = max(cov[0][0], 0.0);
  cov[1][1] = max(cov[1][1], 0.0);
  cov[0][1] = cov[1][0] = clamp(cov[0][1], -sqrt(cov[0][0] * cov[1][1]), sqrt(cov[0][0] * cov[1][1]));
  vec3 e1, e2;
  basisAround(plane.l, e1, e2);
  vec3 tu = unitAxes.x * plane.u, tw = unitAxes.y * plane.w;
  tu = (tu - plane.l * dot(plane.l, tu)) / plane.distance;
  tw = (tw - plane.l * dot(plane.l, tw)) / plane.distance;
  mat2 T = mat2(dot(e1, tu), dot(e2, tu), dot(e1, tw), dot(e2, tw));
  vec3 dl1, dl2;
  lightOutline(L, s.position, plane.l, sqrt(min(lightSolidAngle(L, s.position, plane.l) / PI, 1.0)), dl1, dl2);
  mat2 D = mat2(dot(e1, dl1), dot(e2, dl1), dot(e1, dl2), dot(e2, dl2));
  // lightImage is linear in the outline: keep the widening within about 0.1 rad (trace <= 0.03).
  mat2 spaceC = 4.0 * T * cov * transpose(T);
  spaceC *= spread * 0.03 / max(spaceC[0][0] + spaceC[1][1], max(0.03 / (size * size), 1e-30));
  mat2 C = D * transpose(D) + spaceC;
  float halfTrace = 0.5 * (C[0][0] + C[1][1]), halfDiff = 0.5 * (C[0][0] - C[1][1]);
  float root = sqrt(halfDiff * halfDiff + C[0][1] * C[0][1]);
  float l1 = max(halfTrace + root, 0.0), l2 = max(halfTrace - root, 0.0);
  // The major axis at angle atan2(2 C01, C00 - C11) / 2: no normalisation of a vector that can
  // underflow (a nearly diagonal C of tiny entries).
  float offDiagonal = 2.0 * C[0][1], diagonalGap = C[0][0] - C[1][1];
  float angle = abs(offDiagonal) + abs(diagonalGap) > 0.0 ? 0.5 * atan(offDiagonal, diagonalGap) : 0.0;
  vec2 v1 = vec2(cos(angle), sin(angle));
  float k = 0.8862269 * plane.distance;  // sqrt(pi)/2: the quad of the ellipse's area
  LightData wide;  // a quad light whose ellipse of equal area (its lightOutline) is C's
  // Same energy over a wider outline: the radiance scaled by |det D| / sqrt(det C) <= 1 (C >= D D^T),
  // bounded by 1 where rounding leaves l2 at 0.
  wide.colour_type = vec4(lightRadiance(L) * min(abs(determinant(D)) / max(sqrt(l1 * l2), 1e-30), 1.0), float(LIGHT_QUAD));
  wide.position_radius = vec4(s.position + plane.distance * plane.l, 0.0);
  wide.direction_cos = vec4(-plane.l, 0.0);
  wide.axis_u = vec4(k * sqrt(l1) * (v1.x * e1 + v1.y * e2), 0.0);
  wide.axis_v = vec4(k * sqrt(l2) * (v1.x * e2 - v1.y * e1), 0.0);
  return wide;
}

// What the reflection space makes of a light with a disk form: the podee term (Fresnel x coverage
// x radiance at the selected reflection vector), its weight in the pixel's specular, and the
// light the smooth shading of the rest takes (the light itself, or the light widened by the
// reflection space: reflectionSpaceLight).
struct ReflectionSpaceTerm {
  vec3 specular;
  float weight;
  LightData smoothLight;
};

ReflectionSpaceTerm reflectionSpaceTerm(Surface s, LightData L, LightPlane plane, CornerRays corners, Lobe lobe,
                                        ReflectionSpaceOptions options) {
  // Where the reflection space does not apply, the smooth shading of `conventional` (never the
  // mirror path) takes the whole specular term.
  ReflectionSpaceTerm term = ReflectionSpaceTerm(vec3(0.0), 0.0, L);
  if (dot(s.view, s.vertexNormal) <= 0.0) return term;
  float angularRadius = plane.angularRadius;

  // Lobe extension: the light convolved with the lobe is approximated by the light scaled by
  // 1/sqrt(P) with radiance P L (same energy, same peak). P = 1 for a mirror (the paper).
  float cosThetaD = dot(s.view, normalize(s.view + plane.l));
  float mass = options.glossy ? lobeMassOnLight(lobe, angularRadius, cosThetaD) : 1.0;
  float scale = inversesqrt(max(mass, 1e-8));
  vec2 axes = options.area != AREA_EXACT ? vec2(sqrt(plane.axes.x * plane.axes.y)) : plane.axes;  // circle of equal area
  axes *= scale;

  // Reflection space: the corner rays' hits with the light plane, in coordinates where the
  // (scaled) light is the unit disk. Only the part of the reflection space in front of the plane
  // (r . normal > 0) reaches it: the spherical quadrilateral of the corner directions clipped at
  // the plane's horizon. A corner behind it is replaced by the point where its edge to a corner in
  // front crosses the horizon, m = (r_j . N) r_i - (r_i . N) r_j, which the plane meets at
  // infinity in m's direction (clamped, as rays that nearly graze the plane, to 1e4 plane
  // distances): the clip exactly where one corner is in front (a triangle: its two edges'
  // crossings) or two adjacent ones are; with one corner behind, the clip has five vertices, and
  // the corner's own tangential direction, which lies between its two crossings, stands for both.
  // With no corner in front the reflection space lies wholly behind the plane (a pixel's spans
  // less than a hemisphere) and no reflected ray reaches the light. (Every corner was formerly
  // pushed to infinity along its own tangential part: the four corners of a pixel that reflects
  // away from the light, all behind the plane, surrounded the light's centre and covered it.)
  float facing[4];
  for (int i = 0; i < 4; ++i) facing[i] = dot(corners.direction[i], plane.normal);
  bool reaches = max(max(facing[0], facing[1]), max(facing[2], facing[3])) > 0.0;
  vec2 q[4];
  for (int i = 0; i < 4; ++i) {
    vec3 o = lightIsDistant(L) ? s.position : corners.origin[i];  // lights at infinity show no parallax
    vec3 r = corners.direction[i];
    // (prev, next, opposite: constants once the loop is unrolled; the corner in front is chosen
    // by a select of values, so that no array is indexed at run time.)
    int prev = (i + 3) % 4, next = (i + 1) % 4, opposite = (i + 2) % 4;
    if (facing[i] <= 0.0 && (facing[prev] > 0.0) != (facing[next] > 0.0)) {
      bool prevInFront = facing[prev] > 0.0;
      float facingJ = prevInFront ? facing[prev] : facing[next];
      vec3 rJ = prevInFront ? corners.direction[prev] : corners.direction[next];
      r = normalize(facingJ * r - facing[i] * rJ);  // on the horizon
    } else if (facing[i] <= 0.0 && facing[prev] <= 0.0 && facing[next] <= 0.0 && reaches) {
      // Opposite the only corner in front: not a vertex of the clip, which is the triangle of that
      // corner and its edges' crossings; repeat one crossing.
      r = normalize(facing[opposite] * corners.direction[next] - facing[next] * corners.direction[opposite]);
    }
    float t = dot(plane.centre - o, plane.normal) / max(dot(r, plane.normal), 1e-4);
    vec3 x = o + t * r - plane.centre;
    q[i] = vec2(dot(x, plane.u), dot(x, plane.w)) / axes;
  }
  convexHullQuad(q);

  // Reflection vector selection (sec. 3.1): the point closest to the light's centre.
  vec2 closest = closestPointInConvexQuad(q, vec2(0.0));
  vec3 selected = plane.centre + closest.x * axes.x * plane.u + closest.y * axes.y * plane.w;
  vec3 l = normalize(selected - s.position);
  if (dot(l, s.vertexNormal) <= 0.0) return term;  // the light is below this surface

  // Result weighting (sec. 3.2): the fraction of the pixel whose reflection reaches the light.
  // Under the paper's assumption, a constant Jacobian from the pixel to the plane, it is the
  // fraction of the reflection space the light covers. We assume a constant Jacobian to solid
  // angle seen from p instead: the same on a flat mirror (the space is small and near the light),
  // exact for a mirror sphere (whose image maps to reflected directions with a constant Jacobian),
  // and bounded when corners point away from the light, where the plane's area is unbounded. The
  // covered fraction is then (covered plane area) x (solid angle per unit plane area at the
  // selected point) / (solid angle of the reflection space).
  vec3 toCentre = plane.centre - s.position;
  vec3 axisU = axes.x * plane.u, axisW = axes.y * plane.w;
  vec3 first = toCentre + q[0].x * axisU + q[0].y * axisW;
  vec3 e1 = (q[1].x - q[0].x) * axisU + (q[1].y - q[0].y) * axisW;
  vec3 e2 = (q[2].x - q[0].x) * axisU + (q[2].y - q[0].y) * axisW;
  vec3 e3 = (q[3].x - q[0].x) * axisU + (q[3].y - q[0].y) * axisW;
  // The hits' solid angle carries the parallax of corner rays from different points (all of it
  // on a flat mirror); the corner directions' own solid angle is the spread of a strongly curved
  // pixel, which the plane truncates when corners point away from the light. The larger counts.
  vec3 r0 = corners.direction[0], r1 = corners.direction[1], r2 = corners.direction[2], r3 = corners.direction[3];
  float directionSolidAngle = triangleSolidAngle(r0, r1 - r0, r2 - r0) + triangleSolidAngle(r0, r2 - r0, r3 - r0);
  float spaceSolidAngle = max(triangleSolidAngle(first, e1, e2) + triangleSolidAngle(first, e2, e3), directionSolidAngle);
  vec3 toSelected = selected - s.position;
  float perArea = abs(dot(plane.normal, toSelected)) / pow(dot(toSelected, toSelected), 1.5);
  float covered = unitDiskIntersectionArea(q, options.area) * axes.x * axes.y;
  vec2 mean = 0.25 * (q[0] + q[1] + q[2] + q[3]);
  float coverage = !reaches ? 0.0
                 : spaceSolidAngle > 1e-20 ? clamp(covered * perArea / spaceSolidAngle, 0.0, 1.0)
                                           : (dot(mean, mean) <= 1.0 ? 1.0 : 0.0);
  // Fresnel at the selected half vector; the lobe's Smith masking-shadowing (1 for a mirror).
  vec3 wo = toLocal(s, s.view), wi = toLocal(s, l);
  float masking = options.glossy ? 1.0 / (1.0 + lobeLambda(lobe, wo) + lobeLambda(lobe, wi)) : 1.0;
  vec3 h = normalize(s.view + l);
  vec3 podee = fresnelSchlick(s.f0, max(dot(s.view, h), 0.0)) * masking * mass * coverage * lightRadiance(L);

  // The equal-peak disk is right for the core of a lobe narrower than the light (P_c near 1) whose
  // blur the reflection space does not resolve; elsewhere it moves the lobe's tails into the core.
  // resolved = Omega(Q) / (Omega(Q) + Omega_L (1/P_c - 1)) compares the reflection space with the
  // solid angle the lobe adds to the light; the disk's weight is resolved x P_c (1 for a mirror:
  // the paper). The rest is the smooth shading of the pixel's average: the lobe's mass over the
  // light widened by the reflection space (as far as its blur is unresolved, and not at grazing
  // view, where the corners are extrapolated past the silhouette).
  float blurSolidAngle = lightSolidAngle(L, s.position, plane.l) * (scale * scale - 1.0);
  float resolved = blurSolidAngle > 0.0 ? spaceSolidAngle / (spaceSolidAngle + blurSolidAngle) : 1.0;
  term.weight = resolved * mass;
  term.specular = podee;
  if (term.weight < 1.0) {
    vec2 q1[4];
    for (int i = 0; i < 4; ++i) q1[i] = q[i] * scale;
    float grazing = clamp(2.0 * wo.z, 0.0, 1.0);
    term.smoothLight = reflectionSpaceLight(s, L, plane, axes / scale, q1, resolved * grazing * grazing);
  }
  return term;
}

// Reflected radiance of a light with a disk form (disk, sphere, sun) through the pixel whose
// corner rays are `corners`. Other kinds of light are not handled here. The specular term is the
// weighted sum of the podee term and of one smooth shading (of the light or of its widened form),
// the latter computed where its weight is not 0 (core/driver_profile.glsl).
Radiance shadeReflectionSpace(Surface s, LightData L, CornerRays corners, Lobe lobe, ReflectionSpaceOptions options) {
  LightPlane plane = lightPlane(L, s.position, options.area == AREA_EXACT);
  // Nothing from a light whose emitting side p does not see, or that lies wholly below the
  // surface's tangent plane (whatever the normal map says).
  if (!plane.valid || dot(plane.l, s.vertexNormal) < -sin(plane.angularRadius)) return Radiance(vec3(0.0), vec3(0.0));
  Radiance result = Radiance(vec3(0.0), vec3(0.0));
  vec3 centreDir = lightCentreDirection(L, s.position);
  float solidAngle = lightSolidAngle(L, s.position, centreDir);
  if (toLocal(s, s.view).z <= 0.0 || solidAngle <= 0.0) return result;  // as shadeLobe
  result.diffuse = centreDiffuse(s, L, centreDir, solidAngle);
  ReflectionSpaceTerm term = reflectionSpaceTerm(s, L, plane, corners, lobe, options);
  result.specular = term.weight * term.specular;
  if (blendSideNeeded(term.weight < 1.0))
    result.specular += (1.0 - term.weight) * shadeLobe(s, term.smoothLight, lobe).specular;
  return result;
}
