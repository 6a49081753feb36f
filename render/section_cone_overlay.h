#pragma once
// The survey's section cones drawn around the limbs (core/skinning/
// section_cones.h): for each limb bone (not the helper bones, which lie
// inside their limbs), its memorised sections at the cone's
// two bases (15 % and 85 % along the bone) joined into a translucent
// elliptic cone. Each cone is built once in the skin's bind space and carried by
// its bone's skinning matrix, so it follows the pose as the skin does.

#include <memory>
#include <vector>

#include <glm/glm.hpp>

class vtkRenderer;

namespace mq {
struct Character;
}

namespace mq::render {

class SectionConeOverlay {
 public:
  explicit SectionConeOverlay(vtkRenderer* renderer);
  ~SectionConeOverlay();
  SectionConeOverlay(const SectionConeOverlay&) = delete;
  SectionConeOverlay& operator=(const SectionConeOverlay&) = delete;

  // Fits and builds the cones of every skinned mesh (about half a second on
  // the mannequin); replaces any shown before.
  void build(const Character& character);
  void clear();
  int coneCount() const;
  // Moves each cone with its bone.
  void update(const std::vector<glm::mat4>& worldFromBone);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace mq::render
