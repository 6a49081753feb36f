#pragma once
// What the editor's garment tool draws over a garment besides the cloth
// shading: the garment coloured by stretch (shown instead of the shaded
// cloth while the overlay is on), and dots for pinned and selected vertices
// (drawn on top, so pins stay visible behind the cloth).

#include <cstdint>
#include <memory>
#include <vector>

class vtkActor;

namespace mq::render {

// Colour of a stretch ratio (edge length / rest): 1.0 and below neutral
// (light grey), rising through yellow to red at `redAt` (1.1 by default).
void stretchColor(float stretch, unsigned char rgb[3], float redAt = 1.1f);

class GarmentOverlay {
 public:
  GarmentOverlay();
  ~GarmentOverlay();
  GarmentOverlay(const GarmentOverlay&) = delete;
  GarmentOverlay& operator=(const GarmentOverlay&) = delete;

  vtkActor* stretchActor();
  vtkActor* pinActor();
  vtkActor* selectionActor();

  void setTriangles(const std::vector<uint32_t>& triangles);
  // Positions (3 per vertex) for the stretch mesh and the dots.
  void setPositions(const std::vector<float>& positions);
  // Per-vertex stretch ratios (empty: neutral everywhere).
  void setStretch(const std::vector<float>& stretch);
  void setPinned(const std::vector<uint32_t>& vertices);
  void setSelected(const std::vector<uint32_t>& vertices);
  void setStretchVisible(bool visible);
  void setDotsVisible(bool visible);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace mq::render
