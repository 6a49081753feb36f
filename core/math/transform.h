#pragma once
// Small fixed-size math on GLM: translation/rotation/scale transforms and
// quaternion helpers. Quaternions are unit; files store them (x, y, z, w).

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

namespace mq {

// A local transform split into its parts, as glTF nodes and animation
// channels store it: matrix = T * R * S.
struct Trs {
  glm::vec3 translation{0.0f};
  glm::quat rotation{1.0f, 0.0f, 0.0f, 0.0f};  // glm::quat(w, x, y, z)
  glm::vec3 scale{1.0f};

  glm::mat4 matrix() const;
  static Trs fromMatrix(const glm::mat4& m);  // assumes no shear
};

// Shortest-path spherical interpolation; the result is normalised.
glm::quat slerpShortest(glm::quat a, glm::quat b, float t);

// Rotation from Euler angles in degrees, applied X then Y then Z
// (intrinsic Z * Y * X), the order the properties panel shows.
glm::quat quatFromEulerDegrees(const glm::vec3& degrees);
glm::vec3 eulerDegreesFromQuat(const glm::quat& q);

// The rotation edit (a bone's local rotation on top of its parent's) that
// turns the bone by `radians` about the world axis `worldAxis` through its
// joint, given its edit and world rotation before the turn (a gizmo drag).
glm::quat editAfterWorldRotation(const glm::quat& editBefore, const glm::quat& worldRotationBefore,
                                 const glm::vec3& worldAxis, float radians);

}  // namespace mq
