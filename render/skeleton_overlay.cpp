#include "render/skeleton_overlay.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include <vtkActor.h>
#include <vtkCellArray.h>
#include <vtkFloatArray.h>
#include <vtkNew.h>
#include <vtkOpenGLPolyDataMapper.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkProperty.h>
#include <vtkRenderer.h>
#include <vtkShaderProperty.h>
#include <vtkUnsignedCharArray.h>

#include "core/skeleton/skeleton.h"

namespace mq::render {
namespace {

constexpr std::array<unsigned char, 3> kBoneColour{110, 190, 255};
constexpr std::array<unsigned char, 3> kJointColour{235, 240, 250};
constexpr std::array<unsigned char, 3> kHighlightColour{255, 125, 0};

// A unit UV sphere: directions (also the normals) and triangles.
struct SphereTemplate {
  std::vector<glm::vec3> directions;
  std::vector<uint32_t> triangles;
};

SphereTemplate makeSphereTemplate(int rings, int segments) {
  SphereTemplate s;
  for (int i = 0; i <= rings; ++i) {
    const float theta = static_cast<float>(M_PI) * i / rings;
    for (int j = 0; j < segments; ++j) {
      const float phi = 2.0f * static_cast<float>(M_PI) * j / segments;
      s.directions.emplace_back(std::sin(theta) * std::cos(phi), std::cos(theta), std::sin(theta) * std::sin(phi));
    }
  }
  for (int i = 0; i < rings; ++i)
    for (int j = 0; j < segments; ++j) {
      const uint32_t a = i * segments + j, b = i * segments + (j + 1) % segments;
      const uint32_t c = a + segments, d = b + segments;
      s.triangles.insert(s.triangles.end(), {a, b, c, b, d, c});
    }
  return s;
}

const SphereTemplate& sphereTemplate() {
  static const SphereTemplate s = makeSphereTemplate(6, 10);
  return s;
}

// Octahedral stick: head, a square ring near the head, tail; 8 flat triangles.
constexpr int kStickTriangles = 8;
constexpr int kStickVertices = 3 * kStickTriangles;

float distanceToSegment(const glm::vec2& p, const glm::vec2& a, const glm::vec2& b) {
  const glm::vec2 ab = b - a;
  const float len2 = glm::dot(ab, ab);
  const float t = len2 > 0.0f ? std::clamp(glm::dot(p - a, ab) / len2, 0.0f, 1.0f) : 0.0f;
  return glm::length(p - (a + t * ab));
}

}  // namespace

struct SkeletonOverlay::Impl {
  vtkNew<vtkActor> actor;
  vtkNew<vtkOpenGLPolyDataMapper> mapper;
  vtkNew<vtkPolyData> polyData;
  vtkNew<vtkPoints> points;
  vtkNew<vtkFloatArray> normals;
  vtkNew<vtkUnsignedCharArray> colours;

  std::vector<int> parents;
  std::vector<Segment> segments;
  std::vector<glm::vec3> joints;
  std::vector<int> vertexOwner;  // bone per VTK vertex, for highlighting
  float jointRadius = 0.02f;
  int highlighted = -1;

  float* pointData() { return static_cast<vtkFloatArray*>(points->GetData())->GetPointer(0); }

  void buildTopology() {
    const SphereTemplate& sphere = sphereTemplate();
    const size_t vertexCount = joints.size() * sphere.directions.size() + segments.size() * kStickVertices;
    points->SetNumberOfPoints(static_cast<vtkIdType>(vertexCount));
    normals->SetNumberOfTuples(static_cast<vtkIdType>(vertexCount));
    colours->SetNumberOfTuples(static_cast<vtkIdType>(vertexCount));
    vertexOwner.assign(vertexCount, -1);

    vtkNew<vtkCellArray> cells;
    vtkIdType base = 0;
    for (size_t j = 0; j < joints.size(); ++j) {
      for (size_t t = 0; t < sphere.triangles.size(); t += 3) {
        const vtkIdType tri[3] = {base + sphere.triangles[t], base + sphere.triangles[t + 1],
                                  base + sphere.triangles[t + 2]};
        cells->InsertNextCell(3, tri);
      }
      std::fill_n(vertexOwner.begin() + base, sphere.directions.size(), static_cast<int>(j));
      base += static_cast<vtkIdType>(sphere.directions.size());
    }
    for (const Segment& s : segments) {
      for (int t = 0; t < kStickTriangles; ++t) {
        const vtkIdType tri[3] = {base + 3 * t, base + 3 * t + 1, base + 3 * t + 2};
        cells->InsertNextCell(3, tri);
      }
      std::fill_n(vertexOwner.begin() + base, kStickVertices, s.bone);
      base += kStickVertices;
    }
    polyData->SetPolys(cells);
    recolour();
  }

