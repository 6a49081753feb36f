#include "core/hair/hairstyle.h"

#include "core/util/error.h"

namespace mq {

namespace {

// Common to every built-in style: the hair falls (a uniform stream down and
// slightly back), springs from a source under the crown, and parts around
// the face (a source in front of it pushes the flow aside).
HairStyle baseStyle(const std::string& name) {
  HairStyle s;
  s.name = name;
  s.primitives.streams.push_back({glm::vec3(0.0f, -1.0f, -0.25f), 1.0f});
  s.primitives.sources.push_back({glm::vec3(0.0f, 0.10f, -0.01f), 0.9f, 0.07f});
  s.primitives.sources.push_back({glm::vec3(0.0f, -0.02f, 0.14f), 3.0f, 0.08f});
  return s;
}

HairStyle longStraight() {
  HairStyle s = baseStyle("long_straight");
  s.length = 0.45f;
  s.clumping = 0.3f;
  s.frizz = 0.002f;
  s.strandNoise = 0.008f;
  return s;
}

HairStyle bob() {
  HairStyle s = baseStyle("bob");
  s.length = 0.2f;
  s.lengthVariation = 0.05f;
  s.lengthMap.push_back({glm::vec3(0.0f, 0.06f, 0.1f), 0.55f, 0.06f});  // a shorter fringe
  s.clumping = 0.5f;
  s.frizz = 0.002f;
  s.strandNoise = 0.004f;
  s.noiseAmplitude = 0.08f;
  return s;
}

HairStyle wavy() {
  HairStyle s = baseStyle("wavy");
  s.length = 0.38f;
  s.waveAmplitude = 0.012f;
  s.waveLength = 0.07f;
  // Two counter-rotating vortices behind the head swing the back hair in a broad S.
  s.primitives.vortices.push_back({glm::vec3(0.0f, -0.16f, -0.16f), glm::vec3(1, 0, 0), 0.5f, 0.06f});
  s.primitives.vortices.push_back({glm::vec3(0.0f, -0.30f, -0.16f), glm::vec3(1, 0, 0), -0.5f, 0.06f});
  s.clumping = 0.5f;
  s.frizz = 0.003f;
  return s;
}

HairStyle curly() {
  HairStyle s = baseStyle("curly");
  s.length = 0.30f;
  s.scalpOutflow = 0.9f;
  s.curlRadius = 0.012f;
  s.curlLength = 0.045f;
  s.pointsPerStrand = 48;
  // A crown swirl.
  s.primitives.vortices.push_back({glm::vec3(0.0f, 0.12f, -0.03f), glm::vec3(0, 1, 0), 0.4f, 0.05f});
  s.clumping = 0.7f;
  s.frizz = 0.004f;
  return s;
}

}  // namespace

float unpaintedValue(const HairStyle& style, GroomBrush brush) {
  switch (brush) {
    case GroomBrush::PaintClumping:
      return style.clumping;
    case GroomBrush::PaintMelanin:
      return style.shading.melanin;
    case GroomBrush::PaintPheomelanin:
      return style.shading.pheomelanin;
    default:
      return paintRange(brush).unpainted;
  }
}

std::vector<std::string> builtinHairStyleNames() { return {"long_straight", "bob", "wavy", "curly"}; }

HairStyle builtinHairStyle(const std::string& name) {
  if (name == "long_straight") return longStraight();
  if (name == "bob") return bob();
  if (name == "wavy") return wavy();
  if (name == "curly") return curly();
  std::string known;
  for (const std::string& n : builtinHairStyleNames()) known += (known.empty() ? "" : ", ") + n;
  throw Error("unknown hairstyle '" + name + "' (built-in styles: " + known + ")");
}

}  // namespace mq
