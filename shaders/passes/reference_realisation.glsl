// The reference with binomial-glints materials as one fixed realisation of their microfacets
// (glints/binomial/realisation.glsl), integrated over each light by the reference's MIS: the
// reference backend `raster-realisation`. Every other material as passes/reference.glsl. The
// binomial-glints kind reads REFERENCE_SURFACE, which the forward pass's variant sets
// to REFERENCE_SURFACE_REALISATION for this module (src/render/renderer.cpp, forward_variant).
#include "passes/reference.glsl"
