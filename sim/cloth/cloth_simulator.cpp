#include "sim/cloth/cloth_simulator.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "sim/cloth/collision/body_feature_contact.h"
#include "sim/cloth/collision/contact_response.h"
#include "sim/cloth/collision/self_collision.h"
#include "sim/cloth/constraints/contact_aware_limit.h"
#include "sim/cloth/constraints/stretch_limit.h"
#include "sim/cloth/integrators/integrator.h"
#include "sim/cloth/parallel.h"

namespace mq::cloth {

namespace {

// Vertices held by a contact (or a closing seam) weigh this much of their
// free inverse mass in the elongation limit: the limit then moves their
// neighbours instead.
constexpr float kContactInvMassScale = 0.05f;
constexpr int kSelfCollisionPasses = 20;      // per substep, at most
constexpr float kMaxApproachReach = 0.08f;    // m: how far ahead findApproachingBody() looks at most
constexpr float kApproachPerSubstep = 0.03f;  // m: see substepsForBodySpeed()
constexpr int kMaxBodySpeedSubsteps = 4;
constexpr int kContactLimitRounds = 8;  // with a body: see constraints/contact_aware_limit.h

ClothState initialState(const ClothMesh& mesh, const ClothTopology& topology, const Fabric& fabric) {
  ClothState s;
  const size_t n = mesh.vertexCount();
  s.x.resize(n);
  s.v.assign(n, glm::vec3(0.0f));
  s.mass.resize(n);
  s.invMass.resize(n);
  for (size_t i = 0; i < n; ++i) {
    s.x[i] = vec3At(mesh.positions, i);
    s.mass[i] = mesh.masses.empty() ? fabric.massPerArea * topology.vertexArea[i] : mesh.masses[i];
    if (!(s.mass[i] > 0.0f) || !std::isfinite(s.mass[i]))
      throw Error("cloth vertex " + std::to_string(i) + " has no positive mass");
    s.invMass[i] = 1.0f / s.mass[i];
  }
  return s;
}

void validateSettings(const ClothSettings& s) {
  auto finite = [](glm::vec3 v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); };
  if (!finite(s.gravity) || !finite(s.wind)) throw Error("cloth gravity and wind must be finite");
  if (!std::isfinite(s.airDamping) || s.airDamping < 0.0f) throw Error("cloth air damping must be >= 0");
  if (!std::isfinite(s.maxStretch) || s.maxStretch < 1.0f) throw Error("cloth max stretch must be >= 1");
  if (!std::isfinite(s.collisionThickness) || s.collisionThickness < 0.0f || !std::isfinite(s.selfThickness) ||
      s.selfThickness < 0.0f)
    throw Error("cloth collision thickness must be >= 0");
  if (s.substeps < 0 || s.cgMaxIterations < 1 || !(s.cgTolerance > 0.0f))
    throw Error("cloth solver settings out of range (substeps >= 0, cg iterations >= 1, tolerance > 0)");
}

// The first point of the segment from -> to within `thickness` of the
// collider, by bisection (to itself when `from` is already that close or the
// segment never gets that close).
glm::vec3 firstContactAlong(const PrimitiveCollider& c, const glm::vec3& from, const glm::vec3& to, float thickness) {
  glm::vec3 n;
  if (c.signedDistance(to, n) >= 0.0f || c.signedDistance(from, n) < thickness) return to;
  float lo = 0.0f, hi = 1.0f;  // lo: outside, hi: inside
  for (int k = 0; k < 12; ++k) {
    const float mid = 0.5f * (lo + hi);
    (c.signedDistance(glm::mix(from, to, mid), n) >= 0.0f ? lo : hi) = mid;
  }
  return glm::mix(from, to, lo);
}

}  // namespace

const char* clothPhaseName(ClothPhase phase) {
  static const char* const names[kClothPhaseCount] = {
      "body_pose",     "approach",       "integrate",     "collide",
      "stretch_limit", "self_collision", "body_features", "limit_after_contacts",
      "finish"};
  return names[int(phase)];
}

ClothSimulator::ClothSimulator(const ClothMesh& mesh, const Fabric& fabric, const ClothSettings& settings)
    : ClothSimulator(mesh, buildClothTopology(mesh), fabric, settings) {}

