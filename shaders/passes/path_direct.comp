// The path tracer's shading of its hits (`path` reference backend), one path vertex at a time: per
// hit, the surface record the forward pass builds (core/surface_record.glsl) from the attributes
// and their per-sub-pixel derivatives that the host interpolated at the hit (ray differentials),
// the material's prepare step, then every light's samples as the raster reference draws them
// (passes/reference_estimator.glsl: the same streams, the same weights), each written as a shadow
// ray with its contribution, and the direction the path goes on in (a bounce) with its weight. The
// host traces the rays, adds the contributions whose light is visible and follows the bounces. One
// program per material variant ($MATERIAL and the forward pass's defines:
// src/render/path_reference.cpp); the backends `path:<method>` put a method's footprint NDF in
// normal-map-glints materials' $MATERIAL slot, whose environment lights are then shaded by lobes.
layout(local_size_x = 64) in;

#define METHOD_SHADES_ENVIRONMENT
#include "core/frame.glsl"
#include "lights/lights.glsl"
#include "core/surface_record.glsl"
#include "$MATERIAL"
#include "passes/reference_estimator.glsl"

// A hit as the host interpolated it (src/render/path_reference.cpp, PathHit: std430, vec4s).
struct PathHit {
  vec4 position;       // xyz; w unused
  vec4 normal;         // as interpolated (not normalised)
  vec4 tangent;        // xyz, w the handedness
  vec4 faceNormal;     // the triangle's
  vec4 dPdx, dPdy;     // per sub-pixel, right and up (GL's screen axes)
  vec4 dNdx, dNdy;     // of the interpolated normal
  vec4 dTangentdx, dTangentdy;
  vec4 uv;             // xy: the mesh's uv; zw: its derivative along x
  vec4 dUVdy_global;   // xy: the uv's derivative along y; zw: the sub-pixel in the film's grid (GL's y up)
  vec4 incoming;       // after a bounce (w = 1): xyz the unit direction back along the ray; camera rays: w = 0
  vec4 dViewdx, dViewdy;  // after a bounce: the derivatives of that direction
};

// A shadow ray from the hit: towards dir_dist.xyz, the light dir_dist.w away (0: no ray).
struct PathShadowRay {
  vec4 dir_dist;
  vec4 diffuse;
  vec4 specular;
};

layout(std430, binding = PATH_HITS_BINDING) readonly buffer PathHits { PathHit hits[]; };
layout(std430, binding = PATH_SHADOW_RAYS_BINDING) writeonly buffer PathShadowRays { PathShadowRay shadowRays[]; };
layout(std430, binding = PATH_EMISSION_BINDING) writeonly buffer PathEmission { vec4 emission[]; };
// Where the path goes on: dir_lobe.xyz (world space; w 0: it ends, 1 the diffuse lobe, 2 the
// specular one), and the bounce's weights f cos / pdf of the diffuse and the specular lobe
// (diffuse.rgb, specular.rgb). Off a mirror, the reflected ray's direction differentials (dDdx.w =
// 1; Igehy 1999): its origin's are the hit's dP. Off anything else, dDdy.w is the roughness of the
// material's smooth lobe, which widens later footprints (path/ray_cone.hpp).
struct PathBounce {
  vec4 dir_lobe;
  vec4 diffuse;
  vec4 specular;
  vec4 dDdx;
  vec4 dDdy;
};
layout(std430, binding = PATH_CONTINUATION_BINDING) writeonly buffer PathBounces { PathBounce bounces[]; };

uniform uint uFirst;        // the draw's hits: [uFirst, uFirst + uCount)
uniform uint uCount;
uniform uint uRaysPerHit;   // slots per hit: each delta light 1, each light with extent 2 n + 1
uniform uint uDepth;        // the path vertex: 0 where camera rays hit (the raster reference's streams)
uniform bool uBounce;       // whether the path goes on from here

