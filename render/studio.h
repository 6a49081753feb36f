#pragma once
// The studio look shared by every view: three-point lighting and a gradient
// backdrop. Lights are camera lights, so the look holds while the user orbits:
// the key from the upper left of the viewer, a cool fill from the right, and
// a strong rim from behind that outlines the silhouette.

class vtkRenderer;

namespace mq::render {

void addThreePointLights(vtkRenderer* renderer);
void setStudioBackground(vtkRenderer* renderer);
// Image-based lighting for physically based materials: a neutral studio
// environment (soft sky, a large warm softbox at the key's side, a dark
// floor) generated here, so no file is needed. Off when `enabled` is false
// (VTK then skips its precomputation).
void useStudioEnvironment(vtkRenderer* renderer, bool enabled);

}  // namespace mq::render