ClothSimulator::ClothSimulator(const ClothMesh& mesh, const ClothTopology& topology, const Fabric& fabric,
                               const ClothSettings& settings)
    : settings_(settings), fabric_(fabric), triangles_(mesh.triangles), topology_(topology) {
  fabric_.validate();
  validateSettings(settings_);
  if (settings_.friction < 0.0f) settings_.friction = fabric_.friction;
  for (const auto& [a, b] : mesh.seams)
    if (a >= mesh.vertexCount() || b >= mesh.vertexCount()) throw Error("cloth seam vertex out of range");
  forces_ = std::make_unique<ClothForces>(topology_, mesh, fabric_, settings_);
  integrator_ = makeIntegrator(settings_);
  stretchLimiter_ = StretchLimiter(forces_->springs().springs(), forces_->structuralCount(), mesh.vertexCount());
  if (settings_.selfCollisions) selfCollision_ = std::make_unique<SelfCollision>(triangles_, mesh.vertexCount());
  state_ = initialState(mesh, topology_, fabric_);
  bodyFeatures_ = std::make_unique<BodyFeatureContact>(triangles_, state_.x);
  freeInvMass_ = state_.invMass;
  bodyQueries_.resize(state_.size());
  updateStats();
}

ClothSimulator::~ClothSimulator() = default;

// Colliders, body and pins -------------------------------------------------

void ClothSimulator::addCollider(const PrimitiveCollider& collider) {
  colliders_.push_back(collider);
  penetrating_ = -1;
}

void ClothSimulator::setBody(const std::vector<float>& positions, const std::vector<uint32_t>& triangles) {
  body_.setMesh(positions, triangles, std::max(0.02f, 3.0f * settings_.collisionThickness));
  pendingBody_.clear();
  penetrating_ = -1;
}

void ClothSimulator::updateBody(const std::vector<float>& posedPositions) {
  if (body_.empty()) throw Error("updateBody() before setBody()");
  if (posedPositions.size() != 3 * body_.positions().size()) throw Error("posed body has a different vertex count");
  pendingBody_ = posedPositions;
}

ClothSimulator::Pin* ClothSimulator::findPin(uint32_t vertex) {
  for (Pin& p : pins_)
    if (p.vertex == vertex) return &p;
  return nullptr;
}

void ClothSimulator::pinVertex(uint32_t vertex) { pinVertex(vertex, state_.x.at(vertex)); }

void ClothSimulator::pinVertex(uint32_t vertex, glm::vec3 target) {
  if (vertex >= state_.size()) throw Error("pinned vertex out of range");
  if (Pin* p = findPin(vertex)) {
    *p = {vertex, target};
  } else {
    pins_.push_back({vertex, target});
  }
  state_.invMass[vertex] = 0.0f;
}

void ClothSimulator::pinToBodyVertex(uint32_t vertex, uint32_t bodyVertex) {
  if (bodyVertex >= body_.positions().size()) throw Error("pin body vertex out of range");
  pinVertex(vertex);
  Pin* p = findPin(vertex);
  p->bodyVertex = bodyVertex;
  p->offset = state_.x[vertex] - body_.positions()[bodyVertex];
}

// Stepping ------------------------------------------------------------------

int ClothSimulator::substepsFor(float dt) const {
  if (settings_.substeps > 0) return settings_.substeps;
  const float hMax = integrator_->stableStep(state_, *forces_);
  if (!std::isfinite(hMax)) return 1;
  return std::max(1, int(std::ceil(dt / hMax)));
}

// More solver steps when a body part comes towards the cloth near it faster
// than kApproachPerSubstep a step (a swinging shin in a trouser leg moves up
// to 10 cm a frame at 30 fps, the walking T-shirt's arms under 2 cm): the
// cloth it carries then moves less per step, and the elongation limit has
// less to pull back over it.
int ClothSimulator::substepsForBodySpeed(float dt) {
  if (body_.empty() || !(body_.maxSpeed() > 0.0f)) return 1;
  approachReach_ = std::min(kMaxApproachReach, settings_.collisionThickness + body_.maxSpeed() * dt);
  // The nearest contacts within the whole reach for every vertex (reused by
  // the first substep's findApproachingBody()): a vertex's last query bounds
  // its clearance (BodyQuery), so a far one's search ends at once. (Shorter
  // reaches away from fast body parts, from a tree of the body's speeds, gave
  // the same contacts for more work.)
  findNearestBody(approachReach_, stepStartContacts_, stepStartFound_);
  float fastest = 0.0f;
  for (size_t i = 0; i < state_.size(); ++i)
    if (stepStartFound_[i] && stepStartContacts_[i].signedDistance >= 0.0f)
      fastest = std::max(fastest, glm::dot(stepStartContacts_[i].velocity, stepStartContacts_[i].normal));
  return std::clamp(int(std::ceil(fastest * dt / kApproachPerSubstep)), 1, kMaxBodySpeedSubsteps);
}

