// Reads a DXF sewing pattern through dxflib (see pattern_dxf.h): dxflib hands
// over entities, which are gathered per block, chained into closed outlines
// and turned into panels, edges, seams and placements.
#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <map>
#include <set>
#include <sstream>
#include <unordered_map>

#include <glm/gtc/type_precision.hpp>

#include <dl_creationadapter.h>
#include <dl_dxf.h>
#include <nlohmann/json.hpp>

#include "core/garment/garment_json.h"
#include "core/garment/pattern_dxf.h"
#include "core/garment/pattern_dxf_layers.h"
#include "core/garment/pattern_dxf_scan.h"
#include "core/garment/pattern_fit.h"
#include "core/util/atomic_file.h"
#include "core/util/error.h"

namespace mq {
namespace {

constexpr size_t kMaxPoints = 1000000;  // vertices, control points and arc samples in all
constexpr size_t kMaxPanels = 500;
constexpr int kMaxEdgesPerPanel = 10000;
constexpr size_t kMaxTexts = 100000;
constexpr double kMaxCoordinate = 1e7;  // drawing units
constexpr double kArcStep = 5.0 * M_PI / 180.0;

struct DxfCurve {
  enum class Kind { Line, Bezier, Polyline };
  Kind kind = Kind::Polyline;
  std::string layer, container;    // container: the block, "" for model space
  std::vector<glm::dvec2> points;  // Bezier: its 3 or 4 control points
  bool closed = false;
};

struct DxfMark {  // a text or a point
  std::string layer, container, text;
  glm::dvec2 at{0.0};
};

struct DxfDrawing {
  std::vector<DxfCurve> curves;
  std::vector<DxfMark> texts, points;
  int units = 0;  // $INSUNITS
  size_t pointCount = 0;
  bool tooLarge = false, badNumber = false;
};

// Points along the arc from angle a0 to a1 (radians, counter-clockwise).
void appendArc(std::vector<glm::dvec2>& out, glm::dvec2 centre, double radius, double a0, double a1) {
  while (a1 < a0) a1 += 2.0 * M_PI;
  const int steps = std::clamp(int(std::ceil((a1 - a0) / kArcStep)), 1, 72);
  for (int i = 0; i <= steps; ++i) {
    const double a = a0 + (a1 - a0) * i / steps;
    out.push_back(centre + radius * glm::dvec2(std::cos(a), std::sin(a)));
  }
}

// A polyline segment from a to b with a bulge (tan of a quarter of its arc's angle; negative: clockwise).
void appendBulge(std::vector<glm::dvec2>& out, glm::dvec2 a, glm::dvec2 b, double bulge) {
  const double chord = glm::length(b - a);
  if (std::abs(bulge) < 1e-9 || chord < 1e-12) {
    out.push_back(b);
    return;
  }
  const double angle = 4.0 * std::atan(bulge);
  const double radius = chord / (2.0 * std::sin(std::abs(angle) / 2.0));
  const glm::dvec2 middle = 0.5 * (a + b), along = (b - a) / chord, left(-along.y, along.x);
  const double offset = std::sqrt(std::max(radius * radius - 0.25 * chord * chord, 0.0));
  const bool major = std::abs(angle) > M_PI;
  const glm::dvec2 centre = middle + left * (offset * ((bulge > 0.0) != major ? 1.0 : -1.0));
  const int steps = std::clamp(int(std::ceil(std::abs(angle) / kArcStep)), 1, 72);
  const double a0 = std::atan2(a.y - centre.y, a.x - centre.x);
  for (int i = 1; i < steps; ++i) {
    const double t = a0 + angle * i / steps;
    out.push_back(centre + radius * glm::dvec2(std::cos(t), std::sin(t)));
  }
  out.push_back(b);
}

// A B-spline (rational if weighted) sampled along its knot span, by de Boor.
std::vector<glm::dvec2> sampleSpline(const std::vector<glm::dvec3>& weighted, const std::vector<double>& knots,
                                     int degree) {
  const int n = int(weighted.size());
  const double t0 = knots[size_t(degree)], t1 = knots[size_t(n)];
  const int samples = std::clamp(16 * (n - degree), 16, 4096);
  std::vector<glm::dvec2> out;
  for (int s = 0; s <= samples; ++s) {
    const double t = t0 + (t1 - t0) * s / samples;
    int k = degree;
    while (k < n - 1 && t >= knots[size_t(k + 1)]) ++k;
    std::vector<glm::dvec3> d(weighted.begin() + (k - degree), weighted.begin() + k + 1);
    for (int r = 1; r <= degree; ++r)
      for (int j = degree; j >= r; --j) {
        const double span = knots[size_t(j + 1 + k - r)] - knots[size_t(j + k - degree)];
        const double alpha = span > 0.0 ? (t - knots[size_t(j + k - degree)]) / span : 0.0;
        d[size_t(j)] = (1.0 - alpha) * d[size_t(j - 1)] + alpha * d[size_t(j)];
      }
    const glm::dvec3 p = d[size_t(degree)];
    out.push_back(std::abs(p.z) > 1e-12 ? glm::dvec2(p) / p.z : glm::dvec2(p));
  }
  return out;
}

// Gathers what a pattern needs from dxflib's callbacks.
class DxfCollector : public DL_CreationAdapter {
 public:
  explicit DxfCollector(DxfDrawing& drawing) : drawing_(drawing) {}

