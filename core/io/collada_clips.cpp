#include "core/io/collada_clips.h"

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <cstring>
#include <map>
#include <sstream>

#include "core/util/error.h"

namespace mq {
namespace {

// Just enough XML for Collada: elements, attributes, text; comments,
// processing instructions and DOCTYPE skipped.
struct XmlNode {
  std::string tag;
  std::map<std::string, std::string> attributes;
  std::string text;
  std::vector<XmlNode> children;

  std::string attribute(const std::string& name) const {
    auto it = attributes.find(name);
    return it == attributes.end() ? std::string() : it->second;
  }
  void collect(const std::string& name, std::vector<const XmlNode*>& out) const {
    if (tag == name) out.push_back(this);
    for (const XmlNode& c : children) c.collect(name, out);
  }
  std::vector<const XmlNode*> all(const std::string& name) const {
    std::vector<const XmlNode*> out;
    collect(name, out);
    return out;
  }
};

class XmlReader {
 public:
  XmlReader(const std::string& text, const std::string& path) : s_(text), path_(path) {}

  XmlNode document() {
    XmlNode root;
    root.tag = "#document";
    readChildren(root);
    return root;
  }

 private:
  [[noreturn]] void fail(const std::string& problem) const {
    const int line = 1 + static_cast<int>(std::count(s_.begin(), s_.begin() + std::min(i_, s_.size()), '\n'));
    throw FileError(path_, "line " + std::to_string(line) + ": " + problem);
  }
  bool startsWith(const char* p) const { return s_.compare(i_, std::strlen(p), p) == 0; }
  void skipPast(const char* end) {
    const size_t at = s_.find(end, i_);
    if (at == std::string::npos) fail(std::string("unterminated markup, missing '") + end + "'");
    i_ = at + std::strlen(end);
  }
  std::string name() {
    const size_t start = i_;
    while (i_ < s_.size() && !std::isspace(static_cast<unsigned char>(s_[i_])) && s_[i_] != '>' && s_[i_] != '/' &&
           s_[i_] != '=')
      ++i_;
    if (i_ == start) fail("expected a name");
    return s_.substr(start, i_ - start);
  }
  void skipSpace() {
    while (i_ < s_.size() && std::isspace(static_cast<unsigned char>(s_[i_]))) ++i_;
  }

  // Reads children until the parent's closing tag (or the end for the document).
  void readChildren(XmlNode& parent) {
    while (i_ < s_.size()) {
      const size_t lt = s_.find('<', i_);
      parent.text.append(s_, i_, (lt == std::string::npos ? s_.size() : lt) - i_);
      if (lt == std::string::npos) {
        i_ = s_.size();
        break;
      }
      i_ = lt;
      if (startsWith("<!--")) {
        skipPast("-->");
        continue;
      }
      if (startsWith("<![CDATA[")) {
        i_ += 9;
        const size_t end = s_.find("]]>", i_);
        if (end == std::string::npos) fail("unterminated CDATA");
        parent.text.append(s_, i_, end - i_);
        i_ = end + 3;
        continue;
      }
      if (startsWith("<?") || startsWith("<!")) {
        skipPast(">");
        continue;
      }
      if (startsWith("</")) {
        i_ += 2;
        const std::string closing = name();
        if (closing != parent.tag) fail("</" + closing + "> closes <" + parent.tag + ">");
        skipPast(">");
        return;
      }
      ++i_;
      parent.children.push_back(readElement());
    }
    if (parent.tag != "#document") fail("file ends inside <" + parent.tag + ">");
  }

  XmlNode readElement() {
    XmlNode node;
    node.tag = name();
    for (;;) {
      skipSpace();
      if (i_ >= s_.size()) fail("file ends inside a tag");
      if (s_[i_] == '/') {
        skipPast(">");
        return node;
      }
      if (s_[i_] == '>') {
        ++i_;
        break;
      }
      const std::string key = name();
      skipSpace();
      if (i_ >= s_.size() || s_[i_] != '=') fail("attribute '" + key + "' has no value");
      ++i_;
      skipSpace();
      const char quote = i_ < s_.size() ? s_[i_] : '\0';
      if (quote != '"' && quote != '\'') fail("attribute '" + key + "' is not quoted");
      const size_t end = s_.find(quote, i_ + 1);
      if (end == std::string::npos) fail("unterminated attribute value");
      node.attributes[key] = s_.substr(i_ + 1, end - i_ - 1);
      i_ = end + 1;
    }
    readChildren(node);
    return node;
  }

  const std::string& s_;
  std::string path_;
  size_t i_ = 0;
};

std::vector<float> floatsOf(const std::string& text) {
  std::vector<float> out;
  const char* p = text.c_str();
  char* end = nullptr;
  for (float v = std::strtof(p, &end); end != p; v = std::strtof(p, &end)) {
    out.push_back(v);
    p = end;
  }
  return out;
}

std::string stripHash(const std::string& ref) { return !ref.empty() && ref[0] == '#' ? ref.substr(1) : ref; }

struct Library {
  std::map<std::string, const XmlNode*> byId;
  std::map<std::string, std::string> nodeNames;  // node id -> name

