#include "sim/garment/garment_simulation.h"

#include <algorithm>
#include <cmath>

#include "core/geometry/nearest_points.h"
#include "core/util/error.h"
#include "sim/cloth/collision/cloth_surface_collider.h"
#include "sim/garment/garment_sewing.h"

namespace mq::cloth {

namespace {

// While sewing, velocities decay with this time constant: the cloth creeps
// into place instead of swinging from the seams' pull.
constexpr float kSewingVelocityDecaySeconds = 0.05f;
constexpr float kStallSeconds = 0.5f;

uint32_t nearestVertex(const std::vector<float>& positions, glm::vec3 p) {
  uint32_t best = 0;
  float bestDistance = 1e30f;
  for (size_t i = 0; i < positions.size() / 3; ++i) {
    const float d = glm::dot(vec3At(positions, i) - p, vec3At(positions, i) - p);
    if (d < bestDistance) bestDistance = d, best = uint32_t(i);
  }
  return best;
}

}  // namespace

struct GarmentSimulation::Impl {
  GarmentSimulationSettings settings;
  ClothMesh mesh;                   // unwelded, with its seams
  std::vector<uint32_t> triangles;  // the garment mesh's
  std::vector<float> body;          // the body now (flat), empty: none
  std::vector<uint32_t> bodyTriangles;
  std::unique_ptr<ClothSimulator> sim;
  std::vector<PrimitiveCollider> colliders;
  bool welded = false;
  std::vector<glm::vec3> weldPositions;  // unwelded positions at the weld
  SeamWeld weld;                         // identity until welded
  struct Pin {
    uint32_t vertex;          // garment-mesh index
    int64_t bodyVertex = -1;  // >= 0: follows it
  };
  std::vector<Pin> pins;
  std::vector<uint32_t> pinned;  // garment-mesh indices, in pin order
  // Sewing in two stages: first the seams within a panel (a sleeve or a
  // trouser leg closing into a tube around its limb), then all of them. A
  // sleeve sewn to the armhole first would be turned level by the armhole's
  // shape and let the arm out through its open underside.
  std::vector<std::pair<uint32_t, uint32_t>> firstStage;
  bool allSeams = false;
  // Layering: the garments worn under this one, and their welded surfaces
  // as one collider (rebuilt when the set of welded solvers changes).
  std::vector<const GarmentSimulation*> inner;
  ClothSurfaceCollider innerSurface;
  std::vector<std::pair<const ClothSimulator*, size_t>> innerSurfaceSources;

  float sewingTime = 0.0f;
  float bestGap = 1e30f, bestGapTime = 0.0f;  // for stall detection

  void sewAll() {
    allSeams = true;
    sim->sewSeams(mesh.seams, settings.sewingSpeed, settings.sewingStretchRelief);
    bestGap = 1e30f, bestGapTime = sewingTime;
  }

  // The seams being sewn are as closed as they will get: closed, or the gap
  // has not shrunk by a millimetre for kStallSeconds (the body holds them).
  bool stageDone(float gap) {
    if (gap < bestGap - 1e-3f) bestGap = gap, bestGapTime = sewingTime;
    return gap <= settings.weldGap || sewingTime - bestGapTime > kStallSeconds;
  }

  uint32_t running(uint32_t garmentVertex) const { return welded ? weld.newIndex[garmentVertex] : garmentVertex; }

  void applyPin(const Pin& p) {
    if (p.bodyVertex >= 0)
      sim->pinToBodyVertex(running(p.vertex), uint32_t(p.bodyVertex));
    else
      sim->pinVertex(running(p.vertex));
  }

