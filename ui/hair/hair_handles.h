#pragma once
// 3D handles of a hairstyle's flow primitives in the viewport: a small
// sphere per primitive (streams blue, sources green, vortices orange; the
// selected one larger and yellow) with a line along its direction or axis.
// Positions are head space (world axes, origin at the head proxy's centre);
// a stream, which has no position, sits on its direction 22 cm out.

#include <vector>

#include <glm/glm.hpp>
#include <vtkRenderer.h>
#include <vtkSmartPointer.h>

#include "core/hair/hairstyle.h"

class vtkActor;
class vtkRenderer;

namespace mq::ui {

// A primitive of a style by kind and index (HairStyle keeps three lists).
struct PrimitiveRef {
  enum Kind { Stream, Source, Vortex };
  Kind kind = Stream;
  int index = -1;
  bool valid() const { return index >= 0; }
  bool operator==(const PrimitiveRef& o) const { return kind == o.kind && index == o.index; }
};

// All primitives of `style` in list order: streams, sources, vortices.
std::vector<PrimitiveRef> primitivesOf(const HairStyle& style);
// Head-space point where a primitive's handle sits, and back.
glm::vec3 handlePosition(const HairStyle& style, const PrimitiveRef& ref);
void moveHandle(HairStyle& style, const PrimitiveRef& ref, const glm::vec3& headSpace);

class HairHandles {
 public:
  explicit HairHandles(vtkRenderer* renderer);
  ~HairHandles();

  // worldFromHead: head space to world (the rest head centre, carried by
  // the head's current pose).
  void update(const HairStyle& style, const glm::mat4& worldFromHead, const PrimitiveRef& selected);
  void setVisible(bool visible);
  bool visible() const { return visible_; }
  // The primitive whose handle is within `radiusPixels` of display point
  // (x, y) (VTK display coordinates), nearest the camera first; invalid if none.
  PrimitiveRef pick(int x, int y, float radiusPixels = 12.0f) const;
  // World point under display (x, y) at the depth of world point `atDepthOf`.
  glm::vec3 displayToWorld(int x, int y, const glm::vec3& atDepthOf) const;

 private:
  struct Handle {
    PrimitiveRef ref;
    glm::vec3 world;
    vtkSmartPointer<vtkActor> sphere, line;
  };
  void clear();

  vtkSmartPointer<vtkRenderer> renderer_;  // kept alive: the handles leave it on destruction
  std::vector<Handle> handles_;
  bool visible_ = true;
};

}  // namespace mq::ui
