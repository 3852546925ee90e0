// The pixel footprint (docs/methods.md, "Pixel footprint"): how the shading point and what it
// carries change over one pixel, as first-order differentials along the pixel's two axes (one
// pixel of the render target along screen x and along y), and the quantities the families derive
// from them. Built once per pixel: by passes/forward.frag from screen-space derivatives, or by a
// ray-tracing backend from the ray differentials at the hit (Igehy 1999; pbrt-v4's
// SurfaceInteraction::ComputeDifferentials); every field is one both can fill. Changing how
// footprints are computed is this file. Nothing here takes a derivative (compute shaders and
// ray-tracing backends include it too).
#include "generated/gpu_contract.glsl"

// PIXEL_FILTER_SIGMA (the contract's, from kPixelFilterSigma in src/core/pixel_filter_width.hpp):
// the standard deviation in pixels of the Gaussian pixel filter that footprint models assume,
// shared with the reference's `--reference-filter gaussian`.

struct Footprint {
  vec3 dPdx, dPdy;              // of the shading point's world position
  vec3 dNdx, dNdy;              // of the interpolated vertex normal, as interpolated (not renormalised),
                                // on the side the viewer sees
  vec3 dTdx, dTdy;              // of the unit vertex tangent (orthogonalised against the normal)
  vec3 dVdx, dVdy;              // of the unit view direction (surface to viewer)
  vec2 dVertexUVdx, dVertexUVdy;  // of the mesh's texture coordinates (before any texture transform)
  vec2 dUVdx, dUVdy;            // of the normal map's coordinates (its tiling and transform applied):
                                // the uv Jacobian J = [dUVdx dUVdy]
  // Derived from J by footprintWithUV:
  mat2 uvCovariance;            // J J^T: the uv covariance of a pixel filter of unit variance per axis
  vec2 majorAxis;               // unit uv direction of the ellipse's major axis
  float majorLength;            // J's singular values: the ellipse's semi-axes (uv per pixel)
  float minorLength;
};

// The covariance of the parallelogram spanned by two derivative vectors: U U^T, U = [dx dy].
mat2 derivativeCovariance(vec2 dx, vec2 dy) { return outerProduct(dx, dx) + outerProduct(dy, dy); }

// The footprint ellipse of J: its semi-axes are J's singular values, the roots of the eigenvalues
// of J J^T = [[a, b], [b, c]]. Without cancellation (Kneiphof & Klein replaced Deliot & Belcour's
// inverse of J): the larger from the half-difference d, the smaller as |det J| over the larger;
// the major direction from the row of J J^T - L I that does not vanish.
void footprintEllipse(mat2 covariance, float detJ, out vec2 major, out float majorLength, out float minorLength) {
  float a = covariance[0][0], b = covariance[1][0], c = covariance[1][1];
  float d = 0.5 * (a - c);
  float root = sqrt(d * d + b * b);
  majorLength = sqrt(0.5 * (a + c) + root);
  minorLength = majorLength > 0.0 ? abs(detJ) / majorLength : 0.0;
  vec2 e = d >= 0.0 ? vec2(d + root, b) : vec2(b, root - d);
  float len = length(e);
  major = len > 0.0 ? e / len : vec2(1.0, 0.0);
}

// f with the uv Jacobian (dUVdx, dUVdy) and the quantities derived from it.
Footprint footprintWithUV(Footprint f, vec2 dUVdx, vec2 dUVdy) {
  f.dUVdx = dUVdx;
  f.dUVdy = dUVdy;
  f.uvCovariance = derivativeCovariance(dUVdx, dUVdy);
  footprintEllipse(f.uvCovariance, dUVdx.x * dUVdy.y - dUVdx.y * dUVdy.x, f.majorAxis, f.majorLength, f.minorLength);
  return f;
}

Footprint makeFootprint(vec3 dPdx, vec3 dPdy, vec3 dNdx, vec3 dNdy, vec3 dTdx, vec3 dTdy, vec3 dVdx, vec3 dVdy,
                        vec2 dVertexUVdx, vec2 dVertexUVdy, vec2 dUVdx, vec2 dUVdy) {
  Footprint f;
  f.dPdx = dPdx;
  f.dPdy = dPdy;
  f.dNdx = dNdx;
  f.dNdy = dNdy;
  f.dTdx = dTdx;
  f.dTdy = dTdy;
  f.dVdx = dVdx;
  f.dVdy = dVdy;
  f.dVertexUVdx = dVertexUVdx;
  f.dVertexUVdy = dVertexUVdy;
  return footprintWithUV(f, dUVdx, dUVdy);
}

// A footprint known only by its uv Jacobian (the other differentials zero): tests, and families
// handed a uv footprint alone.
Footprint uvFootprint(vec2 dUVdx, vec2 dUVdy) {
  return makeFootprint(vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0),
                       vec2(0.0), vec2(0.0), dUVdx, dUVdy);
}

