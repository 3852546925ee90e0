// Environment (src/scene/lights/environment.cpp): radiance from every direction at infinity, a
// lat-long map that is piecewise constant per texel (it is the light: no filtered read), turned
// about +y. Not compact (lights/lights.glsl): the interface it offers is lightRadianceFrom, lightHit,
// and a sampler by the map's luminance x sin(theta) with its density; the prefiltered maps of the
// split sum belong to the lobe methods (lobe/environment_shading.glsl).
// Fields: colour_type.rgb: the intensity; position_radius: (cos, sin) of the turn, the map's
// width and height; direction_cos.x: 1 when the map has luminance to sample by, y: 1 when visible;
// axis_u.xyz: its luminance levels L_1 .. L_3 for glints under it (glints/binomial/environment_glints.glsl).
// The map's convention (src/scene/lights/environment_map.hpp): texel row 0 at the top, polar angle
// theta = pi v from +y, azimuth phi = 2 pi (u - 0.5), d = (sin theta sin phi, cos theta,
// -sin theta cos phi): the map's centre is -z and it is not mirrored seen from inside.
#include "core/constants.glsl"
#include "lights/light_data.glsl"

layout(binding = ENVIRONMENT_RADIANCE_UNIT) uniform sampler2D uEnvironmentRadiance;
// Rows y < H: row y's conditional CDF over its W texels (W + 1 entries); row H: the marginal CDF
// over rows (H + 1 entries). Built by src/scene/lights/environment_sampling.cpp.
layout(binding = ENVIRONMENT_CDF_UNIT) uniform sampler2D uEnvironmentCdf;

// Binary-search steps of the CDFs: enough for a row of 2048 texels (kMaxEnvironmentWidth).
const int ENVIRONMENT_CDF_SEARCH_STEPS = 12;

ivec2 environmentSize(LightData L) { return ivec2(L.position_radius.zw); }

// World direction to the map's (u, v): the turn undone, then the convention above.
vec2 environmentUv(LightData L, vec3 dir) {
  float c = L.position_radius.x, s = L.position_radius.y;
  vec3 d = vec3(c * dir.x - s * dir.z, dir.y, s * dir.x + c * dir.z);  // rotation by -turn about +y
  float theta = acos(clamp(d.y, -1.0, 1.0));
  float phi = atan(d.x, -d.z);
  return vec2(fract(phi * (0.5 * INV_PI) + 0.5), theta * INV_PI);
}

// A direction of the map's space in the world's: the rotation by +turn about +y.
vec3 environmentMapToWorld(LightData L, vec3 d) {
  float c = L.position_radius.x, s = L.position_radius.y;
  return vec3(c * d.x + s * d.z, d.y, -s * d.x + c * d.z);
}

// The map's (u, v) to a world direction (the inverse of environmentUv).
vec3 environmentDirection(LightData L, vec2 uv) {
  float theta = PI * uv.y, phi = TWO_PI * (uv.x - 0.5);
  float sinT = sin(theta);
  return environmentMapToWorld(L, vec3(sinT * sin(phi), cos(theta), -sinT * cos(phi)));
}

ivec2 environmentTexel(LightData L, vec2 uv) {
  ivec2 size = environmentSize(L);
  return clamp(ivec2(uv * vec2(size)), ivec2(0), size - 1);
}

vec3 environmentLightRadianceFrom(LightData L, vec3 dir) {
  return L.colour_type.rgb * texelFetch(uEnvironmentRadiance, environmentTexel(L, environmentUv(L, dir)), 0).rgb;
}

bool environmentLightHit(LightData L, vec3 origin, vec3 dir, out float dist) {
  dist = FAR_AWAY;
  return true;  // every direction reaches it (the raster reference has no occluders)
}

float environmentCdf(int i, int row) { return texelFetch(uEnvironmentCdf, ivec2(i, row), 0).r; }

// The interval [i, i + 1) of CDF `row` (count intervals) holding u: the largest i with cdf(i) <= u.
int environmentCdfInterval(int row, int count, float u) {
  int lo = 0, hi = count;
  for (int step = 0; step < ENVIRONMENT_CDF_SEARCH_STEPS; ++step) {
    int mid = (lo + hi) / 2;
    if (environmentCdf(mid, row) <= u) lo = mid;
    else hi = mid;
  }
  return min(lo, count - 1);
}

// Density over (u, v) of texel (x, y): the marginal's and the row's piece, per unit u and v.
float environmentTexelDensity(ivec2 size, ivec2 texel) {
  float row = environmentCdf(texel.y + 1, size.y) - environmentCdf(texel.y, size.y);
  float column = environmentCdf(texel.x + 1, texel.y) - environmentCdf(texel.x, texel.y);
  return row * float(size.y) * column * float(size.x);
}

// Solid-angle density: d omega = 2 pi^2 sin(theta) du dv.
float environmentLightPdf(LightData L, vec3 p, vec3 dir, float dist) {
  if (L.direction_cos.x < 0.5) return 0.0;
  vec2 uv = environmentUv(L, dir);
  float sinT = sin(PI * uv.y);
  if (sinT <= 0.0) return 0.0;
  return environmentTexelDensity(environmentSize(L), environmentTexel(L, uv)) / (2.0 * PI * PI * sinT);
}

// Row by the marginal CDF, then texel by the row's, each continuous within its piece.
bool environmentLightSample(LightData L, vec3 p, vec2 u, out vec3 dir, out float dist, out float pdf) {
  dist = FAR_AWAY;
  dir = vec3(0.0, 1.0, 0.0);
  pdf = 0.0;
  if (L.direction_cos.x < 0.5) return false;
  ivec2 size = environmentSize(L);
  int y = environmentCdfInterval(size.y, size.y, u.y);
  float y0 = environmentCdf(y, size.y), y1 = environmentCdf(y + 1, size.y);
  float v = (float(y) + clamp((u.y - y0) / max(y1 - y0, 1e-30), 0.0, 1.0)) / float(size.y);
  int x = environmentCdfInterval(y, size.x, u.x);
  float x0 = environmentCdf(x, y), x1 = environmentCdf(x + 1, y);
  float uu = (float(x) + clamp((u.x - x0) / max(x1 - x0, 1e-30), 0.0, 1.0)) / float(size.x);
  dir = environmentDirection(L, vec2(uu, v));
  // The density lightPdf gives this direction, not the sampled piece's: the two differ only where
  // rounding puts the direction in a neighbouring texel, and MIS needs the one lightPdf returns.
  pdf = environmentLightPdf(L, p, dir, dist);
  return pdf > 0.0;
}
