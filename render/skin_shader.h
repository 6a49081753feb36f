#pragma once
// Physically based skin for the character's surfaces (survey §1.3-1.5;
// research brief ../shared/docs/research/skin-appearance.md §0, §5.1), as
// vtkShaderProperty replacements on a SurfaceMapper:
//  - subsurface scattering pre-integrated over the surface's curvature
//    (Penner and Borshukov, "Pre-integrated skin shading", GPU Pro 2, 2011):
//    per light, one fetch of the table D(N.L, curvature) built from the
//    skin's own diffusion profile (render/skin_lut_texture.h), curvature per
//    vertex from the rest mesh;
//  - specular of Kelemen and Szirmay-Kalos with a Beckmann distribution and
//    Schlick's Fresnel at F0 = 0.028 (d'Eon and Luebke, GPU Gems 3 ch. 14),
//    two lobes mixed as Unreal's dual specular;
//  - the survey's rim term (1 - N.V)^k for lights behind (§1.4.1, [Nvi02]);
//  - translucency of thin parts: the diffusion transmittance exp(-d sigma_tr)
//    per channel through the per-vertex inward thickness d, shaped by
//    saturate(0.3 + N_back.L) (Jimenez et al., "Real-time realistic skin
//    translucency", IEEE CG&A 2010);
//  - micro-relief: cellular plateaus and furrows on the rest position
//    (§1.3.3; core/geometry/cellular_relief.h), faded out below 4 px a cell;
//  - Volino wrinkles (§1.3.2): height t(l/L) from the per-vertex compression,
//    a sinusoidal bump across the compression direction.
// Both bumps are rest-space height gradients carried to view space through
// the triangle's rest-to-view Jacobian, read from screen derivatives of the
// interpolated rest position (Mikkelsen, "Bump mapping unparametrized
// surfaces on the GPU", 2010): exact per triangle, no tangents needed.

#include "render/surface_shading.h"

namespace mq::optics {
struct SkinOptics;
}

namespace mq::render {

// The scattering profile a look names (its preset, else its tone).
optics::SkinOptics skinOpticsOf(const SurfaceLook& look);

// Installs the skin shader on `actor`, whose mapper is a SurfaceMapper.
void applySkinShading(vtkActor* actor, const SurfaceLook& look, vtkTexture* albedoMap);

}  // namespace mq::render
