// Writes a garment's pattern as AAMA-style DXF through dxflib (see pattern_dxf.h).
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <set>

#include <dl_dxf.h>

#include "core/garment/pattern_dxf.h"
#include "core/garment/pattern_dxf_layers.h"
#include "core/garment/pattern_outline.h"
#include "core/util/atomic_file.h"
#include "core/util/error.h"

namespace mq {
namespace {

constexpr double kMillimetres = 1000.0;  // pattern metres to drawing units
constexpr double kMargin = 20.0;         // mm between panels
constexpr double kNameHeight = 12.0;     // mm
constexpr double kLabelHeight = 4.0;     // mm, edge names and seam numbers
constexpr float kNotchDepth = 0.006f;    // metres into the panel

struct Layer {
  const char* name;
  int colour;
  bool off;
};
const Layer kLayers[] = {
    {"0", 7, false},
    {dxf_layers::kBoundary, 7, false},
    {dxf_layers::kTurnPoints, 3, false},
    {dxf_layers::kNotches, 1, false},
    {dxf_layers::kGrainLine, 5, false},
    {dxf_layers::kSewLine, 4, false},
    {dxf_layers::kEdgeNames, 8, false},
    {dxf_layers::kSeams, 1, false},
    {dxf_layers::kPlacement, 8, true},
};

DL_Attributes on(const char* layer) { return DL_Attributes(layer, 256, -1, -1, "BYLAYER"); }

// A text left-aligned on its baseline at `at` (millimetres).
DL_TextData text(glm::dvec2 at, double height, const std::string& value) {
  return DL_TextData(at.x, at.y, 0.0, at.x, at.y, 0.0, height, 1.0, 0, 0, 0, value, "STANDARD", 0.0);
}

glm::dvec2 mm(glm::vec2 p) { return glm::dvec2(p) * kMillimetres; }

// A block name AutoCAD accepts, unique in the file.
std::string blockName(const std::string& panelName, std::set<std::string>& taken) {
  std::string name;
  for (char c : panelName) name += std::string("<>/\\\":;?*|=`,").find(c) == std::string::npos && c >= ' ' ? c : '_';
  if (name.empty()) name = "piece";
  std::string unique = name;
  for (int i = 2; !taken.insert(unique).second; ++i) unique = name + "_" + std::to_string(i);
  return unique;
}

class PatternDxfWriter {
 public:
  PatternDxfWriter(const Garment& garment, float allowance) : garment_(garment), allowance_(allowance) {}

  void write(const std::string& file) {
    std::unique_ptr<DL_WriterA> writer(dxf_.out(file.c_str(), DL_Codes::AC1015));
    if (!writer) throw Error("cannot open a scratch file for the DXF writer");
    dw_ = writer.get();
    std::set<std::string> taken;
    for (const Panel& panel : garment_.panels) blocks_.push_back(blockName(panel.name, taken));
    writeHeaderAndTables();
    dw_->sectionBlocks();
    for (const char* space : {"*Model_Space", "*Paper_Space", "*Paper_Space0"}) {
      dxf_.writeBlock(*dw_, DL_BlockData(space, 0, 0.0, 0.0, 0.0));
      dxf_.writeEndBlock(*dw_, space);
    }
    for (size_t i = 0; i < garment_.panels.size(); ++i) writePanelBlock(i);
    dw_->sectionEnd();
    writeLayout();
    dxf_.writeObjects(*dw_);
    dxf_.writeObjectsEnd(*dw_);
    dw_->dxfEOF();
    dw_->close();
  }

