// Body collider queries, the cloth's body cost: the default mannequin in a
// frame of its walk (moved to the next frame, as a simulation step moves it),
// queried from points around its skin, one thread. Points: every second body
// vertex pushed out along its normal by 0 to 3 cm (and a few 5 mm in), where
// a garment's vertices are. Counter ns_per_query: CPU time per query.
//
//   BM_BodyNearest/<radius mm>    nearestContact (20: the contact radius, 80:
//                                 the widest approach radius)
//   BM_BodyNearestHinted/<mm>     the same, given the nearest triangle of the
//                                 point 2 mm away (a cloth vertex's last query)
//   BM_BodyNearestKept            a cloth vertex's queries in a substep, each
//                                 through its last one (BodyQuery): at the
//                                 new pose (hint: its triangle of the last
//                                 pose), 2 mm on, again from there, and from
//                                 there with the 80 mm approach radius
//   BM_BodyFirstHit               firstHitAlong over a 1 cm move of each point
//   BM_BodyMove                   a step's moves of the body itself: setTarget
//                                 to the next frame and moveTo(1) (the trees
//                                 refitted, the slot corners gathered), wall
//                                 time with the shared pool
//
//   mannequin-bench --benchmark_filter=Body
#include <benchmark/benchmark.h>

#include <ctime>

#include "core/character/default_mannequin.h"
#include "core/character/posed_character.h"
#include "sim/cloth/collision/body_collider.h"
#include "tests/bench/query_timing.h"

namespace {

using namespace mq::cloth;

struct BodyScene {
  BodyCollider body;
  std::vector<glm::vec3> points, moves;
  std::vector<int32_t> hints;  // nearest triangle of each point moved back by a fifth of its move
};

const BodyScene& walkingBody() {
  static const BodyScene scene = [] {
    BodyScene s;
    const mq::Character mannequin = mq::makeDefaultMannequin();
    const int walk = mannequin.findClip("walk");
    mq::PosedCharacter posed;
    posed.evaluate(mannequin, walk, 0.5f, nullptr, nullptr);
    const std::vector<float> start = concatenatedPositions(posed.meshes());
    std::vector<float> normals;
    for (const mq::PosedMesh& m : posed.meshes()) normals.insert(normals.end(), m.normals.begin(), m.normals.end());
    s.body.setMesh(start, concatenatedTriangles(mannequin), 0.02f);
    posed.evaluate(mannequin, walk, 0.5f + 1.0f / 30.0f, nullptr, nullptr);
    s.body.setTarget(concatenatedPositions(posed.meshes()), 1.0f / 30.0f);
    s.body.moveTo(1.0f);
    uint32_t random = 12345;
    auto next = [&] { return float((random = random * 1664525u + 1013904223u) >> 8) / float(1 << 24); };
    for (size_t v = 0; 3 * v + 2 < start.size(); v += 2) {
      const glm::vec3 p(start[3 * v], start[3 * v + 1], start[3 * v + 2]);
      const glm::vec3 n = glm::normalize(glm::vec3(normals[3 * v], normals[3 * v + 1], normals[3 * v + 2]));
      const float offset = next() < 0.05f ? -0.005f : 0.03f * next();
      s.points.push_back(p + offset * n);
      s.moves.push_back(0.01f * glm::normalize(glm::vec3(next() - 0.5f, next() - 0.5f, next() - 0.5f)));
      BodyContact last;
      s.hints.push_back(s.body.nearestContact(s.points.back() - 0.2f * s.moves.back(), last, 0.08f) ? last.triangle
                                                                                                    : -1);
    }
    return s;
  }();
  return scene;
}

using mq::bench::timeQueries;

void BM_BodyNearest(benchmark::State& state) {
  const BodyScene& s = walkingBody();
  const float radius = 0.001f * float(state.range(0));
  timeQueries(state, s.points.size(), [&](size_t i) {
    BodyContact contact;
    return s.body.nearestContact(s.points[i], contact, radius);
  });
}
BENCHMARK(BM_BodyNearest)->Arg(20)->Arg(80)->Unit(benchmark::kMillisecond);

void BM_BodyNearestHinted(benchmark::State& state) {
  const BodyScene& s = walkingBody();
  const float radius = 0.001f * float(state.range(0));
  timeQueries(state, s.points.size(), [&](size_t i) {
    BodyContact contact;
    return s.body.nearestContact(s.points[i], contact, radius, s.hints[i]);
  });
}
BENCHMARK(BM_BodyNearestHinted)->Arg(20)->Arg(80)->Unit(benchmark::kMillisecond);

void BM_BodyNearestKept(benchmark::State& state) {
  const BodyScene& s = walkingBody();
  std::vector<BodyQuery> last(s.points.size());
  for (size_t i = 0; i < s.points.size(); ++i) {
    last[i].contact.triangle = s.hints[i];
    last[i].pose = 0;  // of another pose
  }
  const size_t n = s.points.size();
  timeQueries(state, 4 * n, [&](size_t k) {
    const size_t i = k % n, round = k / n;
    BodyContact contact;
    if (round == 0) last[i].pose = 0;
    const glm::vec3 p = round == 0 ? s.points[i] - 0.2f * s.moves[i] : s.points[i];
    return s.body.nearestContact(p, contact, round == 3 ? 0.08f : 0.02f, last[i]);
  });
}
BENCHMARK(BM_BodyNearestKept)->Unit(benchmark::kMillisecond);

void BM_BodyFirstHit(benchmark::State& state) {
  const BodyScene& s = walkingBody();
  timeQueries(state, s.points.size(), [&](size_t i) {
    BodyContact contact;
    return s.body.firstHitAlong(s.points[i], s.points[i] + s.moves[i], contact);
  });
}
BENCHMARK(BM_BodyFirstHit)->Unit(benchmark::kMillisecond);

void BM_BodyMove(benchmark::State& state) {
  const mq::Character mannequin = mq::makeDefaultMannequin();
  const int walk = mannequin.findClip("walk");
  mq::PosedCharacter posed;
  std::vector<float> frames[2];
  for (int k = 0; k < 2; ++k) {
    posed.evaluate(mannequin, walk, 0.5f + float(k) / 30.0f, nullptr, nullptr);
    frames[k] = concatenatedPositions(posed.meshes());
  }
  BodyCollider body;
  body.setMesh(frames[0], concatenatedTriangles(mannequin), 0.02f);
  int next = 1;
  for (auto _ : state) {
    body.setTarget(frames[next], 1.0f / 30.0f);
    body.moveTo(1.0f);
    next = 1 - next;
  }
  benchmark::DoNotOptimize(body.moved());
}
BENCHMARK(BM_BodyMove)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
