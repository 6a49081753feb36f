#pragma once
// A keyframed track: key times and values with one interpolation mode.
// Values are flat floats with `components` per value: 3 for a translation or
// scale, 4 for a rotation quaternion (x, y, z, w as glTF stores it), K for K
// morph weights. Outside its keys a track holds its first or last value.

#include <vector>

namespace mq {

enum class Interpolation {
  Step,         // hold the previous key
  Linear,       // lerp; shortest-path slerp for rotations
  CubicSpline,  // glTF cubic Hermite: per key (in-tangent, value, out-tangent)
  Bezier,       // cubic Bezier: per key (in-handle, value, out-handle), absolute
};

struct Track {
  Interpolation interpolation = Interpolation::Linear;
  int components = 3;
  bool isRotation = false;  // components == 4, renormalise and slerp
  std::vector<float> times;
  std::vector<float> values;  // keys * components, or keys * 3 * components

  bool empty() const { return times.empty(); }
  int keyCount() const { return static_cast<int>(times.size()); }
  float startTime() const { return times.empty() ? 0.0f : times.front(); }
  float endTime() const { return times.empty() ? 0.0f : times.back(); }
  // Checks sizes and that times increase; throws std::invalid_argument.
  void validate() const;
  // Writes `components` floats at time t.
  void sample(float t, float* out) const;

 private:
  const float* keyValue(int key) const;  // the value itself, not a tangent
};

}  // namespace mq
