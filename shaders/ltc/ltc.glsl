// Linearly transformed cosines: integrals of a clamped-cosine lobe over a light's polygon or disk
// after the light is mapped through M^-1 (Heitz, Dupuy, Hill, Neubelt 2016, sec. 4; Heitz & Hill
// 2017 for disks). Pure geometry: the matrices come from ltc/ltc_tables.glsl, the shading from
// ltc/ltc_shading.glsl. Every position here is relative to the shading point, in the frame the
// matrix acts on; M^-1 = identity gives the exact form factor (the Lambert integral).
//
// Form factor of a spherical polygon (Lambert; LTC eq. 11): (1/2pi) sum over its edges of
// acos(v_i . v_j) (v_i x v_j / |v_i x v_j|) . z, each vertex on the unit sphere. The angle is taken
// as atan(|v_i x v_j|, v_i . v_j), exact for short and for nearly opposite edges alike.
#include "core/constants.glsl"
#include "lights/light_shapes.glsl"

// A clipped polygon as its edges, each in a fixed slot: the polygon's sides (slots 0 ..
// LIGHT_POLYGON_MAX_VERTICES - 1), then one edge along the clip plane per clip (a convex polygon
// crosses a plane at most twice, so each clip adds at most one edge). No slot is chosen at run
// time: every array here is indexed by constants once the constant-bound loops are unrolled, so no
// driver spills the polygon to local memory (the Sutherland-Hodgman list this replaces wrote its
// output at a running count: a dynamically indexed vec3[6], copied three times per light).
// Unused slots hold the degenerate edge (z, z), whose contribution is exactly 0.
#define LTC_CLIPPED_MAX_VERTICES (LIGHT_POLYGON_MAX_VERTICES + 2)

struct LtcPolygonEdges {
  vec3 from[LTC_CLIPPED_MAX_VERTICES];
  vec3 to[LTC_CLIPPED_MAX_VERTICES];
};

const vec3 LTC_NO_EDGE = vec3(0.0, 0.0, 1.0);

// The edge's contribution to the vector form factor, times 2 pi (a, b need not be unit).
vec3 ltcEdgeVector(vec3 a, vec3 b) {
  vec3 va = normalize(a), vb = normalize(b);
  vec3 c = cross(va, vb);
  float s = length(c);
  float theta = atan(s, dot(va, vb));
  return c * (s > 1e-7 ? theta / s : 1.0);
}

// The sides of the polygon v[0..count): side i from v[i] to v[i + 1], the last back to v[0].
LtcPolygonEdges ltcPolygonSides(vec3 v[LIGHT_POLYGON_MAX_VERTICES], int count) {
  LtcPolygonEdges e;
  for (int i = 0; i < LTC_CLIPPED_MAX_VERTICES; ++i) {
    bool side = i < LIGHT_POLYGON_MAX_VERTICES && i < count;
    int at = min(i, LIGHT_POLYGON_MAX_VERTICES - 1), next = min(i + 1, LIGHT_POLYGON_MAX_VERTICES - 1);
    e.from[i] = side ? v[at] : LTC_NO_EDGE;
    e.to[i] = side ? (i + 1 < count ? v[next] : v[0]) : LTC_NO_EDGE;
  }
  return e;
}

// The edges in slots [0, horizon) clipped to z >= 0 (Sutherland-Hodgman, edge by edge), and in
// slot `horizon` the edge along z = 0 from where the boundary leaves the half-space to where it
// comes back, which closes the clipped polygon with its winding kept.
void ltcClipEdges(inout LtcPolygonEdges e, const int horizon) {
  vec3 leaves = LTC_NO_EDGE, returns = LTC_NO_EDGE;
  for (int i = 0; i < horizon; ++i) {
    vec3 a = e.from[i], b = e.to[i];
    bool aIn = a.z >= 0.0, bIn = b.z >= 0.0;
    float dz = a.z - b.z;
    vec3 x = mix(a, b, a.z / (dz != 0.0 ? dz : 1.0));  // used only where the edge crosses: dz != 0
    leaves = aIn && !bIn ? x : leaves;
    returns = !aIn && bIn ? x : returns;
    bool kept = aIn || bIn;
    e.from[i] = kept ? (aIn ? a : x) : LTC_NO_EDGE;
    e.to[i] = kept ? (bIn ? b : x) : LTC_NO_EDGE;
  }
  e.from[horizon] = leaves;
  e.to[horizon] = returns;
}

