// Geometry the light kinds (shaders/lights/) share: cones (spheres and suns), planar emitters
// (disks and quads), and the forms a kind offers to methods that integrate over its shape.
#include "core/constants.glsl"
#include "lights/light_data.glsl"

// The disk form of a light seen from p (LIGHT_FORM_DISK): a disk of `radius` about `centre` that
// subtends the light's solid angle. A disk light is its own; a sphere or a sun is the disk facing
// p (normal -l) through its centre, or at unit distance for a sun, that subtends its cone.
struct LightDisk {
  vec3 centre;
  vec3 normal;          // the emitting side
  float radius;
  float distance;       // from p to the centre
  float angularRadius;  // half-angle of the cone of the light's solid angle seen from p
  bool facing;          // normal = -(unit direction from p to the centre)
};

// The polygon form of a light (LIGHT_FORM_POLYGON): up to this many vertices, counter-clockwise
// seen from the emitting side.
#define LIGHT_POLYGON_MAX_VERTICES 4

// Unit direction from p towards a point c.
vec3 directionTowards(vec3 c, vec3 p) {
  vec3 d = c - p;
  return d * inversesqrt(max(dot(d, d), 1e-24));
}

// Orthonormal basis around unit n (Duff et al. 2017).
void basisAround(vec3 n, out vec3 t, out vec3 b) {
  float s = n.z >= 0.0 ? 1.0 : -1.0;
  float a = -1.0 / (s + n.z);
  float c = n.x * n.y * a;
  t = vec3(1.0 + s * n.x * n.x * a, s * c, -s * n.x);
  b = vec3(c, s + n.y * n.y * a, -n.y);
}

// --- Cones --------------------------------------------------------------------------------------

// sin^2 of a cone's half-angle from 1 - cos, without cancellation: (1 - c)(1 + c).
float coneSin2(float oneMinusCos) { return oneMinusCos * (2.0 - oneMinusCos); }

// Smallest 1 - cos of a cone that densities and radiances use (below 1e-7 degrees): keeps a cone's
// pdf under 2e17, so that MIS weights built from squared pdfs stay finite.
const float MIN_CONE_ONE_MINUS_COS = 1e-18;

// Is the direction dir inside the cone of half-angle acos(1 - oneMinusCos) (< 90 degrees) around
// axis? Compares sin^2 from the cross product, exact near the axis, not cosines near 1.
bool inCone(vec3 dir, vec3 axis, float oneMinusCos) {
  float c = dot(dir, axis);
  if (c <= 0.0) return false;
  vec3 x = cross(dir, axis);
  return dot(x, x) <= coneSin2(oneMinusCos) * dot(dir, dir) * dot(axis, axis);
}

// Uniform direction in the cone of half-angle acos(1 - oneMinusCosMax) around axis;
// pdf = 1 / (2 pi oneMinusCosMax). Samples 1 - cos directly, so small cones keep their resolution.
vec3 sampleCone(vec3 axis, float oneMinusCosMax, vec2 u) {
  float oneMinusCosT = u.x * oneMinusCosMax;
  float cosT = 1.0 - oneMinusCosT;
  float sinT = sqrt(max(0.0, coneSin2(oneMinusCosT)));
  float phi = TWO_PI * u.y;
  vec3 t, b;
  basisAround(axis, t, b);
  return normalize(sinT * cos(phi) * t + sinT * sin(phi) * b + cosT * axis);
}

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

// A cone's outline: a circle of radius sin(half-angle) about its axis lc.
void coneOutline(vec3 lc, float sinHalf, out vec3 dl1, out vec3 dl2) {
  basisAround(lc, dl1, dl2);
  dl1 *= sinHalf;
  dl2 *= sinHalf;
}

// The major semi-axis of the ellipse of conjugate semi-axes a, b (a light's outline, in radians):
// the square root of the largest eigenvalue of a a^T + b b^T, whose trace is |a|^2 + |b|^2 and whose
// determinant (in the ellipse's plane) is |a x b|^2.
float outlineMajorRadius(vec3 a, vec3 b) {
  float trace = dot(a, a) + dot(b, b);
  vec3 n = cross(a, b);
  return sqrt(0.5 * (trace + sqrt(max(trace * trace - 4.0 * dot(n, n), 0.0))));
}

// --- Planar emitters (one-sided: the front face, along the normal n, emits) ---------------------

// Solid angle of a small planar emitter of area A about c seen from p: A cos / d^2 (0 from behind).
float planarSolidAngle(vec3 c, vec3 n, float area, vec3 p, vec3 centreDir) {
  vec3 d = c - p;
  float d2 = max(dot(d, d), 1e-12);
  float cosL = -dot(centreDir, n);
  return cosL <= 0.0 ? 0.0 : area * cosL / d2;
}

// Solid-angle density of uniform area sampling: dist^2 / (A cos).
float planarPdf(vec3 n, float area, vec3 dir, float dist) {
  float cosL = abs(dot(dir, n));
  return dist * dist / max(area * cosL, 1e-20);
}

// The ray (origin, unit dir) towards the front face of the plane through c: its distance and
// the hit's offset from c. false from behind or when the plane is behind the origin.
bool planeHit(vec3 c, vec3 n, vec3 origin, vec3 dir, out float dist, out vec3 offset) {
  dist = FAR_AWAY;
  offset = vec3(0.0);
  float cosL = dot(dir, n);
  if (cosL >= 0.0) return false;
  dist = dot(c - origin, n) / cosL;
  if (dist <= 0.0) return false;
  offset = origin + dist * dir - c;
  return true;
}

// Where the reflected ray (p, r) meets the light's plane, or the centre c if it does not: the
// start of a planar light's representative point (Karis 2013).
vec3 reflectedRayOnPlane(vec3 c, vec3 n, vec3 p, vec3 r) {
  float denom = dot(r, n);
  vec3 q = c;
  if (denom < -1e-6) {
    float t = dot(c - p, n) / denom;
    if (t > 0.0) q = p + t * r;
  }
  return q;
}

// Direction and distance from p to a sampled point q of a planar light; false if q is p or p is
// behind the emitting face.
bool directionToPlanarPoint(vec3 q, vec3 p, vec3 n, out vec3 dir, out float dist) {
  vec3 d = q - p;
  dist = length(d);
  if (dist <= 0.0) return false;
  dir = d / dist;
  return dot(dir, n) < 0.0;
}

// The outline of a planar light with conjugate semi-axes a1, a2 about c, seen from p: the axes
// projected perpendicular to the direction lc to the centre, as changes of that unit direction.
void projectedOutline(vec3 c, vec3 a1, vec3 a2, vec3 p, vec3 lc, out vec3 dl1, out vec3 dl2) {
  float dist = max(length(c - p), 1e-12);
  dl1 = (a1 - lc * dot(lc, a1)) / dist;
  dl2 = (a2 - lc * dot(lc, a2)) / dist;
}
