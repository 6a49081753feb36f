#include "core/skinning/weight_regeneration.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numeric>
#include <queue>
#include <sstream>

#include <nlohmann/json.hpp>

#include "core/character/character.h"
#include "core/geometry/surface_segment_query.h"
#include "core/io/json_fields.h"
#include "core/mesh/mesh.h"
#include "core/mesh/position_weld.h"
#include "core/skinning/section_cones.h"
#include "core/util/memory_budget.h"
#include "core/util/thread_pool.h"

namespace mq {
namespace {

constexpr int kMaxInfluences = 4;
constexpr double kBlendedWeight = 0.05;    // a second weight above this makes a vertex "blended"
constexpr double kConvergedExcess = 1e-3;  // an edge this close to its bound counts as within it
constexpr int kVisibleCandidates = 4;      // best-scored bones tried for visibility
constexpr double kInsideStart = 0.01;      // the visibility segment starts this far in (of its length)
constexpr double kBaseRatio = 1.6;         // a trusted cone's bases differ by at most this in radius

// The welded skin: one vertex per position, weights dense per (vertex, joint).
struct WeldedWeights {
  PositionWeld weld;
  std::vector<glm::dvec3> positions;
  int joints = 0;
  std::vector<float> weights;  // vertex * joints + joint

  float* of(size_t v) { return &weights[v * size_t(joints)]; }
  const float* of(size_t v) const { return &weights[v * size_t(joints)]; }
};

WeldedWeights weldWeights(const Mesh& mesh) {
  WeldedWeights w;
  w.weld = weldByPosition(mesh.positions, mesh.triangles);
  w.joints = int(mesh.skin.jointBones.size());
  // Dense weights, their Jacobi moves and the blend's distances.
  checkMemoryBudget("rebuilding the weights of '" + mesh.name + "'",
                    double(w.weld.vertexCount()) * double(w.joints) * (2 * sizeof(float) + sizeof(double)));
  w.positions.resize(w.weld.vertexCount());
  for (size_t v = 0; v < w.positions.size(); ++v) w.positions[v] = glm::dvec3(mesh.position(w.weld.representative[v]));
  w.weights.assign(w.positions.size() * size_t(w.joints), 0.0f);
  const SkinBinding& skin = mesh.skin;
  const int k = skin.influencesPerVertex;
  for (size_t v = 0; v < w.positions.size(); ++v) {
    const size_t original = w.weld.representative[v];
    for (int i = 0; i < k; ++i) {
      const float weight = skin.weights[original * k + i];
      if (weight > 0.0f) w.of(v)[skin.joints[original * k + i]] += weight;
    }
  }
  return w;
}

size_t countBlended(const WeldedWeights& w) {
  size_t blended = 0;
  for (size_t v = 0; v < w.positions.size(); ++v) {
    std::array<float, 2> top{0.0f, 0.0f};
    for (int j = 0; j < w.joints; ++j) {
      const float x = w.of(v)[j];
      if (x > top[0])
        top = {x, top[0]};
      else if (x > top[1])
        top[1] = x;
    }
    blended += top[1] > kBlendedWeight;
  }
  return blended;
}

// A bone with a segment to measure against (a leaf with no vertex of its own has none).
bool hasSegment(const SectionCone& cone) { return cone.length > 1e-6; }

// The point of the bone's segment nearest to p.
glm::dvec3 closestOnAxis(const SectionCone& cone, const glm::dvec3& p) {
  return cone.head + std::clamp(glm::dot(p - cone.head, cone.axis), 0.0, cone.length) * cone.axis;
}

// Whether a joint's cone describes its limb: fitted, a limb, and with bases
// of like size (a thigh's base cut through the hips is not its section).
bool trustedCone(const SectionCone& cone) {
  if (!cone.limb) return false;
  const double near = std::sqrt(cone.enclosing[0].a * cone.enclosing[0].b);
  const double far = std::sqrt(cone.enclosing[1].a * cone.enclosing[1].b);
  return std::max(near, far) <= kBaseRatio * std::min(near, far);
}

// Each joint's cylinder radius: the median distance to its segment of the
// vertices nearest to it (for the survey's "distance to each cylinder").
std::vector<double> cylinderRadii(const std::vector<SectionCone>& cones, const WeldedWeights& w) {
  std::vector<std::vector<double>> nearest(cones.size());
  for (const glm::dvec3& p : w.positions) {
    int best = -1;
    double bestDistance = 0.0;
    for (size_t j = 0; j < cones.size(); ++j) {
      if (!hasSegment(cones[j])) continue;
      const double d = glm::length(p - closestOnAxis(cones[j], p));
      if (best < 0 || d < bestDistance) best = int(j), bestDistance = d;
    }
    if (best >= 0) nearest[best].push_back(bestDistance);
  }
  std::vector<double> radii(cones.size(), 0.0);
  for (size_t j = 0; j < cones.size(); ++j) {
    if (!nearest[j].empty()) {
      auto middle = nearest[j].begin() + nearest[j].size() / 2;
      std::nth_element(nearest[j].begin(), middle, nearest[j].end());
      radii[j] = *middle;
    }
    if (!(radii[j] > 0.0)) radii[j] = 0.25 * cones[j].length;
  }
  return radii;
}

// The survey's rigid score of vertex p for one bone: its radial and axial
// distances to the bone's cylinder, in cylinder radii.
double rigidScore(const SectionCone& cone, double radius, const glm::dvec3& p, double axialWeight) {
  const glm::dvec3 d = p - cone.head;
  const double s = glm::dot(d, cone.axis) / cone.length;
  const double beyond = (s < 0.0 ? -s : s > 1.0 ? s - 1.0 : 0.0) * cone.length;
  const double radial = glm::length(d - glm::dot(d, cone.axis) * cone.axis);
  return (radial + axialWeight * beyond) / radius;
}

// Scores compare cylinders of different radii, which moves the border
// between a thick bone and its thinner child off their joint (the elbow's
// into the forearm). Across a joint, the side of the plane through it,
// normal to the child, decides instead.
int sideOfJoint(int chosen, const glm::dvec3& p, const std::vector<SectionCone>& cones,
                const std::vector<int>& parents) {
  for (size_t c = 0; c < cones.size(); ++c) {
    if (parents[c] != chosen || !hasSegment(cones[c])) continue;
    const double along = glm::dot(p - cones[c].head, cones[c].axis);
    if (along > 0.0 && along < cones[c].length) return int(c);
  }
  const int parent = parents[chosen];
  if (parent >= 0 && hasSegment(cones[parent]) && glm::dot(p - cones[chosen].head, cones[chosen].axis) < 0.0)
    return parent;
  return chosen;
}

// Rigid skinning: one bone per vertex, the best-scored one it sees.
void assignRigidly(WeldedWeights& w, const std::vector<SectionCone>& cones, const std::vector<double>& radii,
                   const std::vector<int>& parents, const SurfaceSegmentQuery& surface, double axialWeight,
                   ThreadPool* pool) {
  auto assign = [&](size_t begin, size_t end) {
    std::vector<std::pair<double, int>> scored;
    for (size_t v = begin; v < end; ++v) {
      const glm::dvec3& p = w.positions[v];
      scored.clear();
      for (size_t j = 0; j < cones.size(); ++j)
        if (hasSegment(cones[j])) scored.emplace_back(rigidScore(cones[j], radii[j], p, axialWeight), int(j));
      float* weights = w.of(v);
      if (scored.empty()) continue;  // no bone with a segment: keep the file's weights
      const size_t tried = std::min<size_t>(kVisibleCandidates, scored.size());
      std::partial_sort(scored.begin(), scored.begin() + tried, scored.end());
      int chosen = scored[0].second;
      for (size_t c = 0; c < tried; ++c) {
        const glm::dvec3 axisPoint = closestOnAxis(cones[scored[c].second], p);
        if (!surface.hits(p + kInsideStart * (axisPoint - p), axisPoint)) {
          chosen = scored[c].second;
          break;
        }
      }
      chosen = sideOfJoint(chosen, p, cones, parents);
      std::fill(weights, weights + w.joints, 0.0f);
      weights[chosen] = 1.0f;
    }
  };
  if (pool)
    pool->parallelFor(0, w.positions.size(), 512, assign);
  else
    assign(0, w.positions.size());
}

// The transition length of each joint: `transition` section radii of its
// memorised section at its head (the joint end), or of its cylinder.
std::vector<double> transitionLengths(const std::vector<SectionCone>& cones, const std::vector<double>& radii,
                                      double transition) {
  std::vector<double> lengths(cones.size());
  for (size_t j = 0; j < cones.size(); ++j) {
    const Ellipse2& section = cones[j].minimum[0];
    lengths[j] = transition * (trustedCone(cones[j]) ? std::sqrt(section.a * section.b) : radii[j]);
  }
  return lengths;
}

struct Edge {
  uint32_t a, b;
  double length;
};

std::vector<Edge> uniqueEdges(const WeldedWeights& w) {
  std::vector<std::pair<uint32_t, uint32_t>> pairs;
  const std::vector<uint32_t>& t = w.weld.triangles;
  pairs.reserve(t.size());
  for (size_t i = 0; i + 2 < t.size(); i += 3)
    for (int e = 0; e < 3; ++e) {
      const uint32_t a = t[i + e], b = t[i + (e + 1) % 3];
      pairs.emplace_back(std::min(a, b), std::max(a, b));
    }
  std::sort(pairs.begin(), pairs.end());
  pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
  std::vector<Edge> edges;
  edges.reserve(pairs.size());
  for (const auto& [a, b] : pairs) edges.push_back({a, b, glm::length(w.positions[a] - w.positions[b])});
  return edges;
}

// Blends rigid regions: each bone's weight falls from 1 in its region to 0
// at its transition length along the skin (edge-path distance, Dijkstra
// bounded by that length), with a smoothstep profile; then normalised. This
// is the field the threshold passes move towards, reached at once: its slope
// is bounded by about 1.5 / l_b.
void blendRegions(WeldedWeights& w, const std::vector<Edge>& edges, const std::vector<double>& lengths) {
  const size_t n = w.positions.size();
  std::vector<uint32_t> start(n + 1, 0), next(2 * edges.size());
  std::vector<double> edgeLength(2 * edges.size());
  for (const Edge& e : edges) ++start[e.a + 1], ++start[e.b + 1];
  for (size_t v = 0; v < n; ++v) start[v + 1] += start[v];
  std::vector<uint32_t> fill(start.begin(), start.end() - 1);
  for (const Edge& e : edges) {
    edgeLength[fill[e.a]] = e.length, next[fill[e.a]++] = e.b;
    edgeLength[fill[e.b]] = e.length, next[fill[e.b]++] = e.a;
  }
  std::vector<int> region(n, -1);
  for (size_t v = 0; v < n; ++v)
    for (int j = 0; j < w.joints; ++j)
      if (w.of(v)[j] >= 1.0f) region[v] = j;
  std::vector<float> blended(w.weights.size(), 0.0f);
  std::vector<double> distance(n, std::numeric_limits<double>::infinity());
  std::vector<uint32_t> reached;
  using Item = std::pair<double, uint32_t>;
  for (int j = 0; j < w.joints; ++j) {
    std::priority_queue<Item, std::vector<Item>, std::greater<Item>> queue;
    for (size_t v = 0; v < n; ++v)
      if (region[v] == j) distance[v] = 0.0, queue.emplace(0.0, uint32_t(v)), reached.push_back(uint32_t(v));
    while (!queue.empty()) {
      const auto [d, v] = queue.top();
      queue.pop();
      if (d > distance[v]) continue;
      for (uint32_t i = start[v]; i < start[v + 1]; ++i) {
        const double nd = d + edgeLength[i];
        if (nd >= lengths[j] || nd >= distance[next[i]]) continue;
        if (std::isinf(distance[next[i]])) reached.push_back(next[i]);
        distance[next[i]] = nd;
        queue.emplace(nd, next[i]);
      }
    }
    for (uint32_t v : reached) {
      const double x = distance[v] / lengths[j];
      blended[v * size_t(w.joints) + j] = float(1.0 - x * x * (3.0 - 2.0 * x));
      distance[v] = std::numeric_limits<double>::infinity();
    }
    reached.clear();
  }
  for (size_t v = 0; v < n; ++v) {
    if (region[v] < 0) continue;  // kept the file's weights
    float* out = &blended[v * size_t(w.joints)];
    const float sum = std::accumulate(out, out + w.joints, 0.0f);
    for (int j = 0; j < w.joints; ++j) w.of(v)[j] = out[j] / sum;
  }
}

// The share t of the difference both ends of an edge move towards each other
// so that no bone's weight differs by more than its bound; 0 when within.
double edgeMove(const float* wa, const float* wb, int joints, double length, const std::vector<double>& lengths,
                double* excessOut) {
  double move = 0.0, excess = 0.0;
  for (int j = 0; j < joints; ++j) {
    const double diff = std::abs(double(wa[j]) - double(wb[j]));
    if (diff <= 0.0) continue;
    const double over = diff - length / lengths[j];
    if (over <= 0.0) continue;
    excess = std::max(excess, over);
    move = std::max(move, over / (2.0 * diff));
  }
  *excessOut = excess;
  return excess > kConvergedExcess ? move : 0.0;
}

// The steps of a run, reported to the callbacks; a cancel unwinds the run.
struct Cancelled {};
class Steps {
 public:
  Steps(const WeightCallbacks* callbacks, int total) : callbacks_(callbacks), total_(total) {}
  // One step done (or `count`); throws Cancelled when asked to stop.
  void done(int count = 1) {
    done_ = std::min(total_, done_ + count);
    if (!callbacks_) return;
    if (callbacks_->progress) callbacks_->progress(done_, total_);
    if (callbacks_->cancelled && callbacks_->cancelled()) throw Cancelled{};
  }

