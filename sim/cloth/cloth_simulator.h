#pragma once
// The cloth simulation a caller steps: the CLI, the editor (live while the
// character plays, or baking with progress and cancel) and the tests.
//
// One step(dt) reads top to bottom (cloth_simulator.cpp). For each solver
// substep, one stage after another:
//  1. find the cloth a moving body part is about to reach (the solver then
//     moves it with the part); move the body and the pin targets; find the
//     resting contacts;
//  2. integrate, then apply the resting contacts' friction;
//  3. collide with the colliders and the body;
//  4. limit the elongation (the sewing variant while seams close);
//  5. resolve self-collisions;
//  6. collide again (and with the surface of the cloth it is worn over,
//     when layered);
//  7. push cloth triangles off the body's vertices (body_feature_contact.h);
//  8. limit the elongation again, keeping contacts out;
//  9. put pinned vertices on their targets, check for NaNs.
// Each stage's time goes to its ClothPhase in the stats.
//
//   ClothSimulator sim(mesh, fabricPreset("cotton"), settings);
//   sim.addCollider(PrimitiveCollider::sphere({0, 0, 0}, 0.3f));
//   sim.setBody(restPositions, triangles);            // optional
//   for each frame: sim.updateBody(posed); sim.step(1 / 24.f); use sim.positions();

#include <chrono>
#include <cstdint>
#include <memory>
#include <vector>

#include "core/garment/fabric.h"
#include "core/util/error.h"
#include "sim/cloth/cloth_settings.h"
#include "sim/cloth/cloth_state.h"
#include "sim/cloth/cloth_topology.h"
#include "sim/cloth/collision/body_collider.h"
#include "sim/cloth/collision/primitive_collider.h"
#include "sim/cloth/constraints/seam_closing.h"
#include "sim/cloth/constraints/stretch_limit.h"
#include "sim/cloth/forces/cloth_forces.h"

namespace mq::cloth {

class BodyFeatureContact;
class ClothSurfaceCollider;
class Integrator;
class SelfCollision;

// A NaN or infinity appeared in the state: reported, never propagated.
class ClothDiverged : public Error {
 public:
  using Error::Error;
};

// The parts of a step(), for its time profile (ClothStats::phaseSeconds).
enum class ClothPhase : int {
  BodyPose,            // the body's new pose and the step's first contacts (substepsForBodySpeed)
  Approach,            // body parts about to reach the cloth, the body moved, pins, resting contacts
  Integrate,           // the integrator (the implicit solve), resting friction
  Collide,             // colliders and the body, both passes
  StretchLimit,        // the elongation limit after integrating (or sewing)
  SelfCollision,       // cloth-cloth proximity
  BodyFeatures,        // body vertices under cloth triangles
  LimitAfterContacts,  // the elongation limit keeping contacts out
  Finish,              // pins placed, NaN check, stats
  Count
};
constexpr int kClothPhaseCount = int(ClothPhase::Count);

struct ClothStats;

// Adds the time of its scope to one phase of the stats: one per stage.
class PhaseTimer {
 public:
  PhaseTimer(ClothStats& stats, ClothPhase phase);
  ~PhaseTimer();
  PhaseTimer(const PhaseTimer&) = delete;
  PhaseTimer& operator=(const PhaseTimer&) = delete;

