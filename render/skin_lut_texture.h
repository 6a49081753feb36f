#pragma once
// The pre-integrated skin table (Penner 2011; core/optics/preintegrated.h) as
// a VTK texture for the skin shader: 256 N.L columns x 128 curvature rows,
// RGB floats, linear filtering, clamped to the edges. Built once per skin
// (a few tens of ms, on the calling thread) and kept for the process.

#include <string>

#include "core/optics/preintegrated.h"

class vtkTexture;

namespace mq::optics {
struct SkinOptics;
}

namespace mq::render {

// Shared; the caller does not own it. `key` names the skin (its preset, or
// its tone parameters): one table per key.
vtkTexture* preintegratedSkinTexture(const std::string& key, const optics::SkinOptics& skin);

// The layout the shader needs (same for every skin).
const optics::PreintegratedLutSettings& skinLutSettings();

}  // namespace mq::render