 private:
  const WeightCallbacks* callbacks_;
  int total_, done_ = 0;
};

constexpr int kStagesPerMesh = 3;  // cones, rigid assignment, blend

int stepsOf(const WeightSettings& settings) { return kStagesPerMesh + (settings.smooth ? settings.passes : 0); }

// Jacobi passes of the cone-threshold smoothing; returns the passes run and
// the largest excess left.
std::pair<int, double> smoothWelded(WeldedWeights& w, const std::vector<Edge>& edges,
                                    const std::vector<double>& lengths, int maxPasses, Steps& steps) {
  std::vector<double> delta(w.weights.size());
  std::vector<int> moves(w.positions.size());
  int pass = 0;
  double largest = 0.0;
  for (; pass < maxPasses; ++pass) {
    std::fill(delta.begin(), delta.end(), 0.0);
    std::fill(moves.begin(), moves.end(), 0);
    largest = 0.0;
    bool moved = false;
    for (const Edge& e : edges) {
      double excess = 0.0;
      const double t = edgeMove(w.of(e.a), w.of(e.b), w.joints, e.length, lengths, &excess);
      largest = std::max(largest, excess);
      if (t <= 0.0) continue;
      moved = true;
      ++moves[e.a], ++moves[e.b];
      for (int j = 0; j < w.joints; ++j) {
        const double m = t * (double(w.of(e.b)[j]) - double(w.of(e.a)[j]));
        delta[e.a * size_t(w.joints) + j] += m;
        delta[e.b * size_t(w.joints) + j] -= m;
      }
    }
    if (!moved) break;
    // The average of a vertex's moves: each is a convex combination, so is it.
    for (size_t v = 0; v < w.positions.size(); ++v) {
      if (moves[v] == 0) continue;
      for (int j = 0; j < w.joints; ++j)
        w.of(v)[j] = float(std::max(0.0, double(w.of(v)[j]) + delta[v * size_t(w.joints) + j] / moves[v]));
    }
    steps.done();
  }
  steps.done(maxPasses - pass);  // converged early
  return {pass, largest > kConvergedExcess ? largest : 0.0};
}

// Writes the welded weights back, the four largest per vertex, normalised.
void writeBack(const WeldedWeights& w, SkinBinding& skin, size_t vertexCount) {
  const int k = std::min(kMaxInfluences, std::max(1, w.joints));
  skin.influencesPerVertex = k;
  skin.joints.assign(vertexCount * k, 0);
  skin.weights.assign(vertexCount * k, 0.0f);
  std::vector<int> order(w.joints);
  for (size_t v = 0; v < vertexCount; ++v) {
    const float* weights = w.of(w.weld.weldedIndex[v]);
    std::iota(order.begin(), order.end(), 0);
    std::partial_sort(order.begin(), order.begin() + k, order.end(),
                      [&](int a, int b) { return weights[a] != weights[b] ? weights[a] > weights[b] : a < b; });
    for (int i = 0; i < k; ++i) {
      skin.joints[v * k + i] = uint16_t(order[i]);
      skin.weights[v * k + i] = weights[order[i]];
    }
  }
  skin.normalise();
}

}  // namespace

bool WeightSettings::operator==(const WeightSettings& o) const {
  return regenerate == o.regenerate && smooth == o.smooth && axialWeight == o.axialWeight &&
         transition == o.transition && passes == o.passes;
}

std::string WeightReport::summary() const {
  std::ostringstream out;
  out << "weights of " << vertices << " vertices: " << blendedAfter << " blended (second weight > 0.05; was "
      << blendedBefore << ")";
  if (passes > 0) out << ", " << passes << " smoothing passes";
  if (largestExcess > 0.0) out << ", not converged (largest excess " << largestExcess << ")";
  return out.str();
}

namespace {

WeightReport regenerateInSteps(Mesh& mesh, const Skeleton& skeleton, const WeightSettings& settings, ThreadPool* pool,
                               Steps& steps) {
  WeightReport report;
  if (mesh.skin.empty() || !settings.active()) return report;
  WeldedWeights w = weldWeights(mesh);
  report.vertices = mesh.vertexCount();
  report.blendedBefore = countBlended(w);
  const std::vector<SectionCone> cones = fitSectionCones(mesh, skeleton);
  const std::vector<double> radii = cylinderRadii(cones, w);
  const std::vector<Edge> edges = uniqueEdges(w);
  const std::vector<double> lengths = transitionLengths(cones, radii, settings.transition);
  steps.done();
  if (settings.regenerate) {
    const SurfaceSegmentQuery surface(mesh.positions, mesh.triangles);
    assignRigidly(w, cones, radii, skinJointParents(mesh.skin, skeleton), surface, settings.axialWeight, pool);
    steps.done();
    blendRegions(w, edges, lengths);
    steps.done();
  } else {
    steps.done(2);
  }
  if (settings.smooth) {
    const auto [passes, excess] = smoothWelded(w, edges, lengths, settings.passes, steps);
    report.passes = passes;
    report.largestExcess = excess;
  }
  report.blendedAfter = countBlended(w);
  writeBack(w, mesh.skin, mesh.vertexCount());
  return report;
}

void regenerateAll(Character& character, const WeightSettings& settings, ThreadPool* pool, Steps& steps,
                   WeightReport& total) {
  const bool helpers = !character.helperBones.empty();
  if (helpers) removeHelperBones(character);
  for (Mesh& mesh : character.meshes) {
    const WeightReport r = regenerateInSteps(mesh, character.skeleton, settings, pool, steps);
    mesh.dropSkinningBindings();  // the cones' creases follow the dominant bones
    total.vertices += r.vertices;
    total.blendedBefore += r.blendedBefore;
    total.blendedAfter += r.blendedAfter;
    total.passes = std::max(total.passes, r.passes);
    total.largestExcess = std::max(total.largestExcess, r.largestExcess);
  }
  if (helpers) addHelperBones(character);
}

}  // namespace

SkinningSnapshot::SkinningSnapshot(const Character& c)
    : skeleton_(c.skeleton), helperBones_(c.helperBones), skinsBeforeHelpers_(c.skinsBeforeHelpers) {
  for (const Mesh& mesh : c.meshes) skins_.push_back(mesh.skin);
}

void SkinningSnapshot::restore(Character& c) const {
  c.skeleton = skeleton_;
  c.helperBones = helperBones_;
  c.skinsBeforeHelpers = skinsBeforeHelpers_;
  for (size_t m = 0; m < c.meshes.size() && m < skins_.size(); ++m) {
    c.meshes[m].skin = skins_[m];
    c.meshes[m].dropSkinningBindings();
  }
}

WeightReport regenerateMeshWeights(Mesh& mesh, const Skeleton& skeleton, const WeightSettings& settings,
                                   ThreadPool* pool) {
  Steps steps(nullptr, stepsOf(settings));
  return regenerateInSteps(mesh, skeleton, settings, pool, steps);
}

WeightReport regenerateWeights(Character& character, const WeightSettings& settings, ThreadPool* pool,
                               const WeightCallbacks* callbacks) {
  WeightReport total;
  if (!settings.active()) return total;
  const SkinningSnapshot before(character);
  Steps steps(callbacks, stepsOf(settings) * int(character.meshes.size()));
  try {
    regenerateAll(character, settings, pool, steps, total);
  } catch (const Cancelled&) {
    before.restore(character);
    WeightReport cancelled;
    cancelled.cancelled = true;
    return cancelled;
  }
  return total;
}

WeightSettings weightSettingsFromJson(const nlohmann::json& value, const std::string& path) {
  const JsonFields f(value, path);
  f.allowOnly({"regenerate", "smooth", "axial_weight", "transition", "passes"});
  WeightSettings s;
  s.regenerate = f.boolean("regenerate", s.regenerate);
  s.smooth = f.boolean("smooth", s.smooth);
  s.axialWeight = f.number("axial_weight", float(s.axialWeight), 0.0, WeightSettings::kMaxAxialWeight);
  s.transition =
      f.number("transition", float(s.transition), WeightSettings::kMinTransition, WeightSettings::kMaxTransition);
  s.passes = int(f.integer("passes", s.passes, 1, WeightSettings::kMaxPasses));
  return s;
}

nlohmann::json toJson(const WeightSettings& s) {
  return {{"regenerate", s.regenerate},
          {"smooth", s.smooth},
          {"axial_weight", s.axialWeight},
          {"transition", s.transition},
          {"passes", s.passes}};
}

}  // namespace mq
