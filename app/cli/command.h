#pragma once
// mannequin-cli subcommands register themselves here; each lives in its own
// cmd_<name>.cpp and is linked into the executable.

#include <functional>
#include <string>
#include <vector>

namespace mq {
struct Character;
struct LoadedScene;
struct BoneMatchReport;
}  // namespace mq

namespace mq::cli {

struct Command {
  std::string name;
  std::string usage;    // one line: arguments
  std::string summary;  // one line: what it does
  // Returns the process exit code; throws mq::Error for user errors.
  std::function<int(const std::vector<std::string>& args)> run;
  std::string details = {};  // shown by "<command> --help" only, after the summary
};

std::vector<Command>& commands();

struct Registration {
  explicit Registration(Command c) { commands().push_back(std::move(c)); }
};

// Small argument helpers shared by the commands.
class Args {
 public:
  explicit Args(const std::vector<std::string>& args);
  // Value of --name, or fallback when absent; throws mq::Error if the flag has no value.
  std::string option(const std::string& name, const std::string& fallback = "") const;
  bool has(const std::string& name) const;  // --name present (flag or option)
  double number(const std::string& name, double fallback) const;
  const std::vector<std::string>& positional() const { return positional_; }
  // Throws mq::Error when an option not in `known` was given.
  void allowOnly(const std::vector<std::string>& known) const;

 private:
  std::vector<std::string> positional_;
  std::vector<std::pair<std::string, std::string>> options_;  // "--x" -> value ("" for flags)
};

// --skinning lbs|dqs|cones: overrides the method the scene (or file) chose.
// --helper-bones: adds helper bones at the joints (a humanoid's).
// --regenerate-weights, --smooth-weights: rebuild the skin weights
// (weight_regeneration.h) before the helper bones are added.
// Throws mq::Error naming the choices for an unknown method, or why a
// character cannot have helper bones.
void applySkinningOption(const Args& args, LoadedScene& scene);
// " with N helper bones" for a character that has them, else "" (for summaries).
std::string withHelperBones(const Character& character);
// --scale S: the character file's units to metres (0.01 for centimetres);
// --auto-rig: a mesh without bones gets a humanoid skeleton and skin
// (core/character/auto_rig.h), to pose and to play motions on. Throws
// mq::Error for a scale that is not a positive number or a mesh the auto-rig
// refuses.
void applyCharacterOptions(const Args& args, LoadedScene& scene);

// --clip NAME|INDEX|rest: the clip to play, -1 for rest (the rest pose with
// the document's pose edits); without it, the scene's clip (-1 when the
// document names none). Throws mq::FileError naming `file` and the clips it
// has for an unknown clip.
int clipOption(const Args& args, const LoadedScene& scene, const std::string& file);
// "clip 'walk'", or "the rest pose" for -1 (for summaries).
std::string clipLabel(const LoadedScene& scene, int clip);

// "motion walk.bvh: matched 19 of 31 bones; unmatched: ..." on stderr, beside
// the load warnings, so that --json output on stdout stays valid.
void printMotionMatch(const std::string& bvhPath, const BoneMatchReport& match);
// The same for the motion a scene document applied, if it has one.
void printMotionMatch(const LoadedScene& scene);

}  // namespace mq::cli
