#include "sim/hair/hair_simulator.h"

#include <algorithm>
#include <cassert>
#include <cmath>

#include <glm/gtx/quaternion.hpp>

#include "core/math/transform.h"
#include "core/util/thread_pool.h"

namespace mq {

namespace {

constexpr float kReferenceStep = 1.0f / 60.0f;  // stiffnesses are given per this step

glm::vec3 load(const float* a, size_t i) { return {a[3 * i], a[3 * i + 1], a[3 * i + 2]}; }
void store(float* a, size_t i, const glm::vec3& v) {
  a[3 * i] = v.x;
  a[3 * i + 1] = v.y;
  a[3 * i + 2] = v.z;
}

// A stiffness k applied once per reference step, converted to substep h so
// the same share of the error remains after 1/60 s whatever the substep.
float perSubstep(float k, float h) {
  k = glm::clamp(k, 0.0f, 1.0f);
  return 1.0f - std::pow(1.0f - k, h / kReferenceStep);
}

glm::quat rotationOf(const glm::mat4& m) {
  return glm::normalize(glm::quat_cast(
      glm::mat3(glm::normalize(glm::vec3(m[0])), glm::normalize(glm::vec3(m[1])), glm::normalize(glm::vec3(m[2])))));
}

// Per-strand scratch for one strand's substep (reused per thread).
struct StrandScratch {
  std::vector<glm::vec3> correction, normal;
  std::vector<uint8_t> contact;
  void resize(int n) {
    correction.resize(n);
    normal.resize(n);
    contact.resize(n);
  }
};

}  // namespace

void HairSimulator::setRest(const Strands& guides) {
  rest_ = guides;
  strandCount_ = guides.strandCount();
  pointsPerStrand_ = guides.pointsPerStrand;
  const size_t total = strandCount_ * size_t(pointsPerStrand_);
  restLengths_.assign(total, 0.0f);
  restDirs_.assign(total, glm::vec3(0.0f, -1.0f, 0.0f));
  const int n = pointsPerStrand_;
  for (size_t s = 0; s < strandCount_; ++s) {
    const float* r = rest_.strand(s);
    const size_t base = s * n;
    for (int i = 0; i + 1 < n; ++i) {
      const glm::vec3 seg = load(r, i + 1) - load(r, i);
      const float len = glm::length(seg);
      restLengths_[base + i + 1] = len;
      restDirs_[base + i] = len > 1e-9f ? seg / len : (i > 0 ? restDirs_[base + i - 1] : glm::vec3(0, -1, 0));
    }
    if (n >= 2) restDirs_[base + n - 1] = restDirs_[base + n - 2];
  }
  interactionReady_ = false;
  setParams(params_);
  reset();
}

void HairSimulator::setParams(const HairSimParams& params) {
  // A new radius needs new rest densities, even while the interaction is off.
  if (params.interaction.radius != params_.interaction.radius) interactionReady_ = false;
  if (!params.adaptiveWisps && params_.adaptiveWisps) {
    active_.clear();
    wisps_ = AdaptiveWisps{};
  }
  params_ = params;
  if (!params_.interaction.enabled() || strandCount_ == 0) return;
  if (!interactionReady_) {
    interaction_.setRest(rest_.points, strandCount_, pointsPerStrand_, params_.interaction);
    interactionReady_ = true;
  } else {
    interaction_.setParams(params_.interaction);
  }
}

void HairSimulator::reset() {
  positions_ = rest_.points;
  velocities_.assign(positions_.size(), 0.0f);
  frames_.assign(strandCount_ * size_t(pointsPerStrand_), glm::quat(1.0f, 0.0f, 0.0f, 0.0f));
  previousRoots_.clear();
  hasPreviousRoots_ = false;
  active_.clear();
  wisps_ = AdaptiveWisps{};  // rebuilt at the next step, every guide simulated
}

Strands HairSimulator::current() const {
  Strands out = rest_;
  out.points = positions_;
  return out;
}

void HairSimulator::placeStrand(size_t s, const glm::vec3* points, const glm::vec3* velocities,
                                const glm::quat* frames) {
  const size_t base = s * size_t(pointsPerStrand_);
  for (int i = 0; i < pointsPerStrand_; ++i) {
    store(positions_.data(), base + i, points[i]);
    store(velocities_.data(), base + i, velocities[i]);
    frames_[base + i] = frames[i];
  }
}

void HairSimulator::step(float dt, const glm::mat4& posedFromRest, const PosedHairColliders* body) {
  const glm::quat rotation = rotationOf(posedFromRest);
  std::vector<glm::vec3> positions(strandCount_);
  std::vector<glm::quat> rotations(strandCount_, rotation);
  for (size_t s = 0; s < strandCount_; ++s)
    positions[s] = glm::vec3(posedFromRest * glm::vec4(load(rest_.strand(s), 0), 1.0f));
  step(dt, positions, rotations, body);
}

void HairSimulator::step(float dt, const std::vector<glm::vec3>& rootPositions,
                         const std::vector<glm::quat>& rootRotations, const PosedHairColliders* body) {
  assert(rootPositions.size() == strandCount_ && rootRotations.size() == strandCount_);
  if (strandCount_ == 0 || pointsPerStrand_ < 2 || !(dt > 0.0f)) return;
  std::vector<RootTarget> targets(strandCount_);
  for (size_t s = 0; s < strandCount_; ++s) targets[s] = {rootPositions[s], glm::normalize(rootRotations[s])};

  if (!hasPreviousRoots_) {
    // First step after a reset: place the rest shape at the roots, so a
    // character that starts away from its bind pose does not whip its hair.
    const int n = pointsPerStrand_;
    for (size_t s = 0; s < strandCount_; ++s) {
      const float* r = rest_.strand(s);
      const glm::vec3 rest0 = load(r, 0);
      for (int i = 0; i < n; ++i) {
        store(positions_.data() + 3 * s * n, i, targets[s].position + targets[s].rotation * (load(r, i) - rest0));
        frames_[s * n + i] = targets[s].rotation;
      }
    }
    previousRoots_ = targets;
    hasPreviousRoots_ = true;
  }

  const int substeps = std::max(1, int(std::ceil(dt / params_.maxSubstep - 1e-4f)));
  const float h = dt / float(substeps);
  bendPerSubstep_ = perSubstep(params_.bendStiffness, h);
  const float global = perSubstep(params_.globalStiffness, h);
  globalPerPoint_.assign(pointsPerStrand_, 0.0f);
  for (int i = 1; i < pointsPerStrand_; ++i) {
    const float along = float(i) / float(pointsPerStrand_ - 1);
    const float range = std::max(params_.globalRange, 1e-6f);
    globalPerPoint_[i] = global * std::max(0.0f, 1.0f - along / range);
  }

  std::vector<RootTarget> roots(strandCount_);
  for (int k = 1; k <= substeps; ++k) {
    const float t = float(k) / float(substeps);
    for (size_t s = 0; s < strandCount_; ++s) {
      roots[s].position = glm::mix(previousRoots_[s].position, targets[s].position, t);
      roots[s].rotation = slerpShortest(previousRoots_[s].rotation, targets[s].rotation, t);
    }
    substep(h, roots, body);
  }
  previousRoots_ = std::move(targets);
  if (params_.adaptiveWisps) {
    if (!wisps_.built()) wisps_.build(*this, params_.wisps);
    wisps_.update(*this, dt, body && !body->empty() ? body : nullptr);
  }
}

void HairSimulator::substep(float h, const std::vector<RootTarget>& roots, const PosedHairColliders* body) {
  if (body && body->empty()) body = nullptr;
  if (!(interactionReady_ && params_.interaction.enabled())) {
    ThreadPool::shared().parallelFor(0, strandCount_, 64, [&](size_t begin, size_t end) {
      for (size_t s = begin; s < end; ++s)
        if (isActive(s)) stepStrand(s, h, roots[s], body);
    });
    return;
  }
  // Hair against hair acts on the predicted positions of all strands, before
  // each strand restores its lengths and leaves the body.
  const size_t n = size_t(pointsPerStrand_);
  predicted_.resize(strandCount_ * n);
  ThreadPool::shared().parallelFor(0, strandCount_, 64, [&](size_t begin, size_t end) {
    for (size_t s = begin; s < end; ++s) {
      if (isActive(s)) {
        predictStrand(s, h, roots[s], predicted_.data() + s * n);
      } else {  // where its owner placed it
        for (size_t i = 0; i < n; ++i) predicted_[s * n + i] = load(positions_.data(), s * n + i);
      }
    }
  });
  interaction_.apply(predicted_, positions_, h);
  ThreadPool::shared().parallelFor(0, strandCount_, 64, [&](size_t begin, size_t end) {
    for (size_t s = begin; s < end; ++s)
      if (isActive(s)) solveStrand(s, h, roots[s], body, predicted_.data() + s * n);
  });
}

void HairSimulator::stepStrand(size_t s, float h, const RootTarget& root, const PosedHairColliders* body) {
  thread_local std::vector<glm::vec3> p;
  p.resize(pointsPerStrand_);
  predictStrand(s, h, root, p.data());
  solveStrand(s, h, root, body, p.data());
}

// Steps 1 and 2: free motion, then the pull toward the rest shape.
void HairSimulator::predictStrand(size_t s, float h, const RootTarget& root, glm::vec3* p) const {
  const int n = pointsPerStrand_;
  const size_t base = s * size_t(n);
  const float* x = positions_.data() + 3 * base;
  const float* v = velocities_.data() + 3 * base;
  const float* r = rest_.points.data() + 3 * base;

  // 1. Predict.
  const float damping = std::exp(-params_.airDamping * h);
  p[0] = root.position;
  for (int i = 1; i < n; ++i) p[i] = load(x, i) + (load(v, i) * damping + params_.gravity * h) * h;

  // 2. Global shape: the rest shape carried rigidly by the root.
  const glm::vec3 rest0 = load(r, 0);
  for (int i = 1; i < n && globalPerPoint_[i] > 0.0f; ++i) {
    const glm::vec3 target = root.position + root.rotation * (load(r, i) - rest0);
    p[i] += globalPerPoint_[i] * (target - p[i]);
  }
}

// Steps 3 and 4 from the predicted positions p; commits the strand.
void HairSimulator::solveStrand(size_t s, float h, const RootTarget& root, const PosedHairColliders* body,
                                glm::vec3* p) {
  thread_local StrandScratch scratch;
  const int n = pointsPerStrand_;
  scratch.resize(n);
  glm::vec3* correction = scratch.correction.data();
  glm::vec3* normal = scratch.normal.data();
  uint8_t* contact = scratch.contact.data();
  const size_t base = s * size_t(n);
  float* x = positions_.data() + 3 * base;
  float* v = velocities_.data() + 3 * base;
  const glm::vec3* restDir = restDirs_.data() + base;
  const float* restLength = restLengths_.data() + base;
  glm::quat* frame = frames_.data() + base;

  // 3. Bend, keep length, collide: one pass from the root.
  glm::quat carried = root.rotation;
  frame[0] = carried;
  contact[0] = 0;
  correction[0] = glm::vec3(0.0f);
  for (int i = 0; i + 1 < n; ++i) {
    const glm::vec3 wanted = carried * restDir[i];
    const float length = restLength[i + 1];
    const glm::vec3 segment = p[i + 1] - p[i];
    const float segmentLength = glm::length(segment);
    const glm::vec3 current = segmentLength > 1e-9f ? segment / segmentLength : wanted;
    glm::vec3 direction = glm::mix(current, wanted, bendPerSubstep_);
    const float dirLength = glm::length(direction);
    direction = dirLength > 1e-6f ? direction / dirLength : wanted;
    glm::vec3 q = p[i] + direction * length;
    contact[i + 1] = 0;
    if (body) {
      // Push out and restore the length until both hold (a few passes
      // slide the point along the surface); end pushed out (never inside).
      bool outside = false;
      for (int pass = 0; pass < 6 && !outside; ++pass) {
        outside = !body->pushOut(q, normal[i + 1]);
        if (outside) break;
        contact[i + 1] = 1;
        const glm::vec3 d = q - p[i];
        const float dl = glm::length(d);
        if (dl > 1e-9f) q = p[i] + d * (length / dl);
      }
      // Still in (the segment points deep into the body, and each pass
      // only halves the way in): along the surface instead, the inward part
      // of the segment taken off (again for each surface met, in the crease
      // between two colliders), so the last push-out moves the point by the
      // surface's curvature only and the length nearly holds.
      for (int pass = 0; pass < 4 && !outside; ++pass) {
        const glm::vec3 n = normal[i + 1];
        glm::vec3 d = q - p[i];
        d -= std::min(0.0f, glm::dot(d, n)) * n;
        const float dl = glm::length(d);
        if (dl > 1e-9f) q = p[i] + d * (length / dl);
        outside = !body->pushOut(q, normal[i + 1]);
      }
    }
    correction[i + 1] = q - p[i + 1];
    p[i + 1] = q;
    const glm::vec3 actual = q - p[i];
    const float actualLength = glm::length(actual);
    if (actualLength > 1e-9f) carried = glm::normalize(glm::rotation(wanted, actual / actualLength) * carried);
    frame[i + 1] = carried;
  }

  // 4. Velocities with FTL damping and friction; commit positions.
  const float invH = 1.0f / h;
  store(v, 0, (p[0] - load(x, 0)) * invH);
  store(x, 0, p[0]);
  for (int i = 1; i < n; ++i) {
    glm::vec3 vi = (p[i] - load(x, i)) * invH;
    if (i + 1 < n) vi -= params_.ftlDamping * correction[i + 1] * invH;
    if (contact[i]) {
      // Contact: no velocity into the body, tangential motion slowed.
      const glm::vec3 nrm = normal[i];
      const float vn = glm::dot(vi, nrm);
      const glm::vec3 tangential = vi - vn * nrm;
      vi = (1.0f - params_.friction) * tangential + std::max(vn, 0.0f) * nrm;
    }
    store(v, i, vi);
    store(x, i, p[i]);
  }
}

}  // namespace mq
