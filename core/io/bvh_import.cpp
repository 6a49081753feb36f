#include "core/io/bvh_import.h"

#include <glm/gtx/quaternion.hpp>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <map>

#include "core/io/file_bytes.h"
#include "core/util/error.h"
#include "core/util/utf8.h"

namespace mq {
namespace {

enum class Channel { Xposition, Yposition, Zposition, Xrotation, Yrotation, Zrotation };

struct BvhJoint {
  std::string name;
  int parent = -1;
  glm::vec3 offset{0.0f};
  std::vector<Channel> channels;
  int firstChannel = 0;  // column of its first channel in a frame row
};

struct BvhData {
  std::vector<BvhJoint> joints;
  int channelCount = 0;
  int frames = 0;
  float frameTime = 0.0f;
  std::vector<float> values;  // frames * channelCount
};

struct Token {
  std::string text;
  int line;
};

// A recursive-descent reader of the HIERARCHY and MOTION sections.
class BvhParser {
 public:
  BvhParser(const std::string& path, const std::string& text) : path_(path) { tokenize(text); }

  BvhData parse() {
    expect("HIERARCHY");
    if (peek() != "ROOT") fail("expected ROOT");
    while (peek() == "ROOT") parseJoint(-1);
    expect("MOTION");
    parseMotion();
    return std::move(data_);
  }

 private:
  [[noreturn]] void fail(const std::string& problem) const {
    const int line = pos_ < tokens_.size() ? tokens_[pos_].line : (tokens_.empty() ? 1 : tokens_.back().line);
    throw FileError(path_, "line " + std::to_string(line) + ": " + problem);
  }

  void tokenize(const std::string& text) {
    int line = 1;
    size_t i = 0;
    while (i < text.size()) {
      const char c = text[i];
      if (c == '\n') ++line;
      if (std::isspace(static_cast<unsigned char>(c))) {
        ++i;
        continue;
      }
      if (c == '{' || c == '}') {
        tokens_.push_back({std::string(1, c), line});
        ++i;
        continue;
      }
      const size_t start = i;
      while (i < text.size() && !std::isspace(static_cast<unsigned char>(text[i])) && text[i] != '{' && text[i] != '}')
        ++i;
      tokens_.push_back({text.substr(start, i - start), line});
    }
  }

  std::string peek() const { return pos_ < tokens_.size() ? tokens_[pos_].text : std::string(); }
  // The next token as it may appear in a message: printable, short.
  std::string shown() const {
    std::string t = peek().substr(0, 24);
    for (char& c : t)
      if (!std::isprint(static_cast<unsigned char>(c))) c = '?';
    return t;
  }
  const Token& next() {
    if (pos_ >= tokens_.size()) fail("unexpected end of file");
    return tokens_[pos_++];
  }
  void expect(const std::string& word) {
    if (peek() != word) fail("expected '" + word + "', found '" + shown() + "'");
    ++pos_;
  }
  float number() {
    const std::string& t = next().text;
    char* end = nullptr;
    const float v = std::strtof(t.c_str(), &end);
    if (end == t.c_str() || *end != '\0' || !std::isfinite(v)) {
      --pos_;
      fail("expected a number, found '" + t + "'");
    }
    return v;
  }
  glm::vec3 vec3() {
    const float x = number(), y = number(), z = number();
    return {x, y, z};
  }

  Channel channel() {
    static const std::map<std::string, Channel> names = {
        {"Xposition", Channel::Xposition}, {"Yposition", Channel::Yposition}, {"Zposition", Channel::Zposition},
        {"Xrotation", Channel::Xrotation}, {"Yrotation", Channel::Yrotation}, {"Zrotation", Channel::Zrotation}};
    auto it = names.find(peek());
    if (it == names.end()) fail("unknown channel '" + shown() + "'");
    ++pos_;
    return it->second;
  }

  void parseJoint(int parent) {
    ++pos_;  // ROOT or JOINT
    if (peek().empty() || peek() == "{") fail("joint without a name");
    BvhJoint joint;
    joint.name = next().text;
    joint.parent = parent;
    expect("{");
    expect("OFFSET");
    joint.offset = vec3();
    if (peek() == "CHANNELS") {
      ++pos_;
      const float n = number();
      if (n < 0 || n > 6 || n != std::floor(n)) fail("CHANNELS count must be 0..6");
      for (int c = 0; c < static_cast<int>(n); ++c) joint.channels.push_back(channel());
    }
    joint.firstChannel = data_.channelCount;
    data_.channelCount += static_cast<int>(joint.channels.size());
    const int index = static_cast<int>(data_.joints.size());
    data_.joints.push_back(std::move(joint));
    while (peek() != "}") {
      if (peek() == "JOINT") {
        parseJoint(index);
      } else if (peek() == "End") {
        ++pos_;
        expect("Site");
        expect("{");
        expect("OFFSET");
        vec3();
        expect("}");
      } else {
        fail("expected JOINT, End Site or '}', found '" + shown() + "'");
      }
    }
    expect("}");
  }

