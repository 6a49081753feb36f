#pragma once
// Hair drawn as polylines with a hair shader (VTK OpenGL shader replacements
// on the actor's vtkShaderProperty):
//  - Kajiya-Kay diffuse: the sine of the tangent-light angle;
//  - two shifted highlights after Marschner et al. (Scheuermann's shifted
//    tangents): a white primary shifted toward the tip and a broader
//    secondary tinted with the hair colour and shifted toward the root
//    (optional);
//  - colour blended from root to tip with a small per-strand variation;
//  - transparency at the tips (screen-door, so it needs no sorting);
//  - self-shadowing: a per-vertex term computed on the CPU, light falling off
//    exponentially with the hair between a vertex and the key light, counted
//    either exactly per light-aligned column (deep-opacity style, the
//    default) or with opacity shadow maps (Kim and Neumann 2001: a stack of
//    opacity maps at regular depths along the light, each holding the hair
//    in front of it, interpolated between the two maps around a vertex).
// Tangents and the shadow term are custom vertex attributes; the scene's
// lights (camera, head or scene lights) are read every frame.

#include <memory>
#include <vector>

#include <glm/glm.hpp>

#include "core/hair/strands.h"

class vtkActor;

namespace mq::render {

enum class HairShadowMethod {
  PointCount,   // exact: the points ahead of each vertex in its light column
  OpacityMaps,  // opacity shadow maps: opacityMapCount slices, linear in depth
};

struct HairShading {
  glm::vec3 rootColor{0.10f, 0.06f, 0.035f};
  glm::vec3 tipColor{0.25f, 0.16f, 0.09f};
  float colorVariation = 0.15f;      // per-strand brightness variation (share)
  float diffuse = 0.9f;
  float ambient = 0.18f;
  float primarySpecular = 0.5f;      // white highlight
  float primaryExponent = 60.0f;
  float primaryShift = 0.08f;        // tangent shift toward the tip
  bool secondaryHighlight = true;    // the tinted, shifted second highlight
  float secondarySpecular = 0.5f;
  float secondaryExponent = 25.0f;
  float secondaryShift = -0.12f;
  float tipOpacity = 0.3f;           // opacity at the tip (1 at the root)
  float tipFadeStart = 0.7f;         // share of the strand where the fade starts
  bool selfShadowing = true;
  float shadowPerStrand = 0.05f;     // light lost per strand crossing (Beer-Lambert)
  float shadowCellSize = 0.004f;     // metres: light-aligned grid cell
  float minShadow = 0.25f;           // floor: light scattered in from around
  HairShadowMethod shadowMethod = HairShadowMethod::PointCount;
  int opacityMapCount = 32;          // OpacityMaps: slices from the hair's front to its back
};

class HairActor {
 public:
  HairActor();
  ~HairActor();
  HairActor(const HairActor&) = delete;
  HairActor& operator=(const HairActor&) = delete;

  // The prop to add to a SceneView (addProp) or any vtkRenderer.
  vtkActor* actor();

  // Rebuilds the polylines for `strands` (topology and points).
  void setStrands(const Strands& strands);
  // New positions for the same strands (laid out like Strands::points);
  // tangents and shadows follow. Ignored when the size does not match.
  void updatePositions(const std::vector<float>& points);
  void setColors(const glm::vec3& root, const glm::vec3& tip);
  void setShading(const HairShading& shading);
  const HairShading& shading() const;
  void setVisible(bool visible);

  // The per-vertex shadow term (1 lit .. minShadow) for a light coming from
  // `towardLight` (world), as the actor uses it; exposed for tests.
  // Uses shading.shadowMethod.
  static std::vector<float> computeSelfShadow(const Strands& strands, const glm::vec3& towardLight,
                                              const HairShading& shading);
  // The OpacityMaps method alone (same units and floor as the exact count).
  static std::vector<float> computeOpacityMapShadow(const Strands& strands, const glm::vec3& towardLight,
                                                    const HairShading& shading);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace mq::render
