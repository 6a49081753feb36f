#include "core/skinning/skinning_method.h"

namespace mq {
namespace {

constexpr SkinningMethod kAll[] = {SkinningMethod::Lbs, SkinningMethod::Dqs, SkinningMethod::Cones};

}  // namespace

const char* skinningMethodName(SkinningMethod method) {
  switch (method) {
    case SkinningMethod::Lbs:
      return "lbs";
    case SkinningMethod::Dqs:
      return "dqs";
    case SkinningMethod::Cones:
      return "cones";
  }
  return "lbs";
}

std::optional<SkinningMethod> parseSkinningMethod(const std::string& name) {
  for (SkinningMethod m : kAll)
    if (name == skinningMethodName(m)) return m;
  return std::nullopt;
}

std::string skinningMethodChoices() { return "lbs, dqs or cones"; }

}  // namespace mq
