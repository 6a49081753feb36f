#pragma once
// The layers and texts of Mannequin's DXF patterns, shared by the writer and
// the reader (see pattern_dxf.h): the AAMA/ASTM D6673 layer numbers, and the
// texts that carry what DXF has no entity for.

#include <optional>
#include <string>

#include "core/garment/panel_placement.h"

namespace mq::dxf_layers {

constexpr const char* kBoundary = "1";
constexpr const char* kTurnPoints = "2";
constexpr const char* kNotches = "4";
constexpr const char* kGrainLine = "7";
constexpr const char* kSewLine = "14";
constexpr const char* kEdgeNames = "MQ_EDGE";
constexpr const char* kSeams = "MQ_SEAM";
constexpr const char* kPlacement = "MQ_PLACEMENT";

constexpr const char* kPieceNamePrefix = "Piece Name: ";
constexpr const char* kStyleNamePrefix = "Style Name: ";

// "cylinder RADIUS CX CY CZ AX AY AZ FX FY FZ U V BONE" (or "plane ..."),
// metres; the bone name last, as it may hold spaces.
std::string placementText(const PanelPlacement& placement);
// nullopt when the text is not a placement or holds a non-finite number.
std::optional<PanelPlacement> placementFromText(const std::string& text);

}  // namespace mq::dxf_layers
