#pragma once
// A garment's drape kept while its cloth does not run: what the viewport
// shows after an edit or an undo (instead of the flat placed panels), and
// where the next Simulate or Bake starts (GarmentSimulation::startFromDrape).

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "core/garment/garment.h"
#include "core/geometry/rigid_carry.h"

namespace mq::ui {

class HeldDrape {
 public:
  // positions: 3 per garment-mesh vertex; body: the body they lie on (flat), empty: none.
  HeldDrape(std::vector<float> positions, std::vector<float> body) : carry_(std::move(positions), std::move(body)) {}

  const std::vector<float>& positions() const { return carry_.points(); }
  const std::vector<float>& body() const { return carry_.from(); }
  // The drape on the body posed otherwise, for showing it while the cloth
  // does not run: each vertex follows the rigid motion of the body around it.
  std::vector<float> carriedTo(const std::vector<float>& posedBody) const { return carry_.carry(posedBody); }
  // The same drape on the garment's rebuilt mesh (core/garment/drape_transfer.h).
  HeldDrape rebuiltAs(const GarmentMesh& before, const GarmentMesh& after) const;
  bool fits(const GarmentMesh& mesh) const { return positions().size() == 3 * mesh.vertexCount(); }

 private:
  RigidCarry carry_;
};

// The drapes of the last few garment states, newest first, by the state's
// key: an undo returns to a state and finds its drape.
class DrapeMemory {
 public:
  void remember(const std::string& key, const HeldDrape& drape);
  const HeldDrape* recall(const std::string& key) const;
  void clear() { kept_.clear(); }

 private:
  static constexpr size_t kKept = 16;
  std::vector<std::pair<std::string, HeldDrape>> kept_;
};

}  // namespace mq::ui
