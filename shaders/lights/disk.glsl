// Disk light (src/scene/lights/disk.cpp), one-sided. Fields: colour_type.rgb: radiance
// [W/(m^2 sr)]; position_radius: centre and radius; direction_cos.xyz: emitting normal n.
#include "lights/light_data.glsl"
#include "lights/light_shapes.glsl"

float diskLightArea(LightData L) {
  float r = L.position_radius.w;
  return PI * r * r;
}

vec3 diskLightCentreDirection(LightData L, vec3 p) { return directionTowards(L.position_radius.xyz, p); }

vec3 diskLightRadiance(LightData L) { return L.colour_type.rgb; }

float diskLightSolidAngle(LightData L, vec3 p, vec3 centreDir) {
  return planarSolidAngle(L.position_radius.xyz, L.direction_cos.xyz, diskLightArea(L), p, centreDir);
}

// The disk's point closest to the reflected ray's hit with its plane.
vec3 diskLightRepresentativeDirection(LightData L, vec3 p, vec3 r, vec3 centreDir, float sinHalf) {
  vec3 c = L.position_radius.xyz;
  vec3 q = reflectedRayOnPlane(c, L.direction_cos.xyz, p, r);
  vec3 d = q - c;
  float rad = L.position_radius.w;
  float len = length(d);
  return normalize((len > rad ? c + d * (rad / len) : q) - p);
}

void diskLightOutline(LightData L, vec3 p, vec3 centreDir, float sinHalf, out vec3 dl1, out vec3 dl2) {
  vec3 a1, a2;
  basisAround(L.direction_cos.xyz, a1, a2);
  a1 *= L.position_radius.w;
  a2 *= L.position_radius.w;
  projectedOutline(L.position_radius.xyz, a1, a2, p, centreDir, dl1, dl2);
}

bool diskLightHit(LightData L, vec3 origin, vec3 dir, out float dist) {
  vec3 d;
  if (!planeHit(L.position_radius.xyz, L.direction_cos.xyz, origin, dir, dist, d)) return false;
  return dot(d, d) <= L.position_radius.w * L.position_radius.w;
}

// Uniform by area.
float diskLightPdf(LightData L, vec3 p, vec3 dir, float dist) {
  return planarPdf(L.direction_cos.xyz, diskLightArea(L), dir, dist);
}

bool diskLightSample(LightData L, vec3 p, vec2 u, out vec3 dir, out float dist, out float pdf) {
  dist = FAR_AWAY;
  // Concentric square-to-disk mapping (Shirley & Chiu 1997).
  vec2 s = 2.0 * u - 1.0;
  float r, phi;
  if (s == vec2(0.0)) { r = 0.0; phi = 0.0; }
  else if (abs(s.x) > abs(s.y)) { r = s.x; phi = (PI / 4.0) * (s.y / s.x); }
  else { r = s.y; phi = PI / 2.0 - (PI / 4.0) * (s.x / s.y); }
  vec3 tx, ty;
  basisAround(L.direction_cos.xyz, tx, ty);
  vec3 q = L.position_radius.xyz + L.position_radius.w * r * (cos(phi) * tx + sin(phi) * ty);
  if (!directionToPlanarPoint(q, p, L.direction_cos.xyz, dir, dist)) return false;
  pdf = diskLightPdf(L, p, dir, dist);
  return true;
}

LightDisk diskLightDiskForm(LightData L, vec3 p) {
  vec3 c = L.position_radius.xyz, n = L.direction_cos.xyz;
  float radius = L.position_radius.w;
  float distance = length(c - p);
  float cosL = -dot(n, diskLightCentreDirection(L, p));
  return LightDisk(c, n, radius, distance, atan(radius * sqrt(max(cosL, 0.0)) / distance), false);
}