 private:
  void writeHeaderAndTables() {
    dxf_.writeHeader(*dw_);
    dw_->dxfString(9, "$INSUNITS");
    dw_->dxfInt(70, 4);  // millimetres
    dw_->dxfString(9, "$MEASUREMENT");
    dw_->dxfInt(70, 1);  // metric
    dw_->sectionEnd();
    dw_->sectionTables();
    dxf_.writeVPort(*dw_);
    dw_->tableLinetypes(3);
    dxf_.writeLinetype(*dw_, DL_LinetypeData("BYBLOCK", "", 0, 0, 0.0));
    dxf_.writeLinetype(*dw_, DL_LinetypeData("BYLAYER", "", 0, 0, 0.0));
    dxf_.writeLinetype(*dw_, DL_LinetypeData("CONTINUOUS", "Solid line", 0, 0, 0.0));
    dw_->tableEnd();
    dw_->tableLayers(int(std::size(kLayers)));
    for (const Layer& layer : kLayers)
      dxf_.writeLayer(*dw_, DL_LayerData(layer.name, 0, layer.off),
                      DL_Attributes("", layer.colour, 100, "CONTINUOUS", 1.0));
    dw_->tableEnd();
    dw_->tableStyle(1);
    dxf_.writeStyle(*dw_, DL_StyleData("STANDARD", 0, 0.0, 1.0, 0.0, 0, 2.5, "txt", ""));
    dw_->tableEnd();
    dxf_.writeView(*dw_);
    dxf_.writeUcs(*dw_);
    dw_->tableAppid(1);
    dxf_.writeAppid(*dw_, "ACAD");
    dw_->tableEnd();
    dxf_.writeDimStyle(*dw_, 2.5, 0.625, 0.625, 0.625, 2.5);
    dxf_.writeBlockRecord(*dw_);
    for (const std::string& block : blocks_) dxf_.writeBlockRecord(*dw_, block);
    dw_->tableEnd();
    dw_->sectionEnd();
  }

  void writeEdge(const Panel& panel, int edge) {
    const PanelEdge& e = panel.edges[edge];
    const glm::dvec2 start = mm(panel.edgeStart(edge)), end = mm(panel.edgeEnd(edge));
    if (e.shape == EdgeShape::Line) {
      dxf_.writeLine(*dw_, DL_LineData(start.x, start.y, 0.0, end.x, end.y, 0.0), on(dxf_layers::kSewLine));
      return;
    }
    // A Bezier curve is the B-spline of its degree with a clamped single-span knot vector.
    std::vector<glm::dvec2> controls = {start, mm(e.control[0])};
    if (e.shape == EdgeShape::Cubic) controls.push_back(mm(e.control[1]));
    controls.push_back(end);
    const int degree = int(controls.size()) - 1;
    dxf_.writeSpline(*dw_, DL_SplineData(degree, 2 * (degree + 1), int(controls.size()), 0, 8),
                     on(dxf_layers::kSewLine));
    for (int k = 0; k < 2 * (degree + 1); ++k) dxf_.writeKnot(*dw_, DL_KnotData(k <= degree ? 0.0 : 1.0));
    for (glm::dvec2 c : controls) dxf_.writeControlPoint(*dw_, DL_ControlPointData(c.x, c.y, 0.0, 1.0));
  }

  void writePolygon(const std::vector<glm::vec2>& polygon, const char* layer) {
    dxf_.writePolyline(*dw_, DL_PolylineData(int(polygon.size()), 0, 0, 1), on(layer));
    for (glm::vec2 p : polygon) dxf_.writeVertex(*dw_, DL_VertexData(mm(p).x, mm(p).y, 0.0, 0.0));
    dxf_.writePolylineEnd(*dw_);
  }

  void writeSeamMarks(size_t panelIndex) {
    const Panel& panel = garment_.panels[panelIndex];
    for (size_t s = 0; s < garment_.seams.size(); ++s) {
      const Seam& seam = garment_.seams[s];
      for (bool sideA : {true, false}) {
        if ((sideA ? seam.panelA : seam.panelB) != panel.name) continue;
        const int edge = panel.findEdge(sideA ? seam.edgeA : seam.edgeB);
        const PatternSegment notch = edgeNotch(panel, edge, kNotchDepth);
        const glm::vec2 inward = glm::normalize(notch.to - notch.from);
        const glm::dvec2 from = mm(notch.from - inward * allowance_), to = mm(notch.to);
        dxf_.writeLine(*dw_, DL_LineData(from.x, from.y, 0.0, to.x, to.y, 0.0), on(dxf_layers::kNotches));
        const std::string label = "seam " + std::to_string(s + 1) +
                                  (sideA           ? " a"
                                   : seam.reversed ? " b reversed"
                                                   : " b");
        dxf_.writeText(*dw_, text(mm(notch.from), kLabelHeight, label), on(dxf_layers::kSeams));
      }
    }
  }

