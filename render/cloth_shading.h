#pragma once
// Garments drawn with a cloth shader (VTK OpenGL shader replacements on the
// actor's vtkShaderProperty, replacing VTK's lighting):
//  - Minnaert's limb-darkening/brightening model, I = (N.L)^k (N.V)^(k-1):
//    k < 1 brightens grazing angles (velvet, the rim of silk and satin),
//    k = 1 is Lambert, k > 1 darkens them;
//  - Ashikhmin's microfacet sheen as the alternative: the velvet
//    distribution D(h) = (1 + 4 exp(-cot^2 t / s^2) / sin^4 t) / (pi (1 + 4 s^2))
//    over the denominator 4 (N.L + N.V - N.L N.V) (Ashikhmin, Premoze and
//    Shirley 2000; Neubelt and Pettineo 2013), on a Lambert base;
//  - a texture for printed fabrics, sampled at the panel's pattern UVs
//    (metres) times a repeat per metre;
//  - a procedural bump for ribbed fabrics: cosine ribs across pattern u, the
//    normal tilted along the pattern-space tangent found from screen-space
//    derivatives (no tangent arrays needed).

#include <memory>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "render/offscreen.h"

class vtkActor;

namespace mq::render {

enum class ClothModel { Minnaert, AshikhminSheen };

struct ClothShading {
  ClothModel model = ClothModel::Minnaert;
  glm::vec3 color{0.75f, 0.75f, 0.75f};
  float ambient = 0.12f;
  float minnaertK = 1.0f;      // Minnaert exponent
  glm::vec3 sheenColor{1.0f};  // Ashikhmin sheen
  float sheen = 0.6f;
  float sheenRoughness = 0.35f;  // sigma of the velvet distribution
  bool printed = false;          // multiply by the print texture
  float printRepeatPerMetre = 4.0f;
  bool ribbed = false;
  float ribSpacing = 0.006f;  // metres between ribs, across pattern u
  float ribDepth = 0.6f;      // normal tilt at the steepest point of a rib
};

// Shading that suits a fabric preset name (cotton, silk, denim, wool, leather,
// velvet, satin, rib-knit); unknown names get Lambert cotton. Minnaert's k
// per fabric: velvet 0.55, satin 0.7, silk 0.75, wool 0.9, cotton and denim
// 1.0, leather 1.15.
ClothShading clothShadingForFabric(const std::string& fabric);

// A garment actor: a triangle mesh with pattern UVs and the cloth shader.
class ClothActor {
 public:
  ClothActor();
  ~ClothActor();
  ClothActor(const ClothActor&) = delete;
  ClothActor& operator=(const ClothActor&) = delete;

  // The prop to add to a SceneView (addProp) or any vtkRenderer.
  vtkActor* actor();

  // New mesh: positions (3 per vertex), triangles, pattern UVs (2 per vertex, metres).
  void setMesh(const std::vector<float>& positions, const std::vector<uint32_t>& triangles,
               const std::vector<float>& uvs);
  // New positions for the same mesh (e.g. each simulated frame); normals follow.
  void updatePositions(const std::vector<float>& positions);
  void setShading(const ClothShading& shading);
  const ClothShading& shading() const;
  // The print for printed fabrics (repeats every 1 / printRepeatPerMetre metres).
  void setPrint(const RgbImage& image);
  void setVisible(bool visible);

  // A small seamless print (stripes and dots) for tests and the editor's default.
  static RgbImage defaultPrint(int size = 64);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace mq::render
