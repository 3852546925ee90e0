#pragma once
// Scene snippets shared by tests in different binaries.
#include <string>

namespace glintlab::test {

/// The smallest valid scene: one material, one sphere, one point light; everything else default.
inline const std::string kMinimalScene = R"(
[[material]]
name = "m"
[[shape]]
type = "sphere"
material = "m"
[[light]]
type = "point"
position = [0, 2, 3]
)";

}  // namespace glintlab::test