  void recolour() {
    for (size_t v = 0; v < vertexOwner.size(); ++v) {
      const bool isJoint = v < joints.size() * sphereTemplate().directions.size();
      const auto& c = vertexOwner[v] == highlighted ? kHighlightColour : isJoint ? kJointColour : kBoneColour;
      colours->SetTypedTuple(static_cast<vtkIdType>(v), c.data());
    }
    colours->Modified();
  }

  void writeJoints(float* p, float* n) {
    const SphereTemplate& sphere = sphereTemplate();
    for (const glm::vec3& centre : joints)
      for (const glm::vec3& d : sphere.directions) {
        const glm::vec3 q = centre + jointRadius * d;
        *p++ = q.x, *p++ = q.y, *p++ = q.z;
        *n++ = d.x, *n++ = d.y, *n++ = d.z;
      }
  }

  void writeStick(const glm::vec3& head, const glm::vec3& tail, float*& p, float*& n) const {
    const glm::vec3 axis = tail - head;
    const float length = glm::length(axis);
    const glm::vec3 dir = length > 1e-6f ? axis / length : glm::vec3(0, 1, 0);
    const glm::vec3 ref = std::abs(dir.y) < 0.9f ? glm::vec3(0, 1, 0) : glm::vec3(1, 0, 0);
    const glm::vec3 u = glm::normalize(glm::cross(dir, ref));
    const glm::vec3 v = glm::cross(dir, u);
    const float width = std::clamp(0.1f * length, 0.3f * jointRadius, 1.1f * jointRadius);
    const glm::vec3 ringCentre = head + 0.18f * axis;
    const glm::vec3 ring[4] = {ringCentre + width * u, ringCentre + width * v, ringCentre - width * u,
                               ringCentre - width * v};
    auto emit = [&](const glm::vec3& a, const glm::vec3& b, const glm::vec3& c) {
      glm::vec3 normal = glm::cross(b - a, c - a);
      const float len = glm::length(normal);
      normal = len > 0.0f ? normal / len : dir;
      for (const glm::vec3* q : {&a, &b, &c}) {
        *p++ = q->x, *p++ = q->y, *p++ = q->z;
        *n++ = normal.x, *n++ = normal.y, *n++ = normal.z;
      }
    };
    for (int i = 0; i < 4; ++i) {
      emit(head, ring[(i + 1) % 4], ring[i]);
      emit(tail, ring[i], ring[(i + 1) % 4]);
    }
  }
};

SkeletonOverlay::SkeletonOverlay() : impl_(std::make_unique<Impl>()) {
  Impl& m = *impl_;
  m.normals->SetNumberOfComponents(3);
  m.normals->SetName("Normals");
  m.colours->SetNumberOfComponents(3);
  m.colours->SetName("Colours");
  m.points->SetDataTypeToFloat();
  m.polyData->SetPoints(m.points);
  m.polyData->GetPointData()->SetNormals(m.normals);
  m.polyData->GetPointData()->SetScalars(m.colours);
  m.mapper->SetInputData(m.polyData);
  m.mapper->SetColorModeToDirectScalars();
  m.mapper->ScalarVisibilityOn();
  // Always on top: squeeze the overlay's depth towards the near plane (order
  // among its own fragments is kept, so joints still hide sticks behind them).
  m.actor->GetShaderProperty()->AddFragmentShaderReplacement("//VTK::Depth::Impl", true,
                                                             "gl_FragDepth = 0.02 * gl_FragCoord.z;\n", false);
  m.actor->GetShaderProperty()->AddFragmentShaderReplacement("//VTK::Coincident::Impl", true, "", false);
  m.actor->SetMapper(m.mapper);
  m.actor->GetProperty()->SetAmbient(0.5);
  m.actor->GetProperty()->SetDiffuse(0.6);
  m.actor->GetProperty()->SetSpecular(0.3);
  m.actor->GetProperty()->SetSpecularPower(30.0);
  m.actor->PickableOff();
}

SkeletonOverlay::~SkeletonOverlay() = default;

vtkActor* SkeletonOverlay::actor() { return impl_->actor; }

void SkeletonOverlay::setSkeleton(const Skeleton& skeleton, float jointRadius) {
  Impl& m = *impl_;
  m.jointRadius = jointRadius;
  m.parents.clear();
  m.segments.clear();
  for (int b = 0; b < skeleton.boneCount(); ++b) {
    const int parent = skeleton.bone(b).parent;
    m.parents.push_back(parent);
    if (parent >= 0) m.segments.push_back({parent, b});
  }
  m.joints.assign(skeleton.boneCount(), glm::vec3(0.0f));
  if (m.highlighted >= skeleton.boneCount()) m.highlighted = -1;
  m.buildTopology();
  update(skeleton.worldTransforms(skeleton.restPose()));
}

void SkeletonOverlay::update(const std::vector<glm::mat4>& worldFromBone) {
  Impl& m = *impl_;
  if (worldFromBone.size() != m.joints.size()) return;
  for (size_t b = 0; b < m.joints.size(); ++b) m.joints[b] = glm::vec3(worldFromBone[b][3]);
  float* p = m.pointData();
  float* n = m.normals->GetPointer(0);
  if (!p) return;
  m.writeJoints(p, n);
  p += 3 * m.joints.size() * sphereTemplate().directions.size();
  n += 3 * m.joints.size() * sphereTemplate().directions.size();
  for (const Segment& s : m.segments) m.writeStick(m.joints[s.bone], m.joints[s.child], p, n);
  m.points->Modified();
  m.normals->Modified();
  m.polyData->Modified();
}

void SkeletonOverlay::setHighlightedBone(int bone) {
  if (bone == impl_->highlighted) return;
  impl_->highlighted = bone;
  impl_->recolour();
  impl_->polyData->Modified();
}

int SkeletonOverlay::highlightedBone() const { return impl_->highlighted; }

const std::vector<glm::vec3>& SkeletonOverlay::joints() const { return impl_->joints; }

const std::vector<SkeletonOverlay::Segment>& SkeletonOverlay::segments() const { return impl_->segments; }

int SkeletonOverlay::nearestBoneTo(const glm::vec3& x) const {
  const Impl& m = *impl_;
  int best = -1;
  float bestDistance = std::numeric_limits<float>::max();
  auto consider = [&](int bone, float d) {
    if (d < bestDistance) bestDistance = d, best = bone;
  };
  for (size_t b = 0; b < m.joints.size(); ++b) consider(static_cast<int>(b), glm::length(x - m.joints[b]));
  // A segment counts only alongside itself: a point beyond its tail belongs to
  // the child (e.g. the palm to the hand, not the forearm).
  for (const Segment& s : m.segments) {
    const glm::vec3 a = m.joints[s.bone], ab = m.joints[s.child] - a;
    const float len2 = glm::dot(ab, ab);
    if (len2 <= 0.0f) continue;
    const float t = glm::dot(x - a, ab) / len2;
    if (t < 0.0f || t >= 1.0f) continue;
    consider(s.bone, glm::length(x - (a + t * ab)));
  }
  return best;
}

int SkeletonOverlay::nearestBoneOnScreen(vtkRenderer* renderer, double x, double y, double maxPixels) const {
  const Impl& m = *impl_;
  std::vector<glm::vec2> screen(m.joints.size());
  for (size_t b = 0; b < m.joints.size(); ++b) {
    renderer->SetWorldPoint(m.joints[b].x, m.joints[b].y, m.joints[b].z, 1.0);
    renderer->WorldToDisplay();
    double d[3];
    renderer->GetDisplayPoint(d);
    screen[b] = glm::vec2(static_cast<float>(d[0]), static_cast<float>(d[1]));
  }
  const glm::vec2 click(static_cast<float>(x), static_cast<float>(y));
  int best = -1;
  double bestDistance = maxPixels;
  // Joints win ties with the sticks that meet at them.
  constexpr float kJointPreference = 3.0f;
  for (size_t b = 0; b < screen.size(); ++b) {
    const double d = glm::length(click - screen[b]) - kJointPreference;
    if (d <= bestDistance) bestDistance = d, best = static_cast<int>(b);
  }
  for (const Segment& s : m.segments) {
    const double d = distanceToSegment(click, screen[s.bone], screen[s.child]);
    if (d < bestDistance) bestDistance = d, best = s.bone;
  }
  return best;
}

}  // namespace mq::render
