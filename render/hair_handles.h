#pragma once
// 3D handles of a hairstyle's flow primitives in the viewport: a small
// sphere per primitive (streams blue, sources green, vortices orange; the
// selected one larger and yellow) with a line along its direction or axis;
// a vortex's line ends in a small cube, the tip handle that turns its axis.
// Positions are head space (world axes, origin at the head proxy's centre);
// a stream, which has no position, sits on its direction 22 cm out.

#include <vector>

#include <vtkRenderer.h>
#include <vtkSmartPointer.h>
#include <glm/glm.hpp>

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
// Head-space point of a vortex's tip handle (the end of its axis line), and
// the axis turned toward a head-space point: normalize(point - position).
glm::vec3 axisTipPosition(const HairStyle& style, const PrimitiveRef& ref);
void turnAxisToward(HairStyle& style, const PrimitiveRef& ref, const glm::vec3& headSpace);

// What a pick hit: a primitive's sphere (moves it) or a vortex's axis tip
// (turns the axis).
struct HandleHit {
  enum Part { Body, AxisTip };
  PrimitiveRef ref;
  Part part = Body;
  bool valid() const { return ref.valid(); }
};

class HairHandles {
 public:
  explicit HairHandles(vtkRenderer* renderer);
  ~HairHandles();

  // worldFromHead: head space to world (the rest head centre, carried by
  // the head's current pose).
  void update(const HairStyle& style, const glm::mat4& worldFromHead, const PrimitiveRef& selected);
  void setVisible(bool visible);
  bool visible() const { return visible_; }
  // The handle within `radiusPixels` of display point (x, y) (VTK display
  // coordinates): a tip before a sphere (a tip sits on its sphere's line),
  // then nearest the camera first; invalid if none.
  HandleHit pick(int x, int y, float radiusPixels = 12.0f) const;
  // World point under display (x, y) at the depth of world point `atDepthOf`.
  glm::vec3 displayToWorld(int x, int y, const glm::vec3& atDepthOf) const;

 private:
  struct Handle {
    PrimitiveRef ref;
    glm::vec3 world, tipWorld;
    bool hasTip = false;  // vortices with an axis
    vtkSmartPointer<vtkActor> sphere, line, tip;
  };
  void clear();

  vtkSmartPointer<vtkRenderer> renderer_;  // kept alive: the handles leave it on destruction
  std::vector<Handle> handles_;
  bool visible_ = true;
};

}  // namespace mq::ui
