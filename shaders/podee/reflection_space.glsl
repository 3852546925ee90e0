// Plane geometry of a pixel's reflection space (Podee et al., sec. 3): the quadrilateral spanned
// on the light plane by the four pixel-corner reflection vectors, in coordinates where the
// projected light is the unit disk centred at the origin (an affine map, so area ratios and the
// order of points are kept). Pure functions; tested in tests/glsl/test_reflection_space.cpp.
#include "core/constants.glsl"
#include "generated/gpu_contract.glsl"

float cross2(vec2 a, vec2 b) { return a.x * b.y - a.y * b.x; }

// Shoelace area of the polygon q0..q3 (positive when counter-clockwise), about its first vertex
// so that small polygons far from the origin keep their precision.
float quadArea(vec2 q[4]) {
  return 0.5 * (cross2(q[1] - q[0], q[2] - q[0]) + cross2(q[2] - q[0], q[3] - q[0]));
}

// Is p inside the convex counter-clockwise polygon q0..q3 (boundary included)? Nothing is inside
// a polygon without area; the repeated vertex of a triangle makes an edge of length 0, which
// excludes nothing.
bool insideConvexQuad(vec2 q[4], vec2 p) {
  bool inside = quadArea(q) > 0.0;
  for (int i = 0; i < 4; ++i) inside = inside && cross2(q[(i + 1) % 4] - q[i], p - q[i]) >= 0.0;
  return inside;
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
// shoelace sum of the chord polygon (about its first point, which lies in the disk, so that
// neither huge polygons nor tiny ones far from the disk's centre lose precision), and the exit
// point waiting for the arc to the next entry.
struct ChordWalk {
  vec2 anchor, first, last;
  bool started;
  float twiceArea;
  bool exited, entryBeforeExit;
  vec2 exitPoint, firstEntry;
  float segments;  // area between the arcs and their chords
};

void walkTo(inout ChordWalk w, vec2 p) {
  if (w.started) {
    w.twiceArea += cross2(w.last - w.anchor, p - w.anchor);
  } else {
    w.first = p;
    w.anchor = p;
  }
  w.started = true;
  w.last = p;
}

// The arc from an exit to the next entry runs counter-clockwise inside the polygon.
float arcSegment(vec2 exitPoint, vec2 entry) {
  float phi = atan(cross2(exitPoint, entry), dot(exitPoint, entry));
  return circularSegmentArea(phi < 0.0 ? phi + 2.0 * PI : phi);
}

// The edge a -> b crosses the rim where the line, at signed distance h from the centre, meets it:
// half a chord sqrt(1 - h^2) either side of the foot of the perpendicular. Everything is measured
// from the endpoint nearer the centre, so that an endpoint far away (a corner ray that nearly
// misses the light plane) costs no precision.
void walkEdge(inout ChordWalk w, vec2 a, vec2 b) {
  if (dot(a, a) <= 1.0) walkTo(w, a);
  vec2 d = b - a;
  float len = length(d);
  if (!(len > 1e-30)) return;
  vec2 dir = d / len;
  bool fromA = dot(a, a) <= dot(b, b);
  vec2 base = fromA ? a : b;
  float h = cross2(dir, base);
  if (abs(h) >= 1.0) return;  // misses (or touches) the circle
  float halfChord = sqrt((1.0 - h) * (1.0 + h));
  float foot = -dot(base, dir);
  // Offsets of the crossings from base along dir; the segment spans [0, len] from a, [-len, 0] from b.
  float entryOffset = foot - halfChord, exitOffset = foot + halfChord;
  bool entryOnEdge = fromA ? entryOffset > 0.0 && entryOffset < len : entryOffset < 0.0 && entryOffset > -len;
  bool exitOnEdge = fromA ? exitOffset > 0.0 && exitOffset < len : exitOffset < 0.0 && exitOffset > -len;
  if (entryOnEdge) {
    vec2 e = base + entryOffset * dir;
    walkTo(w, e);
    if (w.exited) w.segments += arcSegment(w.exitPoint, e);
    else if (!w.entryBeforeExit) { w.entryBeforeExit = true; w.firstEntry = e; }
    w.exited = false;
  }
  if (exitOnEdge) {
    w.exitPoint = base + exitOffset * dir;
    walkTo(w, w.exitPoint);
    w.exited = true;
  }
}

// Area of (unit disk) ∩ (the convex counter-clockwise polygon q0..q3): the chord polygon by the
// shoelace formula plus a circular segment for every arc of the disk's rim inside the polygon.
float unitDiskQuadArea(vec2 q[4]) {
  ChordWalk w;
  w.started = false;
  w.twiceArea = 0.0;
  w.exited = false;
  w.entryBeforeExit = false;
  w.segments = 0.0;
  for (int i = 0; i < 4; ++i) walkEdge(w, q[i], q[(i + 1) % 4]);
  if (w.exited && w.entryBeforeExit) w.segments += arcSegment(w.exitPoint, w.firstEntry);
  // The rim is never crossed: the disk is wholly inside the polygon (whose area is then at least
  // pi) or wholly outside.
  if (!w.started) return insideConvexQuad(q, vec2(0.0)) ? min(PI, quadArea(q)) : 0.0;
  w.twiceArea += cross2(w.last - w.anchor, w.first - w.anchor);
  // An intersection is no larger than either shape; this also holds for slivers of (nearly)
  // collinear corners, whose edges cross the rim forth and back and leave rounding in the arcs.
  return clamp(0.5 * w.twiceArea + w.segments, 0.0, min(PI, max(quadArea(q), 0.0)));
}

// The convex hull of four points as a counter-clockwise quadrilateral (a triangle repeats one
// vertex). A pixel's corner quad can be folded (a bow tie) or a dart when the surface curves
// strongly inside the pixel; the bilinear map then covers its hull, so the hull is the reflection
// space. Orientation tests only (no angles), so one corner far away costs no precision: the two
// segments that cross are the diagonals; if no two cross, one point lies inside the triangle of
// the others, which is then the largest of the four triangles.
void convexHullQuad(inout vec2 q[4]) {
  vec2 a = q[0], b = q[1], c = q[2], d = q[3];
  float abc = cross2(b - a, c - a), abd = cross2(b - a, d - a), acd = cross2(c - a, d - a), bcd = cross2(c - b, d - b);
  if (abc * acd > 0.0 && abd * bcd > 0.0) {         // diagonals ac, bd: a b c d
  } else if (abc * abd < 0.0 && acd * bcd < 0.0) {  // diagonals ab, cd: a c b d
    q = vec2[](a, c, b, d);
  } else if (abd * acd < 0.0 && abc * bcd < 0.0) {  // diagonals ad, bc: a b d c
    q = vec2[](a, b, d, c);
  } else {
    vec4 areas = abs(vec4(abc, abd, acd, bcd));
    float largest = max(max(areas.x, areas.y), max(areas.z, areas.w));
    q = largest == areas.x ? vec2[](a, b, c, c)
      : largest == areas.y ? vec2[](a, b, d, d)
      : largest == areas.z ? vec2[](a, c, d, d) : vec2[](b, c, d, d);
  }
  if (quadArea(q) < 0.0) q = vec2[](q[0], q[3], q[2], q[1]);
}

// The point of the convex counter-clockwise polygon q closest to `target`: the target itself
// when inside, else the closest point of the nearest edge (Podee et al., sec. 3.1).
vec2 closestPointInConvexQuad(vec2 q[4], vec2 target) {
  float best = 1e38;
  vec2 closest = q[0];
  for (int i = 0; i < 4; ++i) {
    vec2 a = q[i], e = q[(i + 1) % 4] - a;
    float ee = dot(e, e);
    float t = ee > 0.0 ? clamp(dot(target - a, e) / ee, 0.0, 1.0) : 0.0;
    vec2 c = a + t * e;
    float d2 = dot(target - c, target - c);
    if (d2 < best) {
      best = d2;
      closest = c;
    }
  }
  return insideConvexQuad(q, target) ? target : closest;
}

// Area of the lens where the unit disk meets the disk of radius r centred at distance d.
float unitDiskLensArea(float r, float d) {
  if (d >= 1.0 + r) return 0.0;
  if (d <= abs(1.0 - r)) return PI * min(r, 1.0) * min(r, 1.0);
  float a1 = preciseAcos(clamp((d * d + 1.0 - r * r) / (2.0 * d), -1.0, 1.0));
  float a2 = preciseAcos(clamp((d * d + r * r - 1.0) / (2.0 * d * r), -1.0, 1.0));
  float k = (-d + 1.0 + r) * (d + 1.0 - r) * (d - 1.0 + r) * (d + 1.0 + r);
  float lens = a1 + r * r * a2 - 0.5 * sqrt(max(k, 0.0));
  // A small disk on the rim, where the general formula cancels: there the rim is a straight line
  // at signed distance h = 1 - d from the small disk's centre, and the part of the small disk
  // inside it is r^2 (pi - acos(h / r)) + h sqrt(r^2 - h^2).
  float h = 1.0 - d;
  float onALine = r * r * (PI - preciseAcos(clamp(h / r, -1.0, 1.0))) + h * sqrt(max(r * r - h * h, 0.0));
  return clamp(r < 0.01 ? onALine : lens, 0.0, PI * min(r * r, 1.0));
}

// Area of (unit disk) ∩ (the convex counter-clockwise quad q) as the method's `area` choice computes
// it: AREA_LENS takes the quad as the disk of equal area at the mean of its corners (a lens, closed
// form); AREA_EXACT and AREA_CIRCLE (whose light is already a circle) the exact area (chord polygon
// plus circular segments).
float unitDiskIntersectionArea(vec2 q[4], int area) {
  bool allInside = dot(q[0], q[0]) <= 1.0 && dot(q[1], q[1]) <= 1.0 && dot(q[2], q[2]) <= 1.0 && dot(q[3], q[3]) <= 1.0;
  if (allInside) return quadArea(q);  // exact, and free of the cancellation of nearly equal terms
  vec2 mean = 0.25 * (q[0] + q[1] + q[2] + q[3]);
  return area == AREA_LENS ? unitDiskLensArea(sqrt(max(quadArea(q), 0.0) / PI), length(mean)) : unitDiskQuadArea(q);
}

// Solid angle of the triangle a, b = a + ab, c = a + ac seen from the origin (Van Oosterom &
// Strackee 1983): tan(Omega / 2) = |a . (b x c)| / (|a||b||c| + (a.b)|c| + (b.c)|a| + (c.a)|b|).
// The edges come in separately, so that tiny, distant triangles keep their precision.
float triangleSolidAngle(vec3 a, vec3 ab, vec3 ac) {
  vec3 b = a + ab, c = a + ac;
  float la = length(a), lb = length(b), lc = length(c);
  float triple = abs(dot(a, cross(ab, ac)));
  float denominator = la * lb * lc + dot(a, b) * lc + dot(b, c) * la + dot(c, a) * lb;
  return 2.0 * atan(triple, denominator);
}
