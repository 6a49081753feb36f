#pragma once
// The studio look shared by every view: three-point lighting and a gradient
// backdrop. Lights are camera lights, so the look holds while the user orbits:
// the key from the upper left of the viewer, a cool fill from the right, and
// a strong rim from behind that outlines the silhouette.

class vtkRenderer;

namespace mq::render {

void addThreePointLights(vtkRenderer* renderer);
void setStudioBackground(vtkRenderer* renderer);

}  // namespace mq::render
