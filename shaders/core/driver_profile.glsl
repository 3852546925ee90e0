// The code-shape choices of the driver profile a program is compiled in (DRIVER_PROFILE, defined
// by the shader library: src/gl/driver_profile.hpp; docs/methods.md, "Driver profiles"). Both
// profiles compute the same physics; they differ in what each kind of driver makes fast code of.
#define DRIVER_PROFILE_SOFTWARE 0
#define DRIVER_PROFILE_HARDWARE 1

#if DRIVER_PROFILE == DRIVER_PROFILE_HARDWARE
// GPUs: a light loop unrolled per light repeats long bodies through the instruction cache, so
// per-kind loops stay rolled; a blend's branch skips the side its weight zeroes, since
// neighbouring pixels mostly agree.
#define PROFILE_ROLLED_LIGHT_LOOPS 1
#define PROFILE_BRANCHING_BLENDS 1
#else
// Mesa's llvmpipe (SIMD on a CPU): both sides of every branch run over the whole vector and each
// loop iteration costs, so loops with constant counts unroll and blends compute both sides.
#define PROFILE_ROLLED_LIGHT_LOOPS 0
#define PROFILE_BRANCHING_BLENDS 0
#endif
// Attributes at an offset from the pixel centre are stepped along the fine derivatives in both
// profiles (core/fragment_inputs.glsl): exact wherever the triangle's planes are, and cheap on a
// GPU (quad shuffles); interpolateAtOffset is affine on llvmpipe 22.x and, by the GL spec, may
// clamp offsets above 0.5 - 2^-subpixel bits, short of the pixel corners podee needs.

// The condition of a blend's side whose weight may be 0 there: `if (blendSideNeeded(w > 0.0))`. The
// hardware profile skips the side; the software profile always computes it (its weight, 0, then
// zeroes it exactly: write the blend as a weighted sum, not mix, so both profiles agree to the bit).
bool blendSideNeeded(bool weighted) { return PROFILE_BRANCHING_BLENDS == 0 || weighted; }
