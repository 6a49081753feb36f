// Integrators: stable and finite, implicit agrees with explicit at small
// steps, energy decreases with damping, the implicit one is stable at one
// step per frame for every fabric preset.
#include <gtest/gtest.h>

#include <cstring>
#include <limits>

#include "cloth_test_scenes.h"
#include "sim/cloth/integrators/implicit_euler.h"
#include "sim/cloth/parallel.h"

namespace mq::cloth {
namespace {

using test::hangingSheetMesh;

ClothSettings settingsFor(IntegratorKind kind) {
  ClothSettings s;
  s.integrator = kind;
  s.stretchLimit = StretchLimitMode::Off;
  s.cgMaxIterations = 400;
  s.cgTolerance = 1e-6f;
  return s;
}

// Cotton with light spring damping: stiff Rayleigh damping would force
// explicit integrators into tiny steps (their bound is h < m / sum kd).
Fabric lightlyDampedCotton() {
  Fabric f = fabricPreset("cotton");
  f.damping = 2e-5f;
  return f;
}

std::unique_ptr<ClothSimulator> smallHangingSheet(IntegratorKind kind, int columns = 8) {
  auto sim = std::make_unique<ClothSimulator>(hangingSheetMesh(columns, columns, 0.3f, 0.3f, 1.0f),
                                              lightlyDampedCotton(), settingsFor(kind));
  test::pinTopRow(*sim, columns);
  return sim;
}

TEST(ClothIntegrators, EachIsStableAndFiniteOnASmallScene) {
  for (IntegratorKind kind :
       {IntegratorKind::SymplecticEuler, IntegratorKind::Verlet, IntegratorKind::RK4, IntegratorKind::ImplicitEuler}) {
    auto sim = smallHangingSheet(kind);
    for (int frame = 0; frame < 24; ++frame) sim->step(1.0f / 24.0f);
    EXPECT_TRUE(test::allFinite(*sim)) << integratorName(kind);
    const ClothStats& st = sim->stats();
    // It hangs below its pins and has not flown away.
    EXPECT_LT(st.boundsMin.y, 0.75f) << integratorName(kind);
    EXPECT_GT(st.boundsMin.y, 0.6f) << integratorName(kind);
    EXPECT_LT(st.maxStretch, 1.2f) << integratorName(kind);
  }
}

TEST(ClothIntegrators, ImplicitMatchesExplicitAtSmallSteps) {
  const float dt = 1.0f / 4000.0f;
  auto reference = smallHangingSheet(IntegratorKind::RK4);
  auto implicit = smallHangingSheet(IntegratorKind::ImplicitEuler);
  auto symplectic = smallHangingSheet(IntegratorKind::SymplecticEuler);
  auto verlet = smallHangingSheet(IntegratorKind::Verlet);
  const std::vector<glm::vec3> start = reference->positions();
  for (int k = 0; k < 800; ++k) {  // 0.2 s
    reference->step(dt);
    implicit->step(dt);
    symplectic->step(dt);
    verlet->step(dt);
  }
  float moved = 0.0f, dImplicit = 0.0f, dSymplectic = 0.0f, dVerlet = 0.0f;
  for (size_t i = 0; i < start.size(); ++i) {
    moved = std::max(moved, glm::length(reference->positions()[i] - start[i]));
    dImplicit = std::max(dImplicit, glm::length(implicit->positions()[i] - reference->positions()[i]));
    dSymplectic = std::max(dSymplectic, glm::length(symplectic->positions()[i] - reference->positions()[i]));
    dVerlet = std::max(dVerlet, glm::length(verlet->positions()[i] - reference->positions()[i]));
  }
  EXPECT_GT(moved, 0.01f);  // the sheet swung noticeably
  EXPECT_LT(dImplicit, 0.05f * moved);
  EXPECT_LT(dSymplectic, 0.02f * moved);
  EXPECT_LT(dVerlet, 0.02f * moved);
}

double totalEnergy(const ClothSimulator& sim) { return sim.kineticEnergy() + sim.potentialEnergy(); }

TEST(ClothIntegrators, EnergyDecreasesWithDampingAndNoCollider) {
  for (IntegratorKind kind : {IntegratorKind::ImplicitEuler, IntegratorKind::SymplecticEuler}) {
    auto sim = smallHangingSheet(kind);
    double previous = totalEnergy(*sim);
    const double start = previous;
    double scale = 0.0;
    for (int frame = 0; frame < 48; ++frame) {
      sim->step(1.0f / 24.0f);
      const double e = totalEnergy(*sim);
      scale = std::max(scale, std::abs(start - e));
      // Neither method conserves this energy exactly step by step (implicit
      // Euler is linearised once per step, symplectic Euler's energy
      // oscillates around its decay): a frame may gain 0.05 % of the total.
      const double slack = 5e-4 * std::abs(start);
      EXPECT_LE(e, previous + slack) << integratorName(kind) << " frame " << frame;
      previous = e;
    }
    EXPECT_LT(previous, start - 0.1 * scale) << integratorName(kind);
  }
}

TEST(ClothIntegrators, ImplicitIsStableAtOneStepPerFrameForEveryPreset) {
  for (const std::string& name : fabricPresetNames()) {
    for (float fps : {24.0f, 60.0f}) {
      ClothSettings settings;  // implicit, one step per frame, limit on
      settings.maxRefinement = 1;
      ClothSimulator sim(hangingSheetMesh(16, 16, 0.5f, 0.5f, 1.0f), fabricPreset(name), settings);
      test::pinTopRow(sim, 16);
      for (int frame = 0; frame < int(2 * fps); ++frame) sim.step(1.0f / fps);
      EXPECT_EQ(sim.stats().substeps, 1);
      EXPECT_TRUE(test::allFinite(sim)) << name << " at " << fps;
      EXPECT_LE(sim.stats().maxStretch, 1.1001f) << name << " at " << fps;
      EXPECT_GT(sim.stats().boundsMin.y, 0.3f) << name << " at " << fps;
      EXPECT_LT(sim.stats().boundsMax.y, 1.0001f) << name << " at " << fps;
    }
  }
}

TEST(ClothIntegrators, ANanInTheStateIsReportedNotPropagated) {
  auto sim = smallHangingSheet(IntegratorKind::ImplicitEuler);
  sim->step(1.0f / 24.0f);
  sim->mutableState().x[20].y = std::numeric_limits<float>::quiet_NaN();
  try {
    sim->step(1.0f / 24.0f);
    FAIL() << "no error for a NaN";
  } catch (const ClothDiverged& e) {
    EXPECT_NE(std::string(e.what()).find("vertex 20"), std::string::npos) << e.what();
  }
}

TEST(ClothIntegrators, ExplicitBlowUpIsReportedAsDivergence) {
  // One symplectic Euler step per frame on stiff cloth is far beyond its
  // stability bound: the solver must say so instead of returning NaNs.
  ClothSettings settings = settingsFor(IntegratorKind::SymplecticEuler);
  settings.substeps = 1;
  ClothSimulator sim(hangingSheetMesh(8, 8, 0.3f, 0.3f, 1.0f), fabricPreset("denim"), settings);
  test::pinTopRow(sim, 8);
  EXPECT_THROW(
      {
        for (int frame = 0; frame < 200; ++frame) sim.step(1.0f / 24.0f);
      },
      ClothDiverged);
}

TEST(ClothIntegrators, DeterministicForTheSameInput) {
  for (CgPreconditioner preconditioner : {CgPreconditioner::BlockJacobi, CgPreconditioner::TwoLevel}) {
    auto run = [preconditioner] {
      ClothSettings settings;
      settings.cgPreconditioner = preconditioner;
      ClothSimulator sim(test::horizontalSheetMesh(40, 1.0f, {0, 0.5f, 0}), fabricPreset("silk"), settings);
      sim.addCollider(PrimitiveCollider::sphere({0, 0, 0}, 0.3f));
      for (int frame = 0; frame < 12; ++frame) sim.step(1.0f / 24.0f);
      return sim.positions();
    };
    const auto a = run(), b = run();
    ASSERT_EQ(a.size(), b.size());
    EXPECT_EQ(0, std::memcmp(a.data(), b.data(), a.size() * sizeof(glm::vec3))) << cgPreconditionerName(preconditioner);
  }
}

// The implicit solve of a large cloth runs on the thread pool or on the
// calling thread alone, whichever was faster lately (PoolChooser): both must
// give the same motion bit for bit, with either preconditioner, with pins
// and with resting contacts filtered.
TEST(ClothIntegrators, ImplicitSolveOnThePoolMatchesItAloneBitForBit) {
  const int columns = 96;  // 9,216 vertices: over the size the pool is used for
  ASSERT_GE(size_t(columns * columns), 2 * kParallelGrain);
  const ClothMesh mesh = test::horizontalSheetMesh(columns, 1.0f, {0, 0.5f, 0});
  const ClothTopology topology = buildClothTopology(mesh);
  const Fabric fabric = fabricPreset("cotton");
  for (CgPreconditioner preconditioner : {CgPreconditioner::BlockJacobi, CgPreconditioner::TwoLevel}) {
    ClothSettings settings;
    settings.cgPreconditioner = preconditioner;
    settings.cgMaxIterations = 30;
    ClothForces forces(topology, mesh, fabric, settings);
    auto run = [&](ImplicitEuler::PoolUse use) {
      ClothState s;
      for (size_t i = 0; i < mesh.vertexCount(); ++i) {
        const glm::vec3 x = vec3At(mesh.positions, i);
        s.x.push_back(x);
        s.v.push_back(glm::vec3(std::sin(7.0f * x.x), -0.5f, std::cos(5.0f * x.z)));  // a rippling start
        s.mass.push_back(1e-4f);
        s.invMass.push_back(i < size_t(columns) ? 0.0f : 1e4f);  // the first row pinned
      }
      s.contactNormal.assign(s.size(), glm::vec3(0.0f));
      s.contactSpeed.assign(s.size(), 0.0f);
      for (size_t i = s.size() / 2; i < s.size() / 2 + 500; ++i) s.contactNormal[i] = {0.0f, 1.0f, 0.0f};
      ImplicitEuler solver(settings.cgMaxIterations, 1e-4f, preconditioner == CgPreconditioner::TwoLevel);
      solver.setPoolUse(use);
      int iterations = 0;
      for (int step = 0; step < 3; ++step) iterations += solver.step(s, 1.0f / 30.0f, forces).solverIterations;
      EXPECT_GT(iterations, 3);
      return s;
    };
    const ClothState pool = run(ImplicitEuler::PoolUse::Always), alone = run(ImplicitEuler::PoolUse::Never);
    EXPECT_EQ(0, std::memcmp(pool.x.data(), alone.x.data(), pool.x.size() * sizeof(glm::vec3)))
        << cgPreconditionerName(preconditioner);
    EXPECT_EQ(0, std::memcmp(pool.v.data(), alone.v.data(), pool.v.size() * sizeof(glm::vec3)))
        << cgPreconditionerName(preconditioner);
    EXPECT_NE(pool.x[mesh.vertexCount() - 1], vec3At(mesh.positions, mesh.vertexCount() - 1));  // it moved
  }
}

// The two-level preconditioner (block Jacobi plus rigidly moving patches) is
// a better preconditioner for the same system: on a stiff sheet draped over
// a sphere (resting contacts filtered) with its first rows pinned, it
// reaches the same tolerance in far
// fewer CG iterations, and nearer the exact motion (block Jacobi's
// preconditioned residual hides the error of slow, smooth motions).
std::vector<glm::vec3> drapeWithPreconditioner(CgPreconditioner preconditioner, float tolerance, int& iterations) {
  ClothSettings settings;
  settings.stretchLimit = StretchLimitMode::Off;
  settings.cgMaxIterations = 20000;
  settings.cgTolerance = tolerance;
  settings.cgPreconditioner = preconditioner;
  const int columns = 48;
  ClothSimulator sim(test::horizontalSheetMesh(columns, 1.0f, {0, 0.32f, 0}), fabricPreset("denim"), settings);
  sim.addCollider(PrimitiveCollider::sphere({0, 0, 0}, 0.3f));
  for (uint32_t v = 0; v < uint32_t(3 * columns); ++v) sim.pinVertex(v);
  iterations = 0;
  for (int frame = 0; frame < 6; ++frame) {
    sim.step(1.0f / 24.0f);
    iterations += sim.stats().solverIterations;
  }
  EXPECT_TRUE(test::allFinite(sim));
  return sim.positions();
}

float largestDistance(const std::vector<glm::vec3>& a, const std::vector<glm::vec3>& b) {
  float d = 0.0f;
  for (size_t i = 0; i < a.size(); ++i) d = std::max(d, glm::length(a[i] - b[i]));
  return d;
}

TEST(ClothIntegrators, TwoLevelPreconditionerConvergesInFewerIterationsNearerTheExactMotion) {
  int exactIterations = 0, jacobiIterations = 0, twoLevelIterations = 0;
  // (1e-6: below that the float solve loses the recursion's accuracy.)
  const auto exact = drapeWithPreconditioner(CgPreconditioner::TwoLevel, 1e-6f, exactIterations);
  const auto jacobi = drapeWithPreconditioner(CgPreconditioner::BlockJacobi, 1e-3f, jacobiIterations);
  const auto twoLevel = drapeWithPreconditioner(CgPreconditioner::TwoLevel, 1e-3f, twoLevelIterations);
  EXPECT_LT(twoLevelIterations, jacobiIterations / 2) << jacobiIterations << " vs " << twoLevelIterations;
  std::vector<glm::vec3> start;
  const ClothMesh mesh = test::horizontalSheetMesh(48, 1.0f, {0, 0.32f, 0});
  for (size_t i = 0; i < mesh.vertexCount(); ++i) start.push_back(vec3At(mesh.positions, i));
  const float moved = largestDistance(exact, start);
  EXPECT_GT(moved, 0.05f);
  EXPECT_LT(largestDistance(twoLevel, exact), largestDistance(jacobi, exact)) << "moved " << moved;
}

// Patches whose vertices are all pinned have no coarse unknowns (their rows
// of A_c are zero): the solve drops them and the free rows still move as
// block Jacobi moves them.
TEST(ClothIntegrators, TwoLevelHandlesPatchesWithoutAFreeVertex) {
  auto run = [](CgPreconditioner preconditioner) {
    ClothSettings settings = settingsFor(IntegratorKind::ImplicitEuler);
    settings.cgPreconditioner = preconditioner;
    const int columns = 24;
    ClothSimulator sim(test::horizontalSheetMesh(columns, 0.5f, {0, 1, 0}), lightlyDampedCotton(), settings);
    for (uint32_t v = 0; v < uint32_t(columns * (columns - 3)); ++v) sim.pinVertex(v);
    for (int frame = 0; frame < 12; ++frame) sim.step(1.0f / 24.0f);
    EXPECT_TRUE(test::allFinite(sim)) << cgPreconditionerName(preconditioner);
    return sim.positions();
  };
  const auto jacobi = run(CgPreconditioner::BlockJacobi), twoLevel = run(CgPreconditioner::TwoLevel);
  const ClothMesh mesh = test::horizontalSheetMesh(24, 0.5f, {0, 1, 0});
  float moved = 0.0f;
  for (size_t i = 0; i < mesh.vertexCount(); ++i)
    moved = std::max(moved, glm::length(jacobi[i] - vec3At(mesh.positions, i)));
  EXPECT_GT(moved, 0.02f);  // the free edge bends down
  EXPECT_LT(largestDistance(jacobi, twoLevel), 0.01f * moved) << "moved " << moved;
}

TEST(ClothIntegrators, PreconditionerNamesRoundTrip) {
  for (CgPreconditioner p : {CgPreconditioner::BlockJacobi, CgPreconditioner::TwoLevel}) {
    CgPreconditioner parsed{};
    ASSERT_TRUE(parseCgPreconditioner(cgPreconditionerName(p), parsed));
    EXPECT_EQ(parsed, p);
  }
  CgPreconditioner unused{};
  EXPECT_FALSE(parseCgPreconditioner("multigrid", unused));
}
}  // namespace
}  // namespace mq::cloth
