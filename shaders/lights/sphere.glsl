// Sphere light (src/scene/lights/sphere.cpp). Fields: colour_type.rgb: radiance [W/(m^2 sr)];
// position_radius: centre and radius R. Seen from p it is the cone of half-angle asin(R / d).
#include "lights/light_data.glsl"
#include "lights/light_shapes.glsl"

vec3 sphereLightCentreDirection(LightData L, vec3 p) { return directionTowards(L.position_radius.xyz, p); }

vec3 sphereLightRadiance(LightData L) { return L.colour_type.rgb; }

// 1 - cos of the half-angle the sphere subtends from p, as sin^2 / (1 + cos): no cancellation for
// small or distant spheres.
float sphereConeOneMinusCos(LightData L, vec3 p) {
  vec3 d = L.position_radius.xyz - p;
  float r = L.position_radius.w;
  float sin2 = min(r * r / max(dot(d, d), 1e-30), 1.0);
  return sin2 / (1.0 + sqrt(1.0 - sin2));
}

// The projected disk, pi sin^2 theta = pi R^2 / d^2 (the irradiance at normal incidence is L times it).
float sphereLightSolidAngle(LightData L, vec3 p, vec3 centreDir) {
  vec3 d = L.position_radius.xyz - p;
  float d2 = max(dot(d, d), 1e-12);
  float r = L.position_radius.w;
  return PI * min(r * r / d2, 1.0);
}

vec3 sphereLightRepresentativeDirection(LightData L, vec3 p, vec3 r, vec3 centreDir, float sinHalf) {
  return closestInCone(r, centreDir, sqrt(1.0 - sinHalf * sinHalf), sinHalf);
}

void sphereLightOutline(LightData L, vec3 p, vec3 centreDir, float sinHalf, out vec3 dl1, out vec3 dl2) {
  coneOutline(centreDir, sinHalf, dl1, dl2);
}

bool sphereLightHit(LightData L, vec3 origin, vec3 dir, out float dist) {
  dist = FAR_AWAY;
  vec3 c = L.position_radius.xyz;
  float r = L.position_radius.w;
  vec3 oc = origin - c;
  float b = dot(oc, dir);
  vec3 perp = oc - b * dir;  // r^2 - |perp|^2, not b^2 - |oc|^2 + r^2: no cancellation far away
  float disc = r * r - dot(perp, perp);
  if (disc < 0.0) return false;
  float s = sqrt(disc);
  dist = -b - s;
  if (dist <= 0.0) dist = -b + s;
  return dist > 0.0;
}

// Uniform over the cone the sphere subtends.
float sphereLightPdf(LightData L, vec3 p, vec3 dir, float dist) {
  return 1.0 / (TWO_PI * max(sphereConeOneMinusCos(L, p), MIN_CONE_ONE_MINUS_COS));
}

bool sphereLightSample(LightData L, vec3 p, vec2 u, out vec3 dir, out float dist, out float pdf) {
  dist = FAR_AWAY;
  vec3 toC = L.position_radius.xyz - p;
  dir = sampleCone(normalize(toC), sphereConeOneMinusCos(L, p), u);
  pdf = sphereLightPdf(L, p, dir, dist);
  return sphereLightHit(L, p, dir, dist);
}

// The cone tangent to the sphere cut by the plane through its centre normal to l: a circle of
// radius R d / sqrt(d^2 - R^2). Inside the sphere every direction reaches the light: unbounded.
LightDisk sphereLightDiskForm(LightData L, vec3 p) {
  vec3 c = L.position_radius.xyz;
  float radius = L.position_radius.w;
  float distance = length(c - p);
  float d2 = distance * distance;
  bool outside = d2 > radius * radius * 1.0001;
  return LightDisk(c, -sphereLightCentreDirection(L, p),
                   outside ? radius * distance * inversesqrt(d2 - radius * radius) : 1e20, distance,
                   outside ? asin(radius / distance) : 0.5 * PI, true);
}
