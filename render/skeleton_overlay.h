#pragma once
// The skeleton drawn over the character: a joint sphere per bone and an
// octahedral stick from each joint to each child joint. A stick belongs to
// the bone at its root (rotating that bone swings the stick). The overlay
// is drawn on top of everything (its fragments are pulled towards the near
// plane), so bones stay visible inside the body.

#include <memory>
#include <vector>

#include <glm/glm.hpp>

class vtkActor;
class vtkRenderer;

namespace mq {
class Skeleton;
}

namespace mq::render {

class SkeletonOverlay {
 public:
  SkeletonOverlay();
  ~SkeletonOverlay();

  vtkActor* actor();
  // Rebuilds the topology for `skeleton`; `jointRadius` in metres sets the size.
  void setSkeleton(const Skeleton& skeleton, float jointRadius);
  // Moves the geometry to the posed joints.
  void update(const std::vector<glm::mat4>& worldFromBone);
  void setHighlightedBone(int bone);
  int highlightedBone() const;

  // World-space joint positions and bone segments as last updated.
  const std::vector<glm::vec3>& joints() const;
  struct Segment {
    int bone;   // the bone that owns (rotates) the segment
    int child;  // the joint it ends at
  };
  const std::vector<Segment>& segments() const;
  // The bone whose segment or joint lies nearest `worldPoint`, or -1 without bones.
  int nearestBoneTo(const glm::vec3& worldPoint) const;
  // The bone drawn nearest display position (x, y) within `maxPixels`, or -1.
  int nearestBoneOnScreen(vtkRenderer* renderer, double x, double y, double maxPixels) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace mq::render