std::pair<long long, long long> ClothSimulator::bodyQueryCounts() const {
  long long queries = 0, searches = 0;
  for (const BodyQuery& q : bodyQueries_) queries += q.queries, searches += q.searches;
  return {queries, searches};
}

bool ClothSimulator::nearestBodyContact(size_t i, float radius, BodyContact& contact) {
  BodyQuery& last = bodyQueries_[i];
  ++last.queries;
  return !body_.provesNoneWithin(last, state_.x[i], radius) && body_.nearestContact(state_.x[i], contact, radius, last);
}

void ClothSimulator::findNearestBody(float radius, std::vector<BodyContact>& contacts, std::vector<uint8_t>& found) {
  contacts.resize(state_.size());
  found.assign(state_.size(), 0);
  forRange(state_.size(), [&](size_t b, size_t e) {
    for (size_t i = b; i < e; ++i) found[i] = freeInvMass_[i] != 0.0f && nearestBodyContact(i, radius, contacts[i]);
  });
}

PhaseTimer::PhaseTimer(ClothStats& stats, ClothPhase phase)
    : stats_(stats), phase_(phase), start_(std::chrono::steady_clock::now()) {}

PhaseTimer::~PhaseTimer() {
  stats_.phaseSeconds[int(phase_)] += std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
}

void ClothSimulator::step(float dt) {
  if (!(dt > 0.0f) || !std::isfinite(dt)) throw Error("cloth step needs a positive time step");
  std::fill(std::begin(stats_.phaseSeconds), std::end(stats_.phaseSeconds), 0.0);
  const auto [queriesBefore, searchesBefore] = bodyQueryCounts();
  const int baseSubsteps = startStep(dt);
  int substeps = baseSubsteps;
  // Adaptive refinement: when the elongation limit could not hold a step
  // (a violent impact), the step is redone with twice the substeps.
  // The state to redo the step from (not copied when no redo can come).
  const ClothState start = substeps < settings_.maxRefinement * baseSubsteps ? state_ : ClothState{};
  for (;;) {
    const float h = dt / float(substeps);
    stats_.solverIterations = stats_.selfContacts = stats_.stretchPasses = stats_.bodyFeatureContacts = 0;
    stats_.solverResidual = 0.0f;
    limitHeld_ = true;
    // The last try may spend 20 times the passes on the limit.
    lastTry_ = substeps * 2 > settings_.maxRefinement * baseSubsteps;
    passBudget_ = settings_.stretchIterations * (lastTry_ ? 20 : 1);
    if (!body_.empty()) body_.restartStep();
    for (int k = 0; k < substeps; ++k) substep(h, float(k + 1) / float(substeps), k == 0);
    if (limitHeld_ || substeps >= settings_.maxRefinement * baseSubsteps) break;
    state_ = start;
    substeps *= 2;
  }
  const PhaseTimer timer(stats_, ClothPhase::Finish);
  stats_.substeps = substeps;
  const auto [queriesAfter, searchesAfter] = bodyQueryCounts();
  stats_.bodyQueries = queriesAfter - queriesBefore;
  stats_.bodySearches = searchesAfter - searchesBefore;
  ++stats_.steps;
  stats_.simulatedTime += dt;
  updateStats();
}

int ClothSimulator::startStep(float dt) {
  const PhaseTimer timer(stats_, ClothPhase::BodyPose);
  checkFinite("before the step");
  if (!pendingBody_.empty()) {
    body_.setTarget(pendingBody_, dt);
    pendingBody_.clear();
  } else if (!body_.empty()) {
    body_.setTarget(body_.flatPositions(), dt);  // the body stands still
  }
  approachReach_ = 0.0f;
  return std::max(substepsFor(dt), settings_.substeps > 0 ? 1 : substepsForBodySpeed(dt));
}

