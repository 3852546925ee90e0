// Plane geometry of a pixel's reflection space (Podee et al., sec. 3): the quadrilateral spanned
// on the light plane by the four pixel-corner reflection vectors, in coordinates where the
// projected light is the unit disk centred at the origin (an affine map, so area ratios and the
// order of points are kept). Pure functions; tested in tests/gl/test_reflection_space.cpp.
#include "common/constants.glsl"

float cross2(vec2 a, vec2 b) { return a.x * b.y - a.y * b.x; }

// Signed angle from u to v in (-pi, pi]; 0 when either is the zero vector.
float signedAngle(vec2 u, vec2 v) {
  float c = dot(u, v), s = cross2(u, v);
  return c == 0.0 && s == 0.0 ? 0.0 : atan(s, c);
}

// acos through atan: exact to float precision where acos' polynomial lowering (some drivers,
// Mesa's among them) is not.
float preciseAcos(float x) { return atan(sqrt(max(1.0 - x * x, 0.0)), x); }

// Area of the circular segment cut from the unit disk by a chord subtending angle phi in [0, 2 pi]:
// (phi - sin phi) / 2, by its series where the difference would cancel.
float circularSegmentArea(float phi) {
  float p2 = phi * phi;
  return phi < 0.25 ? phi * p2 * (1.0 / 12.0 - p2 * (1.0 / 240.0 - p2 / 10080.0)) : 0.5 * (phi - sin(phi));
}

// Walks the boundary of (convex polygon) ∩ (unit disk) with the arcs replaced by chords: the
// shoelace sum of the chord polygon (about an anchor near it, so that small polygons far from the
// disk's centre keep their precision), and the exit point waiting for the arc to the next entry.
struct ChordWalk {
  vec2 anchor, first, last;
  bool started;
  float twiceArea;
  bool exited, entryBeforeExit;
  vec2 exitPoint, firstEntry;
  float segments;  // area between the arcs and their chords
};

void walkTo(inout ChordWalk w, vec2 p) {
  if (w.started) w.twiceArea += cross2(w.last - w.anchor, p - w.anchor);
  else w.first = p;
  w.started = true;
  w.last = p;
}

// The arc from an exit to the next entry runs counter-clockwise inside the polygon.
float arcSegment(vec2 exitPoint, vec2 entry) {
  float phi = atan(cross2(exitPoint, entry), dot(exitPoint, entry));
  return circularSegmentArea(phi < 0.0 ? phi + 2.0 * PI : phi);
}

void walkEdge(inout ChordWalk w, vec2 a, vec2 b) {
  if (dot(a, a) <= 1.0) walkTo(w, a);
  vec2 d = b - a;
  float dd = dot(d, d);
  float half_b = dot(a, d), c = dot(a, a) - 1.0;
  float disc = half_b * half_b - dd * c;
  if (dd < 1e-30 || disc <= 1e-12 * dd * dd) return;  // misses or touches the circle
  float root = sqrt(disc);
  // Stable roots of dd t^2 + 2 half_b t + c = 0.
  float qq = -half_b - (half_b >= 0.0 ? root : -root);
  float t1 = qq / dd, t2 = abs(qq) > 0.0 ? c / qq : t1;
  vec2 ts = vec2(min(t1, t2), max(t1, t2));
  if (ts.x > 0.0 && ts.x < 1.0) {  // entry
    vec2 e = a + ts.x * d;
    walkTo(w, e);
    if (w.exited) w.segments += arcSegment(w.exitPoint, e);
    else if (!w.entryBeforeExit) { w.entryBeforeExit = true; w.firstEntry = e; }
    w.exited = false;
  }
  if (ts.y > 0.0 && ts.y < 1.0) {  // exit
    w.exitPoint = a + ts.y * d;
    walkTo(w, w.exitPoint);
    w.exited = true;
  }
}

bool insideConvexQuad(vec2 q[4], vec2 p) {
  bool inside = true;
  for (int i = 0; i < 4; ++i) inside = inside && cross2(q[(i + 1) % 4] - q[i], p - q[i]) >= 0.0;
  return inside;
}

// Area of (unit disk) ∩ (the convex counter-clockwise polygon q0..q3): the chord polygon by the
// shoelace formula plus a circular segment for every arc of the disk's rim inside the polygon.
float unitDiskQuadArea(vec2 q[4]) {
  ChordWalk w;
  w.anchor = q[0];
  w.started = false;
  w.twiceArea = 0.0;
  w.exited = false;
  w.entryBeforeExit = false;
  w.segments = 0.0;
  for (int i = 0; i < 4; ++i) walkEdge(w, q[i], q[(i + 1) % 4]);
  if (w.exited && w.entryBeforeExit) w.segments += arcSegment(w.exitPoint, w.firstEntry);
  if (!w.started) return insideConvexQuad(q, vec2(0.0)) ? PI : 0.0;  // the rim is never crossed
  w.twiceArea += cross2(w.last - w.anchor, w.first - w.anchor);
  return 0.5 * w.twiceArea + w.segments;
}