 private:
  ClothStats& stats_;
  ClothPhase phase_;
  std::chrono::steady_clock::time_point start_;
};
// "body_pose", "approach", ... (the stats JSON's keys).
const char* clothPhaseName(ClothPhase phase);

struct ClothStats {
  float maxStretch = 1.0f;      // largest structural length / rest length now
  float maxStretchEver = 1.0f;  // ... over all steps so far
  glm::vec3 boundsMin{0.0f}, boundsMax{0.0f};
  int substeps = 0;             // solver steps in the last step()
  int solverIterations = 0;     // CG iterations in the last step() (implicit)
  float solverResidual = 0.0f;  // the largest relative residual a solve of the last step() ended with (implicit)
  int selfContacts = 0;         // cloth-cloth pairs closer than the thickness in the last step()
  int bodyFeatureContacts = 0;  // body vertices under (or through) cloth triangles in the last step()
  int stretchPasses = 0;        // elongation-limit passes in the last step()
  long long bodyQueries = 0;    // nearest-point body queries of cloth vertices in the last step()
  long long bodySearches = 0;  // ... of them, those that searched the body (the others: a vertex's last query sufficed)
  double phaseSeconds[kClothPhaseCount] = {};  // wall time of each phase in the last step()
  long long steps = 0;
  double simulatedTime = 0.0;
};

class ClothSimulator {
 public:
  ClothSimulator(const ClothMesh& mesh, const Fabric& fabric, const ClothSettings& settings);
  // With springs from `topology` instead of the mesh's shape (e.g. remapped
  // after welding seams, see sim/garment/garment_sewing.h).
  ClothSimulator(const ClothMesh& mesh, const ClothTopology& topology, const Fabric& fabric,
                 const ClothSettings& settings);
  ~ClothSimulator();

  // Colliders and the body
  void addCollider(const PrimitiveCollider& collider);
  // Replaces the colliders (a collider moved between steps: the editor's drag).
  void setColliders(const std::vector<PrimitiveCollider>& colliders) { colliders_ = colliders; }
  const std::vector<PrimitiveCollider>& colliders() const { return colliders_; }
  void setBody(const std::vector<float>& positions, const std::vector<uint32_t>& triangles);
  // The posed body (same vertices) at the end of the next step().
  void updateBody(const std::vector<float>& posedPositions);

  // Layering: the surface of the cloth this one is worn over (not owned;
  // null: none), moved by the caller (setTarget) before each step(); see
  // cloth_simulator_layers.cpp.
  void setInnerSurface(ClothSurfaceCollider* surface) { innerSurface_ = surface; }

  // Pins: a pinned vertex follows its target exactly.
  void pinVertex(uint32_t vertex);  // where it is now
  void pinVertex(uint32_t vertex, glm::vec3 target);
  void pinToBodyVertex(uint32_t vertex, uint32_t bodyVertex);  // keeps today's offset

  // Sewing: the distance of each pair shrinks by at most closingSpeed * h per
  // solver step, solved together with the elongation limit in the position
  // pass (the seam vertices made heavier there, so the panels follow their
  // seams rather than the seams being pulled back). Unlike the zero-length
  // seam springs of ClothMesh::seams, a wide gap cannot close in one step.
  // While sewing, the elongation limit is maxStretch * stretchRelief (panels
  // bent around the body may need a little more before the seams meet).
  void sewSeams(const std::vector<std::pair<uint32_t, uint32_t>>& seams, float closingSpeed,
                float stretchRelief = 1.0f);

  // Stepping; throws ClothDiverged when the state is not finite.
  void step(float dt);

  // Results
  const std::vector<glm::vec3>& positions() const { return state_.x; }
  std::vector<float> flatPositions() const;
  const std::vector<uint32_t>& triangles() const { return triangles_; }
  const ClothState& state() const { return state_; }
  ClothState& mutableState() {
    penetrating_ = -1;
    return state_;
  }  // tests and tools: edit, then step
  const ClothStats& stats() const { return stats_; }
  // Vertices inside a collider or the body now: counted when asked (a body
  // query per vertex, too dear for every step), kept until the cloth, the
  // colliders or the body change. Not for concurrent callers.
  int penetratingVertices() const;
  const ClothSettings& settings() const { return settings_; }
  const ClothForces& forces() const { return *forces_; }
  double kineticEnergy() const;
  double potentialEnergy() const;
  float currentMaxStretch() const;
  int countPenetrating() const;
  // Solver steps one step(dt) takes with these settings at least (automatic
  // substeps add more while a body part comes fast towards the cloth).
  int substepsFor(float dt) const;

