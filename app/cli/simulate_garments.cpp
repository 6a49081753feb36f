#include "app/cli/simulate_garments.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>

#include <nlohmann/json.hpp>

#include "core/garment/fabric_color.h"
#include "core/garment/garment_json.h"
#include "core/mesh/bent_edges.h"
#include "core/util/error.h"
#include "sim/cloth/baked_cloth.h"
#include "sim/garment/dressing.h"
#include "sim/garment/garment_layers.h"
#include "sim/garment/garment_scene.h"

namespace mq::cli {

namespace {

float median(std::vector<float> values) {
  if (values.empty()) return 0.0f;
  std::nth_element(values.begin(), values.begin() + values.size() / 2, values.end());
  return values[values.size() / 2];
}

}  // namespace

void ClothNow::add(const cloth::ClothSimulator& sim, size_t vertexCount) {
  const cloth::ClothStats& stats = sim.stats();
  maxStretch = std::max(maxStretch, stats.maxStretch);
  penetratingVertices += sim.penetratingVertices();
  vertices += vertexCount;
  boundsMin = glm::min(boundsMin, stats.boundsMin);
  boundsMax = glm::max(boundsMax, stats.boundsMax);
}

SimulatedGarments::SimulatedGarments(const nlohmann::json& section, const cloth::ClothSceneSpec& spec,
                                     const std::vector<float>& bodyPositions,
                                     const std::vector<uint32_t>& bodyTriangles, const std::string& documentPath,
                                     bool layered)
    : layered_(layered) {
  try {
    garments_ = garmentsFromJson(section);
    for (size_t i = 0; i < garments_.size(); ++i)
      sims_.push_back(cloth::makeGarmentSimulation(garments_[i], spec, bodyPositions, bodyTriangles,
                                                   "garments[" + std::to_string(i) + "]"));
  } catch (const FileError&) {
    throw;
  } catch (const Error& e) {
    throw FileError(documentPath, e.what());
  }
  order_ = cloth::layerOrder(garments_);
  cloth::wearInLayers(sims_, order_, layered_);
  maxInsideInner_.assign(sims_.size(), 0);
  bentShareSum_.assign(sims_.size(), 0.0);
  sewingSteps_.assign(sims_.size(), 0);
  substeps_.assign(sims_.size(), 0);
  stretchPasses_.assign(sims_.size(), 0);
  solverIterations_.assign(sims_.size(), 0);
  residuals_.assign(sims_.size(), {});
}

SimulatedGarments::~SimulatedGarments() = default;

DressingResult SimulatedGarments::dress(const std::vector<float>& restBody, const std::vector<float>& startBody,
                                        float dt) {
  const auto t0 = std::chrono::steady_clock::now();
  std::vector<cloth::GarmentSimulation*> simulations;
  for (const auto& sim : sims_) simulations.push_back(sim.get());
  const std::vector<cloth::DrapeSteps> steps =
      cloth::dressGarments(simulations, order_, restBody, startBody, dt, [this](size_t) { return layered_; });
  DressingResult r;
  for (size_t i = 0; i < steps.size(); ++i) {
    sewingSteps_[i] = steps[i].sewing;
    r.steps = std::max(r.steps, steps[i].total);
  }
  r.steps += int(std::ceil(cloth::kDressingSettleSeconds / dt));
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return r;
}

void SimulatedGarments::step(float dt, const std::vector<float>* posedBody) {
  ++frames_;
  for (size_t i : order_) {
    sims_[i]->step(dt, posedBody);
    substeps_[i] += sims_[i]->stats().substeps;
    stretchPasses_[i] += sims_[i]->stats().stretchPasses;
    solverIterations_[i] += sims_[i]->stats().solverIterations;
    residuals_[i].push_back(sims_[i]->stats().solverResidual);
    for (int k = 0; k < cloth::kClothPhaseCount; ++k) phaseSeconds_[k] += sims_[i]->stats().phaseSeconds[k];
  }
}

int SimulatedGarments::insideInner(size_t garment) const {
  std::vector<const cloth::GarmentSimulation*> inner;
  for (size_t k = 0; k < order_.size() && order_[k] != garment; ++k) inner.push_back(sims_[order_[k]].get());
  return cloth::verticesInside(*sims_[garment], inner);
}

void SimulatedGarments::measureFrame() {
  int total = 0;
  for (size_t i = 0; i < sims_.size(); ++i) {
    const int inside = insideInner(i);
    maxInsideInner_[i] = std::max(maxInsideInner_[i], inside);
    total += inside;
    bentShareSum_[i] += bentEdges(sims_[i]->positions(), sims_[i]->triangles(), kBentDegrees).share();
  }
  maxInsideInnerTotal_ = std::max(maxInsideInnerTotal_, total);
  ++measuredFrames_;
}

void SimulatedGarments::exportFrame(const std::string& dir, int frame) const {
  for (size_t i = 0; i < sims_.size(); ++i)
    cloth::writeObj(
        (std::filesystem::path(dir) / cloth::objFrameName(cloth::garmentFileStem(garments_[i].name, i), size_t(frame)))
            .string(),
        sims_[i]->positions(), sims_[i]->triangles());
}

void SimulatedGarments::recordFrame(float fps) {
  if (recorded_.empty())
    for (const auto& sim : sims_) recorded_.emplace_back(sim->triangles(), fps);
  for (size_t i = 0; i < sims_.size(); ++i) recorded_[i].addFrame(sims_[i]->positions());
}

void SimulatedGarments::exportPointCaches(const std::string& dir) const {
  for (size_t i = 0; i < recorded_.size(); ++i)
    recorded_[i].exportPointCache(dir, cloth::garmentFileStem(garments_[i].name, i));
}

std::vector<BakedSurface> SimulatedGarments::bakedSurfaces() const {
  std::vector<BakedSurface> surfaces;
  for (size_t i = 0; i < recorded_.size(); ++i) {
    BakedSurface s;
    s.name = garments_[i].name;
    s.triangles = recorded_[i].triangles();
    for (size_t f = 0; f < recorded_[i].frameCount(); ++f) s.frames.push_back(recorded_[i].frame(f));
    s.color = glm::vec4(fabricColor(garments_[i].fabric), 1.0f);
    surfaces.push_back(std::move(s));
  }
  return surfaces;
}

void SimulatedGarments::addTo(ClothNow& now) const {
  for (const auto& sim : sims_) now.add(sim->simulator(), sim->vertexCount());
}

nlohmann::json SimulatedGarments::stats() const {
  nlohmann::json out = nlohmann::json::array();
  for (size_t i = 0; i < sims_.size(); ++i) {
    const cloth::GarmentSimulation& sim = *sims_[i];
    const cloth::ClothStats& st = sim.stats();
    out.push_back({{"name", garments_[i].name},
                   {"layer", garments_[i].layer},
                   {"layer_order", size_t(std::find(order_.begin(), order_.end(), i) - order_.begin())},
                   {"inside_inner_vertices", insideInner(i)},
                   {"max_inside_inner_vertices", maxInsideInner_[i]},
                   {"vertices", sim.vertexCount()},
                   {"welded", sim.welded()},
                   {"sewing_steps", sewingSteps_[i]},
                   {"substeps_per_frame", frames_ ? double(substeps_[i]) / frames_ : 0.0},
                   {"stretch_passes_per_frame", frames_ ? double(stretchPasses_[i]) / frames_ : 0.0},
                   {"cg_iterations_per_frame", frames_ ? double(solverIterations_[i]) / frames_ : 0.0},
                   {"cg_residual_median", median(residuals_[i])},
                   {"cg_residual_max",
                    residuals_[i].empty() ? 0.0f : *std::max_element(residuals_[i].begin(), residuals_[i].end())},
                   {"seam_gap", sim.seamGap()},
                   {"bent_edge_share", bentEdges(sim.positions(), sim.triangles(), kBentDegrees).share()},
                   {"mean_bent_edge_share", measuredFrames_ ? bentShareSum_[i] / measuredFrames_ : 0.0},
                   {"max_stretch", st.maxStretch},
                   {"penetrating_vertices", sim.simulator().penetratingVertices()},
                   {"bbox_min", {st.boundsMin.x, st.boundsMin.y, st.boundsMin.z}},
                   {"bbox_max", {st.boundsMax.x, st.boundsMax.y, st.boundsMax.z}}});
  }
  return out;
}

}  // namespace mq::cli
