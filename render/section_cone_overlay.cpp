#include "render/section_cone_overlay.h"

#include <algorithm>
#include <cmath>

#include <vtkActor.h>
#include <vtkCellArray.h>
#include <vtkMatrix4x4.h>
#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderer.h>
#include <vtkSmartPointer.h>

#include "core/character/character.h"
#include "core/skinning/section_cones.h"

namespace mq::render {
namespace {

constexpr int kAround = 32;
constexpr double kOpacity = 0.35;
constexpr double kColour[3] = {0.25, 0.75, 1.0};

// The cone's memorised section at s along the bone (0 head, 1 tail), as the
// cones interpolate it between their bases (held beyond them).
glm::dvec3 sectionPoint(const SectionCone& cone, double s, double angle) {
  const double t =
      std::clamp((s - SectionCone::kBaseNear) / (SectionCone::kBaseFar - SectionCone::kBaseNear), 0.0, 1.0);
  const glm::dvec2 direction(std::cos(angle), std::sin(angle));
  const glm::dvec2 centre = (1.0 - t) * cone.minimum[0].center + t * cone.minimum[1].center;
  const double radius = (1.0 - t) * cone.minimum[0].radius(direction) + t * cone.minimum[1].radius(direction);
  const glm::dvec2 at = centre + radius * direction;
  return cone.head + s * cone.length * cone.axis + at.x * cone.side + at.y * cone.front;
}

vtkSmartPointer<vtkActor> coneActor(const SectionCone& cone) {
  // Between the two fitted bases only: beyond them the cone holds its base
  // (section_cones.h), which would poke out of a head or a foot.
  const double rings[] = {SectionCone::kBaseNear, 0.5 * (SectionCone::kBaseNear + SectionCone::kBaseFar),
                          SectionCone::kBaseFar};
  vtkNew<vtkPoints> points;
  for (double s : rings)
    for (int a = 0; a < kAround; ++a) {
      const glm::dvec3 p = sectionPoint(cone, s, 2.0 * M_PI * a / kAround);
      points->InsertNextPoint(p.x, p.y, p.z);
    }
  vtkNew<vtkCellArray> quads;
  for (vtkIdType r = 0; r + 1 < vtkIdType(std::size(rings)); ++r)
    for (vtkIdType a = 0; a < kAround; ++a) {
      const vtkIdType b = (a + 1) % kAround;
      const vtkIdType quad[4] = {r * kAround + a, r * kAround + b, (r + 1) * kAround + b, (r + 1) * kAround + a};
      quads->InsertNextCell(4, quad);
    }
  vtkNew<vtkPolyData> polyData;
  polyData->SetPoints(points);
  polyData->SetPolys(quads);
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputData(polyData);
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(mapper);
  actor->GetProperty()->SetColor(kColour[0], kColour[1], kColour[2]);
  actor->GetProperty()->SetOpacity(kOpacity);
  actor->GetProperty()->SetSpecular(0.2);
  actor->PickableOff();
  return actor;
}

}  // namespace

struct SectionConeOverlay::Impl {
  vtkRenderer* renderer = nullptr;
  struct Drawn {
    vtkSmartPointer<vtkActor> actor;
    vtkSmartPointer<vtkMatrix4x4> skinning;  // the actor's user matrix, rewritten per pose
    int bone = -1;
    glm::mat4 inverseBind{1.0f};
  };
  std::vector<Drawn> cones;
};

SectionConeOverlay::SectionConeOverlay(vtkRenderer* renderer) : impl_(std::make_unique<Impl>()) {
  impl_->renderer = renderer;
}

SectionConeOverlay::~SectionConeOverlay() { clear(); }

void SectionConeOverlay::build(const Character& character) {
  clear();
  std::vector<bool> helper(character.skeleton.boneCount(), false);
  for (const HelperBone& h : character.helperBones) helper[h.bone] = true;
  for (const Mesh& mesh : character.meshes) {
    if (mesh.skin.empty()) continue;
    const std::vector<SectionCone> cones = fitSectionCones(mesh, character.skeleton);
    for (size_t j = 0; j < cones.size(); ++j) {
      const int bone = mesh.skin.jointBones[j];
      if (!cones[j].limb || bone < 0 || bone >= int(helper.size()) || helper[bone]) continue;
      Impl::Drawn drawn{coneActor(cones[j]), vtkSmartPointer<vtkMatrix4x4>::New(), bone, mesh.skin.inverseBind[j]};
      drawn.actor->SetUserMatrix(drawn.skinning);
      impl_->renderer->AddActor(drawn.actor);
      impl_->cones.push_back(drawn);
    }
  }
}

void SectionConeOverlay::clear() {
  for (const Impl::Drawn& drawn : impl_->cones) impl_->renderer->RemoveActor(drawn.actor);
  impl_->cones.clear();
}

int SectionConeOverlay::coneCount() const { return int(impl_->cones.size()); }

void SectionConeOverlay::update(const std::vector<glm::mat4>& worldFromBone) {
  for (Impl::Drawn& drawn : impl_->cones) {
    if (drawn.bone < 0 || drawn.bone >= int(worldFromBone.size())) continue;
    const glm::mat4 skinning = worldFromBone[drawn.bone] * drawn.inverseBind;
    for (int r = 0; r < 4; ++r)
      for (int c = 0; c < 4; ++c) drawn.skinning->SetElement(r, c, skinning[c][r]);  // glm is column-major
    drawn.actor->Modified();
  }
}

}  // namespace mq::render
