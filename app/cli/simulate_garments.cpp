#include "app/cli/simulate_garments.h"

#include <cctype>
#include <filesystem>

#include <nlohmann/json.hpp>

#include "core/garment/garment_json.h"
#include "core/util/error.h"
#include "sim/cloth/baked_cloth.h"
#include "sim/garment/garment_scene.h"

namespace mq::cli {

namespace {

std::string fileStem(const Garment& garment, size_t index) {
  std::string stem = "garment" + std::to_string(index);
  if (!garment.name.empty()) stem += "_";
  for (char c : garment.name) stem += std::isalnum(static_cast<unsigned char>(c)) || c == '-' ? c : '_';
  return stem;
}

}  // namespace

void ClothNow::add(const cloth::ClothStats& stats, size_t vertexCount) {
  maxStretch = std::max(maxStretch, stats.maxStretch);
  penetratingVertices += stats.penetratingVertices;
  vertices += vertexCount;
  boundsMin = glm::min(boundsMin, stats.boundsMin);
  boundsMax = glm::max(boundsMax, stats.boundsMax);
}

SimulatedGarments::SimulatedGarments(const nlohmann::json& section, const cloth::ClothSceneSpec& spec,
                                     const std::vector<float>& bodyPositions,
                                     const std::vector<uint32_t>& bodyTriangles, const std::string& documentPath) {
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
  weldFrame_.assign(sims_.size(), -1);
}

SimulatedGarments::~SimulatedGarments() = default;

void SimulatedGarments::step(float dt, const std::vector<float>* posedBody) {
  ++steps_;
  for (size_t i = 0; i < sims_.size(); ++i) {
    sims_[i]->step(dt, posedBody);
    if (weldFrame_[i] < 0 && sims_[i]->welded()) weldFrame_[i] = steps_;
  }
}

void SimulatedGarments::exportFrame(const std::string& dir, int frame) const {
  for (size_t i = 0; i < sims_.size(); ++i)
    cloth::writeObj((std::filesystem::path(dir) / cloth::objFrameName(fileStem(garments_[i], i), size_t(frame))).string(),
                    sims_[i]->positions(), sims_[i]->triangles());
}

void SimulatedGarments::addTo(ClothNow& now) const {
  for (const auto& sim : sims_) now.add(sim->stats(), sim->vertexCount());
}

nlohmann::json SimulatedGarments::stats() const {
  nlohmann::json out = nlohmann::json::array();
  for (size_t i = 0; i < sims_.size(); ++i) {
    const cloth::GarmentSimulation& sim = *sims_[i];
    const cloth::ClothStats& st = sim.stats();
    out.push_back({{"name", garments_[i].name},
                   {"vertices", sim.vertexCount()},
                   {"welded", sim.welded()},
                   {"welded_after_frames", weldFrame_[i]},
                   {"seam_gap", sim.seamGap()},
                   {"max_stretch", st.maxStretch},
                   {"penetrating_vertices", st.penetratingVertices},
                   {"bbox_min", {st.boundsMin.x, st.boundsMin.y, st.boundsMin.z}},
                   {"bbox_max", {st.boundsMax.x, st.boundsMax.y, st.boundsMax.z}}});
  }
  return out;
}

}  // namespace mq::cli
