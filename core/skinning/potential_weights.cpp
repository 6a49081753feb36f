#include "core/skinning/potential_weights.h"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "core/util/thread_pool.h"

namespace mq {
namespace {

// Bones a vertex may follow: the bone of the nearest primitive and its
// neighbours in the hierarchy, so a thigh never pulls the other thigh's skin.
std::vector<std::vector<int>> skinNeighbourhoods(const Skeleton& skeleton) {
  std::vector<std::vector<int>> allowed(skeleton.boneCount());
  for (int b = 0; b < skeleton.boneCount(); ++b) {
    allowed[b].push_back(b);
    const int parent = skeleton.bone(b).parent;
    if (parent >= 0) {
      allowed[b].push_back(parent);
      if (skeleton.bone(parent).parent >= 0) allowed[b].push_back(skeleton.bone(parent).parent);
    }
    for (int c : skeleton.children(b)) allowed[b].push_back(c);
  }
  return allowed;
}

// Dense per-vertex bone weights (vertices x bones) from primitive potentials.
std::vector<float> potentialWeights(const Mesh& mesh, const ImplicitBody& body, const Skeleton& skeleton) {
  constexpr float kFalloff = 0.02f;
  // The pelvis reaches further down the thighs, so the crotch and the
  // buttocks blend between the hip and both legs instead of being torn
  // between the two thighs.
  const int pelvis = skeleton.findBone("pelvis");
  auto falloff = [&](int bone) { return bone == pelvis ? 2.0f * kFalloff : kFalloff; };
  const int bones = skeleton.boneCount();
  const auto allowed = skinNeighbourhoods(skeleton);
  const auto& prims = body.primitives();
  std::vector<float> dense(mesh.vertexCount() * bones, 0.0f);
  ThreadPool::shared().parallelFor(0, mesh.vertexCount(), 512, [&](size_t begin, size_t end) {
    std::vector<float> distance(prims.size());
    std::vector<float> perBone(bones);
    for (size_t v = begin; v < end; ++v) {
      const glm::vec3 p = mesh.position(v);
      size_t nearest = 0;
      for (size_t i = 0; i < prims.size(); ++i) {
        distance[i] = prims[i].distance(p);
        if (distance[i] < distance[nearest]) nearest = i;
      }
      std::fill(perBone.begin(), perBone.end(), 0.0f);
      for (size_t i = 0; i < prims.size(); ++i)
        perBone[prims[i].bone] += std::exp(-std::max(distance[i], 0.0f) / falloff(prims[i].bone));
      for (int b : allowed[prims[nearest].bone]) dense[v * bones + b] = perBone[b];
    }
  });
  return dense;
}

// Averages each vertex's weights with its mesh neighbours' (uniform
// Laplacian), which removes the seams where the nearest primitive changes.
void smoothOverSurface(const Mesh& mesh, int bones, int iterations, std::vector<float>& dense) {
  const size_t n = mesh.vertexCount();
  std::vector<std::vector<uint32_t>> neighbours(n);
  for (size_t t = 0; t < mesh.triangleCount(); ++t)
    for (int e = 0; e < 3; ++e) neighbours[mesh.triangles[3 * t + e]].push_back(mesh.triangles[3 * t + (e + 1) % 3]);
  std::vector<float> next(dense.size());
  for (int it = 0; it < iterations; ++it) {
    ThreadPool::shared().parallelFor(0, n, 1024, [&](size_t begin, size_t end) {
      for (size_t v = begin; v < end; ++v) {
        float* out = &next[v * bones];
        for (int b = 0; b < bones; ++b) out[b] = 0.5f * dense[v * bones + b];
        const float share = 0.5f / float(neighbours[v].size());
        for (uint32_t u : neighbours[v])
          for (int b = 0; b < bones; ++b) out[b] += share * dense[u * bones + b];
      }
    });
    dense.swap(next);
  }
}

}  // namespace

void bindPotentialWeights(Mesh& mesh, const ImplicitBody& body, const Skeleton& skeleton) {
  const int bones = skeleton.boneCount();
  std::vector<float> dense = potentialWeights(mesh, body, skeleton);
  smoothOverSurface(mesh, bones, 12, dense);
  SkinBinding& skin = mesh.skin;
  skin.influencesPerVertex = bones;
  skin.jointBones.resize(bones);
  std::iota(skin.jointBones.begin(), skin.jointBones.end(), 0);
  skin.inverseBind = skeleton.inverseBindMatrices();
  // Traces that smoothing carried far from a bone are dropped.
  for (size_t v = 0; v < mesh.vertexCount(); ++v) {
    float* w = &dense[v * bones];
    const float sum = std::accumulate(w, w + bones, 0.0f);
    for (int b = 0; b < bones; ++b)
      if (w[b] < 0.01f * sum) w[b] = 0.0f;
  }
  skin.weights = std::move(dense);
  skin.joints.resize(skin.weights.size());
  for (size_t i = 0; i < skin.joints.size(); ++i) skin.joints[i] = uint16_t(i % bones);
  skin.normalise();
  skin.limitInfluences(4);
}

}  // namespace mq
