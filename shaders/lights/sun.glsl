// Sun (src/scene/lights/sun.cpp): a distant disk, the cone of half-angle theta about -direction.
// Fields: colour_type.rgb: irradiance E at normal incidence [W/m^2]; direction_cos.xyz: travel
// direction, w: cos theta; axisU.w: 1 - cos theta, computed in double (exact at small angles).
#include "lights/light_data.glsl"
#include "lights/light_shapes.glsl"

// 1 - cos theta from the CPU: 1 - direction_cos.w in float keeps only ~160 steps at 0.25 degrees.
// Hand-built records (tests) must set it too.
float sunOneMinusCos(LightData L) { return L.axis_u.w; }

vec3 sunLightCentreDirection(LightData L, vec3 p) { return -L.direction_cos.xyz; }

// E = L pi sin^2 theta: the radiance of a uniform disk of that irradiance.
vec3 sunLightRadiance(LightData L) {
  return L.colour_type.rgb / (PI * coneSin2(max(sunOneMinusCos(L), MIN_CONE_ONE_MINUS_COS)));
}

// The projected disk, pi sin^2 theta.
float sunLightSolidAngle(LightData L, vec3 p, vec3 centreDir) { return PI * coneSin2(sunOneMinusCos(L)); }

vec3 sunLightRepresentativeDirection(LightData L, vec3 p, vec3 r, vec3 centreDir, float sinHalf) {
  return closestInCone(r, centreDir, 1.0 - sunOneMinusCos(L), sinHalf);
}

void sunLightOutline(LightData L, vec3 p, vec3 centreDir, float sinHalf, out vec3 dl1, out vec3 dl2) {
  coneOutline(centreDir, sinHalf, dl1, dl2);
}

bool sunLightHit(LightData L, vec3 origin, vec3 dir, out float dist) {
  dist = FAR_AWAY;
  return inCone(dir, -L.direction_cos.xyz, sunOneMinusCos(L));
}

// Uniform over the cone: 1 / (2 pi (1 - cos theta)).
float sunLightPdf(LightData L, vec3 p, vec3 dir, float dist) {
  return 1.0 / (TWO_PI * max(sunOneMinusCos(L), MIN_CONE_ONE_MINUS_COS));
}

bool sunLightSample(LightData L, vec3 p, vec2 u, out vec3 dir, out float dist, out float pdf) {
  dist = FAR_AWAY;
  dir = sampleCone(-L.direction_cos.xyz, sunOneMinusCos(L), u);
  pdf = sunLightPdf(L, p, dir, dist);
  return true;
}

// The cone's section at unit distance: a disk of radius tan(theta) facing p.
LightDisk sunLightDiskForm(LightData L, vec3 p) {
  float cosT = L.direction_cos.w, sinT = sqrt(max(1.0 - cosT * cosT, 0.0));
  vec3 l = sunLightCentreDirection(L, p);
  return LightDisk(p + l, -l, sinT / max(cosT, 1e-6), 1.0, acos(cosT), true);
}
