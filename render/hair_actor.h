#pragma once
// Hair drawn as polylines with a hair shader (VTK OpenGL shader replacements
// on the actor's vtkShaderProperty):
//  - Kajiya-Kay diffuse: the sine of the tangent-light angle;
//  - two shifted highlights after Marschner et al. (Scheuermann's shifted
//    tangents): a white primary shifted toward the tip and a broader
//    secondary tinted with the hair colour and shifted toward the root
//    (optional);
//  - colour blended from root to tip with a small per-strand variation,
//    tinted where the strands' pigments are painted (below);
//  - transparency at the tips (screen-door, so it needs no sorting);
//  - self-shadowing: a per-vertex term computed on the CPU
//    (core/optics/hair_self_shadow.h) for the view's key light.
// Tangents and the shadow term are custom vertex attributes; the scene's
// lights (camera, head or scene lights) are read every frame.
//
// Or, with HairShadingParams::model = Physical, the fibre of
// core/optics/hair_bsdf.h per fragment and per light: the R, TT and TRT
// lobes' longitudinal terms M_p evaluated in the shader (a GLSL port of the
// core function), their azimuthal terms averaged across the fibre read from
// a small table the core computes (hairAzimuthalTable, 3 lobes x 8 exit
// angles x 32 azimuths, uniforms), plus an ambient term, the light from all
// around times the fibre's mean albedo, and a volume term per light, the
// light scattered between fibres (hairVolumeReflectance). Its colour comes from the pigments;
// the root and tip colours are not used. The same self-shadowing and tip
// transparency as Kajiya-Kay.
//
// Painted pigments (Strands::pigmentPaint, the groom's paint_melanin and
// paint_pheomelanin maps) tint each strand by the ratio of its fibre's mean
// albedo to the style's, per channel: all but the R lobe for the physical
// fibre, the colours for Kajiya-Kay. The lobes keep the style's shapes (the
// azimuthal table is the style's). The tints are computed with the fibre
// the actor has when the arrays are built: set it (setFibre) first.
//
// The arrays it draws (HairGeometry) are built by static functions that touch
// no VTK object already shown, so an editor can build them on a worker thread
// and hand them over with showGeometry(), a pointer swap. The strands are
// drawn in interleaved chunks (each an even sample of the hair): with a frame
// budget, a frame draws chunks until the budget is spent and frames that do
// not erase (the renderer's Erase off, the other props hidden) draw the
// rest over it, so no frame holds the GUI up for long and the finished image
// is the one a single frame draws (screen-door transparency needs no order).
// While the camera moves (the render window's desired update rate above the
// still rate, as VTK's interactor sets it) the shadow keeps its light.

#include <cstddef>
#include <functional>
#include <memory>
#include <optional>
#include <vector>

#include <glm/glm.hpp>

#include "core/hair/hairstyle.h"
#include "core/hair/strands.h"
#include "core/optics/hair_self_shadow.h"

class vtkActor;
class vtkRenderer;

namespace mq::render {

using HairShadowMethod = optics::HairShadowMethod;  // core/optics/hair_self_shadow.h

struct HairShading {
  glm::vec3 rootColor{0.10f, 0.06f, 0.035f};
  glm::vec3 tipColor{0.25f, 0.16f, 0.09f};
  float colorVariation = 0.15f;  // per-strand brightness variation (share)
  float diffuse = 0.9f;
  float ambient = 0.18f;
  float primarySpecular = 0.5f;  // white highlight
  float primaryExponent = 60.0f;
  float primaryShift = 0.08f;      // tangent shift toward the tip
  bool secondaryHighlight = true;  // the tinted, shifted second highlight
  float secondarySpecular = 0.5f;
  float secondaryExponent = 25.0f;
  float secondaryShift = -0.12f;
  float tipOpacity = 0.3f;    // opacity at the tip (1 at the root)
  float tipFadeStart = 0.7f;  // share of the strand where the fade starts
  bool selfShadowing = true;
  float shadowPerStrand = 0.05f;  // light lost per strand crossing (Beer-Lambert)
  float shadowCellSize = 0.004f;  // metres: light-aligned grid cell
  float minShadow = 0.25f;        // floor: light scattered in from around
  HairShadowMethod shadowMethod = HairShadowMethod::PointCount;
  int opacityMapCount = 32;      // OpacityMaps: slices from the hair's front to its back
  HairShadingParams fibre;       // the model; pigments and roughness for Physical
  unsigned physicalLobes = 31u;  // Physical: R 1, TT 2, TRT 4, residual 8, volume 16 (pictures of one lobe)

