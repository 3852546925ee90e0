// Lights: the interface every shading module uses, whatever the kind. Each kind is one file,
// shaders/lights/<kind>.glsl, with functions <kind>Light<Function> and the exact geometry of its
// light; approximations of a light belong to the methods. The dispatch below is generated from
// the kinds' registry (src/scene/lights/light_kinds.cpp, src/render/shader_contract.cpp): with a constant
// kind, as in the light loop (lights/light_loop.glsl), it folds to the kind's own function; kinds
// the scene lacks (LIGHT_<ID>_COUNT 0) are not compiled, and a property that every kind of the
// scene answers alike is a literal, so test a property rather than compare lightForm(L).
//
// Every kind:
//   bool lightHasExtent(L), lightIsDistant(L), lightIsCompact(L)  declared by the kind;
//   bool lightHasDiskForm(L), lightHasPolygonForm(L)
//                                              int lightForm(L): LIGHT_FORM_*
// Compact kinds (one radiance over a bounded extent; not an environment):
//   vec3 lightCentreDirection(L, p)            unit direction from p to the light's centre
// Delta lights (no extent):
//   void deltaLightIncidence(L, p, out l, out irradiance)  direction and irradiance at normal incidence
// Compact lights with extent:
//   vec3 lightRadiance(L)                      radiance (delta lights: intensity or irradiance)
//   float lightSolidAngle(L, p, centreDir)     projected solid angle about centreDir (0 from behind):
//                                              the irradiance at normal incidence over the radiance
//   vec3 lightRepresentativeDirection(L, p, r, centreDir, sinHalf)  the light's direction closest
//                                              to r (Karis 2013); sinHalf: of the cone of equal solid angle
//   void lightOutline(L, p, centreDir, sinHalf, out dl1, out dl2)   the outline seen from p as an
//                                              ellipse of conjugate semi-axes, changes of centreDir
// Every light with extent:
//   vec3 lightRadianceFrom(L, dir)             the radiance arriving from direction dir (compact
//                                              kinds: lightRadiance; an environment: its map)
//   bool lightHit(L, origin, dir, out dist)    does the ray reach the emitting side, and where
//   bool sampleLightDirection(L, p, u, out dir, out dist, out pdf)  a direction towards the light
//   float lightPdf(L, p, dir, dist)            the solid-angle density of sampleLightDirection
// Forms, for methods that integrate over the light's shape (lights/light_shapes.glsl):
//   LightDisk lightDiskForm(L, p)              LIGHT_FORM_DISK: disks, spheres, suns
//   int lightPolygonForm(L, out vertex[])      LIGHT_FORM_POLYGON: quads
#include "lights/light_data.glsl"
#include "lights/light_shapes.glsl"
#include "generated/light_kinds.glsl"

// Where a light shines from and its irradiance at normal incidence, a light with extent taken as a
// point at its centre carrying radiance x solid angle: the form the glint models are defined for
// (Chermain et al.'s BRDFs and Deliot & Belcour's counting take point and directional lights; a
// representative point would move with each glint's own lobe, and the glints with it).
void centreLightIncidence(LightData L, vec3 p, out vec3 l, out vec3 irradiance) {
  if (!lightHasExtent(L)) {
    deltaLightIncidence(L, p, l, irradiance);
  } else {
    l = lightCentreDirection(L, p);
    irradiance = lightRadiance(L) * lightSolidAngle(L, p, l);
  }
}
