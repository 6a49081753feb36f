#pragma once
// The hair actor's GLSL, as VTK shader replacements on polylines: a vertex
// stage that passes the fibre's tangent and parameters, and one fragment
// stage per shading model, each in a file named for its method:
//  - kajiya_kay_shader.cpp: Kajiya-Kay diffuse with two shifted highlights
//    (Scheuermann after Marschner et al.), plus the parts both models share
//    (the fibre's frame, the screen-door tip fade);
//  - hair_fibre_shader.cpp: the physically based fibre of
//    core/optics/hair_bsdf.h (d'Eon's longitudinal lobes in the shader, the
//    azimuthal terms from a table the core computes).
// A fragment replacement of //VTK::Light::Impl is kHairFibreFrame + one
// model's lighting + kHairTipFade. Lights come as view_lights.h's uniforms.

#include <string>

namespace mq::render {

// //VTK::Normal::Dec and //VTK::Light::Impl of the vertex shader.
extern const char* const kHairVertexDec;
extern const char* const kHairVertexImpl;

// Fragment parts shared by both models.
extern const char* const kHairFibreFrame;  // opens the block: T, V, volumeNormal, along, shadow
extern const char* const kHairTipFade;     // closes it: writes `color`, thinning at the tips

// Kajiya-Kay: //VTK::Normal::Dec of the fragment shader, and the lighting.
extern const char* const kKajiyaKayFragmentDec;
extern const char* const kKajiyaKayLighting;

// The physical fibre: its table's size (azimuths x exit angles), the
// fragment declarations (with the table's size and M_p's functions), and
// the lighting.
constexpr int kTablePhi = 32, kTableTheta = 8;
std::string physicalHairFragmentDec();
extern const char* const kPhysicalHairLighting;

}  // namespace mq::render
