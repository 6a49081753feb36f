#pragma once
// Surface looks for the character's meshes.

#include <glm/glm.hpp>

class vtkActor;

namespace mq::render {

// The mannequin look: light warm wood with a soft sheen. Meshes that carry a
// colour of their own (not the default grey) keep it, with the same sheen.
void applyMannequinMaterial(vtkActor* actor, const glm::vec3& baseColor);

}  // namespace mq::render
