#include "gl/driver_profile.hpp"

#include <cstdlib>

#include "core/error.hpp"
#include "gl/context.hpp"

namespace glintlab {

std::string_view driver_profile_id(DriverProfile profile) {
  return profile == DriverProfile::Hardware ? "hardware" : "software";
}

std::string driver_profile_define_value(DriverProfile profile) {
  return profile == DriverProfile::Hardware ? "DRIVER_PROFILE_HARDWARE" : "DRIVER_PROFILE_SOFTWARE";
}

DriverProfile choose_driver_profile(const GlContext& context) {
  const char* chosen = std::getenv("GLINTLAB_DRIVER_PROFILE");
  const std::string value = chosen ? chosen : "auto";
  if (value == "software") return DriverProfile::Software;
  if (value == "hardware") return DriverProfile::Hardware;
  if (value != "auto")
    throw InputError("GLINTLAB_DRIVER_PROFILE: value \"" + value + "\" is not allowed; allowed: auto, software, hardware");
  return context.is_software() ? DriverProfile::Software : DriverProfile::Hardware;
}

}  // namespace glintlab
