#include "core/animation/track.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "core/math/transform.h"

namespace mq {
namespace {

bool hasTangents(Interpolation i) { return i == Interpolation::CubicSpline || i == Interpolation::Bezier; }

void normaliseQuat(float* q) {
  const float n = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
  if (n > 0.0f)
    for (int i = 0; i < 4; ++i) q[i] /= n;
}

glm::quat toQuat(const float* xyzw) { return glm::quat(xyzw[3], xyzw[0], xyzw[1], xyzw[2]); }

}  // namespace

const float* Track::keyValue(int key) const {
  const int stride = hasTangents(interpolation) ? 3 * components : components;
  const int offset = hasTangents(interpolation) ? components : 0;
  return values.data() + key * stride + offset;
}

void Track::validate() const {
  const size_t perKey = (hasTangents(interpolation) ? 3u : 1u) * components;
  if (values.size() != times.size() * perKey)
    throw std::invalid_argument("track has " + std::to_string(values.size()) + " values for " +
                                std::to_string(times.size()) + " keys");
  for (size_t i = 0; i < times.size(); ++i) {
    if (!std::isfinite(times[i])) throw std::invalid_argument("track key time is not finite");
    if (i > 0 && times[i] < times[i - 1]) throw std::invalid_argument("track key times decrease");
  }
  for (float v : values)
    if (!std::isfinite(v)) throw std::invalid_argument("track value is not finite");
}

void Track::sample(float t, float* out) const {
  const int n = keyCount();
  if (n == 0) return;
  auto copyKey = [&](int k) {
    std::copy_n(keyValue(k), components, out);
    if (isRotation) normaliseQuat(out);
  };
  if (n == 1 || t <= times.front()) return copyKey(0);
  if (t >= times.back()) return copyKey(n - 1);

  const int k1 = static_cast<int>(std::upper_bound(times.begin(), times.end(), t) - times.begin());
  const int k0 = k1 - 1;
  const float dt = times[k1] - times[k0];
  const float s = dt > 0.0f ? (t - times[k0]) / dt : 0.0f;
  const float* v0 = keyValue(k0);
  const float* v1 = keyValue(k1);

  switch (interpolation) {
    case Interpolation::Step:
      return copyKey(k0);
    case Interpolation::Linear:
      if (isRotation) {
        const glm::quat q = slerpShortest(glm::normalize(toQuat(v0)), glm::normalize(toQuat(v1)), s);
        out[0] = q.x, out[1] = q.y, out[2] = q.z, out[3] = q.w;
        return;
      }
      for (int c = 0; c < components; ++c) out[c] = v0[c] + (v1[c] - v0[c]) * s;
      return;
    case Interpolation::CubicSpline: {
      const float* outTangent0 = v0 + components;
      const float* inTangent1 = v1 - components;
      const float s2 = s * s, s3 = s2 * s;
      const float h00 = 2 * s3 - 3 * s2 + 1, h10 = s3 - 2 * s2 + s;
      const float h01 = -2 * s3 + 3 * s2, h11 = s3 - s2;
      for (int c = 0; c < components; ++c)
        out[c] = h00 * v0[c] + h10 * dt * outTangent0[c] + h01 * v1[c] + h11 * dt * inTangent1[c];
      break;
    }
    case Interpolation::Bezier: {
      const float* handleOut0 = v0 + components;
      const float* handleIn1 = v1 - components;
      const float u = 1.0f - s;
      const float b0 = u * u * u, b1 = 3 * u * u * s, b2 = 3 * u * s * s, b3 = s * s * s;
      for (int c = 0; c < components; ++c) out[c] = b0 * v0[c] + b1 * handleOut0[c] + b2 * handleIn1[c] + b3 * v1[c];
      break;
    }
  }
  if (isRotation) normaliseQuat(out);
}

}  // namespace mq