  void parseMotion() {
    expect("Frames:");
    const float frames = number();
    --pos_;  // problems with the count point at its own line
    if (frames < 1 || frames != std::floor(frames)) fail("Frames must be a positive whole number");
    if (frames > 1e8f) fail("implausible frame count " + std::to_string(static_cast<long long>(frames)));
    ++pos_;
    data_.frames = static_cast<int>(frames);
    expect("Frame");
    expect("Time:");
    data_.frameTime = number();
    if (!(data_.frameTime > 0.0f)) fail("Frame Time must be positive");
    // Reserve by what the file holds, not by what it declares.
    data_.values.reserve(std::min(size_t(data_.frames) * data_.channelCount, tokens_.size() - pos_));
    for (int f = 0; f < data_.frames; ++f) {
      if (pos_ >= tokens_.size())
        fail("file ends after " + std::to_string(f) + " of " + std::to_string(data_.frames) + " frames");
      const int line = tokens_[pos_].line;
      int count = 0;
      while (pos_ < tokens_.size() && tokens_[pos_].line == line) {
        data_.values.push_back(number());
        ++count;
      }
      if (count != data_.channelCount)
        throw FileError(path_, "line " + std::to_string(line) + ": frame " + std::to_string(f) + " has " +
                                   std::to_string(count) + " values, expected " + std::to_string(data_.channelCount));
    }
    if (pos_ < tokens_.size()) fail("more frame rows than the declared " + std::to_string(data_.frames));
  }

