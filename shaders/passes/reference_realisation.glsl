// The reference with binomial-glints materials as one fixed realisation of their microfacets
// (glints/binomial/realisation.glsl), integrated over each light by the reference's MIS: the
// reference backend `raster-realisation`. Every other material as passes/reference.glsl.
#define REFERENCE_BINOMIAL_REALISATION 1
#include "passes/reference.glsl"