// One substep, stage by stage; each stage's time goes to its phase.
void ClothSimulator::substep(float h, float bodyFraction, bool firstOfStep) {
  approachAndMoveBody(h, bodyFraction, firstOfStep);
  integrate(h);
  {
    const PhaseTimer timer(stats_, ClothPhase::Collide);
    collideWithColliders();
  }
  bool held = limitStretch(h);
  if (selfCollision_) {
    const PhaseTimer timer(stats_, ClothPhase::SelfCollision);
    stats_.selfContacts += selfCollision_->resolve(state_, stepStart_, settings_.selfThickness, kSelfCollisionPasses);
  }
  {
    const PhaseTimer timer(stats_, ClothPhase::Collide);
    collideWithColliders();
    if (innerSurface_) collideWithInnerSurface(bodyFraction);
  }
  pushOffBodyVertices();
  if (settings_.stretchLimit == StretchLimitMode::PositionCorrection &&
      (!colliders_.empty() || !body_.empty() || innerSurface_)) {
    const PhaseTimer timer(stats_, ClothPhase::LimitAfterContacts);
    held = limitStretchAfterContacts(h);
    // Pinched cloth on the last try: the limit wins over the contacts.
    if (!held && lastTry_) held = limitStretchOverContacts(h);
  }
  const PhaseTimer timer(stats_, ClothPhase::Finish);
  limitHeld_ = limitHeld_ && held;
  placePins();
  checkFinite("after a solver step");
}

void ClothSimulator::approachAndMoveBody(float h, float bodyFraction, bool firstOfStep) {
  const PhaseTimer timer(stats_, ClothPhase::Approach);
  findApproachingBody(h, firstOfStep);
  if (!body_.empty()) body_.moveTo(bodyFraction);
  preparePins(h);
  findRestingContacts();
  stepStart_ = state_.x;
  touched_.assign(state_.size(), 0);
}

void ClothSimulator::integrate(float h) {
  const PhaseTimer timer(stats_, ClothPhase::Integrate);
  const IntegratorReport solved = integrator_->step(state_, h, *forces_);
  stats_.solverIterations += solved.solverIterations;
  stats_.solverResidual = std::max(stats_.solverResidual, solved.solverResidual);
  applyRestingFriction(h);
}

// The elongation limit after integrating: the sewing variant while seams
// close, else the settings' mode. False when it could not hold.
bool ClothSimulator::limitStretch(float h) {
  const PhaseTimer timer(stats_, ClothPhase::StretchLimit);
  if (sewing_.active()) {
    const bool limit = settings_.stretchLimit == StretchLimitMode::PositionCorrection;
    const SeamClosing::Result r = sewing_.close(state_, stepStart_, limit ? &stretchLimiter_ : nullptr,
                                                activeMaxStretch(), passBudget_, h, kContactInvMassScale);
    stats_.stretchPasses += r.passes;
    return r.held;
  }
  if (settings_.stretchLimit == StretchLimitMode::PositionCorrection) {
    const StretchLimitResult r = stretchLimiter_.limitByPositions(state_, settings_.maxStretch, passBudget_, h);
    stats_.stretchPasses += r.passes;
    return r.maxStretchAfter <= settings_.maxStretch;
  }
  if (settings_.stretchLimit == StretchLimitMode::VelocityCorrection)
    stats_.stretchPasses +=
        limitStretchByVelocities(state_, stepStart_, forces_->springs().springs(), forces_->structuralCount(),
                                 settings_.maxStretch, settings_.stretchIterations, h)
            .passes;
  return true;
}

// Body vertices through cloth triangles, between the cloth's vertices (not
// while sewing: the panels pulled together over the shoulders would be
// pushed apart, and the seams close late).
void ClothSimulator::pushOffBodyVertices() {
  if (body_.empty() || sewing_.active()) return;
  const PhaseTimer timer(stats_, ClothPhase::BodyFeatures);
  stats_.bodyFeatureContacts += bodyFeatures_->resolve(state_, body_, settings_.collisionThickness, touched_, kContact,
                                                       body_.moved() ? kSweptContact : kContact);
}

