#pragma once
// The VTK scene of one character: a renderer holding the character's meshes,
// a skeleton overlay, a ground grid at y = 0, three-point lighting and a
// gradient background. The Qt viewport and the offscreen renderer share it:
// each puts renderer() into its own render window.
//
// Per frame, updatePose() copies the posed vertices into the existing VTK
// arrays; setCharacter() is the only call that rebuilds the actors.

#include <memory>
#include <vector>

#include <glm/glm.hpp>

#include "core/mesh/mesh.h"
#include "render/surface_shading.h"

class vtkActor;
class vtkProp;
class vtkRenderer;

namespace mq {
struct Character;
class PosedCharacter;
}  // namespace mq

namespace mq::render {

class ClothActor;
class HairActor;

class SceneView {
 public:
  SceneView();
  ~SceneView();
  SceneView(const SceneView&) = delete;
  SceneView& operator=(const SceneView&) = delete;

  vtkRenderer* renderer();

  // Character
  // Builds one actor per mesh and the skeleton overlay, shown in the rest pose.
  void setCharacter(const Character& character);
  // Shades every mesh with `look` (setCharacter gives the mannequin look to
  // meshes without a colour of their own, a plain look to the others).
  void setSurfaceLook(const SurfaceLook& look);
  // Copies the posed positions and normals into the actors' arrays.
  void updatePose(const PosedCharacter& posed);
  // World-space bounds of the character as last posed (invalid when empty).
  Aabb characterBounds() const;
  // The actor of mesh `index` (for tools that colour or hide a mesh), or null.
  vtkActor* meshActor(int index);

  // Overlays
  void setSkeletonVisible(bool visible);
  bool skeletonVisible() const;
  // Draws bone `bone` (and its joint) in the highlight colour; -1 for none.
  void setHighlightedBone(int bone);
  int highlightedBone() const;
  void setGridVisible(bool visible);
  // Screen-space ambient occlusion (vtkSSAOPass): contact darkening where
  // limbs meet the body and the feet meet the floor. Costs a few passes per
  // frame; off by default, on for offscreen stills.
  void setAmbientOcclusion(bool enabled);

  // Camera: a front three-quarter view from slightly above that fits the
  // character in an image of width/height `aspect` (0: the render window's).
  void frameAll(double aspect = 0.0);
  // Places the camera (y up); the scene document stores these two points.
  void setCamera(const glm::vec3& position, const glm::vec3& focus);
  glm::vec3 cameraPosition() const;
  glm::vec3 cameraFocus() const;

  // The bone under display position (x, y) (VTK display coordinates: pixels,
  // origin bottom left): the bone whose segment is nearest the surface point
  // hit on the character, or, off the surface, the bone drawn nearest the
  // click within a few pixels; -1 if none. Needs the renderer in a window.
  int pickBone(int x, int y);

  // Adds a garment or a groom; the caller keeps the actor alive while shown.
  // These keep VTK out of callers that only compose a scene (mannequin-cli).
  void add(ClothActor& cloth);
  void add(HairActor& hair);
  // Hooks for other modules (hair, cloth) to add their own actors.
  void addProp(vtkProp* prop);
  void removeProp(vtkProp* prop);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace mq::render