  // Before each step: the inner garments' surfaces where their last step put them.
  void updateInnerSurface(float dt) {
    std::vector<std::pair<const ClothSimulator*, size_t>> sources;
    if (welded)
      for (const GarmentSimulation* g : inner)
        if (g->welded()) sources.push_back({&g->simulator(), g->simulator().positions().size()});
    if (sources.empty()) {
      innerSurfaceSources.clear();
      sim->setInnerSurface(nullptr);
      return;
    }
    std::vector<glm::vec3> positions;
    for (const auto& [solver, count] : sources)
      positions.insert(positions.end(), solver->positions().begin(), solver->positions().end());
    if (sources != innerSurfaceSources) {
      std::vector<uint32_t> triangles;
      uint32_t offset = 0;
      for (const auto& [solver, count] : sources) {
        for (uint32_t v : solver->triangles()) triangles.push_back(v + offset);
        offset += uint32_t(count);
      }
      innerSurface.setMesh(positions, triangles);
      innerSurfaceSources = std::move(sources);
    } else {
      innerSurface.setTarget(positions, dt);
    }
    sim->setInnerSurface(&innerSurface);
  }

  void weldNow() {
    weldPositions = sim->positions();
    WeldedCloth w = weldClothSeams(mesh, buildClothTopology(mesh));
    std::unique_ptr<ClothSimulator> next = continueWelded(*sim, w, settings.fabric, &settings.cloth);
    // A fixed pin keeps its target (where it was pinned), not where the weld averaged it.
    std::vector<std::pair<uint32_t, glm::vec3>> fixedTargets;
    for (const Pin& p : pins)
      if (p.bodyVertex < 0) fixedTargets.push_back({w.weld.newIndex[p.vertex], sim->positions()[p.vertex]});
    sim = std::move(next);
    weld = std::move(w.weld);
    welded = true;
    if (!body.empty()) sim->setBody(body, bodyTriangles);
    for (const Pin& p : pins)
      if (p.bodyVertex >= 0) applyPin(p);
    for (const auto& [v, target] : fixedTargets) sim->pinVertex(v, target);
  }
};

GarmentSimulation::GarmentSimulation(const GarmentMesh& garment, const GarmentSimulationSettings& settings,
                                     const std::vector<float>& bodyPositions,
                                     const std::vector<uint32_t>& bodyTriangles)
    : impl_(std::make_unique<Impl>()) {
  Impl& m = *impl_;
  m.settings = settings;
  if (!(settings.weldGap >= 0.0f) || !std::isfinite(settings.weldGap)) throw Error("garment weld gap must be >= 0");
  if (!(settings.maxSewingSeconds >= 0.0f) || !std::isfinite(settings.maxSewingSeconds))
    throw Error("garment sewing time must be >= 0");
  if (!(settings.sewingSpeed > 0.0f) || !std::isfinite(settings.sewingSpeed))
    throw Error("garment sewing speed must be positive");
  if (bodyPositions.size() % 3 != 0 || bodyTriangles.size() % 3 != 0)
    throw Error("garment body needs 3 floats per vertex and 3 indices per triangle");
  m.mesh = clothMeshFromGarment(garment);
  for (const auto& [a, b] : m.mesh.seams)
    if (a < garment.panelIds.size() && b < garment.panelIds.size() && garment.panelIds[a] == garment.panelIds[b])
      m.firstStage.push_back({a, b});
  m.triangles = garment.triangles;
  // The sewing solver gets no seam springs: the seams close in its position pass.
  ClothMesh unsewn = m.mesh;
  unsewn.seams.clear();
  // Gentle sewing is tuned to the block-Jacobi solve, which leaves the panels'
  // large slow motions out at its iteration cap (sewn with the two-level one,
  // the walking T-shirt ends with vertices in the body).
  ClothSettings sewingCloth = settings.cloth;
  sewingCloth.cgPreconditioner = CgPreconditioner::BlockJacobi;
  m.sim = std::make_unique<ClothSimulator>(unsewn, buildClothTopology(unsewn), settings.fabric, sewingCloth);
  m.weld = computeSeamWeld(m.mesh.vertexCount(), {});
  if (!bodyTriangles.empty()) {
    m.body = bodyPositions;
    m.bodyTriangles = bodyTriangles;
    m.sim->setBody(m.body, m.bodyTriangles);
  }
  if (m.mesh.seams.empty())
    m.weldNow();  // nothing to sew: the same mesh, welded state from the start
  else if (m.firstStage.empty())
    m.sewAll();
  else
    m.sim->sewSeams(m.firstStage, settings.sewingSpeed, settings.sewingStretchRelief);
}

GarmentSimulation::~GarmentSimulation() = default;

void GarmentSimulation::addCollider(const PrimitiveCollider& collider) {
  impl_->colliders.push_back(collider);
  impl_->sim->addCollider(collider);
}

void GarmentSimulation::setColliders(const std::vector<PrimitiveCollider>& colliders) {
  impl_->colliders = colliders;
  impl_->sim->setColliders(colliders);
}

void GarmentSimulation::pin(uint32_t garmentVertex) {
  Impl& m = *impl_;
  if (garmentVertex >= vertexCount())
    throw Error("pinned garment vertex " + std::to_string(garmentVertex) + " out of range");
  m.pins.erase(
      std::remove_if(m.pins.begin(), m.pins.end(), [&](const Impl::Pin& p) { return p.vertex == garmentVertex; }),
      m.pins.end());
  m.pins.push_back({garmentVertex, -1});
  m.applyPin(m.pins.back());
  m.pinned.clear();
  for (const Impl::Pin& p : m.pins) m.pinned.push_back(p.vertex);
}

void GarmentSimulation::pinToBody(uint32_t garmentVertex) {
  Impl& m = *impl_;
  if (garmentVertex >= vertexCount())
    throw Error("pinned garment vertex " + std::to_string(garmentVertex) + " out of range");
  if (m.body.empty()) throw Error("cannot pin a garment vertex to the body: the simulation has no body");
  m.pins.erase(
      std::remove_if(m.pins.begin(), m.pins.end(), [&](const Impl::Pin& p) { return p.vertex == garmentVertex; }),
      m.pins.end());
  const glm::vec3 at = m.sim->positions()[m.running(garmentVertex)];
  m.pins.push_back({garmentVertex, int64_t(nearestVertex(m.body, at))});
  m.applyPin(m.pins.back());
  m.pinned.clear();
  for (const Impl::Pin& p : m.pins) m.pinned.push_back(p.vertex);
}

const std::vector<uint32_t>& GarmentSimulation::pinnedVertices() const { return impl_->pinned; }

void GarmentSimulation::step(float dt, const std::vector<float>* posedBody) {
  Impl& m = *impl_;
  if (posedBody) {
    if (m.body.empty()) throw Error("a posed body was given to a garment simulation without a body");
    if (posedBody->size() != m.body.size()) throw Error("posed body has a different vertex count");
    m.sim->updateBody(*posedBody);
  }
  m.updateInnerSurface(dt);
  m.sim->step(dt);
  if (posedBody) m.body = *posedBody;
  if (m.welded) return;
  const float keep = std::exp(-dt / kSewingVelocityDecaySeconds);
  for (glm::vec3& v : m.sim->mutableState().v) v *= keep;
  m.sewingTime += dt;
  const bool outOfTime = m.sewingTime >= m.settings.maxSewingSeconds;
  if (!m.allSeams) {
    if (m.stageDone(maxSeamGap(m.sim->positions(), m.firstStage)) || outOfTime) m.sewAll();
    if (!outOfTime) return;
  }
  if (m.stageDone(maxSeamGap(m.sim->positions(), m.mesh.seams)) || outOfTime) m.weldNow();
}

void GarmentSimulation::setInnerGarments(std::vector<const GarmentSimulation*> inner) {
  for (const GarmentSimulation* g : inner)
    if (g == this || !g) throw Error("a garment cannot be worn over itself or over nothing");
  impl_->inner = std::move(inner);
}

bool GarmentSimulation::welded() const { return impl_->welded; }

float GarmentSimulation::seamGap() const {
  return impl_->welded ? 0.0f : maxSeamGap(impl_->sim->positions(), impl_->mesh.seams);
}

std::vector<float> GarmentSimulation::positions() const {
  const Impl& m = *impl_;
  const std::vector<glm::vec3>& x = m.sim->positions();
  std::vector<float> out(3 * vertexCount());
  for (size_t i = 0; i < vertexCount(); ++i) {
    const glm::vec3& p = x[m.running(uint32_t(i))];
    out[3 * i] = p.x, out[3 * i + 1] = p.y, out[3 * i + 2] = p.z;
  }
  return out;
}

std::vector<float> GarmentSimulation::vertexStretch() const {
  const Impl& m = *impl_;
  const std::vector<glm::vec3>& x = m.sim->positions();
  const auto& springs = m.sim->forces().springs().springs();
  std::vector<float> running(x.size(), 1.0f);
  for (size_t k = 0; k < m.sim->forces().structuralCount(); ++k) {
    const Spring& s = springs[k];
    if (!(s.rest > 0.0f)) continue;
    const float stretch = glm::length(x[s.a] - x[s.b]) / s.rest;
    running[s.a] = std::max(running[s.a], stretch);
    running[s.b] = std::max(running[s.b], stretch);
  }
  std::vector<float> out(vertexCount());
  for (size_t i = 0; i < out.size(); ++i) out[i] = running[m.running(uint32_t(i))];
  return out;
}

const std::vector<uint32_t>& GarmentSimulation::triangles() const { return impl_->triangles; }
size_t GarmentSimulation::vertexCount() const { return impl_->mesh.vertexCount(); }
const ClothStats& GarmentSimulation::stats() const { return impl_->sim->stats(); }
const ClothSimulator& GarmentSimulation::simulator() const { return *impl_->sim; }

void GarmentSimulation::startFromDrape(const std::vector<float>& positions, const std::vector<float>& body) {
  Impl& m = *impl_;
  if (positions.size() != 3 * vertexCount()) throw Error("the drape is of another garment mesh");
  if (body.size() != m.body.size()) throw Error("the drape's body has a different vertex count");
  for (float value : positions)
    if (!std::isfinite(value)) throw Error("the drape has a non-finite position");
  if (!m.body.empty()) {
    m.body = body;
    m.sim->setBody(m.body, m.bodyTriangles);
  }
  // Pins are re-anchored where the drape has them, before the weld applies
  // them: each body pin to the body vertex nearest its draped place.
  std::vector<float> bodyPinned;
  for (const Impl::Pin& p : m.pins)
    if (p.bodyVertex >= 0) bodyPinned.insert(bodyPinned.end(), &positions[3 * p.vertex], &positions[3 * p.vertex] + 3);
  const std::vector<uint32_t> nearest = nearestPoints(bodyPinned, m.body, 1);
  size_t next = 0;
  for (Impl::Pin& p : m.pins)
    if (p.bodyVertex >= 0) p.bodyVertex = int64_t(nearest[next++]);
  ClothState& state = m.sim->mutableState();
  for (size_t i = 0; i < vertexCount(); ++i) state.x[m.running(uint32_t(i))] = vec3At(positions, i);
  if (!m.welded) {
    m.weldNow();
  } else {  // a garment without seams: welded from the start, pins re-applied here
    for (const Impl::Pin& p : m.pins)
      if (p.bodyVertex >= 0)
        m.applyPin(p);
      else
        m.sim->pinVertex(m.running(p.vertex), vec3At(positions, p.vertex));
  }
  for (glm::vec3& v : m.sim->mutableState().v) v = glm::vec3(0.0f);
}

GarmentSimulation::Snapshot GarmentSimulation::snapshot() const {
  const Impl& m = *impl_;
  if (!m.welded) throw Error("a garment simulation can only be saved once its seams are welded");
  return {m.weldPositions, m.sim->state(), m.body};
}

void GarmentSimulation::restore(const Snapshot& s) {
  Impl& m = *impl_;
  if (s.weldPositions.size() != m.mesh.vertexCount() || s.body.size() != m.body.size())
    throw Error("the garment snapshot is of another garment or body");
  if (!m.welded) {
    m.sim->mutableState().x = s.weldPositions;
    m.weldNow();
  }
  if (s.state.size() != m.sim->state().size()) throw Error("the garment snapshot is of another garment");
  m.sim->mutableState() = s.state;
  if (!m.body.empty()) {
    m.body = s.body;
    m.sim->setBody(m.body, m.bodyTriangles);
  }
}

}  // namespace mq::cloth