  void addBlock(const DL_BlockData& data) override {
    finish();
    container_ = data.name;
  }
  void endBlock() override {
    finish();
    container_.clear();
  }
  void setVariableInt(const std::string& key, int value, int) override {
    if (key == "$INSUNITS") drawing_.units = value;
  }
  void addLine(const DL_LineData& d) override {
    finish();
    DxfCurve curve = started(DxfCurve::Kind::Line);
    curve.points = {{d.x1, d.y1}, {d.x2, d.y2}};
    keep(std::move(curve));
  }
  void addArc(const DL_ArcData& d) override {
    finish();
    DxfCurve curve = started(DxfCurve::Kind::Polyline);
    appendArc(curve.points, {d.cx, d.cy}, d.radius, d.angle1 * M_PI / 180.0, d.angle2 * M_PI / 180.0);
    keep(std::move(curve));
  }
  void addCircle(const DL_CircleData& d) override {
    finish();
    DxfCurve curve = started(DxfCurve::Kind::Polyline);
    appendArc(curve.points, {d.cx, d.cy}, d.radius, 0.0, 2.0 * M_PI);
    curve.points.pop_back();
    curve.closed = true;
    keep(std::move(curve));
  }
  void addPolyline(const DL_PolylineData& d) override {
    finish();
    pending_ = started(DxfCurve::Kind::Polyline);
    pending_->closed = (d.flags & 1) != 0;
  }
  void addVertex(const DL_VertexData& d) override {
    if (!pending_ || pending_->kind != DxfCurve::Kind::Polyline) return;
    vertices_.push_back({d.x, d.y});
    bulges_.push_back(d.bulge);
    count(1);
  }
  void addSpline(const DL_SplineData& d) override {
    finish();
    pending_ = started(DxfCurve::Kind::Bezier);
    degree_ = int(d.degree);
  }
  void addControlPoint(const DL_ControlPointData& d) override {
    if (!pending_ || pending_->kind != DxfCurve::Kind::Bezier) return;
    controls_.push_back({d.x * d.w, d.y * d.w, d.w});
    count(1);
  }
  void addFitPoint(const DL_FitPointData& d) override {
    if (!pending_ || pending_->kind != DxfCurve::Kind::Bezier) return;
    fitPoints_.push_back({d.x, d.y});
    count(1);
  }
  void addKnot(const DL_KnotData& d) override {
    if (!pending_ || pending_->kind != DxfCurve::Kind::Bezier) return;
    knots_.push_back(d.k);
    count(1);
  }
  void addPoint(const DL_PointData& d) override {
    finish();
    drawing_.points.push_back({attributes.getLayer(), container_, "", checked({d.x, d.y})});
    count(1);
  }
  void addText(const DL_TextData& d) override {
    finish();
    // dxflib gives NaN for an alignment point the file leaves out.
    const bool aligned =
        (d.hJustification != 0 || d.vJustification != 0) && std::isfinite(d.apx) && std::isfinite(d.apy);
    drawing_.texts.push_back({attributes.getLayer(), container_, d.text,
                              checked(aligned ? glm::dvec2(d.apx, d.apy) : glm::dvec2(d.ipx, d.ipy))});
    count(1);
  }
  void addInsert(const DL_InsertData&) override { finish(); }
  void endEntity() override { finish(); }
  void endSequence() override { finish(); }
  void endSection() override { finish(); }

