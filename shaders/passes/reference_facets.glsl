// The reference with binomial-glints materials as one fixed field of mirror facets, one per uv
// cell with a GGX-distributed normal of its own random stream (glints/binomial/facets.glsl),
// integrated over each light by the reference's MIS: the reference backend `raster-facets`, the
// binomial methods' ground truth that shares none of their approximations. Every other material as
// passes/reference.glsl. The binomial-glints kind reads REFERENCE_SURFACE, which the forward
// pass's variant sets to REFERENCE_SURFACE_FACETS for this module (src/render/renderer.cpp,
// forward_variant).
#include "passes/reference.glsl"
