#pragma once
// The garments of a scene document as `mannequin-cli simulate` steps them:
// sewn, welded, then playing with the body (the sheet of the "cloth"
// section stays in cmd_simulate.cpp).

#include <memory>
#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "core/garment/garment.h"
#include "core/io/rigged_export.h"
#include "sim/cloth/baked_cloth.h"
#include "sim/cloth/cloth_scene_io.h"
#include "sim/garment/garment_simulation.h"

namespace mq::cli {

// What the stats report over all cloth of a run, now.
struct ClothNow {
  float maxStretch = 1.0f;
  int penetratingVertices = 0;
  size_t vertices = 0;
  glm::vec3 boundsMin{1e30f}, boundsMax{-1e30f};
  void add(const cloth::ClothSimulator& sim, size_t vertexCount);
};

struct DressingResult {
  int steps = 0;
  double seconds = 0.0;  // wall time
};

class SimulatedGarments {
 public:
  // Throws FileError(documentPath, "garments[i]...: problem") for bad garments.
  // layered: each garment worn over those of lower layers (garment_layers.h),
  // stepped inner to outer; otherwise each on its own.
  SimulatedGarments(const nlohmann::json& garmentsSection, const cloth::ClothSceneSpec& spec,
                    const std::vector<float>& bodyPositions, const std::vector<uint32_t>& bodyTriangles,
                    const std::string& documentPath, bool layered = true);
  ~SimulatedGarments();

  bool empty() const { return sims_.empty(); }
  // Before the frames: dresses the garments as every path does
  // (sim/garment/dressing.h): each sewn on the rest body and carried to the
  // start pose, then settled together in layers. Bodies: flat positions, may be empty.
  DressingResult dress(const std::vector<float>& restBody, const std::vector<float>& startBody, float dt);
  // posedBody: the body at the end of the step (null: it stays put).
  void step(float dt, const std::vector<float>* posedBody);
  // After a frame (outside its timing): counts each garment's vertices inside
  // the garments under it (in layer order; counted with layers off too).
  void measureFrame();
  // The most vertices of all garments inside inner garments in any measured frame.
  int maxInsideInnerVertices() const { return maxInsideInnerTotal_; }
  // <dir>/garment<i>_<name>_<frame>.obj, one per garment, in garment-mesh order.
  void exportFrame(const std::string& dir, int frame) const;
  // Keeps this frame for exportPointCaches.
  void recordFrame(float fps);
  // The recorded frames, <dir>/garment<i>_<name>.pc2 and .obj per garment (BakedCloth::exportPointCache).
  void exportPointCaches(const std::string& dir) const;
  // The recorded frames, one surface per garment, coloured by its fabric.
  std::vector<BakedSurface> bakedSurfaces() const;
  void addTo(ClothNow& now) const;
  // Per garment: name, layer, vertices, welded, sewing_steps, seam_gap, max_stretch,
  // penetrating_vertices, inside_inner_vertices (now and max_: in any measured frame),
  // bent_edge_share (now and mean_: over the measured frames), bbox.
  nlohmann::json stats() const;
  // The wall time of each phase of the solver (cloth::ClothPhase), all garments, summed over step().
  const double* phaseSeconds() const { return phaseSeconds_; }

 private:
  std::vector<Garment> garments_;
  std::vector<std::unique_ptr<cloth::GarmentSimulation>> sims_;
  int insideInner(size_t garment) const;
  std::vector<size_t> order_;  // inner to outer (garment_layers.h)
  bool layered_ = true;
  std::vector<int> maxInsideInner_;  // per garment, over measureFrame()
  int maxInsideInnerTotal_ = 0;
  std::vector<int> sewingSteps_;  // per garment: steps sewing on the rest body (in dress())
  std::vector<long long> substeps_, stretchPasses_, solverIterations_;  // per garment, summed over step()
  std::vector<std::vector<float>> residuals_;                           // per garment: each step()'s solver residual
  double phaseSeconds_[cloth::kClothPhaseCount] = {};                   // all garments, summed over step()
  int frames_ = 0;
  // How crinkled: the share of interior edges bent more than kBentDegrees (core/mesh/bent_edges.h).
  static constexpr float kBentDegrees = 15.0f;
  std::vector<double> bentShareSum_;  // per garment, over measureFrame()
  int measuredFrames_ = 0;
  std::vector<cloth::BakedCloth> recorded_;  // per garment, by recordFrame
};

}  // namespace mq::cli
