#include "render/hair_handles.h"

#include <vtkActor.h>
#include <vtkCubeSource.h>
#include <vtkLineSource.h>
#include <vtkNew.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderer.h>
#include <vtkSphereSource.h>

namespace mq::ui {

namespace {
constexpr float kStreamHandleDistance = 0.22f;
constexpr float kLineLength = 0.06f;

glm::vec3 kindColor(PrimitiveRef::Kind kind) {
  switch (kind) {
    case PrimitiveRef::Stream:
      return {0.3f, 0.6f, 1.0f};
    case PrimitiveRef::Source:
      return {0.35f, 0.9f, 0.4f};
    default:
      return {1.0f, 0.55f, 0.15f};
  }
}

vtkSmartPointer<vtkActor> makeActor(vtkAlgorithm* source, const glm::vec3& color) {
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputConnection(source->GetOutputPort());
  // Drawn over the hair: a large depth offset keeps handles inside the hair visible.
  mapper->SetResolveCoincidentTopologyToPolygonOffset();
  mapper->SetRelativeCoincidentTopologyPolygonOffsetParameters(0.0, -66000.0);
  mapper->SetRelativeCoincidentTopologyLineOffsetParameters(0.0, -66000.0);
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(mapper);
  actor->GetProperty()->SetColor(color.x, color.y, color.z);
  actor->GetProperty()->SetLineWidth(2.0f);
  actor->GetProperty()->LightingOff();
  actor->PickableOff();
  return actor;
}

// A dragged value rounded to 1e-4 (0.1 mm for positions): the document
// stores 6 significant digits, so the saved style reopens to the very same
// floats and grows the very same strands as the one shown.
glm::vec3 roundedForTheDocument(const glm::vec3& v) { return glm::round(v * 1e4f) / 1e4f; }

}  // namespace

std::vector<PrimitiveRef> primitivesOf(const HairStyle& style) {
  std::vector<PrimitiveRef> out;
  for (int i = 0; i < int(style.primitives.streams.size()); ++i) out.push_back({PrimitiveRef::Stream, i});
  for (int i = 0; i < int(style.primitives.sources.size()); ++i) out.push_back({PrimitiveRef::Source, i});
  for (int i = 0; i < int(style.primitives.vortices.size()); ++i) out.push_back({PrimitiveRef::Vortex, i});
  return out;
}

glm::vec3 handlePosition(const HairStyle& style, const PrimitiveRef& ref) {
  switch (ref.kind) {
    case PrimitiveRef::Stream: {
      const glm::vec3 d = style.primitives.streams[ref.index].direction;
      return glm::length(d) > 1e-6f ? glm::normalize(d) * kStreamHandleDistance : glm::vec3(0.0f);
    }
    case PrimitiveRef::Source:
      return style.primitives.sources[ref.index].position;
    default:
      return style.primitives.vortices[ref.index].position;
  }
}

void moveHandle(HairStyle& style, const PrimitiveRef& ref, const glm::vec3& headSpace) {
  switch (ref.kind) {
    case PrimitiveRef::Stream:
      if (glm::length(headSpace) > 1e-4f)
        style.primitives.streams[ref.index].direction = roundedForTheDocument(glm::normalize(headSpace));
      break;
    case PrimitiveRef::Source:
      style.primitives.sources[ref.index].position = roundedForTheDocument(headSpace);
      break;
    default:
      style.primitives.vortices[ref.index].position = roundedForTheDocument(headSpace);
      break;
  }
}

glm::vec3 axisTipPosition(const HairStyle& style, const PrimitiveRef& ref) {
  const Vortex& vortex = style.primitives.vortices[ref.index];
  const glm::vec3 axis = glm::length(vortex.axis) > 1e-6f ? glm::normalize(vortex.axis) : glm::vec3(0.0f);
  return vortex.position + axis * kLineLength;
}

void turnAxisToward(HairStyle& style, const PrimitiveRef& ref, const glm::vec3& headSpace) {
  Vortex& vortex = style.primitives.vortices[ref.index];
  const glm::vec3 along = headSpace - vortex.position;
  // Too near the vortex's centre the direction is noise: keep the axis.
  if (glm::length(along) > 1e-3f) vortex.axis = roundedForTheDocument(glm::normalize(along));
}

HairHandles::HairHandles(vtkRenderer* renderer) : renderer_(renderer) {}
HairHandles::~HairHandles() { clear(); }

void HairHandles::clear() {
  for (Handle& h : handles_) {
    renderer_->RemoveActor(h.sphere);
    renderer_->RemoveActor(h.line);
    if (h.tip) renderer_->RemoveActor(h.tip);
  }
  handles_.clear();
}

void HairHandles::update(const HairStyle& style, const glm::mat4& worldFromHead, const PrimitiveRef& selected) {
  clear();
  for (const PrimitiveRef& ref : primitivesOf(style)) {
    Handle h;
    h.ref = ref;
    h.world = glm::vec3(worldFromHead * glm::vec4(handlePosition(style, ref), 1.0f));
    const bool isSelected = ref == selected;
    const glm::vec3 color = isSelected ? glm::vec3(1.0f, 0.95f, 0.2f) : kindColor(ref.kind);
    vtkNew<vtkSphereSource> sphere;
    sphere->SetCenter(h.world.x, h.world.y, h.world.z);
    sphere->SetRadius(isSelected ? 0.009 : 0.006);
    sphere->SetThetaResolution(12);
    sphere->SetPhiResolution(8);
    h.sphere = makeActor(sphere, color);
    glm::vec3 along(0.0f);
    if (ref.kind == PrimitiveRef::Stream) along = style.primitives.streams[ref.index].direction;
    if (glm::length(along) > 1e-6f) along = glm::normalize(glm::mat3(worldFromHead) * along) * kLineLength;
    if (ref.kind == PrimitiveRef::Vortex && glm::length(style.primitives.vortices[ref.index].axis) > 1e-6f) {
      // The line ends at the tip handle, which is placed in head space like the sphere.
      h.tipWorld = glm::vec3(worldFromHead * glm::vec4(axisTipPosition(style, ref), 1.0f));
      h.hasTip = true;
      along = h.tipWorld - h.world;
      const double side = isSelected ? 0.009 : 0.006;
      vtkNew<vtkCubeSource> cube;
      cube->SetCenter(h.tipWorld.x, h.tipWorld.y, h.tipWorld.z);
      cube->SetXLength(side);
      cube->SetYLength(side);
      cube->SetZLength(side);
      h.tip = makeActor(cube, color);
      h.tip->SetVisibility(visible_);
      renderer_->AddActor(h.tip);
    }
    vtkNew<vtkLineSource> line;
    line->SetPoint1(h.world.x, h.world.y, h.world.z);
    line->SetPoint2(h.world.x + along.x, h.world.y + along.y, h.world.z + along.z);
    h.line = makeActor(line, color);
    h.sphere->SetVisibility(visible_);
    h.line->SetVisibility(visible_ && glm::length(along) > 0.0f);
    renderer_->AddActor(h.sphere);
    renderer_->AddActor(h.line);
    handles_.push_back(std::move(h));
  }
}

void HairHandles::setVisible(bool visible) {
  visible_ = visible;
  for (Handle& h : handles_) {
    h.sphere->SetVisibility(visible);
    h.line->SetVisibility(visible);
    if (h.tip) h.tip->SetVisibility(visible);
  }
}

HandleHit HairHandles::pick(int x, int y, float radiusPixels) const {
  if (!visible_) return {};
  HandleHit best;
  double bestDepth = 2.0;
  // Returns whether world point `at` is under the cursor nearer than the best so far.
  auto nearer = [&](const glm::vec3& at) {
    renderer_->SetWorldPoint(at.x, at.y, at.z, 1.0);
    renderer_->WorldToDisplay();
    const double* d = renderer_->GetDisplayPoint();
    const double dx = d[0] - x, dy = d[1] - y;
    if (dx * dx + dy * dy > double(radiusPixels) * radiusPixels || d[2] >= bestDepth) return false;
    bestDepth = d[2];
    return true;
  };
  for (const Handle& h : handles_)
    if (h.hasTip && nearer(h.tipWorld)) best = {h.ref, HandleHit::AxisTip};
  if (best.valid()) return best;
  for (const Handle& h : handles_)
    if (nearer(h.world)) best = {h.ref, HandleHit::Body};
  return best;
}

glm::vec3 HairHandles::displayToWorld(int x, int y, const glm::vec3& atDepthOf) const {
  renderer_->SetWorldPoint(atDepthOf.x, atDepthOf.y, atDepthOf.z, 1.0);
  renderer_->WorldToDisplay();
  const double depth = renderer_->GetDisplayPoint()[2];
  renderer_->SetDisplayPoint(x, y, depth);
  renderer_->DisplayToWorld();
  const double* w = renderer_->GetWorldPoint();
  return glm::vec3(float(w[0] / w[3]), float(w[1] / w[3]), float(w[2] / w[3]));
}

}  // namespace mq::ui