 private:
  struct Pin {
    uint32_t vertex;
    glm::vec3 target;
    int64_t bodyVertex = -1;
    glm::vec3 offset{0.0f};
  };
  // The body's target pose and the step's first contacts; returns the substeps.
  int startStep(float dt);
  void substep(float h, float bodyFraction, bool firstOfStep);
  // The substep's stages (each timed as its ClothPhase).
  void approachAndMoveBody(float h, float bodyFraction, bool firstOfStep);
  void integrate(float h);
  bool limitStretch(float h);
  void pushOffBodyVertices();
  void preparePins(float h);
  void placePins();
  void findRestingContacts();
  void findApproachingBody(float h, bool firstOfStep);
  int substepsForBodySpeed(float dt);
  // The nearest body contact of each free vertex within `radius` (found[i] = 0: none).
  void findNearestBody(float radius, std::vector<BodyContact>& contacts, std::vector<uint8_t>& found);
  // The nearest body contact of vertex i within `radius` (false: none),
  // through its last query (bodyQueries_[i]).
  bool nearestBodyContact(size_t i, float radius, BodyContact& contact);
  std::pair<long long, long long> bodyQueryCounts() const;  // summed over bodyQueries_: queries, searches
  void applyRestingFriction(float h);
  void collideWithColliders();
  void collideWithInnerSurface(float fraction);  // cloth_simulator_layers.cpp
  bool limitStretchAfterContacts(float h);
  bool limitStretchOverContacts(float h);
  void checkFinite(const char* where) const;
  void updateStats();
  Pin* findPin(uint32_t vertex);

  ClothSettings settings_;
  Fabric fabric_;
  std::vector<uint32_t> triangles_;
  ClothTopology topology_;
  std::unique_ptr<ClothForces> forces_;
  std::unique_ptr<Integrator> integrator_;
  std::unique_ptr<SelfCollision> selfCollision_;
  std::unique_ptr<BodyFeatureContact> bodyFeatures_;  // body vertices against cloth triangles
  StretchLimiter stretchLimiter_;                     // over forces_'s structural springs
  ClothState state_;
  std::vector<float> freeInvMass_;
  std::vector<glm::vec3> stepStart_;
  // Per vertex, what the contacts of this substep did to it: 0, kContact, kSweptContact.
  static constexpr uint8_t kContact = 1, kSweptContact = 2;
  std::vector<uint8_t> touched_;
  std::vector<glm::vec3> approachNormal_, approachVelocity_;  // findApproachingBody(); empty: none
  std::vector<float> approachSpeed_;
  // The body contacts at the step's start within approachReach_ (0: none
  // this step), from substepsForBodySpeed(), reused by every try's first
  // substep; the other substeps' in substepContacts_.
  std::vector<BodyContact> stepStartContacts_, substepContacts_;
  std::vector<uint8_t> stepStartFound_, substepFound_;
  // Each vertex's last body query (BodyQuery): a query at the same body pose
  // from the same point is answered by it, one whose point moved less than
  // its distance to the surface less the radius needs no search, and the
  // others start from its nearest triangle.
  std::vector<BodyQuery> bodyQueries_;
  float approachReach_ = 0.0f;
  std::vector<glm::vec3> restingSurfaceVelocity_;  // vertices a collision moved in this substep
  std::vector<PrimitiveCollider> colliders_;
  BodyCollider body_;
  ClothSurfaceCollider* innerSurface_ = nullptr;
  std::vector<float> pendingBody_;
  std::vector<Pin> pins_;
  SeamClosing sewing_;
  float activeMaxStretch() const { return sewing_.maxStretch(settings_.maxStretch); }
  ClothStats stats_;
  mutable int penetrating_ = -1;  // penetratingVertices() since the last change; -1: not counted
  bool limitHeld_ = true;         // the elongation limit held in every substep of this try
  bool lastTry_ = false;          // this try cannot be redone with more substeps
  int passBudget_ = 100;          // elongation-limit passes per call in this try
};

}  // namespace mq::cloth
