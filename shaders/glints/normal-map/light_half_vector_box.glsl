// A light's half-vector region as an axis-aligned box in the plane of projected half vectors
// s = h.xy (docs/methods.md#yan2016, "Lights with extent"): the range over which a method
// averages a P-NDF for a light with extent (yan2016, deng2022). Local frame (z = macro normal).
// The light's outline as seen from the point is an ellipse of conjugate semi-axes dl1, dl2
// (changes of the unit centre direction l_c, lights/lights.glsl's lightOutline); h = (v + l) / |v + l|
// moves by dh = (I - h h^T) dl / |v + l|, so the region is about the ellipse of semi-axes
// ds_i = dh_i.xy around s_c = h_c.xy. Its axis-aligned bounding box has half extents
// (sqrt(ds1.x^2 + ds2.x^2), sqrt(ds1.y^2 + ds2.y^2)); scaled by sqrt(pi |det(ds1, ds2)| / (4 e.x e.y))
// it keeps the ellipse's area, so that a P-NDF nearly constant over the region gets the right mass.
#include "core/constants.glsl"

struct HalfVectorBox {
  vec3 l;           // the light's centre direction l_c (local)
  vec3 h;           // h_c = normalize(v + l_c)
  vec2 centre;      // s_c = h_c.xy
  vec2 halfExtent;  // e
};

// wo: the view direction; lc, dl1, dl2: the light's centre direction and outline (local).
HalfVectorBox halfVectorBox(vec3 wo, vec3 lc, vec3 dl1, vec3 dl2) {
  HalfVectorBox box;
  vec3 sum = wo + lc;
  float len = max(length(sum), 1e-6);
  box.l = lc;
  box.h = sum / len;
  box.centre = box.h.xy;
  vec2 ds1 = (dl1 - box.h * dot(box.h, dl1)).xy / len, ds2 = (dl2 - box.h * dot(box.h, dl2)).xy / len;
  vec2 e = sqrt(ds1 * ds1 + ds2 * ds2);
  float boxArea = 4.0 * e.x * e.y;
  float ellipseArea = PI * abs(ds1.x * ds2.y - ds1.y * ds2.x);
  box.halfExtent = boxArea > 0.0 ? e * sqrt(ellipseArea / boxArea) : e;
  return box;
}
