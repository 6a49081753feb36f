#pragma once
// Private to core/io: the <library_animation_clips> and skin joint lists of
// a Collada file.
// Assimp 5.2.5 ignores clips: it merges single-node animations that happen to
// share a duration, so clip names, membership and start/end are lost. This
// reads them from the XML itself (whole-matrix channels, as Blender and most
// exporters write them).

#include <string>
#include <vector>

#include <glm/glm.hpp>

namespace mq {

struct ColladaNodeTrack {
  std::string nodeId;
  std::string nodeName;  // the node's name attribute ("" if none)
  std::vector<float> times;
  std::vector<glm::mat4> matrices;  // the node's local matrix at each key
  bool step = false;                // STEP interpolation instead of LINEAR
};

struct ColladaClip {
  std::string name;
  float start = 0.0f, end = 0.0f;
  std::vector<ColladaNodeTrack> tracks;
};

struct ColladaExtras {
  // Empty when the file has no clip library or uses channels this reader
  // does not handle (the caller then keeps Assimp's animations).
  std::vector<ColladaClip> clips;
  // Nodes (name, or id when unnamed) listed as skin joints by any
  // controller, weighted or not (Assimp drops joints without weights).
  std::vector<std::string> jointNodes;
};

// Throws FileError for XML it cannot parse.
ColladaExtras readColladaExtras(const std::string& xmlText, const std::string& path);

}  // namespace mq
