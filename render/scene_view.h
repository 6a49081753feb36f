#pragma once
// The VTK scene of one character: a renderer holding the character's meshes,
// a skeleton overlay, a ground grid at y = 0, three-point lighting and a
// gradient background. The Qt viewport and the offscreen renderer share it:
// each puts renderer() into its own render window.
//
// Per frame, updatePose() copies the posed vertices into the existing VTK
// arrays; setCharacter() is the only call that rebuilds the actors.

#include <memory>
#include <optional>
#include <vector>

#include <glm/glm.hpp>

#include <string>

#include "core/material/material.h"
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

// How the character's surfaces are shaded. Auto: each mesh by its file's
// material (physically based, textured), skin shading where a material is
// marked as skin, the mannequin's wood on the built-in mannequin and on
// meshes without a material. The others force one look on every surface.
enum class LookMode { Auto, Skin, Mannequin, Plain };
// The weight-painting ramp: blue at 0, through cyan, green and yellow, to red at 1.
void heatColor(float value, unsigned char rgb[3]);
// "auto", "skin", "mannequin", "plain"; false when `name` is none of them.
bool parseLookMode(const std::string& name, LookMode& mode);
const char* lookModeName(LookMode mode);

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
  // Builds one actor per mesh and material range; the floor goes under the
  // rest pose's lowest point. Shaded by the look mode (Auto at first).
  void setLookMode(LookMode mode);
  LookMode lookMode() const;
  // Replaces material `index` (a user's edit) and reshades.
  void setMaterial(int index, const Material& material);
  const std::vector<Material>& materials() const;
  // Texture images that could not be used, each naming the image and why.
  std::vector<std::string> warnings() const;
  // The skin used where skin applies (LookMode::Skin; materials marked as
  // skin, in their own colour and base colour map); by default
  // SurfaceLook::skinPresetLook("skin1").
  void setSkinLook(const SurfaceLook& look);
  const SurfaceLook& skinLook() const;
  // Shades every surface with `look`, whatever the look mode.
  void setSurfaceLook(const SurfaceLook& look);
  // Colours each mesh by per-vertex values in [0, 1] (a bone's skin weights:
  // blue 0, cyan, green, yellow, red 1), drawn instead of its shaded surface;
  // a mesh without values (or all, for an empty list) is shaded again.
  void setVertexHeat(const std::vector<std::vector<float>>& perMesh);
  // The survey's section cones around the limbs, translucent, following the
  // pose (section_cone_overlay.h); fitting them takes about half a second.
  void showSectionCones(const Character& character);
  void hideSectionCones();
  int sectionConeCount() const;
  // Copies the posed positions and normals into the actors' arrays.
  void updatePose(const PosedCharacter& posed);
  // Height (y) of the floor: the rest pose's lowest point.
  float floorHeight() const;
  // World-space bounds of the character as last posed (invalid when empty).
  Aabb characterBounds() const;
  // The actor of surface part `index` (meshes in order, one part per material
  // range; one per mesh for most files), for tools that pick, colour or hide
  // surfaces; null past the last.
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
  // The point of the character's surface under display position (x, y),
  // world space; none off the character. Needs the renderer in a window.
  std::optional<glm::vec3> pickSurface(int x, int y);

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
