// Quad light (src/scene/lights/quad.cpp), a one-sided rectangle. Fields: colour_type.rgb:
// radiance [W/(m^2 sr)]; position_radius.xyz: centre; direction_cos.xyz: emitting normal n;
// axisU.xyz, axisV.xyz: half edges (u, v, n right-handed).
#include "lights/light_data.glsl"
#include "lights/light_shapes.glsl"

float quadLightArea(LightData L) { return 4.0 * length(L.axis_u.xyz) * length(L.axis_v.xyz); }

vec3 quadLightCentreDirection(LightData L, vec3 p) { return directionTowards(L.position_radius.xyz, p); }

vec3 quadLightRadiance(LightData L) { return L.colour_type.rgb; }

float quadLightSolidAngle(LightData L, vec3 p, vec3 centreDir) {
  return planarSolidAngle(L.position_radius.xyz, L.direction_cos.xyz, quadLightArea(L), p, centreDir);
}

// The quad's point closest to the reflected ray's hit with its plane.
vec3 quadLightRepresentativeDirection(LightData L, vec3 p, vec3 r, vec3 centreDir, float sinHalf) {
  vec3 c = L.position_radius.xyz;
  vec3 d = reflectedRayOnPlane(c, L.direction_cos.xyz, p, r) - c;
  vec3 u = L.axis_u.xyz, v = L.axis_v.xyz;
  float su = clamp(dot(d, u) / dot(u, u), -1.0, 1.0);
  float sv = clamp(dot(d, v) / dot(v, v), -1.0, 1.0);
  return normalize(c + su * u + sv * v - p);
}

// The ellipse of equal area: the half edges scaled by 2 / sqrt(pi).
void quadLightOutline(LightData L, vec3 p, vec3 centreDir, float sinHalf, out vec3 dl1, out vec3 dl2) {
  projectedOutline(L.position_radius.xyz, 1.1283792 * L.axis_u.xyz, 1.1283792 * L.axis_v.xyz, p, centreDir, dl1, dl2);
}

bool quadLightHit(LightData L, vec3 origin, vec3 dir, out float dist) {
  vec3 d;
  if (!planeHit(L.position_radius.xyz, L.direction_cos.xyz, origin, dir, dist, d)) return false;
  vec3 u = L.axis_u.xyz, v = L.axis_v.xyz;
  return abs(dot(d, u)) <= dot(u, u) && abs(dot(d, v)) <= dot(v, v);
}

// Uniform by area.
float quadLightPdf(LightData L, vec3 p, vec3 dir, float dist) {
  return planarPdf(L.direction_cos.xyz, quadLightArea(L), dir, dist);
}

bool quadLightSample(LightData L, vec3 p, vec2 u, out vec3 dir, out float dist, out float pdf) {
  dist = FAR_AWAY;
  vec3 q = L.position_radius.xyz + (2.0 * u.x - 1.0) * L.axis_u.xyz + (2.0 * u.y - 1.0) * L.axis_v.xyz;
  if (!directionToPlanarPoint(q, p, L.direction_cos.xyz, dir, dist)) return false;
  pdf = quadLightPdf(L, p, dir, dist);
  return true;
}

int quadLightPolygonForm(LightData L, out vec3 vertex[LIGHT_POLYGON_MAX_VERTICES]) {
  vec3 c = L.position_radius.xyz, u = L.axis_u.xyz, v = L.axis_v.xyz;
  vertex[0] = c - u - v;
  vertex[1] = c + u - v;
  vertex[2] = c + u + v;
  vertex[3] = c - u + v;
  return 4;
}
