#pragma once
// The precompute settings a method exposes as its parameters (deng2022's rank, ndf_resolution, ...):
// declared once here, so that the method's parameter list, their defaults (PrefilterSettings') and
// the settings read back from parameter values come from the same table.
#include <map>
#include <string>
#include <vector>

#include "prefilter/prefiltered_ndf.hpp"
#include "shading/method.hpp"

namespace glintlab {

/// The settings as host-only method parameters (ParamDecl::host_only: read by the renderer to
/// choose the pyramid it binds, never by a shader), defaults from PrefilterSettings{}.
std::vector<ParamDecl> prefilter_params();

/// The settings that parameter values choose (those of prefilter_params() present in `params`;
/// PrefilterSettings' defaults for the rest).
PrefilterSettings prefilter_settings_from(const std::map<std::string, float>& params);

}  // namespace glintlab