uint gHit, gSlot = 0u;
ivec2 gGlobal;
uint gReferenceLightIndex = 0u;

void emitShadowRay(vec3 dir, float dist, vec3 diffuse, vec3 specular) {
  shadowRays[gHit * uRaysPerHit + gSlot] = PathShadowRay(vec4(dir, dist), vec4(diffuse, 0.0), vec4(specular, 0.0));
  ++gSlot;
}

void emitSample(ReferenceSample r, float diffuseScale, float specularScale) {
  if (r.dist > 0.0) emitShadowRay(r.dir, r.dist, r.diffuse * diffuseScale, r.specular * specularScale);
}

void prepareSurface(inout Surface s) { materialPrepare(s, materials[uMaterial]); }

// The distance to a delta light: its position for the kinds at a point (point, spot: position_radius),
// none for a distant one.
float deltaLightDistance(LightData L, vec3 p) {
  return lightIsDistant(L) ? FAR_AWAY : length(L.position_radius.xyz - p);
}

#ifdef MATERIAL_ENVIRONMENT_LOBES
// An environment on a method's footprint NDF (`path:<method>`, materials/normal-map-glints-footprint.glsl)
// by the environment's spherical Gaussian lobes (Deng et al. 2022, sec. 5.4): each lobe one range
// query of the footprint's NDF over its cone's half-vector box (glints/normal-map/environment_lobes.glsl)
// and one shadow ray along its axis (visibility taken as constant over the lobe, as the paper's
// angular prefiltering does); the diffuse term by the light's own samples.
void emitEnvironmentByLobes(Surface s, LightData L, vec3 wo, ReferenceStream st) {
  const float perSample = 1.0 / float(st.count);
  for (uint j = 0u; j < st.count; ++j) {
    vec3 dir;
    float dist, pdf;
    if (!sampleLightDirection(L, s.position, r2Point(st.first + j, st.rotLight), dir, dist, pdf) || !(pdf > 0.0))
      continue;
    const vec3 wi = toLocal(s, dir);
    if (wi.z > 0.0)
      emitShadowRay(dir, dist, materialDiffuseCos(s, wi) * lightRadianceFrom(L, dir) * (perSample / pdf), vec3(0.0));
  }
  vec3 axis;
  for (int k = 0; k < environmentLobeCount; ++k) {
    const vec3 specular = normalGlintsEnvironmentLobe(s, L, k, wo, gMaskingAlpha, axis);
    if (max(specular.r, max(specular.g, specular.b)) > 0.0) emitShadowRay(axis, FAR_AWAY, vec3(0.0), specular);
  }
}
#endif

// Writes the light's samples as shadow rays; the radiance is the host's to sum.
Radiance shadeLight(Surface s, LightData L) {
  uint lightIndex = gReferenceLightIndex++;
  Radiance none = Radiance(vec3(0.0), vec3(0.0));
  vec3 wo = toLocal(s, s.view);
  if (wo.z <= 0.0) return none;
  if (!lightHasExtent(L)) {
    vec3 l, irradiance;
    deltaLightIncidence(L, s.position, l, irradiance);
    vec3 wi = toLocal(s, l);
    emitShadowRay(l, deltaLightDistance(L, s.position), materialDiffuseCos(s, wi) * irradiance,
                  materialSpecularCos(s, wo, wi) * irradiance);
    return none;
  }
  // Each vertex its own streams; the first the raster reference's.
  ReferenceStream st = referenceStream(gGlobal, lightIndex + uDepth * uint(MAX_LIGHTS));
#ifdef MATERIAL_ENVIRONMENT_LOBES
  if (!lightIsCompact(L) && environmentLobeCount > 0) {
    emitEnvironmentByLobes(s, L, wo, st);
    return none;
  }
#endif
  bool mirror = referenceMirror(s);
  float perSample = 1.0 / float(st.count);
  float specularScale = perSample * referenceSpecularFactor(s, L, wo, st);
  for (uint j = 0u; j < st.count; ++j) {
    emitSample(referenceLightSample(s, L, wo, mirror, st, j), perSample, specularScale);
    emitSample(referenceBrdfSample(s, L, wo, mirror, st, j), perSample, specularScale);
  }
  if (mirror) emitSample(referenceMirrorSample(s, L, wo), 1.0, 1.0);
  return none;
}