  void writePanelBlock(size_t index) {
    const Panel& panel = garment_.panels[index];
    dxf_.writeBlock(*dw_, DL_BlockData(blocks_[index], 0, 0.0, 0.0, 0.0));
    writePolygon(cuttingLine(panel, allowance_), dxf_layers::kBoundary);
    const PatternSegment grain = grainLine(panel);
    const glm::dvec2 from = mm(grain.from), to = mm(grain.to);
    dxf_.writeLine(*dw_, DL_LineData(from.x, from.y, 0.0, to.x, to.y, 0.0), on(dxf_layers::kGrainLine));
    dxf_.writeText(*dw_,
                   text(from + 0.75 * (to - from) + glm::dvec2(0.4 * kNameHeight, 0.0), kNameHeight,
                        std::string(dxf_layers::kPieceNamePrefix) + panel.name),
                   on(dxf_layers::kBoundary));
    for (int e = 0; e < panel.edgeCount(); ++e) {
      const glm::dvec2 corner = mm(panel.corners[e]);
      dxf_.writePoint(*dw_, DL_PointData(corner.x, corner.y, 0.0), on(dxf_layers::kTurnPoints));
      writeEdge(panel, e);
      dxf_.writeText(*dw_, text(mm(panel.sampleEdge(e, 2)[1]), kLabelHeight, panel.edges[e].name),
                     on(dxf_layers::kEdgeNames));
    }
    writeSeamMarks(index);
    dxf_.writeText(*dw_, text({0.0, 0.0}, kLabelHeight, dxf_layers::placementText(panel.placement)),
                   on(dxf_layers::kPlacement));
    dxf_.writeEndBlock(*dw_, blocks_[index]);
  }

  // Model space: the panels side by side, tops level, under the style name.
  void writeLayout() {
    dw_->sectionEntities();
    dxf_.writeText(*dw_, text({0.0, kMargin}, kNameHeight, std::string(dxf_layers::kStyleNamePrefix) + garment_.name),
                   on(dxf_layers::kBoundary));
    double left = 0.0;
    for (size_t i = 0; i < garment_.panels.size(); ++i) {
      const std::vector<glm::vec2> outline = cuttingLine(garment_.panels[i], allowance_);
      glm::dvec2 low = mm(outline[0]), high = low;
      for (glm::vec2 p : outline) low = glm::min(low, mm(p)), high = glm::max(high, mm(p));
      dxf_.writeInsert(*dw_, DL_InsertData(blocks_[i], left - low.x, -high.y, 0.0, 1.0, 1.0, 1.0, 0.0, 1, 1, 0.0, 0.0),
                       on("0"));
      left += high.x - low.x + kMargin;
    }
    dw_->sectionEnd();
  }

  const Garment& garment_;
  const float allowance_;
  DL_Dxf dxf_;
  DL_WriterA* dw_ = nullptr;
  std::vector<std::string> blocks_;
};

}  // namespace

void writePatternDxf(const std::string& path, const Garment& garment, const PatternDxfOptions& options) {
  garment.validate();
  checkSeamAllowance(options.seamAllowance);
  // dxflib writes to a named file: a scratch file, then an atomic save of its text.
  std::string scratch = (std::filesystem::temp_directory_path() / "mannequin-pattern-XXXXXX").string();
  const int fd = mkstemp(scratch.data());
  if (fd < 0) throw FileError(path, "cannot create a scratch file to write the DXF");
  close(fd);
  try {
    PatternDxfWriter(garment, options.seamAllowance).write(scratch);
    const std::string dxfText = readFileText(scratch);
    std::filesystem::remove(scratch);
    writeFileAtomically(path, [&](std::ostream& out) { out << dxfText; });
  } catch (...) {
    std::error_code ignored;
    std::filesystem::remove(scratch, ignored);
    throw;
  }
}

}  // namespace mq