// Shoelace area of the polygon q0..q3 (positive when counter-clockwise), about its first vertex
// so that small polygons far from the origin keep their precision.
float quadArea(vec2 q[4]) {
  return 0.5 * (cross2(q[1] - q[0], q[2] - q[0]) + cross2(q[2] - q[0], q[3] - q[0]));
}

// The convex hull of four points as a counter-clockwise quadrilateral (a triangle repeats one
// vertex). A pixel's corner quad can be folded (a bow tie) or a dart when the surface curves
// strongly inside the pixel; the bilinear map then covers its hull, so the hull is the reflection
// space. The points are ordered by angle about their mean (a star-shaped simple polygon with
// at most one reflex vertex), and a reflex vertex is replaced by its predecessor.
void convexHullQuad(inout vec2 q[4]) {
  vec2 m = 0.25 * (q[0] + q[1] + q[2] + q[3]);
  float key[4];
  for (int i = 0; i < 4; ++i) key[i] = signedAngle(vec2(1.0, 0.0), q[i] - m);
  // Sorting network for four keys: (0,1) (2,3) (0,2) (1,3) (1,2).
  const ivec2 pairs[5] = ivec2[](ivec2(0, 1), ivec2(2, 3), ivec2(0, 2), ivec2(1, 3), ivec2(1, 2));
  for (int k = 0; k < 5; ++k) {
    int i = pairs[k].x, j = pairs[k].y;
    bool swap = key[i] > key[j];
    float ki = key[i];
    vec2 qi = q[i];
    key[i] = swap ? key[j] : ki;
    key[j] = swap ? ki : key[j];
    q[i] = swap ? q[j] : qi;
    q[j] = swap ? qi : q[j];
  }
  vec2 p[4] = q;
  for (int i = 0; i < 4; ++i) {
    vec2 prev = p[(i + 3) % 4], next = p[(i + 1) % 4];
    if (cross2(p[i] - prev, next - p[i]) < 0.0) q[i] = prev;
  }
}

// The point of the convex counter-clockwise polygon q closest to `target`: the target itself
// when inside, else the closest point of the nearest edge (Podee et al., sec. 3.1).
vec2 closestPointInConvexQuad(vec2 q[4], vec2 target) {
  bool inside = true;
  float best = 1e38;
  vec2 closest = q[0];
  for (int i = 0; i < 4; ++i) {
    vec2 a = q[i], e = q[(i + 1) % 4] - a;
    inside = inside && cross2(e, target - a) >= 0.0;
    float ee = dot(e, e);
    float t = ee > 0.0 ? clamp(dot(target - a, e) / ee, 0.0, 1.0) : 0.0;
    vec2 c = a + t * e;
    float d2 = dot(target - c, target - c);
    if (d2 < best) {
      best = d2;
      closest = c;
    }
  }
  return inside ? target : closest;
}

// Area of the lens where the unit disk meets the disk of radius r centred at distance d.
float unitDiskLensArea(float r, float d) {
  if (d >= 1.0 + r) return 0.0;
  if (d <= abs(1.0 - r)) return PI * min(r, 1.0) * min(r, 1.0);
  float a1 = preciseAcos(clamp((d * d + 1.0 - r * r) / (2.0 * d), -1.0, 1.0));
  float a2 = preciseAcos(clamp((d * d + r * r - 1.0) / (2.0 * d * r), -1.0, 1.0));
  float k = (-d + 1.0 + r) * (d + 1.0 - r) * (d - 1.0 + r) * (d + 1.0 + r);
  return a1 + r * r * a2 - 0.5 * sqrt(max(k, 0.0));
}

// How the covered fraction is computed (the method's `area` parameter).
#define COVERAGE_EXACT 0   // exact area of disk ∩ quad (chord polygon plus circular segments)
#define COVERAGE_LENS 1    // the quad as the disk of equal area at the mean of its corners: a lens, closed form

// Fraction of the convex counter-clockwise reflection space q covered by the unit disk.
// A reflection space of (numerically) zero area is a single reflection direction: its
// mean is either on the light or not.
float unitDiskCoverage(vec2 q[4], int mode) {
  float area = quadArea(q);
  vec2 meanCorner = 0.25 * (q[0] + q[1] + q[2] + q[3]);
  if (!(area > 1e-10)) return dot(meanCorner, meanCorner) <= 1.0 ? 1.0 : 0.0;
  bool allInside = dot(q[0], q[0]) <= 1.0 && dot(q[1], q[1]) <= 1.0 && dot(q[2], q[2]) <= 1.0 && dot(q[3], q[3]) <= 1.0;
  if (allInside) return 1.0;  // exact, and free of the cancellation of nearly equal terms
  float covered = mode == COVERAGE_LENS ? unitDiskLensArea(sqrt(area / PI), length(meanCorner)) : unitDiskQuadArea(q);
  return clamp(covered / area, 0.0, 1.0);
}