// Form factor of a polygon clipped to z >= 0, whatever its winding: (1/pi) times the integral of
// the cosine over its directions.
float ltcEdgesFormFactor(LtcPolygonEdges e) {
  float sum = 0.0;
  for (int i = 0; i < LTC_CLIPPED_MAX_VERTICES; ++i) sum += ltcEdgeVector(e.from[i], e.to[i]).z;
  return abs(sum) / TWO_PI;
}

// The integral under the lobe M^-1 of a polygon already clipped to the surface's horizon (slots
// [0, LIGHT_POLYGON_MAX_VERTICES] of ltcClipEdges): mapped by M^-1 and clipped to the cosine's
// horizon. The surface's horizon comes first because the lobe the LTC replaces is zero below it,
// while the fitted LTC may reach there.
float ltcClippedPolygonIntegral(mat3 Minv, LtcPolygonEdges e) {
  for (int i = 0; i <= LIGHT_POLYGON_MAX_VERTICES; ++i) {
    e.from[i] = Minv * e.from[i];
    e.to[i] = Minv * e.to[i];
  }
  ltcClipEdges(e, LIGHT_POLYGON_MAX_VERTICES + 1);
  return ltcEdgesFormFactor(e);
}

// The polygon's integral under the lobe M^-1, clipped at both horizons. M^-1 = identity gives
// the Lambert form factor.
float ltcPolygonIntegral(mat3 Minv, vec3 v[LIGHT_POLYGON_MAX_VERTICES], int count) {
  LtcPolygonEdges e = ltcPolygonSides(v, count);
  ltcClipEdges(e, LIGHT_POLYGON_MAX_VERTICES);
  return ltcClippedPolygonIntegral(Minv, e);
}

// The Lambert form factor of the polygon (M^-1 = identity: one clip).
float ltcPolygonFormFactorClipped(vec3 v[LIGHT_POLYGON_MAX_VERTICES], int count) {
  LtcPolygonEdges e = ltcPolygonSides(v, count);
  ltcClipEdges(e, LIGHT_POLYGON_MAX_VERTICES);
  return ltcEdgesFormFactor(e);
}