  optics::HairShadowSettings shadowSettings() const {
    return {shadowMethod, shadowPerStrand, shadowCellSize, minShadow, opacityMapCount};
  }
};

// The arrays for one set of strands (points, lines, tangents, volume normals,
// root-to-tip/shadow/random parameters, and the subset drawn while the
// camera moves). Immutable once built; shared between threads.
struct HairGeometry;

class HairActor {
 public:
  // Strands in a chunk: 10-20 ms of software GL on a busy machine.
  static constexpr size_t kStrandsPerChunk = 200;

  HairActor();
  ~HairActor();
  HairActor(const HairActor&) = delete;
  HairActor& operator=(const HairActor&) = delete;

  // The prop to add to a SceneView (addProp) or any vtkRenderer.
  vtkActor* actor();

  // Rebuilds the polylines for `strands` (topology and points) on the
  // calling thread.
  void setStrands(const Strands& strands);
  // New positions for the same strands (laid out like Strands::points);
  // tangents and shadows follow. Ignored when the size does not match.
  void updatePositions(const std::vector<float>& points);

  // ---- Building off the GUI thread ----
  // The arrays for `strands`, self-shadowed for a key light from
  // `towardLight` (world) when given, else lit until reshaded. Thread-safe.
  static std::shared_ptr<const HairGeometry> prepareGeometry(std::shared_ptr<const Strands> strands,
                                                             const HairShading& shading,
                                                             const std::optional<glm::vec3>& towardLight);
  // `geometry` with its shadow term recomputed for `towardLight` and
  // `shading` (the other arrays shared). Thread-safe.
  static std::shared_ptr<const HairGeometry> reshade(const std::shared_ptr<const HairGeometry>& geometry,
                                                     const HairShading& shading, const glm::vec3& towardLight);
  // Draws `geometry` from the next frame on (GUI thread; a pointer swap).
  void showGeometry(std::shared_ptr<const HairGeometry> geometry);
  std::shared_ptr<const HairGeometry> geometry() const;
  static size_t strandCount(const HairGeometry& geometry);
  // The key light's direction (world) in the last frame drawn (none before).
  std::optional<glm::vec3> keyLight() const;
  // The direction (world) toward the light the hair is shadowed from, with
  // `renderer`'s lights and camera as they are now.
  static glm::vec3 keyLightOf(vtkRenderer* renderer);
  // Called during a frame whose shadow is stale (the key light turned by
  // more than 3 degrees, the shadow settings or the strands changed) while
  // the camera is still: the owner reshades off the GUI thread and calls
  // showGeometry(). Without it the actor reshades during the frame.
  void setReshadeRequest(std::function<void()> request);
  // Frames stop adding chunks once the hair took this long (0, the
  // default: every frame draws all of it, as offscreen images need).
  void setFrameBudget(double milliseconds);
  // The last frame left chunks to draw: render frames that do not erase,
  // with the other props hidden, until it is false.
  bool hasMoreToDraw() const;
  // Frames that drew the hair so far: one that did not (the hair out of
  // view, culled) must not be continued.
  size_t framesDrawn() const;
  void setColors(const glm::vec3& root, const glm::vec3& tip);
  // The shading model and, for Physical, the pigments and roughness.
  void setFibre(const HairShadingParams& fibre);
  void setShading(const HairShading& shading);
  const HairShading& shading() const;
  void setVisible(bool visible);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace mq::render