  // The entity being read, once all its parts arrived.
  void finish() {
    if (!pending_) return;
    DxfCurve curve = std::move(*pending_);
    pending_.reset();
    if (curve.kind == DxfCurve::Kind::Polyline)
      finishPolyline(curve);
    else
      finishSpline(curve);
    vertices_.clear(), bulges_.clear(), controls_.clear(), knots_.clear(), fitPoints_.clear();
    if (curve.points.size() >= 2) keep(std::move(curve));
  }

 private:
  DxfCurve started(DxfCurve::Kind kind) const {
    DxfCurve curve;
    curve.kind = kind;
    curve.layer = attributes.getLayer();
    curve.container = container_;
    return curve;
  }
  // Every coordinate read, curves', texts' and points' alike (NaN fails too).
  glm::dvec2 checked(const glm::dvec2& p) {
    if (!(std::abs(p.x) < kMaxCoordinate && std::abs(p.y) < kMaxCoordinate)) drawing_.badNumber = true;
    return p;
  }
  void keep(DxfCurve curve) {
    for (glm::dvec2 p : curve.points) checked(p);
    count(curve.points.size());
    if (!drawing_.tooLarge) drawing_.curves.push_back(std::move(curve));
  }
  void count(size_t points) {
    drawing_.pointCount += points;
    if (drawing_.pointCount > kMaxPoints) drawing_.tooLarge = true;
  }
  void finishPolyline(DxfCurve& curve) {
    if (vertices_.empty()) return;
    curve.points.push_back(vertices_[0]);
    const size_t n = vertices_.size();
    for (size_t i = 0; i + 1 < n || (curve.closed && i < n); ++i)
      appendBulge(curve.points, vertices_[i], vertices_[(i + 1) % n], bulges_[i]);
    if (curve.closed) curve.points.pop_back();  // the first vertex again
  }
  // A single-span clamped spline of degree 2 or 3 is a Bezier curve; others are sampled.
  void finishSpline(DxfCurve& curve) {
    const int n = int(controls_.size());
    const bool unweighted = std::all_of(controls_.begin(), controls_.end(), [](glm::dvec3 c) { return c.z == 1.0; });
    const bool validKnots = degree_ >= 1 && degree_ <= 10 && n > degree_ && knots_.size() == size_t(n + degree_ + 1) &&
                            std::is_sorted(knots_.begin(), knots_.end()) && knots_[size_t(degree_)] < knots_[size_t(n)];
    if (validKnots && unweighted && (degree_ == 2 || degree_ == 3) && n == degree_ + 1) {
      for (glm::dvec3 c : controls_) curve.points.push_back(glm::dvec2(c));
      return;
    }
    curve.kind = DxfCurve::Kind::Polyline;
    const bool positiveWeights =
        std::all_of(controls_.begin(), controls_.end(), [](glm::dvec3 c) { return c.z > 0.0; });
    if (validKnots && positiveWeights)
      curve.points = sampleSpline(controls_, knots_, degree_);
    else
      curve.points = fitPoints_;
    curve.closed = false;
  }