// The vector form factor of a disk (centre c, orthogonal semi-axes u, w of equal length) under the
// lobe M^-1, without horizon clipping (Heitz & Hill 2017, sec. 5): M^-1 maps the disk to an ellipse,
// whose cone from the origin is elliptic. In the ellipse's principal frame (e1, e2 in its plane, e3
// normal, plane at distance D) the cone is x^T Q x = 0 with, for a = (D/E1)^2, b = (D/E2)^2 (E: the
// semi-axes) and the centre's tangents (x0, y0) = (c.e1, c.e2) / D,
//   Q = [[a, 0, -a x0], [0, b, -b y0], [-a x0, -b y0, a x0^2 + b y0^2 - 1]],  det Q = -ab.
// Its eigenvalues are l1 >= l2 > 0 > l3; in the eigenframe the cone has tangent half-axes
// sqrt(-l3/l1), sqrt(-l3/l2) about the l3 eigenvector (a x0/(a - l3), b y0/(b - l3), 1), and its
// form factor about that axis is L1 L2 / sqrt((1 + L1^2)(1 + L2^2)) (exact for a circular cone).
// The vector form factor is taken along the axis with that length; ltc/ltc_tables.glsl's sphere
// table then clips the equivalent spherical cap at the horizon.
vec3 ltcDiskVectorFormFactor(mat3 Minv, vec3 c, vec3 u, vec3 w) {
  c = Minv * c;
  u = Minv * u;
  w = Minv * w;
  // Principal semi-axes of the ellipse c + u cos t + w sin t: eigenvectors of the Gram matrix.
  float uu = dot(u, u), ww = dot(w, w), uw = dot(u, w);
  float halfDiff = 0.5 * (uu - ww), root = sqrt(halfDiff * halfDiff + uw * uw);
  float e1Sq = 0.5 * (uu + ww) + root, e2Sq = max(0.5 * (uu + ww) - root, 1e-30 * e1Sq);
  // The major axis: the combination u cos t + w sin t with tan 2t = 2 uw / (uu - ww).
  float t = abs(uw) + abs(uu - ww) > 1e-12 * (uu + ww) ? 0.5 * atan(2.0 * uw, uu - ww) : 0.0;  // circle: any
  vec3 e1 = normalize(u * cos(t) + w * sin(t));
  vec3 e3 = normalize(cross(u, w));
  vec3 e2 = cross(e3, e1);
  float D = dot(c, e3);
  if (D < 0.0) {
    e3 = -e3;
    D = -D;
  }
  D = max(D, 1e-7 * length(c));
  float x0 = dot(c, e1) / D, y0 = dot(c, e2) / D;
  // Q / s with s = max(a, b): same eigenvectors, eigenvalues scaled, entries of order one.
  float a = D * D / e1Sq, b = D * D / e2Sq;
  float scale = max(a, b);
  float as = a / scale, bs = b / scale, inverseScale = 1.0 / scale;
  // Characteristic polynomial l^3 - tr l^2 + m l - det of Q / s: det = -as bs / s, and the sum of
  // its principal 2x2 minors, with the cancelling terms removed, m = as bs (1 + x0^2 + y0^2) - (as + bs) / s.
  float tr = as * (1.0 + x0 * x0) + bs * (1.0 + y0 * y0) - inverseScale;
  float m = as * bs * (1.0 + x0 * x0 + y0 * y0) - (as + bs) * inverseScale;
  // The largest root by the trigonometric solution of the depressed cubic (all its terms add up);
  // the other two from their sum (m - l2 l3) / l1 and product det / l1, which keep their relative
  // precision where the cubic's own smaller roots would cancel (a sliver of a cone near the
  // horizon of a sharp lobe: l1 ~ 1e5, l2 ~ 1).
  float det = -as * bs * inverseScale;
  float q = tr / 3.0;
  float p = (tr * tr - 3.0 * m) / 9.0;  // > 0: three real roots
  float sqrtP = sqrt(max(p, 0.0));
  float r = (2.0 * tr * tr * tr - 9.0 * tr * m + 27.0 * det) / 54.0;
  float phi = acos(clamp(r / max(p * sqrtP, 1e-30), -1.0, 1.0)) / 3.0;
  float l1 = max(q + 2.0 * sqrtP * cos(phi), 1e-30);
  float product = det / l1, sum = (m - product) / l1;  // l2 l3 < 0 and l2 + l3
  float spread = sqrt(sum * sum - 4.0 * product);
  float l2 = sum >= 0.0 ? 0.5 * (sum + spread) : product / (0.5 * (sum - spread));
  float l3 = product / max(l2, 1e-30);
  // L^2 / (1 + L^2) as 1 / (1 + 1/L^2): 1 for a cone as wide as a half-space, 0 for a point.
  float invL1sq = l1 / max(-l3, 1e-30), invL2sq = max(l2, 0.0) / max(-l3, 1e-30);
  float formFactor = sqrt(1.0 / ((1.0 + invL1sq) * (1.0 + invL2sq)));
  vec3 axis = normalize(e1 * (as * x0 / (as - l3)) + e2 * (bs * y0 / (bs - l3)) + e3);
  return formFactor * axis;
}