// Contacts moved vertices after the limit: limit again without pulling them
// back in (sim/cloth/constraints/contact_aware_limit.h).
bool ClothSimulator::limitStretchAfterContacts(float h) {
  ContactSet contacts{touched_, kContact, kSweptContact, nullptr, nullptr};
  if (!body_.empty() && !sewing_.active()) {
    contacts.nearestBody = [this](size_t i, float radius, BodyContact& c) { return nearestBodyContact(i, radius, c); };
    contacts.pushBodyVerticesOut = [this] {
      return bodyFeatures_->reapply(state_, body_, settings_.collisionThickness, touched_);
    };
  }
  ContactAwareLimitSettings limit;
  limit.maxStretch = activeMaxStretch();
  limit.passBudget = passBudget_;
  // The held try gets the plain budget: pinched cloth fails it whatever the passes.
  limit.heldPassBudget = std::min(passBudget_, settings_.stretchIterations);
  limit.h = h;
  limit.contactInvMassScale = kContactInvMassScale;
  limit.bodyRounds = kContactLimitRounds;
  limit.thickness = settings_.collisionThickness;
  const ContactAwareLimitResult r = limitStretchAroundContacts(state_, contacts, stretchLimiter_, limit);
  stats_.stretchPasses += r.passes;
  return r.held;
}

// Cloth pinched between two body parts cannot keep both its contacts and
// its length (more substeps change nothing: the parts squeeze it in every
// one). On the step's last try the length wins: the pinched vertices may
// end this substep a little inside a part, and the next substep's
// collisions push them out again, while the fabric never stretches past
// the limit.
bool ClothSimulator::limitStretchOverContacts(float h) {
  const StretchLimitResult r = stretchLimiter_.limitByPositions(state_, activeMaxStretch(), passBudget_, h);
  stats_.stretchPasses += r.passes;
  return r.maxStretchAfter <= activeMaxStretch();
}

void ClothSimulator::sewSeams(const std::vector<std::pair<uint32_t, uint32_t>>& seams, float closingSpeed,
                              float stretchRelief) {
  sewing_.start(seams, closingSpeed, stretchRelief, state_.size());
}

void ClothSimulator::preparePins(float h) {
  for (const Pin& p : pins_) {
    const glm::vec3 target = p.bodyVertex >= 0 ? body_.positions()[p.bodyVertex] + p.offset : p.target;
    state_.v[p.vertex] = (target - state_.x[p.vertex]) / h;
    state_.invMass[p.vertex] = 0.0f;
  }
}

void ClothSimulator::findRestingContacts() {
  state_.contactNormal.assign(state_.size(), glm::vec3(0.0f));
  state_.contactSpeed.assign(state_.size(), 0.0f);
  restingSurfaceVelocity_.assign(state_.size(), glm::vec3(0.0f));
  if (colliders_.empty() && body_.empty()) return;
  // A vertex resting on a surface: within twice the thickness, not moving
  // away, and pressed onto it by gravity, or on a surface facing down only
  // while it comes towards it (so it can still fall off an overhang). Held on
  // upward-facing surfaces alone, a tight band (trousers on the hips) is
  // squeezed up by their reactions with nothing holding it from above: a
  // converged solve (the two-level preconditioner) lifted it into the body.
  const float reach = 2.0f * settings_.collisionThickness + 1e-4f;
  forRange(state_.size(), [&](size_t b, size_t e) {
    for (size_t i = b; i < e; ++i) {
      if (state_.invMass[i] == 0.0f) continue;
      glm::vec3 normal(0.0f);
      float speed = 0.0f;
      glm::vec3 surfaceVelocity(0.0f);
      for (const PrimitiveCollider& c : colliders_) {
        glm::vec3 n;
        if (c.signedDistance(state_.x[i], n) < reach) normal = n;
      }
      BodyContact contact;
      if (!body_.empty() && nearestBodyContact(i, body_.searchRadius(), contact) && contact.signedDistance < reach) {
        normal = contact.normal;
        speed = glm::dot(contact.velocity, normal);
        surfaceVelocity = contact.velocity;
      }
      const float approach = glm::dot(state_.v[i], normal) - speed;
      const bool facingUp = glm::dot(normal, settings_.gravity) < 0.0f;
      if (normal != glm::vec3(0.0f) && (facingUp ? approach <= 1e-3f : approach < -1e-3f)) {
        state_.contactNormal[i] = normal;
        state_.contactSpeed[i] = speed;
        restingSurfaceVelocity_[i] = surfaceVelocity;
      }
      if (!approachNormal_.empty() && approachNormal_[i] != glm::vec3(0.0f) &&
          (state_.contactNormal[i] == glm::vec3(0.0f) || approachSpeed_[i] > state_.contactSpeed[i])) {
        state_.contactNormal[i] = approachNormal_[i];
        state_.contactSpeed[i] = approachSpeed_[i];
        restingSurfaceVelocity_[i] = approachVelocity_[i];
      }
    }
  });
}