  DxfDrawing& drawing_;
  std::string container_;
  std::optional<DxfCurve> pending_;
  std::vector<glm::dvec2> vertices_, fitPoints_;
  std::vector<double> bulges_, knots_;
  std::vector<glm::dvec3> controls_;
  int degree_ = 0;
};

double metresPerUnit(int units) {
  switch (units) {
    case 0:  // unitless: the millimetres pattern programs write
    case 4:
      return 0.001;
    case 1:
      return 0.0254;
    case 2:
      return 0.3048;
    case 5:
      return 0.01;
    case 6:
      return 1.0;
    default:
      throw Error("unsupported drawing units ($INSUNITS " + std::to_string(units) +
                  "): write the pattern in millimetres, centimetres, metres, inches or feet");
  }
}

// A closed outline: the curves chained end to end, each running forwards.
using Loop = std::vector<DxfCurve>;

glm::dvec2 startOf(const DxfCurve& c) { return c.points.front(); }
glm::dvec2 endOf(const DxfCurve& c) { return c.closed ? c.points.front() : c.points.back(); }
void reverse(DxfCurve& c) { std::reverse(c.points.begin(), c.points.end()); }

// Points by grid cells of the matching tolerance, so that finding the
// points near another one costs its neighbourhood, not the whole drawing (a
// hostile file may hold hundreds of thousands of lines). Entries can be
// taken out and put back.
class PointGrid {
 public:
  explicit PointGrid(double tolerance) : tolerance_(tolerance) {}
  void add(glm::dvec2 p, size_t id) {
    std::vector<Entry>& entries = cells_[key(cellOf(p))];
    if (slot_.size() <= id) slot_.resize(id + 1, npos);
    slot_[id] = entries.size();
    entries.push_back({p, id});
  }
  // In constant time, however many points share its cell (the entry's slot is kept).
  void remove(glm::dvec2 p, size_t id) {
    auto cell = cells_.find(key(cellOf(p)));
    if (cell == cells_.end() || id >= slot_.size() || slot_[id] == npos) return;
    std::vector<Entry>& entries = cell->second;
    const size_t at = slot_[id];
    entries[at] = entries.back();
    slot_[entries[at].id] = at;
    entries.pop_back();
    slot_[id] = npos;
  }
  // The first entry within the tolerance of p that `wanted` accepts; npos if none.
  template <class Wanted>
  size_t find(glm::dvec2 p, Wanted&& wanted) const {
    size_t found = npos;
    visitNear(p, [&](size_t id) { return (found = wanted(id) ? id : npos) != npos; });
    return found;
  }
  // Every entry within the tolerance of p.
  template <class Visit>
  void forEachNear(glm::dvec2 p, Visit&& visit) const {
    visitNear(p, [&](size_t id) { return visit(id), false; });
  }
  static constexpr size_t npos = size_t(-1);

