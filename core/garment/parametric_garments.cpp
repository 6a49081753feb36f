#include "core/garment/parametric_garments.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "core/character/character.h"
#include "core/garment/body_measurements.h"
#include "core/util/error.h"

namespace mq {
namespace {

constexpr float kPi = 3.14159265f;
const glm::vec3 kUp(0, 1, 0), kForward(0, 0, 1);

using Params = std::map<std::string, float>;

// ---- Placement clear of the body --------------------------------------------

bool insidePolygon(const std::vector<glm::vec2>& polygon, glm::vec2 p) {
  bool inside = false;
  for (size_t i = 0, j = polygon.size() - 1; i < polygon.size(); j = i++) {
    glm::vec2 a = polygon[i], b = polygon[j];
    if ((a.y > p.y) != (b.y > p.y) && p.x < (b.x - a.x) * (p.y - a.y) / (b.y - a.y) + a.x) inside = !inside;
  }
  return inside;
}

// Points covering a panel (outline and an interior grid): every point of the
// panel lies within `spacing` of one of them.
std::vector<glm::vec2> coverPoints(const Panel& panel, float spacing) {
  std::vector<glm::vec2> outline = panel.outline(spacing), points = outline;
  glm::vec2 lo(1e30f), hi(-1e30f);
  for (glm::vec2 p : outline) lo = glm::min(lo, p), hi = glm::max(hi, p);
  for (float y = lo.y; y <= hi.y; y += spacing)
    for (float x = lo.x; x <= hi.x; x += spacing)
      if (insidePolygon(outline, {x, y})) points.push_back({x, y});
  return points;
}

constexpr float kCoverSpacing = 0.01f;

float clearance(const std::vector<BodyCapsule>& capsules, const Panel& panel) {
  float nearest = 1e30f;
  for (glm::vec2 p : coverPoints(panel, kCoverSpacing))
    nearest = std::min(nearest, distanceToCapsules(capsules, panel.placement.place(p)));
  return nearest - kCoverSpacing;  // the worst point between two samples
}

// The bone whose capsule comes closest to the panels (for error messages).
std::string nearestBone(const std::vector<BodyCapsule>& capsules, const std::vector<Panel*>& panels) {
  float nearest = 1e30f;
  std::string bone = "body";
  for (const Panel* panel : panels)
    for (glm::vec2 p : coverPoints(*panel, kCoverSpacing))
      for (const BodyCapsule& c : capsules)
        if (float d = c.distance(panel->placement.place(p)); d < nearest)
          nearest = d, bone = "bone '" + c.boneName + "'";
  return bone;
}

// Grows `value` in steps until every panel surely clears the body by half
// `margin` (most of it by about `margin`);
// throws mq::Error when it reaches `limit` first.
template <typename Apply>
void growUntilClear(const std::vector<BodyCapsule>& capsules, std::vector<Panel*> panels, float margin, float value,
                    float limit, Apply apply) {
  for (; value < limit; value += 0.005f) {
    for (Panel* panel : panels) apply(*panel, value);
    bool clear = true;
    for (Panel* panel : panels) clear = clear && clearance(capsules, *panel) >= 0.5f * margin;
    if (clear) return;
  }
  std::string names;
  for (Panel* panel : panels) names += (names.empty() ? "" : ", ") + panel->name;
  throw Error("cannot place panel(s) " + names + " clear of the body (it meets the " + nearestBone(capsules, panels) +
              ")");
}

PanelPlacement cylinder(const std::string& bone, glm::vec3 center, glm::vec3 axis, glm::vec3 facing, float radius,
                        glm::vec2 anchor) {
  PanelPlacement p;
  p.shape = PanelPlacement::Shape::Cylinder;
  p.bone = bone;
  p.center = center;
  p.axis = glm::normalize(axis);
  p.facing = glm::normalize(facing - glm::dot(facing, p.axis) * p.axis);
  p.radius = radius;
  p.anchor = anchor;
  return p;
}

// Front and back panels around the vertical torso axis: the radius grows
// until both clear the body.
void wrapTorso(const BodyMeasurements& body, Panel& front, Panel& back, float topY, float anchorV, float offset) {
  float widest = 0.0f;
  for (const Panel* p : {&front, &back}) {
    float lo = 1e30f, hi = -1e30f;
    for (glm::vec2 c : p->outline(0.01f)) lo = std::min(lo, c.x), hi = std::max(hi, c.x);
    widest += hi - lo;
  }
  glm::vec3 center = body.torsoAxisAt(topY);
  front.placement = cylinder(body.spineBone, center, kUp, kForward, 0.1f, {0.0f, anchorV});
  back.placement = cylinder(body.spineBone, center, kUp, -kForward, 0.1f, {0.0f, anchorV});
  growUntilClear(body.capsules, {&front, &back}, offset, widest / (2.0f * kPi), 1.0f,
                 [](Panel& panel, float radius) { panel.placement.radius = radius; });
}

// ---- Parameters ---------------------------------------------------------------

// Body size relative to the default mannequin the defaults are made for: the
// neck joint's height over the ankles' (1.365 m there); 1 within 3%.
float bodyScale(const BodyMeasurements& body) {
  const float height = body.neck.y - 0.5f * (body.ankle[0].y + body.ankle[1].y);
  const float scale = height / 1.365f;
  return std::abs(scale - 1.0f) < 0.03f ? 1.0f : scale;
}

// Lengths scale with a smaller or larger body; circumferences (eases, the
// leg opening, the flare) do not: girths come from the skin, and a short body
// may have the thighs of a tall one. Nor does the offset from the body.
bool scalesWithBody(const std::string& parameter) {
  return parameter == "length" || parameter == "sleeveLength" || parameter == "sleeveCap" || parameter == "neckWidth";
}

Params resolve(const std::string& type, const Params& given, float scale) {
  Params values;
  std::vector<GarmentParameter> declared = garmentParameters(type);
  for (const GarmentParameter& p : declared)
    values[p.name] = scalesWithBody(p.name) ? std::clamp(scale * p.value, p.min, p.max) : p.value;
  for (const auto& [name, value] : given) {
    auto it = std::find_if(declared.begin(), declared.end(),
                           [&, &key = name](const GarmentParameter& p) { return p.name == key; });
    if (it == declared.end()) throw Error(type + ": unknown parameter '" + name + "'");
    if (!(value >= it->min && value <= it->max)) {
      std::ostringstream message;
      message << type << ": parameter '" << name << "' = " << value << " is outside [" << it->min << ", " << it->max
              << "]";
      throw Error(message.str());
    }
    values[name] = value;
  }
  return values;
}

Seam seam(const std::string& panelA, const std::string& edgeA, const std::string& panelB, const std::string& edgeB) {
  return {panelA, edgeA, panelB, edgeB, true};
}

// ---- T-shirt --------------------------------------------------------------------

constexpr float kShoulderSlope = 0.025f;  // shoulder seams drop this much from neck to shoulder
constexpr float kSleeveDrop = 0.08f;      // m down the arm from the shoulder joint, at least

// Front or back of a T-shirt: hem at v = 0, shoulders at v = length. `plusSide`
// names the body side at +u ("l" on the front, "r" on the back).

Panel shirtBody(const std::string& name, const std::string& plusSide, const std::string& minusSide, float halfWidth,
                float length, float armholeDepth, float shoulderHalf, float neckHalf, float neckDrop) {
  Panel p;
  p.name = name;
  float armpit = length - armholeDepth, slope = kShoulderSlope;
  p.addLine("hem", {-halfWidth, 0.0f});
  p.addLine("side_" + plusSide, {halfWidth, 0.0f});
  p.addQuadratic("armhole_" + plusSide, {halfWidth, armpit}, {shoulderHalf, armpit + 0.25f * armholeDepth});
  p.addLine("shoulder_" + plusSide, {shoulderHalf, length - slope});
  p.addCubic("neck", {neckHalf, length}, {0.5f * neckHalf, length - neckDrop}, {-0.5f * neckHalf, length - neckDrop});
  p.addLine("shoulder_" + minusSide, {-neckHalf, length});
  p.addQuadratic("armhole_" + minusSide, {-shoulderHalf, length - slope},
                 {-shoulderHalf, armpit + 0.25f * armholeDepth});
  p.addLine("side_" + minusSide, {-halfWidth, armpit});
  return p;
}

// A sleeve: cuff at v = 0, cap on top; u runs around the arm. cap_a is the
// half at +u, cap_b the half at -u.
Panel sleevePanel(const std::string& name, float circumference, float length, float capHeight) {
  Panel p;
  p.name = name;
  float half = 0.5f * circumference;
  p.addLine("cuff", {-half, 0.0f});
  p.addLine("under_a", {half, 0.0f});
  p.addQuadratic("cap_a", {half, length}, {0.5f * half, length + capHeight});
  p.addQuadratic("cap_b", {0.0f, length + capHeight}, {-0.5f * half, length + capHeight});
  p.addLine("under_b", {-half, length});
  return p;
}

// An upper arm's fitted capsule is about 1.55 times as thick as the radius of
// its measured girth (the default mannequin's: the deltoid and the joint's
// end). Much thicker, it is not the arm's: the bone also drives skin of the
// shoulder and chest (CesiumMan's left upper arm), and a sleeve sized and
// placed by it sticks out like a wing and closes its cap through the arm.
constexpr float kArmCapsuleGirthRadii = 1.55f, kArmBlobGirthRadii = 1.8f;

// The body's capsules as a sleeve sees them: an upper arm's blob (above)
// becomes a capsule of the usual thickness around the arm up to the elbow,
// along the sleeve's axis (shoulder to wrist: around a bent elbow too); the
// skin it leaves out belongs to the torso's capsules.
std::vector<BodyCapsule> sleeveCapsules(const BodyMeasurements& body) {
  std::vector<BodyCapsule> capsules = body.capsules;
  const float girthRadius = body.upperArmGirth / (2.0f * kPi);
  for (BodyCapsule& c : capsules)
    for (int s = 0; s < 2; ++s)
      if (c.boneName == body.upperArmBone[s] && c.radius > kArmBlobGirthRadii * girthRadius) {
        const glm::vec3 axis = glm::normalize(body.wrist[s] - body.shoulder[s]);
        c.a = body.shoulder[s];
        c.b = c.a + glm::dot(body.elbow[s] - c.a, axis) * axis;
        c.radius = kArmCapsuleGirthRadii * girthRadius + glm::length(body.elbow[s] - c.b);
      }
  return capsules;
}

// How much deeper the armholes are cut than for the default mannequin's arms,
// 45 degrees below level: by sin 45 / sin(angle) for more level arms (at most
// 1.6 times; 1 within 3%). A pattern sewn on arms held out (CesiumMan's, 29
// degrees) has its underarm pulled up when they come down to walk: with the
// default depth the sleeves' undersides and the sides under the armpits were
// caught between arm and torso (up to 32 vertices inside the body in a frame
// of its walk, 25 cut this way).
float armholeDeepening(const BodyMeasurements& body) {
  float below = 0.0f;
  for (int s = 0; s < 2; ++s) below += 0.5f * glm::normalize(body.shoulder[s] - body.wrist[s]).y;
  const float deepening = std::clamp(std::sin(0.25f * kPi) / std::max(below, 0.1f), 1.0f, 1.6f);
  return deepening < 1.03f ? 1.0f : deepening;
}

Garment makeTShirt(const BodyMeasurements& body, const Params& p) {
  Garment g;
  g.name = "T-shirt";
  float offset = p.at("offset");
  float shoulderY = 0.5f * (body.shoulder[0].y + body.shoulder[1].y);
  float topY = shoulderY + 0.05f;  // at least: the top of the shoulder, above the joint
  float halfWidth = 0.25f * (body.chestGirth + p.at("ease"));
  float shoulderHalf = std::min(std::abs(body.shoulder[0].x - body.torsoAxisAt(0).x), halfWidth - 0.03f);
  float neckHalf = std::min(0.5f * p.at("neckWidth"), shoulderHalf - 0.04f);
  // Sewing closes the gap between the front and back shoulder edges along
  // straight lines: they must start above the shoulders, or the seams stop
  // at the body instead of sliding over it.
  topY = std::max(topY, std::max(body.shoulderTop[0], body.shoulderTop[1]) + kShoulderSlope + offset);
  // A roomy armhole: the armpit corners of front, back and sleeve must meet
  // under the arm of an A-pose body without stretching past the limit; deeper
  // for arms held out.
  float length = p.at("length");
  float armholeDepth = std::min(0.25f * topY / 1.5f * armholeDeepening(body), 0.6f * length);
  g.panels.push_back(shirtBody("front", "l", "r", halfWidth, length, armholeDepth, shoulderHalf, neckHalf, 0.08f));
  g.panels.push_back(shirtBody("back", "r", "l", halfWidth, length, armholeDepth, shoulderHalf, neckHalf, 0.02f));
  wrapTorso(body, g.panels[0], g.panels[1], topY, length, offset);

  float circumference = body.upperArmGirth + p.at("sleeveEase");
  const std::vector<BodyCapsule> armCapsules = sleeveCapsules(body);
  for (int s = 0; s < 2; ++s) {
    std::string side = s == 0 ? "l" : "r";
    // A low cap holds the sleeve out like a wing when the arm comes down from
    // the A-pose it was sewn on; a set-in sleeve's cap lets it hang.
    Panel sleeve = sleevePanel("sleeve_" + side, circumference, p.at("sleeveLength"), p.at("sleeveCap"));
    // Along the whole arm (shoulder to wrist), not the upper arm alone: a long
    // sleeve then clears the forward-bent forearm and the hand.
    glm::vec3 axis = glm::normalize(body.shoulder[s] - body.wrist[s]);
    const BodyCapsule* arm = findCapsule(armCapsules, body.upperArmBone[s]);
    float radius = std::max(circumference / (2.0f * kPi), (arm ? arm->radius : 0.05f) + offset + 2.0f * kCoverSpacing);
    sleeve.placement =
        cylinder(body.upperArmBone[s], body.shoulder[s], axis, kUp, radius, {0.0f, p.at("sleeveLength")});
    glm::vec3 shoulder = body.shoulder[s];
    // Starts a little down the arm: a sleeve tube closing right at the
    // shoulder joint would have to pass where the arm meets the torso. (A
    // long sleeve moved down may meet the forearm: then from the joint.)
    auto moveDown = [&](Panel& panel, float shift) { panel.placement.center = shoulder - shift * axis; };
    try {
      growUntilClear(armCapsules, {&sleeve}, offset, kSleeveDrop, 0.4f, moveDown);
    } catch (const Error&) {
      growUntilClear(armCapsules, {&sleeve}, offset, 0.0f, 0.4f, moveDown);
    }
    g.panels.push_back(sleeve);
  }
  // Sleeve u runs axis x up: towards the back on the left arm, the front on the right.
  g.seams = {seam("front", "side_l", "back", "side_l"),          seam("front", "side_r", "back", "side_r"),
             seam("front", "shoulder_l", "back", "shoulder_l"),  seam("front", "shoulder_r", "back", "shoulder_r"),
             seam("front", "armhole_l", "sleeve_l", "cap_b"),    seam("back", "armhole_l", "sleeve_l", "cap_a"),
             seam("front", "armhole_r", "sleeve_r", "cap_a"),    seam("back", "armhole_r", "sleeve_r", "cap_b"),
             seam("sleeve_l", "under_a", "sleeve_l", "under_b"), seam("sleeve_r", "under_a", "sleeve_r", "under_b")};
  return g;
}

// ---- Skirt ------------------------------------------------------------------------

Panel skirtPanel(const std::string& name, const std::string& plusSide, const std::string& minusSide, float hemHalf,
                 float hipHalf, float waistHalf, float length, float hipDepth) {
  Panel p;
  p.name = name;
  float hipV = length - hipDepth;
  p.addLine("hem", {-hemHalf, 0.0f});
  p.addLine("side_" + plusSide, {hemHalf, 0.0f});
  p.addQuadratic("hip_" + plusSide, {hipHalf, hipV}, {hipHalf, length});
  p.addLine("waist", {waistHalf, length});
  p.addQuadratic("hip_" + minusSide, {-waistHalf, length}, {-hipHalf, length});
  p.addLine("side_" + minusSide, {-hipHalf, hipV});
  return p;
}

Garment makeSkirt(const BodyMeasurements& body, const Params& p) {
  Garment g;
  g.name = "Skirt";
  float length = p.at("length");
  float topY = body.waist.y;
  float hipDepth = std::clamp(topY - (body.hip[0].y - 0.03f), 0.05f, 0.6f * length);
  float waistHalf = 0.25f * (body.waistGirth + p.at("waistEase"));
  // A waist no narrower than the chest (CesiumMan's) holds no snug band: the
  // body narrows upwards and pushes it up. A looser band hangs from the hips.
  if (body.waistGirth >= body.chestGirth) waistHalf = std::max(waistHalf, 0.25f * 1.15f * body.waistGirth);
  float hipHalf = std::max(0.25f * (body.hipGirth + p.at("waistEase") + 0.04f), waistHalf);
  float hemHalf = hipHalf + 0.5f * p.at("flare");
  g.panels.push_back(skirtPanel("front", "l", "r", hemHalf, hipHalf, waistHalf, length, hipDepth));
  g.panels.push_back(skirtPanel("back", "r", "l", hemHalf, hipHalf, waistHalf, length, hipDepth));
  wrapTorso(body, g.panels[0], g.panels[1], topY, length, p.at("offset"));
  g.seams = {seam("front", "side_l", "back", "side_l"), seam("front", "hip_l", "back", "hip_l"),
             seam("front", "side_r", "back", "side_r"), seam("front", "hip_r", "back", "hip_r")};
  return g;
}

// ---- Trousers ---------------------------------------------------------------------

// One panel over both legs: hems at v = 0, the crotch at v = length - rise,
// the waist at v = length. Legs are centred at u = +-legCentre.
Panel trouserPanel(const std::string& name, const std::string& plusSide, const std::string& minusSide, float waistHalf,
                   float length, float rise, float legCentre, float legHalf) {
  Panel p;
  p.name = name;
  float crotch = length - rise, inner = legCentre - legHalf, outer = legCentre + legHalf;
  p.addLine("hem_" + minusSide, {-outer, 0.0f});
  p.addQuadratic("inseam_" + minusSide, {-inner, 0.0f}, {-inner, crotch});
  p.addQuadratic("inseam_" + plusSide, {0.0f, crotch}, {inner, crotch});
  p.addLine("hem_" + plusSide, {inner, 0.0f});
  p.addLine("outseam_" + plusSide, {outer, 0.0f});
  p.addLine("waist", {waistHalf, length});
  p.addLine("outseam_" + minusSide, {-waistHalf, length});
  return p;
}

Garment makeTrousers(const BodyMeasurements& body, const Params& p) {
  Garment g;
  g.name = "Trousers";
  float length = p.at("length"), topY = body.waist.y;
  // Below the body's crotch: the crotch seam closes front to back along
  // straight lines, which must not pass through the body.
  float crotchY = std::min(std::min(body.hip[0].y, body.hip[1].y) - 0.07f, body.crotchY - 2.0f * p.at("offset"));
  float rise = std::clamp(topY - crotchY, 0.1f, 0.6f * length);
  float waistHalf = 0.25f * (body.hipGirth + p.at("ease"));
  float legHalf = 0.25f * p.at("legOpening");
  float ankleOffset = 0.5f * (std::abs(body.ankle[0].x - body.ankle[1].x));
  float legCentre = std::max(ankleOffset + 0.02f, legHalf + 0.015f);
  waistHalf = std::max(waistHalf, legCentre + legHalf + 0.01f);
  g.panels.push_back(trouserPanel("front", "l", "r", waistHalf, length, rise, legCentre, legHalf));
  g.panels.push_back(trouserPanel("back", "r", "l", waistHalf, length, rise, legCentre, legHalf));
  wrapTorso(body, g.panels[0], g.panels[1], topY, length, p.at("offset"));
  g.seams = {seam("front", "outseam_l", "back", "outseam_l"), seam("front", "outseam_r", "back", "outseam_r"),
             seam("front", "inseam_l", "back", "inseam_l"), seam("front", "inseam_r", "back", "inseam_r")};
  return g;
}

}  // namespace

std::vector<std::string> parametricGarmentTypes() { return {"tshirt", "skirt", "trousers"}; }

std::vector<GarmentParameter> garmentParameters(const std::string& type) {
  GarmentParameter offset{"offset", 0.02f, 0.005f, 0.1f, "distance kept from the body when placed"};
  if (type == "tshirt")
    return {{"length", 0.66f, 0.35f, 1.1f, "shoulder to hem"},
            {"ease", 0.2f, 0.0f, 0.5f, "chest circumference added to the body's"},
            {"sleeveLength", 0.2f, 0.05f, 0.6f, "armhole to cuff, under the arm"},
            {"sleeveEase", 0.24f, 0.0f, 0.4f, "sleeve circumference added to the upper arm's"},
            {"sleeveCap", 0.18f, 0.03f, 0.3f, "sleeve cap height: taller hangs closer to the body"},
            {"neckWidth", 0.17f, 0.08f, 0.3f, "width of the neck opening"},
            offset};
  if (type == "skirt")
    return {{"length", 0.55f, 0.2f, 1.1f, "waist to hem"},
            {"waistEase", 0.04f, 0.0f, 0.3f, "waist circumference added to the body's"},
            {"flare", 0.3f, 0.0f, 1.0f, "width added at the hem of each panel"},
            offset};
  if (type == "trousers")
    return {{"length", 0.9f, 0.3f, 1.3f, "waist to hem"},
            {"ease", 0.1f, 0.0f, 0.5f, "hip circumference added to the body's"},
            {"legOpening", 0.42f, 0.2f, 0.8f, "circumference of each leg's hem"},
            offset};
  throw Error("unknown garment type '" + type + "' (known: tshirt, skirt, trousers)");
}

Garment makeParametricGarment(const std::string& type, const Character& body, const Params& parameters) {
  BodyMeasurements measurements = measureBody(body);
  Params values = resolve(type, parameters, bodyScale(measurements));
  Garment g = type == "tshirt"  ? makeTShirt(measurements, values)
              : type == "skirt" ? makeSkirt(measurements, values)
                                : makeTrousers(measurements, values);
  g.recipe = {type, values};
  g.validate();
  return g;
}

Garment rebuildParametricGarment(const Garment& garment, const Character& body) {
  if (garment.recipe.type.empty()) throw Error("garment '" + garment.name + "' is not a built-in garment");
  Garment rebuilt = makeParametricGarment(garment.recipe.type, body, garment.recipe.parameters);
  rebuilt.name = garment.name;
  rebuilt.fabric = garment.fabric;
  rebuilt.customFabric = garment.customFabric;
  rebuilt.targetEdgeLength = garment.targetEdgeLength;
  return rebuilt;
}

}  // namespace mq