  std::string path_;
  std::vector<Token> tokens_;
  size_t pos_ = 0;
  BvhData data_;
};

BvhData readBvh(const std::string& path) {
  const std::string text = loadFileText(path);
  // Joint names become bone names in documents and JSON: they must be text.
  const size_t bad = firstInvalidUtf8(text);
  if (bad != std::string::npos) {
    const long line = 1 + std::count(text.begin(), text.begin() + long(bad), '\n');
    throw FileError(path, "line " + std::to_string(line) + ": not UTF-8 text (byte " + std::to_string(bad) + ")");
  }
  return BvhParser(path, text).parse();
}

Skeleton skeletonOf(const BvhData& bvh) {
  Skeleton skeleton;
  for (const BvhJoint& j : bvh.joints) {
    Bone bone;
    bone.name = j.name;
    bone.parent = j.parent;
    bone.rest.translation = j.offset;
    skeleton.addBone(std::move(bone));
  }
  return skeleton;
}

// Local transforms of every joint at one frame: position channels replace
// the offset's components; rotations compose in channel order.
Pose framePose(const BvhData& bvh, int frame) {
  Pose pose(bvh.joints.size());
  const float* row = bvh.values.data() + size_t(frame) * bvh.channelCount;
  for (size_t j = 0; j < bvh.joints.size(); ++j) {
    const BvhJoint& joint = bvh.joints[j];
    Trs& trs = pose[j];
    trs.translation = joint.offset;
    for (size_t c = 0; c < joint.channels.size(); ++c) {
      const float v = row[joint.firstChannel + c];
      switch (joint.channels[c]) {
        case Channel::Xposition:
          trs.translation.x = v;
          break;
        case Channel::Yposition:
          trs.translation.y = v;
          break;
        case Channel::Zposition:
          trs.translation.z = v;
          break;
        case Channel::Xrotation:
          trs.rotation = trs.rotation * glm::angleAxis(glm::radians(v), glm::vec3(1, 0, 0));
          break;
        case Channel::Yrotation:
          trs.rotation = trs.rotation * glm::angleAxis(glm::radians(v), glm::vec3(0, 1, 0));
          break;
        case Channel::Zrotation:
          trs.rotation = trs.rotation * glm::angleAxis(glm::radians(v), glm::vec3(0, 0, 1));
          break;
      }
    }
  }
  return pose;
}

bool hasPosition(const BvhJoint& j) {
  return std::any_of(j.channels.begin(), j.channels.end(), [](Channel c) { return c <= Channel::Zposition; });
}
bool hasRotation(const BvhJoint& j) {
  return std::any_of(j.channels.begin(), j.channels.end(), [](Channel c) { return c >= Channel::Xrotation; });
}

Track emptyTrack(int frames, bool rotation) {
  Track t;
  t.interpolation = Interpolation::Linear;
  t.components = rotation ? 4 : 3;
  t.isRotation = rotation;
  t.times.reserve(frames);
  t.values.reserve(size_t(frames) * t.components);
  return t;
}

void appendKey(Track& track, float time, const glm::vec3& v) {
  track.times.push_back(time);
  track.values.insert(track.values.end(), {v.x, v.y, v.z});
}
void appendKey(Track& track, float time, const glm::quat& q) {
  track.times.push_back(time);
  track.values.insert(track.values.end(), {q.x, q.y, q.z, q.w});
}

// --- retargeting -----------------------------------------------------------

glm::quat rotationOf(const glm::mat4& m) { return Trs::fromMatrix(m).rotation; }

// Vertical extent of the given world positions.
float heightOf(const std::vector<glm::vec3>& points) {
  if (points.empty()) return 0.0f;
  float lo = points[0].y, hi = points[0].y;
  for (const glm::vec3& p : points) lo = std::min(lo, p.y), hi = std::max(hi, p.y);
  return hi - lo;
}

float heightRatio(const std::vector<glm::mat4>& bvhRest, const std::vector<glm::mat4>& targetRest,
                  const std::vector<int>& boneOfJoint) {
  std::vector<glm::vec3> bvhPoints, targetPoints;
  for (size_t j = 0; j < boneOfJoint.size(); ++j) {
    if (boneOfJoint[j] < 0) continue;
    bvhPoints.push_back(glm::vec3(bvhRest[j][3]));
    targetPoints.push_back(glm::vec3(targetRest[boneOfJoint[j]][3]));
  }
  const float hb = heightOf(bvhPoints), ht = heightOf(targetPoints);
  return hb > 1e-6f && ht > 1e-6f ? ht / hb : 1.0f;
}

glm::vec3 originOf(const glm::mat4& m) { return glm::vec3(m[3]); }

// Rotations that turn each driven bone's rest direction (towards its only
// child) onto its BVH joint's rest direction, so a T-pose motion drives an
// A-pose skeleton sensibly. Identity where either side branches or ends.
std::vector<glm::quat> restAlignment(const BvhData& bvh, const std::vector<glm::mat4>& sourceRest,
                                     const Skeleton& target, const std::vector<glm::mat4>& targetRest,
                                     const std::vector<int>& jointOfBone) {
  std::vector<glm::quat> align(target.boneCount(), glm::quat(1, 0, 0, 0));
  for (int b = 0; b < target.boneCount(); ++b) {
    const int j = jointOfBone[b];
    if (j < 0) continue;
    std::vector<int> jointChildren;
    for (size_t c = 0; c < bvh.joints.size(); ++c)
      if (bvh.joints[c].parent == j) jointChildren.push_back(static_cast<int>(c));
    const std::vector<int> boneChildren = target.children(b);
    if (jointChildren.size() != 1 || boneChildren.size() != 1) continue;
    const glm::vec3 dt = originOf(targetRest[boneChildren[0]]) - originOf(targetRest[b]);
    const glm::vec3 db = originOf(sourceRest[jointChildren[0]]) - originOf(sourceRest[j]);
    if (glm::length(dt) < 1e-6f || glm::length(db) < 1e-6f) continue;
    align[b] = glm::rotation(glm::normalize(dt), glm::normalize(db));
  }
  return align;
}

// Where the root goes, from its first-frame position, in the character's units.
glm::vec3 rootDisplacement(const glm::vec3& bvhDisplacement, float scale, bool inPlace) {
  glm::vec3 d = scale * bvhDisplacement;
  if (inPlace) d.x = d.z = 0.0f;  // Y is up: the vertical bob of a walk stays
  return d;
}

Clip retarget(const BvhData& bvh, const std::vector<int>& boneOfJoint, const Skeleton& target, const std::string& name,
              bool inPlace) {
  const Skeleton source = skeletonOf(bvh);
  const std::vector<glm::mat4> sourceRest = source.worldTransforms(source.restPose());
  const Pose targetRestPose = target.restPose();
  const std::vector<glm::mat4> targetRest = target.worldTransforms(targetRestPose);
  const int bones = target.boneCount();

  std::vector<int> jointOfBone(bones, -1);
  int rootJoint = -1;
  for (size_t j = 0; j < boneOfJoint.size(); ++j) {
    if (boneOfJoint[j] < 0) continue;
    jointOfBone[boneOfJoint[j]] = static_cast<int>(j);
    if (rootJoint < 0 && hasPosition(bvh.joints[j])) rootJoint = static_cast<int>(j);
  }
  const float scale = heightRatio(sourceRest, targetRest, boneOfJoint);
  const std::vector<glm::quat> align = restAlignment(bvh, sourceRest, target, targetRest, jointOfBone);

  Clip clip;
  clip.name = name;
  std::vector<int> channelOfBone(bones, -1);
  for (int b = 0; b < bones; ++b) {
    if (jointOfBone[b] < 0) continue;
    channelOfBone[b] = static_cast<int>(clip.boneChannels.size());
    BoneChannel channel;
    channel.bone = b;
    channel.rotation = emptyTrack(bvh.frames, true);
    if (jointOfBone[b] == rootJoint) channel.translation = emptyTrack(bvh.frames, false);
    clip.boneChannels.push_back(std::move(channel));
  }

  const glm::vec3 firstRootPosition =
      rootJoint >= 0 ? glm::vec3(source.worldTransforms(framePose(bvh, 0))[rootJoint][3]) : glm::vec3(0.0f);
  std::vector<glm::quat> worldRotation(bones);
  std::vector<glm::mat4> sourceWorld;
  for (int f = 0; f < bvh.frames; ++f) {
    const float time = f * bvh.frameTime;
    source.worldTransforms(framePose(bvh, f), sourceWorld);
    for (int b = 0; b < bones; ++b) {
      const Bone& bone = target.bone(b);
      const glm::quat parentRotation =
          (bone.parent >= 0 ? worldRotation[bone.parent] : glm::quat(1, 0, 0, 0)) * rotationOf(bone.parentFromOffset);
      glm::quat local = bone.rest.rotation;
      const int j = jointOfBone[b];
      if (j >= 0) {
        const glm::quat change = rotationOf(sourceWorld[j]) * glm::inverse(rotationOf(sourceRest[j]));
        local = glm::normalize(glm::inverse(parentRotation) * change * align[b] * rotationOf(targetRest[b]));
        BoneChannel& channel = clip.boneChannels[channelOfBone[b]];
        appendKey(channel.rotation, time, local);
        if (j == rootJoint) {
          const glm::mat4 parentRest =
              (bone.parent >= 0 ? targetRest[bone.parent] : glm::mat4(1.0f)) * bone.parentFromOffset;
          const glm::vec3 displacement =
              rootDisplacement(glm::vec3(sourceWorld[j][3]) - firstRootPosition, scale, inPlace);
          appendKey(channel.translation, time,
                    bone.rest.translation + glm::inverse(glm::mat3(parentRest)) * displacement);
        }
      }
      worldRotation[b] = parentRotation * local;
    }
  }
  return clip;
}

std::string stemOf(const std::string& path) { return std::filesystem::path(path).stem().string(); }

}  // namespace

Character loadBvhCharacter(const std::string& bvhPath) {
  const BvhData bvh = readBvh(bvhPath);
  Character character;
  character.name = stemOf(bvhPath);
  character.sourcePath = bvhPath;
  character.skeleton = skeletonOf(bvh);

  Clip clip;
  clip.name = stemOf(bvhPath);
  for (size_t j = 0; j < bvh.joints.size(); ++j) {
    BoneChannel channel;
    channel.bone = static_cast<int>(j);
    if (hasRotation(bvh.joints[j])) channel.rotation = emptyTrack(bvh.frames, true);
    if (hasPosition(bvh.joints[j])) channel.translation = emptyTrack(bvh.frames, false);
    if (!bvh.joints[j].channels.empty()) clip.boneChannels.push_back(std::move(channel));
  }
  for (int f = 0; f < bvh.frames; ++f) {
    const Pose pose = framePose(bvh, f);
    for (BoneChannel& channel : clip.boneChannels) {
      const BvhJoint& joint = bvh.joints[channel.bone];
      if (hasRotation(joint)) appendKey(channel.rotation, f * bvh.frameTime, pose[channel.bone].rotation);
      if (hasPosition(joint)) appendKey(channel.translation, f * bvh.frameTime, pose[channel.bone].translation);
    }
  }
  character.clips.push_back(std::move(clip));
  return character;
}

BoneMatchReport matchBvhMotion(const std::string& bvhPath, const Character& target, const std::string& nameMapPath) {
  return matchBones(skeletonOf(readBvh(bvhPath)), target.skeleton, nameMapPath);
}

RetargetedMotion retargetBvhMotion(const std::string& bvhPath, const Character& target, const MotionOptions& options) {
  const BvhData bvh = readBvh(bvhPath);
  RetargetedMotion motion;
  motion.match = matchBones(skeletonOf(bvh), target.skeleton, options.nameMapPath);
  if (motion.match.matchedCount() == 0)
    throw FileError(bvhPath, "no BVH joint matches a bone of '" + target.name +
                                 "' (give a name map: lines 'bvh_joint_name target_bone_name')");
  motion.clip = retarget(bvh, motion.match.boneOfJoint(), target.skeleton, stemOf(bvhPath), options.inPlace);
  return motion;
}

Clip importBvhMotion(const std::string& bvhPath, const Character& target, const std::string& nameMapPath) {
  return retargetBvhMotion(bvhPath, target, {nameMapPath, false}).clip;
}

}  // namespace mq