 private:
  struct Entry {
    glm::dvec2 p;
    size_t id;
  };
  // Calls stop(id) for the entries near p until it returns true.
  template <class Stop>
  void visitNear(glm::dvec2 p, Stop&& stop) const {
    const glm::i64vec2 c = cellOf(p);
    for (int64_t dx = -1; dx <= 1; ++dx)
      for (int64_t dy = -1; dy <= 1; ++dy) {
        auto cell = cells_.find(key(c + glm::i64vec2(dx, dy)));
        if (cell == cells_.end()) continue;
        for (const Entry& e : cell->second)
          if (glm::length(e.p - p) <= tolerance_ && stop(e.id)) return;
      }
  }
  glm::i64vec2 cellOf(glm::dvec2 p) const {
    return {int64_t(std::floor(p.x / tolerance_)), int64_t(std::floor(p.y / tolerance_))};
  }
  static uint64_t key(glm::i64vec2 c) { return uint64_t(c.x) * 0x9E3779B97F4A7C15ull ^ uint64_t(c.y); }
  double tolerance_;
  std::unordered_map<uint64_t, std::vector<Entry>> cells_;
  std::vector<size_t> slot_;  // by id: its index in its cell
};

// Chains open curves into closed loops (closed curves are loops of their own).
// Returns the loops, and the curves left that close no loop in `open`.
// Endpoint ids: 2 * curve for its start, 2 * curve + 1 for its end.
std::vector<Loop> chainLoops(std::vector<DxfCurve> curves, double tolerance, std::vector<DxfCurve>& open) {
  std::vector<Loop> loops;
  PointGrid ends(tolerance);
  auto take = [&](size_t c) { ends.remove(startOf(curves[c]), 2 * c), ends.remove(endOf(curves[c]), 2 * c + 1); };
  auto putBack = [&](size_t c) { ends.add(startOf(curves[c]), 2 * c), ends.add(endOf(curves[c]), 2 * c + 1); };
  for (size_t c = 0; c < curves.size(); ++c)
    if (!curves[c].closed) putBack(c);
  std::vector<bool> used(curves.size(), false);
  for (size_t first = 0; first < curves.size(); ++first) {
    if (used[first]) continue;
    used[first] = true;
    if (curves[first].closed) {
      loops.push_back({curves[first]});
      continue;
    }
    take(first);
    Loop loop{curves[first]};
    std::vector<size_t> taken{first};
    while (glm::length(endOf(loop.back()) - startOf(loop.front())) > tolerance) {
      const size_t found = ends.find(endOf(loop.back()), [](size_t) { return true; });
      if (found == PointGrid::npos) break;
      const size_t next = found / 2;
      used[next] = true;
      take(next);
      taken.push_back(next);
      loop.push_back(curves[next]);
      if (found % 2 == 1) reverse(loop.back());  // met at its end: it runs backwards
    }
    if (loop.size() > 1 && glm::length(endOf(loop.back()) - startOf(loop.front())) <= tolerance) {
      loops.push_back(std::move(loop));
    } else {
      for (size_t i = 1; i < taken.size(); ++i) used[taken[i]] = false, putBack(taken[i]);  // free for another loop
      open.push_back(curves[first]);
    }
  }
  return loops;
}

// The drawing's pieces: per container, the loops on the chosen layer.
struct Piece {
  std::string container;
  Loop loop;
};

std::vector<Piece> findPieces(const DxfDrawing& drawing, double tolerance) {
  auto onLayer = [&](const std::string& layer) {
    return std::any_of(drawing.curves.begin(), drawing.curves.end(),
                       [&](const DxfCurve& c) { return c.layer == layer; });
  };
  const bool sewLines = onLayer(dxf_layers::kSewLine), boundaries = onLayer(dxf_layers::kBoundary);
  std::map<std::string, std::vector<DxfCurve>> byContainer;
  std::vector<std::string> order;
  for (const DxfCurve& c : drawing.curves) {
    if (c.container.rfind("*Paper_Space", 0) == 0 || c.container.rfind("*PAPER_SPACE", 0) == 0) continue;
    const bool wanted = sewLines     ? c.layer == dxf_layers::kSewLine
                        : boundaries ? c.layer == dxf_layers::kBoundary
                                     : true;
    if (!wanted) continue;
    if (!byContainer.count(c.container)) order.push_back(c.container);
    byContainer[c.container].push_back(c);
  }
  std::vector<Piece> pieces;
  for (const std::string& container : order) {
    std::vector<DxfCurve> open;
    for (Loop& loop : chainLoops(byContainer[container], tolerance, open))
      pieces.push_back({container, std::move(loop)});
    if (!open.empty() && (sewLines || boundaries)) {
      const glm::dvec2 gap = endOf(open[0]);
      std::ostringstream where;
      where << "an outline on layer " << open[0].layer << (container.empty() ? "" : " of block \"" + container + "\"")
            << " does not close: nothing continues it from (" << gap.x << ", " << gap.y << ")";
      throw Error(where.str());
    }
  }
  return pieces;
}

// Turn points of a container: the corners a polyline run must keep.
std::vector<glm::dvec2> turnPoints(const DxfDrawing& drawing, const std::string& container) {
  std::vector<glm::dvec2> out;
  for (const DxfMark& p : drawing.points)
    if (p.container == container && p.layer == dxf_layers::kTurnPoints) out.push_back(p.at);
  return out;
}

// The loop as panel corners and edges (metres, in the loop's own direction).
Panel panelFromLoop(const Loop& loop, double scale, const std::vector<glm::dvec2>& turns, double tolerance) {
  Panel panel;
  auto metres = [&](glm::dvec2 p) { return glm::vec2(p * scale); };
  for (const DxfCurve& curve : loop) {
    if (curve.kind == DxfCurve::Kind::Line) {
      panel.addLine("", metres(curve.points[0]));
    } else if (curve.kind == DxfCurve::Kind::Bezier) {
      if (curve.points.size() == 3)
        panel.addQuadratic("", metres(curve.points[0]), metres(curve.points[1]));
      else
        panel.addCubic("", metres(curve.points[0]), metres(curve.points[1]), metres(curve.points[2]));
    } else {
      std::vector<glm::vec2> run;
      for (glm::dvec2 p : curve.points) run.push_back(metres(p));
      if (curve.closed) run.push_back(run.front());
      std::vector<bool> corner(run.size(), false);
      PointGrid turnGrid(tolerance);
      for (size_t t = 0; t < turns.size(); ++t) turnGrid.add(turns[t], t);
      for (size_t i = 0; i < curve.points.size(); ++i)
        corner[i] = turnGrid.find(curve.points[i], [](size_t) { return true; }) != PointGrid::npos;
      for (const FittedEdge& edge : fitOutlineRun(run, corner, turns.empty())) {
        if (edge.shape == EdgeShape::Line)
          panel.addLine("", edge.start);
        else
          panel.addCubic("", edge.start, edge.control[0], edge.control[1]);
      }
    }
  }
  // Corners closer than a micrometre (a closed run's repeated start) go.
  for (int e = panel.edgeCount() - 1; e >= 0 && panel.edgeCount() > 3; --e)
    if (glm::length(panel.edgeEnd(e) - panel.edgeStart(e)) < 1e-6f && panel.edges[e].shape == EdgeShape::Line) {
      panel.corners.erase(panel.corners.begin() + e);
      panel.edges.erase(panel.edges.begin() + e);
    }
  return panel;
}

// Counter-clockwise, as Mannequin's panels are: the same corners, edges reversed.
void makeCounterClockwise(Panel& panel) {
  if (panel.area() >= 0.0f) return;
  Panel reversed = panel;
  const int n = panel.edgeCount();
  for (int i = 0; i < n; ++i) {
    const int source = n - 1 - i;  // edge i of the result runs backwards along `source`
    reversed.corners[size_t(i)] = panel.edgeEnd(source);
    reversed.edges[size_t(i)] = panel.edges[size_t(source)];
    std::swap(reversed.edges[size_t(i)].control[0], reversed.edges[size_t(i)].control[1]);
    if (panel.edges[size_t(source)].shape == EdgeShape::Quadratic)
      reversed.edges[size_t(i)].control[0] = panel.edges[size_t(source)].control[0];
  }
  panel = reversed;
}

std::string uniqueName(const std::string& wanted, std::set<std::string>& taken) {
  std::string name = wanted;
  for (int i = 2; !taken.insert(name).second; ++i) name = wanted + " " + std::to_string(i);
  return name;
}

// Panels without a placement: flat, side by side, 35 cm in front of the body, tops at 1.6 m.
void layOutFlat(std::vector<Panel>& panels, const std::vector<bool>& placed) {
  constexpr float kGap = 0.05f, kTop = 1.6f, kFront = 0.35f;
  float width = 0.0f;
  for (size_t i = 0; i < panels.size(); ++i)
    if (!placed[i]) {
      const std::vector<glm::vec2> outline = panels[i].outline(0.01f);
      float low = outline[0].x, high = low;
      for (glm::vec2 p : outline) low = std::min(low, p.x), high = std::max(high, p.x);
      width += high - low + kGap;
    }
  float left = -0.5f * width;
  for (size_t i = 0; i < panels.size(); ++i) {
    if (placed[i]) continue;
    const std::vector<glm::vec2> outline = panels[i].outline(0.01f);
    glm::vec2 low = outline[0], high = low;
    for (glm::vec2 p : outline) low = glm::min(low, p), high = glm::max(high, p);
    PanelPlacement& placement = panels[i].placement;
    placement = PanelPlacement{};
    placement.anchor = {low.x, high.y};
    placement.center = {left, kTop, kFront};
    left += high.x - low.x + kGap;
  }
}

struct SeamSide {
  int panel = -1, edge = -1;
  bool reversed = false;
};

void addSeams(Garment& garment, const std::map<int, std::pair<SeamSide, SeamSide>>& sides) {
  for (const auto& [number, pair] : sides) {
    if (pair.first.panel < 0 || pair.second.panel < 0)
      throw Error("seam " + std::to_string(number) + " (layer " + dxf_layers::kSeams + ") has only one side");
    Seam seam;
    seam.panelA = garment.panels[size_t(pair.first.panel)].name;
    seam.edgeA = garment.panels[size_t(pair.first.panel)].edges[size_t(pair.first.edge)].name;
    seam.panelB = garment.panels[size_t(pair.second.panel)].name;
    seam.edgeB = garment.panels[size_t(pair.second.panel)].edges[size_t(pair.second.edge)].name;
    seam.reversed = pair.second.reversed;
    garment.seams.push_back(seam);
  }
}

Garment garmentFromDrawing(const DxfDrawing& drawing, const std::string& fallbackName) {
  const double scale = metresPerUnit(drawing.units);
  const double tolerance = 1e-4 / scale;  // 0.1 mm in drawing units
  const std::vector<Piece> pieces = findPieces(drawing, tolerance);
  if (pieces.empty())
    throw Error(
        "not a sewing pattern: no closed outline (on layer 14, the sew line, or 1, the boundary, or any "
        "closed polyline)");
  if (pieces.size() > kMaxPanels) throw Error("more than " + std::to_string(kMaxPanels) + " pattern pieces");

  Garment garment;
  garment.name = fallbackName;
  for (const DxfMark& t : drawing.texts)
    if (t.text.rfind(dxf_layers::kStyleNamePrefix, 0) == 0)
      garment.name = t.text.substr(std::strlen(dxf_layers::kStyleNamePrefix));
  std::set<std::string> panelNames;
  std::vector<bool> placed;
  std::map<int, std::pair<SeamSide, SeamSide>> seams;
  for (const Piece& piece : pieces) {
    std::vector<const DxfMark*> texts;
    for (const DxfMark& t : drawing.texts)
      if (t.container == piece.container) texts.push_back(&t);
    Panel panel = panelFromLoop(piece.loop, scale, turnPoints(drawing, piece.container), tolerance);
    std::string name = piece.container.empty() ? "panel " + std::to_string(garment.panels.size() + 1) : piece.container;
    for (const DxfMark* t : texts)
      if (t->text.rfind(dxf_layers::kPieceNamePrefix, 0) == 0)
        name = t->text.substr(std::strlen(dxf_layers::kPieceNamePrefix));
    panel.name = uniqueName(name, panelNames);
    if (panel.edgeCount() > kMaxEdgesPerPanel)
      throw Error("piece \"" + panel.name + "\" has " + std::to_string(panel.edgeCount()) + " edges (at most " +
                  std::to_string(kMaxEdgesPerPanel) + ")");
    if (panel.edgeCount() < 3 || !(std::abs(panel.area()) > 1e-8f))  // 0.01 cm2
      throw Error("piece \"" + panel.name + "\": its outline encloses no area (" + std::to_string(panel.edgeCount()) +
                  " corners)");
    makeCounterClockwise(panel);
    std::set<std::string> edgeNames;
    const int panelIndex = int(garment.panels.size());
    PointGrid textGrid(tolerance * scale);  // texts by where they stand, in metres
    for (size_t t = 0; t < texts.size(); ++t) textGrid.add(texts[t]->at * scale, t);
    for (int e = 0; e < panel.edgeCount(); ++e) {
      const glm::dvec2 middle(panel.sampleEdge(e, 2)[1]);
      const size_t label = textGrid.find(middle, [&](size_t t) { return texts[t]->layer == dxf_layers::kEdgeNames; });
      panel.edges[size_t(e)].name =
          uniqueName(label != PointGrid::npos ? texts[label]->text : "e" + std::to_string(e), edgeNames);
      std::vector<const DxfMark*> marks;
      textGrid.forEachNear(middle, [&](size_t t) {
        if (texts[t]->layer == dxf_layers::kSeams) marks.push_back(texts[t]);
      });
      for (const DxfMark* t : marks) {
        std::istringstream in(t->text);
        std::string word, side, flag;
        int number = 0;
        if (!(in >> word >> number >> side) || word != "seam" || (side != "a" && side != "b") || number < 1) continue;
        in >> flag;
        (side == "a" ? seams[number].first : seams[number].second) = {panelIndex, e, flag == "reversed"};
      }
    }
    bool hasPlacement = false;
    for (const DxfMark* t : texts)
      if (t->layer == dxf_layers::kPlacement)
        if (auto placement = dxf_layers::placementFromText(t->text)) panel.placement = *placement, hasPlacement = true;
    placed.push_back(hasPlacement);
    garment.panels.push_back(std::move(panel));
  }
  layOutFlat(garment.panels, placed);
  addSeams(garment, seams);
  // Through the document's reader, so that an imported pattern meets every check a saved one does.
  return garmentFromJson(garmentToJson(garment), "pattern");
}

}  // namespace

Garment patternFromDxf(const std::string& dxfText, const std::string& fallbackName) {
  checkDxfText(dxfText);
  DxfDrawing drawing;
  DxfCollector collector(drawing);
  std::istringstream in(dxfText);
  DL_Dxf dxf;
  try {
    if (!dxf.in(in, &collector)) throw Error("not a DXF file");
  } catch (const std::exception& e) {  // dxflib's own number conversions throw on malformed values
    if (dynamic_cast<const Error*>(&e)) throw;
    throw Error(std::string("a malformed value the DXF reader refuses (") + e.what() + ")");
  }
  collector.finish();
  if (drawing.tooLarge) throw Error("more than " + std::to_string(kMaxPoints) + " points: too large for a pattern");
  if (drawing.badNumber) throw Error("a coordinate is not a finite number under 10^7");
  if (drawing.texts.size() > kMaxTexts) throw Error("more than " + std::to_string(kMaxTexts) + " texts: not a pattern");
  return garmentFromDrawing(drawing, fallbackName);
}

Garment readPatternDxf(const std::string& path) {
  const std::string text = readFileText(path);
  try {
    return patternFromDxf(text, std::filesystem::path(path).stem().string());
  } catch (const FileError&) {
    throw;
  } catch (const Error& e) {
    throw FileError(path, e.what());
  }
}

}  // namespace mq
