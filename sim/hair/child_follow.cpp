#include "sim/hair/child_follow.h"

#include <algorithm>
#include <type_traits>

#include <glm/gtx/quaternion.hpp>

#include "core/util/thread_pool.h"
#include "sim/hair/hair_colliders.h"
#include "sim/hair/hair_simulator.h"

namespace mq {

namespace {

glm::vec3 load(const float* a, size_t i) { return {a[3 * i], a[3 * i + 1], a[3 * i + 2]}; }

// A point at parameter t in [0, 1] along a strand of n points (linear).
glm::vec3 alongStrand(const float* strand, int n, float t, int& index, float& blend) {
  const float x = t * float(n - 1);
  index = std::min(n - 2, int(x));
  blend = x - float(index);
  return glm::mix(load(strand, index), load(strand, index + 1), blend);
}

}  // namespace

namespace {

// Per guide point: how far it is from the body (PosedHairColliders::
// clearance). A child point whose rest offset from its anchor is shorter
// than that is outside the body wherever the guide's frame turns it, so it
// skips the body query: most child points are far from every proxy, and the
// query over every proxy is most of a child's cost.
std::vector<float> guideClearances(const std::vector<float>& guidePositions, const PosedHairColliders* body) {
  if (!body) return {};
  std::vector<float> clearances(guidePositions.size() / 3);
  ThreadPool::shared().parallelFor(0, clearances.size(), 1024, [&](size_t begin, size_t end) {
    for (size_t i = begin; i < end; ++i) clearances[i] = body->clearance(load(guidePositions.data(), i));
  });
  return clearances;
}

// Children [firstChild, strandCount) of restChildren into childPositions
// (laid out like restChildren.points).
void followFrom(const Strands& restChildren, size_t firstChild, const Strands& restGuides,
                const std::vector<float>& guidePositions, const std::vector<glm::quat>& guideFrames,
                std::vector<float>& childPositions, const PosedHairColliders* body) {
  const size_t children = restChildren.strandCount();
  const int nc = restChildren.pointsPerStrand, ng = restGuides.pointsPerStrand;
  const size_t guides = restGuides.strandCount();
  if (children <= firstChild) return;
  const bool sameCount = nc == ng;
  const std::vector<float> clearances = guideClearances(guidePositions, body);
  ThreadPool::shared().parallelFor(firstChild, children, 256, [&](size_t begin, size_t end) {
    for (size_t c = begin; c < end; ++c) {
      const float* rest = restChildren.strand(c);
      float* out = childPositions.data() + 3 * c * nc;
      const int g = c < restChildren.guideOf.size() ? restChildren.guideOf[c] : -1;
      if (g < 0 || size_t(g) >= guides || ng < 2) {
        std::copy(rest, rest + 3 * nc, out);
        continue;
      }
      const float* guideRest = restGuides.strand(g);
      const float* guideNow = guidePositions.data() + 3 * size_t(g) * ng;
      const glm::quat* frames = guideFrames.data() + size_t(g) * ng;
      const float* guideClearance = body ? clearances.data() + size_t(g) * ng : nullptr;
      for (int i = 0; i < nc; ++i) {
        glm::vec3 anchorRest, anchorNow;
        glm::quat frame;
        float clearance = 0.0f;
        if (sameCount) {
          anchorRest = load(guideRest, i);
          anchorNow = load(guideNow, i);
          frame = frames[i];
          if (body) clearance = guideClearance[i];
        } else {
          const float t = nc > 1 ? float(i) / float(nc - 1) : 0.0f;
          int index;
          float blend;
          anchorRest = alongStrand(guideRest, ng, t, index, blend);
          anchorNow = alongStrand(guideNow, ng, t, index, blend);
          frame = blend < 0.5f ? frames[index] : frames[index + 1];
          if (body) {
            // The anchor lies between two guide points: each one's clearance
            // less the way from it.
            const float segment = glm::length(load(guideNow, index + 1) - load(guideNow, index));
            clearance =
                std::max(guideClearance[index] - blend * segment, guideClearance[index + 1] - (1.0f - blend) * segment);
          }
        }
        const glm::vec3 offset = load(rest, i) - anchorRest;
        glm::vec3 p = anchorNow + frame * offset;
        if (body && i > 0 && glm::dot(offset, offset) * 1.0001f + 1e-10f >= clearance * clearance) {
          glm::vec3 normal;
          body->pushOut(p, normal);
        }
        out[3 * i] = p.x;
        out[3 * i + 1] = p.y;
        out[3 * i + 2] = p.z;
      }
    }
  });
}

}  // namespace

void followGuides(const Strands& restChildren, const Strands& restGuides, const std::vector<float>& guidePositions,
                  const std::vector<glm::quat>& guideFrames, std::vector<float>& childPositions,
                  const PosedHairColliders* body) {
  childPositions.resize(restChildren.points.size());
  followFrom(restChildren, 0, restGuides, guidePositions, guideFrames, childPositions, body);
}

std::vector<glm::quat> guideFrames(const Strands& restGuides, const std::vector<float>& positions,
                                   const glm::quat& rootRotation) {
  const int n = restGuides.pointsPerStrand;
  const size_t strands = restGuides.strandCount();
  std::vector<glm::quat> frames(strands * size_t(std::max(n, 0)), rootRotation);
  if (n < 2 || positions.size() < restGuides.points.size()) return frames;
  ThreadPool::shared().parallelFor(0, strands, 256, [&](size_t begin, size_t end) {
    for (size_t s = begin; s < end; ++s) {
      const float* rest = restGuides.strand(s);
      const float* now = positions.data() + 3 * s * n;
      glm::quat carried = rootRotation;
      for (int i = 0; i + 1 < n; ++i) {
        const glm::vec3 restSegment = load(rest, i + 1) - load(rest, i);
        const glm::vec3 segment = load(now, i + 1) - load(now, i);
        if (glm::length(restSegment) > 1e-9f && glm::length(segment) > 1e-9f) {
          const glm::vec3 wanted = carried * glm::normalize(restSegment);
          carried = glm::normalize(glm::rotation(wanted, glm::normalize(segment)) * carried);
        }
        frames[s * n + i + 1] = carried;
      }
    }
  });
  return frames;
}

Strands leadingStrands(const Strands& all, size_t guideCount) {
  Strands out;
  out.pointsPerStrand = all.pointsPerStrand;
  guideCount = std::min(guideCount, all.strandCount());
  auto head = [&](const auto& v, size_t perStrand) {
    using V = std::decay_t<decltype(v)>;
    return v.size() >= guideCount * perStrand ? V(v.begin(), v.begin() + guideCount * perStrand) : V();
  };
  out.points = head(all.points, 3 * size_t(all.pointsPerStrand));
  out.rootNormals = head(all.rootNormals, 3);
  out.rootUvs = head(all.rootUvs, 2);
  out.guideOf = head(all.guideOf, 1);
  out.pigmentPaint = head(all.pigmentPaint, 4);
  return out;
}

void poseGroomedStrands(const Strands& all, const HairSimulator& guides, std::vector<float>& positions,
                        const PosedHairColliders* body) {
  positions.resize(all.points.size());
  const size_t guideFloats = std::min(guides.positions().size(), positions.size());
  std::copy(guides.positions().begin(), guides.positions().begin() + guideFloats, positions.begin());
  followFrom(all, guides.strandCount(), guides.rest(), guides.positions(), guides.frames(), positions, body);
}

void followGuides(const Strands& restChildren, const HairSimulator& guides, std::vector<float>& childPositions,
                  const PosedHairColliders* body) {
  followGuides(restChildren, guides.rest(), guides.positions(), guides.frames(), childPositions, body);
}

}  // namespace mq
