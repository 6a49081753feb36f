#pragma once
// Weight regeneration and smoothing (survey 1.2.5, "Filtrage des poids" and
// "Régénération des poids"):
//   - regeneration reduces the skin to rigid skinning, then blends it: each vertex
//     goes to the bone with the lowest score: its radial distance to the
//     bone's cylinder plus `axialWeight` times its distance beyond the
//     bone's ends, in cylinder radii (the median distance to the bone of the
//     vertices nearest to it). A bone counts only when the segment from the
//     vertex to its axis stays inside the skin (the vertex sees the bone).
//     Between a bone and its parent or child, the side of the plane through
//     their joint, normal to the child, decides: radii alone would move the
//     border off the joint, into the thinner bone.
//     The section cones were tried as the cylinders and left: a clavicle's
//     or a thigh's base cut through the torso makes it reach the shins.
//     A leaf bone that has no vertex of its own in the file (an end marker)
//     has no length and gets none. Each bone's weight then fades over
//     `transition` section radii along the skin on both sides of its
//     region's border (a smoothstep of the edge-path distance).
//   - smoothing then bounds how fast a weight may change along the skin: on
//     every edge (i, j) and bone b, |w_b(i) - w_b(j)| <= |x_i - x_j| / l_b,
//     where l_b = `transition` * sqrt(a b) of the bone's memorised section at
//     its joint (the cone's elliptic base; the cylinder's radius for a bone
//     whose cone is not a limb's). The survey sets the threshold by
//     the cone's section and no formula; this one makes the fingers switch
//     over a finger's width and the pelvis over the pelvis's. An edge that
//     exceeds it moves both ends' weights towards each other just enough;
//     passes run until none exceeds it, or `passes` ran. Each move is a
//     convex combination, so weights stay in [0, 1] and sum to 1.
// At most four influences per vertex remain. Vertices at the same position
// (seams) get the same weights. Helper bones are taken out before and put
// back after, so their weights come from the new ones.

#include <cstddef>
#include <functional>
#include <string>

#include <nlohmann/json_fwd.hpp>

#include "core/character/character.h"

namespace mq {

class ThreadPool;

struct WeightSettings {
  // The ranges a document or the CLI may ask for.
  static constexpr double kMaxAxialWeight = 100.0, kMinTransition = 0.05, kMaxTransition = 20.0;
  static constexpr int kMaxPasses = 10000;

  bool regenerate = false;   // rigid assignment by cylinder score, then the blend
  bool smooth = false;       // then the cone-threshold smoothing
  double axialWeight = 0.5;  // of the distance past a bone's ends, against the radial
  double transition = 2.0;   // the blend's and the smoothing's length, in section radii
  int passes = 64;           // smoothing passes at most

  bool active() const { return regenerate || smooth; }
  bool operator==(const WeightSettings& other) const;
  bool operator!=(const WeightSettings& other) const { return !(*this == other); }
};

// What a run did, over all meshes.
struct WeightReport {
  size_t vertices = 0;
  size_t blendedBefore = 0, blendedAfter = 0;  // vertices with a second weight > 0.05
  int passes = 0;                              // smoothing passes of the slowest mesh
  double largestExcess = 0.0;                  // the worst edge's |dw| - threshold left, 0 when converged
  bool cancelled = false;                      // stopped on request: nothing was changed

  std::string summary() const;
};

// What a regeneration changes in a character (its skeleton, for the helper
// bones, and its skins), to put back (a cancelled run, an editor's undo).
class SkinningSnapshot {
 public:
  explicit SkinningSnapshot(const Character& character);
  void restore(Character& character) const;

 private:
  Skeleton skeleton_;
  std::vector<HelperBone> helperBones_;
  std::vector<SkinBinding> skinsBeforeHelpers_, skins_;
};

// For an editor: how far a run is, and a way to stop it. Both are called on
// the calling thread between steps (a mesh's stages, each smoothing pass).
struct WeightCallbacks {
  std::function<void(int done, int total)> progress;
  std::function<bool()> cancelled;
};

// Rewrites `mesh.skin` as the settings say (a mesh without a skin is left).
WeightReport regenerateMeshWeights(Mesh& mesh, const Skeleton& skeleton, const WeightSettings& settings,
                                   ThreadPool* pool);
// Every skinned mesh of the character; helper bones come back afterwards.
// The skinning caches are the caller's to rebuild (prepareSkinning). When
// `callbacks` cancels, the character is left as it was and the report says
// `cancelled`.
WeightReport regenerateWeights(Character& character, const WeightSettings& settings, ThreadPool* pool,
                               const WeightCallbacks* callbacks = nullptr);

// The "weights" object of a scene document's skinning section:
//   {"regenerate": bool, "smooth": bool, "axial_weight": 0..100,
//    "transition": 0.05..20, "passes": 1..10000}
// `path` names it in errors (skinning.weights).
WeightSettings weightSettingsFromJson(const nlohmann::json& value, const std::string& path);
nlohmann::json toJson(const WeightSettings& settings);

}  // namespace mq
