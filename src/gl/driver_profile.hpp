#pragma once
// Driver profiles: the shape of the code the forward programs are compiled in, chosen per driver
// when a context is made (docs/methods.md, "Driver profiles"). The physics is the same in both;
// what differs is what each kind of driver turns into fast code:
// - software (Mesa's llvmpipe, SIMD on a CPU): every branch runs both sides over the whole SIMD
//   vector and each loop iteration is costly, so light loops have constant trip counts (unrolled)
//   and blends are branch-free; vertex attributes at an offset are stepped along the fine
//   derivatives (llvmpipe 22.x interpolates perspective inputs affinely at an offset);
// - hardware (GPUs): unrolled loops and blends that compute both sides cost instruction cache and
//   registers, so per-kind light loops stay rolled, blends branch (neighbouring pixels agree), and
//   interpolateAtOffset is the hardware's own.
// shaders/core/driver_profile.glsl turns the profile into those named choices.
#include <string>
#include <string_view>

namespace glintlab {

class GlContext;

enum class DriverProfile { Software, Hardware };

/// "software" or "hardware": GLINTLAB_DRIVER_PROFILE's values, `glintlab info` and docs.
std::string_view driver_profile_id(DriverProfile profile);
/// The profile of the GLSL define DRIVER_PROFILE (compare with DRIVER_PROFILE_SOFTWARE/_HARDWARE).
std::string driver_profile_define_value(DriverProfile profile);

/// The profile for a context: GLINTLAB_DRIVER_PROFILE (auto, software or hardware) when set and not
/// auto, else software on a software rasteriser (llvmpipe, softpipe) and hardware otherwise. Throws
/// InputError naming the variable, the value and what is allowed.
DriverProfile choose_driver_profile(const GlContext& context);

}  // namespace glintlab