// A moving body part about to reach a cloth vertex in this substep (seen
// from the pose at the substep's start, before moveTo()): the vertex's
// velocity along the contact normal is held by the solver at what keeps it
// the thickness off the moving surface at the substep's end (and it sticks
// to the surface tangentially), so the limb
// carries the cloth in front of it (a trouser leg moves with the leg) and
// the springs drag the rest of the cloth along in the same implicit solve,
// rather than the cloth being pushed out afterwards and the elongation limit
// pulling its neighbours through the limb in straight lines.
void ClothSimulator::findApproachingBody(float h, bool firstOfStep) {
  approachNormal_.clear();
  if (body_.empty() || !(body_.maxSpeed() > 0.0f)) return;
  const float thickness = settings_.collisionThickness;
  const float radius = std::min(kMaxApproachReach, thickness + body_.maxSpeed() * h);
  // The first substep starts where substepsForBodySpeed() looked, with the
  // same body pose, within a reach at least this one: its nearest contacts
  // are these ones where they are closer than `radius` (and none otherwise).
  const bool reuse = firstOfStep && approachReach_ >= radius;
  if (!reuse) findNearestBody(radius, substepContacts_, substepFound_);
  const std::vector<BodyContact>& contacts = reuse ? stepStartContacts_ : substepContacts_;
  const std::vector<uint8_t>& found = reuse ? stepStartFound_ : substepFound_;
  approachNormal_.assign(state_.size(), glm::vec3(0.0f));
  approachSpeed_.assign(state_.size(), 0.0f);
  approachVelocity_.assign(state_.size(), glm::vec3(0.0f));
  forRange(state_.size(), [&](size_t b, size_t e) {
    for (size_t i = b; i < e; ++i) {
      const BodyContact& contact = contacts[i];
      if (!found[i] || contact.signedDistance < 0.0f || !(contact.signedDistance < radius)) continue;
      const float surfaceSpeed = glm::dot(contact.velocity, contact.normal);
      if (surfaceSpeed <= 0.0f) continue;  // not coming towards the vertex
      const float needed = surfaceSpeed - (contact.signedDistance - thickness) / h;
      if (glm::dot(state_.v[i], contact.normal) >= needed) continue;
      // The limb grips what it hits: the vertex takes the surface's
      // tangential velocity too (sticking friction), so a trouser leg turns
      // with the swinging leg instead of being dragged back over it.
      const glm::vec3 relative = state_.v[i] - contact.velocity;
      state_.v[i] -= relative - glm::dot(relative, contact.normal) * contact.normal;
      approachNormal_[i] = contact.normal;
      approachSpeed_[i] = needed;
      approachVelocity_[i] = contact.velocity;
    }
  });
}

// Coulomb friction for vertices resting on a surface (their normal velocity
// is held by the solver, so the contact response sees no approach): the
// tangential velocity relative to the surface shrinks by mu times the normal
// velocity change gravity would have caused in the step, and stops when smaller.
void ClothSimulator::applyRestingFriction(float h) {
  if (state_.contactNormal.empty()) return;
  const float mu = settings_.friction;
  forRange(state_.size(), [&](size_t b, size_t e) {
    for (size_t i = b; i < e; ++i) {
      const glm::vec3& n = state_.contactNormal[i];
      if (n == glm::vec3(0.0f) || state_.invMass[i] == 0.0f) continue;
      const glm::vec3 rel = state_.v[i] - restingSurfaceVelocity_[i];
      const glm::vec3 tangential = rel - glm::dot(rel, n) * n;
      const float speed = glm::length(tangential);
      const float pressure = std::max(0.0f, -glm::dot(settings_.gravity, n)) * h;
      const float kept = speed > 0.0f ? std::max(0.0f, 1.0f - mu * pressure / speed) : 0.0f;
      state_.v[i] -= (1.0f - kept) * tangential;
      // Re-integrate the position with the new velocity (x = x0 + h v).
      state_.x[i] = stepStart_[i] + h * state_.v[i];
    }
  });
}

void ClothSimulator::placePins() {
  for (const Pin& p : pins_)
    state_.x[p.vertex] = p.bodyVertex >= 0 ? body_.positions()[p.bodyVertex] + p.offset : p.target;
}

