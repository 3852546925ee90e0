#pragma once
// The viewer's free camera: orbit about the target, dolly, fly and look, each a pure function of
// the scene's Camera (projection, field of view and clip planes are kept), so the UI, the script
// and the tests move it the same way.
#include <glm/vec3.hpp>

#include "scene/camera.hpp"

namespace glintlab {

/// Rotates the position about the target: `yaw` degrees about the camera's up axis, `pitch`
/// degrees about its right axis (positive: up). Pitch stops 1 degree short of the poles, where
/// the view would flip. The distance to the target is kept.
Camera orbit_camera(const Camera& camera, float yaw_degrees, float pitch_degrees);

/// Moves the position toward the target, to `factor` times its distance (factor > 0); an
/// orthographic camera scales its view height instead (its distance changes nothing seen).
Camera dolly_camera(const Camera& camera, float factor);

/// Translates position and target together by `move` metres in the camera's frame:
/// x right, y up (the camera's up axis), z forward.
Camera fly_camera(const Camera& camera, glm::vec3 move);

/// Turns the view about the position (the target moves, at its distance): `yaw` degrees about
/// the up axis (positive: left), `pitch` degrees about the right axis (positive: up), pitch
/// stopping 1 degree short of the poles.
Camera look_camera(const Camera& camera, float yaw_degrees, float pitch_degrees);

}  // namespace glintlab