#include "lights/light_loop.glsl"

// The bounce: one direction from the diffuse lobe (cosine) or the specular one (the material's
// sampler; a mirror's reflection), chosen by their albedos' luminance, weighted by one-sample MIS
// of the two (the mixture's density). Glinty kinds bounce with their light integrand, the smooth
// BRDF of their model (as glint renderers do for indirect light: docs/methods.md, "The path tracer").
// The derivative of a mirror's reflection R = D - 2 (D.N) N along one step, from the incoming
// direction's dD and the unit normal's dN (Igehy 1999, eq. 14-15).
vec3 reflectionDerivative(vec3 D, vec3 N, vec3 dD, vec3 dN) {
  return dD - 2.0 * (dot(D, N) * dN + (dot(dD, N) + dot(D, dN)) * N);
}

PathBounce pathBounce(Surface s, vec3 normal) {
  PathBounce none = PathBounce(vec4(0.0), vec4(0.0), vec4(0.0), vec4(0.0), vec4(0.0));
  vec3 wo = toLocal(s, s.view);
  if (!uBounce || wo.z <= 0.0) return none;
  uint h = hash3(uvec3(uvec2(gGlobal), uDepth * 7919u + uint(frame.tile.w) + 0x5bd1e995u));
  vec2 u = hashToUnit2(h);
  float pick = uintToUnit(pcgHash(h + 7u));
  float diffuseShare = dot(s.diffuse, vec3(0.2126, 0.7152, 0.0722));
  float specularShare = dot(s.f0, vec3(0.2126, 0.7152, 0.0722));
  // A lobe that reflects nothing is never picked; otherwise each at least 5% of the time (Schlick's
  // Fresnel reflects at grazing angles even when f0 = 0).
  float pDiffuse = diffuseShare <= 0.0 ? 0.0 : clamp(diffuseShare / (diffuseShare + specularShare), 0.05, 0.95);
  if (referenceMirror(s)) {
    // A delta lobe: its weight is F (the diffuse lobe is sampled with probability pDiffuse alone).
    if (pick < pDiffuse) {
      vec3 wi = vec3(sqrt(u.x) * vec2(cos(TWO_PI * u.y), sin(TWO_PI * u.y)), sqrt(max(1.0 - u.x, 0.0)));
      if (wi.z <= 0.0) return none;
      return PathBounce(vec4(toWorld(s, wi), 1.0), vec4(materialDiffuseCos(s, wi) / (pDiffuse * wi.z / PI), 0.0),
                        vec4(0.0), vec4(0.0), vec4(0.0));
    }
    vec3 wi = reflect(-wo, vec3(0.0, 0.0, 1.0));
    // The reflected ray's differentials about the shading normal, whose change is the
    // interpolated normal's (a normal map's own change is not followed).
    vec3 D = -s.view, N = s.normal, n = normal;
    float length_n = length(n);
    vec3 dNdx = (s.footprint.dNdx - N * dot(N, s.footprint.dNdx)) / length_n;
    vec3 dNdy = (s.footprint.dNdy - N * dot(N, s.footprint.dNdy)) / length_n;
    return PathBounce(vec4(toWorld(s, wi), 2.0), vec4(0.0), vec4(fresnelSchlick(s.f0, wo.z) / (1.0 - pDiffuse), 0.0),
                      vec4(reflectionDerivative(D, N, -s.footprint.dVdx, dNdx), 1.0),
                      vec4(reflectionDerivative(D, N, -s.footprint.dVdy, dNdy), 0.0));
  }
  vec3 wi;
  if (pick < pDiffuse) {
    wi = vec3(sqrt(u.x) * vec2(cos(TWO_PI * u.y), sin(TWO_PI * u.y)), sqrt(max(1.0 - u.x, 0.0)));
  } else {
    wi = reflect(-wo, materialSampleNormal(s, wo, u));
  }
  if (wi.z <= 0.0) return none;
  float pdf = pDiffuse * wi.z / PI + (1.0 - pDiffuse) * materialSamplePdf(s, wo, wi);
  if (!(pdf > 0.0)) return none;
  Lobe smoothLobe = materialSmoothLobe(s);
  float alpha = sqrt(max(smoothLobe.A[0][0], smoothLobe.A[1][1]));
  return PathBounce(vec4(toWorld(s, wi), pick < pDiffuse ? 1.0 : 2.0), vec4(materialDiffuseCos(s, wi) / pdf, 0.0),
                    vec4(materialLightIntegrand(s, wo, wi) / pdf, 0.0), vec4(0.0), vec4(0.0, 0.0, 0.0, alpha));
}