  const XmlNode* find(const std::string& ref) const {
    auto it = byId.find(stripHash(ref));
    return it == byId.end() ? nullptr : it->second;
  }
  // The float_array or Name_array text of a <source>.
  std::string arrayText(const XmlNode* source, const char* arrayTag) const {
    for (const XmlNode& c : source->children)
      if (c.tag == arrayTag) return c.text;
    return {};
  }
};

void indexIds(const XmlNode& node, Library& lib) {
  const std::string id = node.attribute("id");
  if (!id.empty()) lib.byId.emplace(id, &node);
  if (node.tag == "node" && !id.empty()) lib.nodeNames[id] = node.attribute("name");
  for (const XmlNode& c : node.children) indexIds(c, lib);
}

// One <channel> of an <animation> as a whole-matrix node track; false if the
// channel is of a kind this reader does not handle.
bool readChannel(const Library& lib, const XmlNode& channel, ColladaNodeTrack& track) {
  const std::string target = channel.attribute("target");
  const size_t slash = target.find('/');
  if (slash == std::string::npos || target.find_first_of(".(", slash) != std::string::npos) return false;
  const XmlNode* sampler = lib.find(channel.attribute("source"));
  if (!sampler) return false;
  std::string input, output, interpolation;
  for (const XmlNode& in : sampler->children) {
    if (in.tag != "input") continue;
    const std::string semantic = in.attribute("semantic");
    if (semantic == "INPUT")
      input = in.attribute("source");
    else if (semantic == "OUTPUT")
      output = in.attribute("source");
    else if (semantic == "INTERPOLATION")
      interpolation = in.attribute("source");
  }
  const XmlNode* inputSource = lib.find(input);
  const XmlNode* outputSource = lib.find(output);
  if (!inputSource || !outputSource) return false;
  track.times = floatsOf(lib.arrayText(inputSource, "float_array"));
  const std::vector<float> values = floatsOf(lib.arrayText(outputSource, "float_array"));
  if (track.times.empty() || values.size() != 16 * track.times.size()) return false;
  for (size_t k = 0; k < track.times.size(); ++k) {
    glm::mat4 m;
    for (int r = 0; r < 4; ++r)
      for (int c = 0; c < 4; ++c) m[c][r] = values[16 * k + 4 * r + c];  // Collada matrices are row-major
    track.matrices.push_back(m);
  }
  if (const XmlNode* interp = lib.find(interpolation))
    track.step = lib.arrayText(interp, "Name_array").find("STEP") != std::string::npos;
  track.nodeId = target.substr(0, slash);
  auto name = lib.nodeNames.find(track.nodeId);
  if (name == lib.nodeNames.end()) return false;
  track.nodeName = name->second;
  return true;
}

std::vector<ColladaClip> readClips(const XmlNode& root, const Library& lib) {
  std::vector<ColladaClip> clips;
  for (const XmlNode* clipNode : root.all("animation_clip")) {
    ColladaClip clip;
    clip.name = clipNode->attribute("name");
    if (clip.name.empty()) clip.name = clipNode->attribute("id");
    clip.start = std::strtof(clipNode->attribute("start").c_str(), nullptr);
    clip.end = clipNode->attribute("end").empty() ? -1.0f : std::strtof(clipNode->attribute("end").c_str(), nullptr);
    for (const XmlNode& instance : clipNode->children) {
      if (instance.tag != "instance_animation") continue;
      const XmlNode* animation = lib.find(instance.attribute("url"));
      if (!animation) return {};
      for (const XmlNode* channel : animation->all("channel")) {
        ColladaNodeTrack track;
        if (!readChannel(lib, *channel, track)) return {};
        clip.tracks.push_back(std::move(track));
      }
    }
    clips.push_back(std::move(clip));
  }
  return clips;
}

// Joint names of <skin> elements are node sids or ids; returns node names.
std::vector<std::string> readJointNodes(const XmlNode& root, const Library& lib) {
  std::map<std::string, std::string> nodeBySid;
  for (const XmlNode* node : root.all("node")) {
    const std::string name = node->attribute("name").empty() ? node->attribute("id") : node->attribute("name");
    if (!node->attribute("sid").empty()) nodeBySid[node->attribute("sid")] = name;
    if (!node->attribute("id").empty()) nodeBySid.emplace(node->attribute("id"), name);
  }
  std::vector<std::string> joints;
  for (const XmlNode* skin : root.all("skin"))
    for (const XmlNode* joints_ : skin->all("joints"))
      for (const XmlNode& input : joints_->children) {
        if (input.tag != "input" || input.attribute("semantic") != "JOINT") continue;
        const XmlNode* source = lib.find(input.attribute("source"));
        if (!source) continue;
        std::istringstream names(lib.arrayText(source, "Name_array"));
        for (std::string n; names >> n;)
          if (auto it = nodeBySid.find(n); it != nodeBySid.end()) joints.push_back(it->second);
      }
  return joints;
}

}  // namespace

ColladaExtras readColladaExtras(const std::string& xmlText, const std::string& path) {
  ColladaExtras extras;
  if (xmlText.empty()) return extras;
  const XmlNode root = XmlReader(xmlText, path).document();
  Library lib;
  indexIds(root, lib);
  extras.clips = readClips(root, lib);
  extras.jointNodes = readJointNodes(root, lib);
  return extras;
}

}  // namespace mq