// f in coordinates `uvPerUnit` times coarser than the normal map's (J / uvPerUnit): a glinty
// material's own uv under a normal-map tiling.
Footprint footprintInUnits(Footprint f, float uvPerUnit) {
  return footprintWithUV(f, f.dUVdx / uvPerUnit, f.dUVdy / uvPerUnit);
}

// The texel covariance of a screen-space Gaussian of `sigma` pixels mapped by J onto a texture of
// `size` texels: sigma^2 (Jx Jx^T + Jy Jy^T), Jx = dUVdx (W, H). Non-finite derivatives (at the
// horizon) give a point.
mat2 footprintTexelCovariance(Footprint f, ivec2 size, float sigma) {
  vec2 jx = f.dUVdx * vec2(size), jy = f.dUVdy * vec2(size);
  mat2 c = sigma * sigma * (outerProduct(jx, jx) + outerProduct(jy, jy));
  bool finite = !any(isnan(vec4(c[0], c[1]))) && !any(isinf(vec4(c[0], c[1])));
  return finite ? c : mat2(0.0);
}

// The surface point `offset` pixels from p (the pixel centre's), to first order.
vec3 footprintPositionAt(Footprint f, vec3 p, vec2 offset) { return p + offset.x * f.dPdx + offset.y * f.dPdy; }

// ---------------------------------------------------------------------------------------------
// Half-vector derivatives from the footprint alone: what a ray-tracing backend calls where the
// raster pass differences the half vector across the pixel quad (kaplanyan-*, tokuyoshi,
// chermain2021). First order, with the interpolated normal taken as unit (as pbrt-v4 takes dn/du
// for the unit normal's derivative): errors of the order of 1 - |N|, under 1e-3 on the built-in
// meshes. (Not so the tangent, which shrinks where the vertex tangents turn fast, near a sphere's
// poles: the footprint holds the unit tangent's derivative.)

// Derivative of the unit vector towards a point `distance` away in direction l (a light's centre,
// or the camera: dV of a pinhole's view direction) as the surface point moves by dP.
vec3 pointDirectionDerivative(vec3 l, float distance, vec3 dP) { return -(dP - l * dot(l, dP)) / distance; }

// The vertex frame's rotation per pixel along one axis, as an angular velocity w (de = w x e for
// every vector e of the frame, and of any frame turned from it by a fixed angle about n): the
// normal's tilt n x dN, and the tangent's twist about n, dT . (n x t) (either handedness).
// n, t: the unit vertex normal and tangent; dT: the unit tangent's derivative.
vec3 vertexFrameRotation(vec3 n, vec3 t, vec3 dN, vec3 dT) { return cross(n, dN) + dot(dT, cross(n, t)) * n; }

// The half vector h = v + l (unnormalised) in a shading frame (t, b, n) that turns with the vertex
// frame (vertexNormal, vertexTangent; no normal map: a map adds its own change of the shading
// normal), and its derivatives along the pixel's axes: d(h.e) = (dh - w x h) . e for each frame
// vector e, dh = dv + dl.
struct HalfVectorDifferential {
  vec3 h;          // local coordinates of v + l
  vec3 dhdx, dhdy;  // their derivatives per pixel
};

HalfVectorDifferential halfVectorDifferential(Footprint f, vec3 v, vec3 l, vec3 dldx, vec3 dldy, mat3 frame,
                                              vec3 vertexNormal, vec3 vertexTangent) {
  vec3 h = v + l;
  vec3 wx = vertexFrameRotation(vertexNormal, vertexTangent, f.dNdx, f.dTdx);
  vec3 wy = vertexFrameRotation(vertexNormal, vertexTangent, f.dNdy, f.dTdy);
  mat3 toLocal = transpose(frame);
  return HalfVectorDifferential(toLocal * h, toLocal * (f.dVdx + dldx - cross(wx, h)),
                                toLocal * (f.dVdy + dldy - cross(wy, h)));
}

// Derivatives of the slope-space half vector h.xy / h.z (Kaplanyan et al. 2016's "plane-plane"
// half vector; chermain2021's slopes are its negative).
void halfVectorSlopeDerivatives(HalfVectorDifferential d, out vec2 dx, out vec2 dy) {
  vec2 slope = d.h.xy / d.h.z;
  dx = (d.dhdx.xy - slope * d.dhdx.z) / d.h.z;
  dy = (d.dhdy.xy - slope * d.dhdy.z) / d.h.z;
}

// Derivatives of the projected half vector normalize(h).xy (Tokuyoshi & Kaplanyan 2019).
void halfVectorProjectedDerivatives(HalfVectorDifferential d, out vec2 dx, out vec2 dy) {
  float len = length(d.h);
  vec3 u = d.h / len;
  dx = (d.dhdx.xy - u.xy * dot(u, d.dhdx)) / len;
  dy = (d.dhdy.xy - u.xy * dot(u, d.dhdy)) / len;
}