void ClothSimulator::collideWithColliders() {
  const float thickness = settings_.collisionThickness;
  forRange(state_.size(), [&](size_t b, size_t e) {
    for (size_t i = b; i < e; ++i) {
      if (state_.invMass[i] == 0.0f) continue;
      for (const PrimitiveCollider& c : colliders_) {
        // A vertex that entered during the step goes back to where it entered
        // (continuous), not to the nearest surface point, which for a fast
        // vertex can be on the far side.
        glm::vec3 n;
        const glm::vec3 entry = firstContactAlong(c, stepStart_[i], state_.x[i], thickness);
        if (entry != state_.x[i]) state_.x[i] = entry;
        const float d = c.signedDistance(state_.x[i], n);
        if (d < thickness) touched_[i] = std::max(touched_[i], kContact);
        if (d < thickness)
          respondToContact(state_.x[i], state_.v[i], n, thickness - d, glm::vec3(0.0f),
                           c.friction >= 0.0f ? c.friction : settings_.friction);
      }
      if (body_.empty()) continue;
      BodyContact contact;
      if (body_.firstHitAlong(stepStart_[i], state_.x[i], contact, bodyQueries_[i])) {
        state_.x[i] = contact.point;
        touched_[i] = body_.moved() ? kSweptContact : std::max(touched_[i], kContact);
      }
      if (nearestBodyContact(i, body_.searchRadius(), contact) && contact.signedDistance < thickness) {
        touched_[i] = std::max(touched_[i], kContact);
        respondToContact(state_.x[i], state_.v[i], contact.normal, thickness - contact.signedDistance, contact.velocity,
                         settings_.friction);
      }
    }
  });
}

void ClothSimulator::checkFinite(const char* where) const {
  for (size_t i = 0; i < state_.size(); ++i) {
    const glm::vec3 &x = state_.x[i], &v = state_.v[i];
    if (!std::isfinite(x.x + x.y + x.z) || !std::isfinite(v.x + v.y + v.z))
      throw ClothDiverged(
          "cloth simulation diverged " + std::string(where) + " (step " + std::to_string(stats_.steps + 1) +
          "): vertex " + std::to_string(i) +
          " has a non-finite position or velocity; try the implicit integrator, more substeps or a softer fabric");
  }
}

// Results -------------------------------------------------------------------

std::vector<float> ClothSimulator::flatPositions() const {
  std::vector<float> flat(3 * state_.size());
  for (size_t i = 0; i < state_.size(); ++i) {
    flat[3 * i] = state_.x[i].x;
    flat[3 * i + 1] = state_.x[i].y;
    flat[3 * i + 2] = state_.x[i].z;
  }
  return flat;
}

double ClothSimulator::kineticEnergy() const {
  return deterministicSum(state_.size(), [&](size_t i) {
    return 0.5 * double(state_.mass[i]) * double(glm::dot(state_.v[i], state_.v[i]));
  });
}

double ClothSimulator::potentialEnergy() const { return forces_->potentialEnergy(state_); }

float ClothSimulator::currentMaxStretch() const {
  return maxStretchOf(state_.x, forces_->springs().springs(), forces_->structuralCount());
}

int ClothSimulator::countPenetrating() const {
  return int(deterministicSum(state_.size(), [&](size_t i) {
    bool inside = false;
    for (const PrimitiveCollider& c : colliders_) {
      glm::vec3 n;
      inside = inside || c.signedDistance(state_.x[i], n) < 0.0f;
    }
    BodyContact contact;
    if (!inside && !body_.empty() &&
        body_.nearestContactSince(state_.x[i], contact, body_.searchRadius(), bodyQueries_[i]))
      inside = contact.signedDistance < 0.0f;
    return inside ? 1.0 : 0.0;
  }));
}

int ClothSimulator::penetratingVertices() const {
  if (penetrating_ < 0) penetrating_ = countPenetrating();
  return penetrating_;
}

void ClothSimulator::updateStats() {
  stats_.maxStretch = currentMaxStretch();
  stats_.maxStretchEver = std::max(stats_.maxStretchEver, stats_.maxStretch);
  penetrating_ = -1;
  glm::vec3 lo(1e30f), hi(-1e30f);
  for (const glm::vec3& x : state_.x) {
    lo = glm::min(lo, x);
    hi = glm::max(hi, x);
  }
  stats_.boundsMin = lo;
  stats_.boundsMax = hi;
}

}  // namespace mq::cloth
