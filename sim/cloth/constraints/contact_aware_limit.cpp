#include "sim/cloth/constraints/contact_aware_limit.h"

#include <algorithm>

#include "sim/cloth/parallel.h"

namespace mq::cloth {
namespace {

// The limit with contact vertices heavy, in rounds that put back what went
// in (see the header).
ContactAwareLimitResult limitKeepingContactsOut(ClothState& state, const ContactSet& contacts, StretchLimiter& limiter,
                                                const ContactAwareLimitSettings& settings,
                                                const std::vector<float>& freeInvMass) {
  const std::vector<uint8_t>& touched = contacts.touched;
  const float thickness = settings.thickness;
  const bool body = static_cast<bool>(contacts.nearestBody);
  std::vector<glm::vec3> normal(body ? state.size() : 0, glm::vec3(0.0f));
  std::vector<float> allowedIn(normal.size(), 0.0f);  // how far along -normal a vertex may go
  const std::vector<glm::vec3> start = body ? state.x : std::vector<glm::vec3>{};
  if (body)
    forRange(state.size(), [&](size_t b, size_t e) {
      for (size_t i = b; i < e; ++i) {
        BodyContact contact;
        if (!touched[i] || freeInvMass[i] == 0.0f || !contacts.nearestBody(i, 2.0f * thickness, contact)) continue;
        normal[i] = contact.normal;
        allowedIn[i] = std::max(0.0f, contact.signedDistance - 0.5f * thickness);
      }
    });
  const int rounds = body ? settings.bodyRounds : 1;
  StretchLimitResult r;
  ContactAwareLimitResult result;
  for (int round = 0; round < rounds; ++round) {
    if (round > 0) {
      bool putBack = false;
      for (size_t i = 0; i < normal.size(); ++i) {
        const float in = -glm::dot(state.x[i] - start[i], normal[i]) - allowedIn[i];
        if (normal[i] == glm::vec3(0.0f) || in <= 0.0f) continue;
        state.x[i] += in * normal[i];
        state.v[i] += (in / settings.h) * normal[i];
        putBack = true;
      }
      // Nothing moved since a round that held: the rounds left would change nothing.
      if (contacts.pushBodyVerticesOut() == 0 && !putBack && r.maxStretchAfter <= settings.maxStretch) break;
    }
    for (size_t i = 0; i < state.size(); ++i)
      if (touched[i]) state.invMass[i] = settings.contactInvMassScale * freeInvMass[i];
    // The last round gets what the others left of the budget.
    const int passes = round + 1 < rounds ? std::max(1, settings.passBudget / rounds)
                                          : std::max(1, settings.passBudget - result.passes);
    r = limiter.limitByPositions(state, settings.maxStretch, passes, settings.h);
    state.invMass = freeInvMass;
    result.passes += r.passes;
  }
  result.held = r.maxStretchAfter <= settings.maxStretch;
  return result;
}

}  // namespace

ContactAwareLimitResult limitStretchAroundContacts(ClothState& state, const ContactSet& contacts,
                                                   StretchLimiter& limiter, const ContactAwareLimitSettings& settings) {
  const std::vector<float> freeInvMass = state.invMass;
  const std::vector<uint8_t>& touched = contacts.touched;
  int heldPasses = 0;
  if (std::find(touched.begin(), touched.end(), contacts.swept) != touched.end()) {
    const std::vector<glm::vec3> x = state.x, v = state.v;
    for (size_t i = 0; i < state.size(); ++i)
      if (touched[i] == contacts.swept)
        state.invMass[i] = 0.0f;
      else if (touched[i])
        state.invMass[i] = settings.contactInvMassScale * freeInvMass[i];
    const StretchLimitResult r =
        limiter.limitByPositions(state, settings.maxStretch, settings.heldPassBudget, settings.h);
    state.invMass = freeInvMass;
    heldPasses = r.passes;
    if (r.maxStretchAfter <= settings.maxStretch) return {true, heldPasses};
    state.x = x, state.v = v;
  }
  ContactAwareLimitResult result = limitKeepingContactsOut(state, contacts, limiter, settings, freeInvMass);
  result.passes += heldPasses;
  return result;
}

}  // namespace mq::cloth