void main() {
  if (gl_GlobalInvocationID.x >= uCount) return;
  gHit = uFirst + gl_GlobalInvocationID.x;
  PathHit h = hits[gHit];
  gGlobal = ivec2(floatBitsToInt(h.dUVdy_global.zw));
  MaterialData m = materials[uMaterial];

  // The footprint as the forward pass's screen-space derivatives give it: each derivative one
  // sub-pixel's step of the quantity (finite, as dFdxFine), from the attributes' derivatives.
  vec3 position = h.position.xyz;
  bool bounced = h.incoming.w > 0.5;
  vec3 view = bounced ? h.incoming.xyz : viewDirectionFrom(position);
  vec3 n = normalize(h.normal.xyz), t, b;
  vertexTangentFrame(n, h.tangent, 1.0, t, b);
  vec3 tx, ty;
  vertexTangentFrame(normalize(h.normal.xyz + h.dNdx.xyz), h.tangent + h.dTangentdx, 1.0, tx, b);
  vertexTangentFrame(normalize(h.normal.xyz + h.dNdy.xyz), h.tangent + h.dTangentdy, 1.0, ty, b);
  vec2 vertexUV = h.uv.xy, dVertexUVdx = h.uv.zw, dVertexUVdy = h.dUVdy_global.xy;
  vec2 uv = normalMapCoordinates(vertexUV);
  vec3 dViewdx = bounced ? h.dViewdx.xyz : viewDirectionFrom(position + h.dPdx.xyz) - view;
  vec3 dViewdy = bounced ? h.dViewdy.xyz : viewDirectionFrom(position + h.dPdy.xyz) - view;
  Footprint footprint = makeFootprint(
      h.dPdx.xyz, h.dPdy.xyz, h.dNdx.xyz, h.dNdy.xyz, tx - t, ty - t, dViewdx, dViewdy, dVertexUVdx, dVertexUVdy,
      normalMapCoordinates(vertexUV + dVertexUVdx) - uv, normalMapCoordinates(vertexUV + dVertexUVdy) - uv);
  vec3 mapped = normalMapValue(uv, footprint.dUVdx, footprint.dUVdy);  // REFERENCE_PASS: at the sample point
  vec3 materialEmission;
  Surface s = surfaceRecord(m, position, h.normal.xyz, h.tangent, vertexUV, uv, view, h.faceNormal.xyz, footprint,
                            mapped, materialEmission);
  prepareSurface(s);
  shadeAllLights(s);
  for (uint slot = gSlot; slot < uRaysPerHit; ++slot)
    shadowRays[gHit * uRaysPerHit + slot].dir_dist = vec4(0.0, 0.0, 1.0, 0.0);
  emission[gHit] = vec4(materialEmission, 0.0);
  bounces[gHit] = pathBounce(s, h.normal.xyz);
}
