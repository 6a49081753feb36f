#pragma once
// One garment simulated on an animated body, as the CLI, the editor and the
// benchmarks run it: the pattern's panels start placed around the body (in
// the pose they were placed for), the seams sew them during the first frames,
// then the seams are welded and the welded cloth goes on (see
// garment_sewing.h for the pieces).
//
// Sewing is gentle: no stiff seam springs; each seam pair's distance shrinks
// by at most sewingSpeed per second in the solver's position pass, solved
// with the elongation limit (ClothSimulator::sewSeams), and velocities decay
// while sewing. Seams within one panel (sleeve and trouser-leg tubes) close
// first, then all seams. The weld comes when every pair is within weldGap,
// when the gap has stopped shrinking for half a second, or after
// maxSewingSeconds. Keep the body still (step without posedBody) until
// welded() for the best fit.
//
// Everything a caller sees is in the garment mesh's vertex order (the
// unwelded GarmentMesh), before and after welding, so a viewer keeps one
// triangle list and pins saved in a scene document stay valid.
//
//   GarmentSimulation sim(buildGarmentMesh(shirt), settings, bodyRest, bodyTriangles);
//   sim.pinToBody(v);                        // optional
//   for each frame: sim.step(1 / 30.f, &posedBody); show sim.positions();

#include <cstdint>
#include <memory>
#include <vector>

#include "core/garment/fabric.h"
#include "core/garment/garment.h"
#include "sim/cloth/cloth_settings.h"
#include "sim/cloth/cloth_simulator.h"
#include "sim/cloth/collision/primitive_collider.h"

namespace mq::cloth {

struct GarmentSimulationSettings {
  ClothSettings cloth;
  Fabric fabric;
  float weldGap = 0.004f;            // m: seams weld once every seam pair is this close
  float maxSewingSeconds = 2.0f;     // simulated time after which the seams weld regardless
  float sewingSpeed = 0.5f;          // m/s: how fast a seam gap may shrink while sewing
  float sewingStretchRelief = 1.0f;  // the elongation limit is this much looser while sewing
};

class GarmentSimulation {
 public:
  // bodyPositions (3 per vertex) and bodyTriangles may be empty: no body.
  GarmentSimulation(const GarmentMesh& garment, const GarmentSimulationSettings& settings,
                    const std::vector<float>& bodyPositions, const std::vector<uint32_t>& bodyTriangles);
  ~GarmentSimulation();

  void addCollider(const PrimitiveCollider& collider);
  // Replaces the colliders, keeping the cloth's state (a collider dragged while it runs).
  void setColliders(const std::vector<PrimitiveCollider>& colliders);
  // Pins, in garment-mesh vertex indices; kept across the weld.
  void pin(uint32_t garmentVertex);        // fixed in space where it is now
  void pinToBody(uint32_t garmentVertex);  // follows the nearest body vertex
  const std::vector<uint32_t>& pinnedVertices() const;

  // Layering: the garments this one is worn over (sim/garment/garment_layers.h).
  // One-way: they do not feel this one, so step them first in each frame;
  // each step then collides this garment with their surfaces as they moved
  // in their last step. In effect once this garment and an inner one are
  // welded (sewing panels have open seams, not hems). They must outlive this
  // simulation or be replaced; {}: none.
  void setInnerGarments(std::vector<const GarmentSimulation*> inner);

  // Advances dt seconds. posedBody (same vertices as the body given at
  // construction) is the body at the end of the step; null: it stays put.
  // Throws ClothDiverged when the state stops being finite.
  void step(float dt, const std::vector<float>* posedBody = nullptr);

  bool welded() const;
  float seamGap() const;                     // largest open seam gap now (0 once welded)
  std::vector<float> positions() const;      // 3 per garment-mesh vertex
  std::vector<float> vertexStretch() const;  // per garment-mesh vertex: largest length / rest of its structural springs
  const std::vector<uint32_t>& triangles() const;  // the garment mesh's
  size_t vertexCount() const;                      // garment-mesh vertices
  const ClothStats& stats() const;                 // of the running solver
  const ClothSimulator& simulator() const;         // sewing solver, then the welded one

  // A welded simulation's state, to continue another simulation built the
  // same way (same garment mesh, settings, body, colliders and pins) from
  // there without sewing again: the editor keeps one per garment between
  // bakes and live runs.
  struct Snapshot {
    std::vector<glm::vec3> weldPositions;  // garment-mesh positions when the seams were welded
    ClothState state;                      // of the welded solver
    std::vector<float> body;               // the body then (flat), empty: none
  };
  // Continues from a drape kept from an earlier run of this garment (with
  // another fabric, other pins or another pattern mapped onto this mesh)
  // instead of sewing flat panels: the seams weld where `positions` put
  // them, the cloth starts at rest, and every pin holds the cloth where the
  // drape has it (a body pin follows the body vertex nearest its draped
  // place), so pins chosen on a drape do not stretch it. `body` is the body
  // the drape lies on (as at construction; empty when there is none). Call
  // before the first step. Throws Error when the sizes do not fit.
  void startFromDrape(const std::vector<float>& positions, const std::vector<float>& body);

  // Throws Error before the weld.
  Snapshot snapshot() const;
  // Welds as this simulation did (so pins keep their offsets), then takes the
  // state and the body. Throws Error when the snapshot's sizes do not fit.
  void restore(const Snapshot& snapshot);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace mq::cloth
